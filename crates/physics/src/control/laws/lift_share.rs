//! The share of a virtual leg's spring work that lifts the centre of mass
//! (Raibert & Hodgins 1991, eq. 2, for a pair of legs off the centre of
//! mass; Murphy & Raibert's dimensionless pitch inertia): eq. 2 predicts
//! the hop "for vertical hopping with a massless leg" under the centre of
//! mass. A vertical force at a point `(dx, dz)` from the centre of mass of
//! a body of mass `M` with roll and pitch inertias `I_roll`, `I_pitch`
//! moves that point as a mass `m = 1/(1/M + dz²/I_pitch + dx²/I_roll)`
//! would; of the work done there, `m/M` goes into the centre of mass's
//! rise and the rest into turning the body, which a flight keeps. The
//! trot's diagonals stand about the centre of mass (a share near 1); the
//! bound's front and rear pairs stand a hip's distance from it (Murphy &
//! Raibert's `j = I/(M d²)`, the share `j/(1 + j)`).

use glam::DVec3;

use crate::creatures::PhysicalCreature;
use crate::dynamics::data::Data;
use crate::dynamics::kinematics::kinematics;

/// The share (0–1] of the work of a pair of legs `pair`'s springs that
/// lifts `creature`'s centre of mass, the creature standing with every
/// joint at zero: the point is the pair's hips' midpoint, the inertias the
/// whole body's about its centre of mass, in the trunk's axes (x lateral,
/// y up, z forward). 1 where the body has no inertia to turn.
#[must_use]
pub fn lift_share(creature: &PhysicalCreature, pair: [usize; 2]) -> f64 {
    let model = &creature.model;
    let mut data = Data::new(model);
    kinematics(model, &mut data);
    let trunk = data.world[creature.trunk];
    let to_trunk = trunk.rot.transpose();
    let mass = model.total_mass();
    if mass.is_nan() || mass <= 0.0 {
        return 1.0;
    }
    // Each body's centre of mass and inertia in the trunk's axes.
    let mut com = DVec3::ZERO;
    for (i, b) in model.bodies().iter().enumerate() {
        let w = data.world[i];
        com += to_trunk * (w.rot * b.com + w.pos - trunk.pos) * b.mass;
    }
    com /= mass;
    let (mut roll, mut pitch) = (0.0, 0.0);
    for (i, b) in model.bodies().iter().enumerate() {
        if b.mass <= 0.0 {
            continue;
        }
        let w = data.world[i];
        let rot = to_trunk * w.rot;
        let inertia = rot * b.inertia_com * rot.transpose();
        let r = to_trunk * (w.rot * b.com + w.pos - trunk.pos) - com;
        roll += inertia.z_axis.z + b.mass * (r.x * r.x + r.y * r.y);
        pitch += inertia.x_axis.x + b.mass * (r.y * r.y + r.z * r.z);
    }
    let hips = pair.map(|i| creature.legs.get(i).map_or(com, |leg| leg.hip_in_trunk));
    let d = (hips[0] + hips[1]) / 2.0 - com;
    let turn = |arm: f64, inertia: f64| {
        if inertia > 0.0 {
            arm * arm / inertia
        } else {
            0.0
        }
    };
    1.0 / (1.0 + mass * (turn(d.z, pitch) + turn(d.x, roll)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::creatures::quadruped;
    use crate::dynamics::crba::mass_matrix;
    use nalgebra::DVector;

    /// The same share from the whole body's locked inertia as the mass
    /// matrix's free-base block holds it (the composite-rigid-body
    /// algorithm): a unit upward force at the hips' midpoint moves that
    /// point as `1/(gᵀ H⁻¹ g)`, `g` the force as a base wrench.
    fn from_the_mass_matrix(creature: &PhysicalCreature, pair: [usize; 2]) -> f64 {
        let model = &creature.model;
        let mut data = Data::new(model);
        let h = mass_matrix(model, &mut data);
        let block = h.view((0, 0), (6, 6)).into_owned();
        let hips = pair.map(|i| creature.legs[i].hip_in_trunk);
        let p = (hips[0] + hips[1]) / 2.0;
        let up = DVec3::Y;
        let moment = p.cross(up);
        let g = DVector::from_row_slice(&[moment.x, moment.y, moment.z, up.x, up.y, up.z]);
        let inverse = block.try_inverse().expect("a body with mass");
        let per_mass = g.dot(&(inverse * &g));
        1.0 / (model.total_mass() * per_mass)
    }

    #[test]
    fn the_diagonals_lift_it_all_and_the_bounds_pairs_less_as_the_mass_matrix_says() {
        let q = quadruped(1.0).expect("model");
        for pair in [[0, 3], [1, 2], [1, 0], [3, 2], [0, 2], [1, 3]] {
            let share = lift_share(&q, pair);
            let check = from_the_mass_matrix(&q, pair);
            assert!(
                (share - check).abs() < 1e-3,
                "{pair:?}: {share} against {check}"
            );
        }
        let diagonal = lift_share(&q, [0, 3]);
        let front = lift_share(&q, [1, 0]);
        assert!(diagonal > 0.99, "diagonal {diagonal}");
        assert!((0.4..0.8).contains(&front), "front {front}");
        // Dynamic scaling keeps j, so the share.
        let big = lift_share(&quadruped(4.0).expect("model"), [1, 0]);
        assert!((big - front).abs() < 1e-9, "{big} at L = 4, {front} at 1");
    }
}
