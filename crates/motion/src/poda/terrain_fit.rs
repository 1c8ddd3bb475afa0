//! Whether a PODA creature can walk its ground at all (issue 45, "a rise
//! larger than the creature"): checked once, when the walk is built, so
//! ground the creature cannot cross is refused naming the field rather
//! than walked through. The lab's reading, since the paper walks on a floor:
//!
//! - **Stairs**: a rise as high as the lowest hip stands above the ground
//!   (or higher) would put the body into the riser before its feet are up
//!   (the body rides the supporting feet: eq. 12–13 on the ground under
//!   them, [`super::terrain_feet`]).
//! - **A plane** steeper than [`MAX_FOOTHOLD_SLOPE_DEG`]: no spot on it is
//!   an acceptable foothold.
//! - **Rough ground** whose bumps reach as high as the lowest hip.
//!
//! A height field is not refused as a whole: the foothold rule moves the
//! feet off its spots too steep or near an edge, one by one.

use gaitlab_core::terrain::Terrain;

use super::terrain_feet::MAX_FOOTHOLD_SLOPE_DEG;
use crate::DriverError;

/// Checks `terrain` against a creature named `name` whose lowest hip stands
/// `lowest_hip_m` above the ground.
///
/// # Errors
/// A [`DriverError`] at `scenario.terrain.rise_m`, `.slope_deg` or
/// `.difficulty` saying what the creature cannot do.
pub fn check_fits(terrain: &Terrain, name: &str, lowest_hip_m: f64) -> Result<(), DriverError> {
    match terrain {
        Terrain::Stairs(stairs) if stairs.rise_m.abs() >= lowest_hip_m => Err(DriverError::new(
            "scenario.terrain.rise_m",
            format!(
                "a {:.3} m step is as high as {name}'s hips stand ({lowest_hip_m:.3} m above the \
                 ground): its body would run into the riser; rises below {lowest_hip_m:.3} m",
                stairs.rise_m.abs()
            ),
        )),
        Terrain::Plane(plane) if plane.slope_deg.abs() > MAX_FOOTHOLD_SLOPE_DEG => {
            Err(DriverError::new(
                "scenario.terrain.slope_deg",
                format!(
                    "{}° is steeper than a foot may stand ({MAX_FOOTHOLD_SLOPE_DEG}°): no \
                     foothold on it",
                    plane.slope_deg
                ),
            ))
        }
        Terrain::Rough(rough) if rough.difficulty * rough.max_height_m >= lowest_hip_m => {
            Err(DriverError::new(
                "scenario.terrain.difficulty",
                format!(
                    "bumps up to {:.3} m are as high as {name}'s hips stand ({lowest_hip_m:.3} m \
                     above the ground); a difficulty below {:.2}",
                    rough.difficulty * rough.max_height_m,
                    lowest_hip_m / rough.max_height_m
                ),
            ))
        }
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use gaitlab_core::terrain::{Plane, Rough, Stairs};

    use super::*;

    fn stairs(rise_m: f64) -> Terrain {
        Terrain::Stairs(Stairs {
            rise_m,
            run_m: 0.3,
            count: 4,
            direction_deg: 90.0,
            start_m: 0.5,
        })
    }

    #[test]
    fn a_rise_as_high_as_the_hips_is_refused_naming_it() {
        assert!(check_fits(&stairs(0.05), "hexapod", 0.08).is_ok());
        assert!(check_fits(&stairs(-0.07), "hexapod", 0.08).is_ok());
        let error = check_fits(&stairs(-0.08), "hexapod", 0.08).expect_err("as high as the hips");
        assert_eq!(error.path, "scenario.terrain.rise_m");
        assert!(error.reason.contains("hexapod's hips"), "{}", error.reason);
    }

    #[test]
    fn a_plane_too_steep_and_bumps_too_high_are_refused() {
        let steep = Terrain::Plane(Plane {
            slope_deg: -31.0,
            direction_deg: 0.0,
        });
        let error = check_fits(&steep, "insect", 0.05).expect_err("too steep");
        assert_eq!(error.path, "scenario.terrain.slope_deg");
        let gentle = Terrain::Plane(Plane {
            slope_deg: 30.0,
            direction_deg: 0.0,
        });
        assert!(check_fits(&gentle, "insect", 0.05).is_ok());
        // Bumps up to 0.08 m at difficulty 1.
        assert!(check_fits(&Terrain::Rough(Rough::new(1, 0.5)), "insect", 0.05).is_ok());
        let error =
            check_fits(&Terrain::Rough(Rough::new(1, 1.0)), "insect", 0.05).expect_err("bumps");
        assert_eq!(error.path, "scenario.terrain.difficulty");
        assert!(error.reason.contains("below 0.62"), "{}", error.reason);
        assert!(check_fits(&Terrain::Flat, "insect", 0.0).is_ok());
    }
}
