//! The lab's additions to Raibert & Hodgins 1991's control, resolved for
//! the gait that runs (`scenario.physics.lab_additions`, docs/physics.md
//! "The lab's additions"). None is in the paper; each is named, and off by
//! default wherever a gait runs by the paper's laws alone.

use gaitlab_core::preset::physics::LabAdditions;

/// Which additions a gait's controller runs with. Defaults for a file with
/// `lab_additions`: the trim off for the biped run and the kangaroo hop (the
/// gallops and the bound do not yet hold their speed without it);
/// Unloading's posture servo on, as such files ran when it was made (the
/// bundled biped turns it off: with its yaw damping it runs without).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Additions {
    /// Integral speed trim on eq. 3's desired speed.
    pub speed_trim: bool,
    /// Eq. 4's posture torque kept on in Unloading (Figure 4 zeroes it).
    pub unloading_posture: bool,
    /// The kangaroo's speed ramp from at most 2 m/s.
    pub speed_ramp: bool,
    /// The kangaroo's tail rest following the trunk's pitch.
    pub tail_feedback: bool,
    /// The file predates the additions being optional: every addition on
    /// and the controllers' earlier defaults, so it runs as it was made.
    pub legacy: bool,
}

/// The gaits with an integral speed trim (the trot has none: it holds
/// its speed by eq. 3 alone).
const TRIMMED: [&str; 5] = ["run", "gallop", "gallop_alternate", "bound", "hop"];

/// The gaits that hold their speed within the paper's 10 % by eq. 3 alone.
const PAPER_SPEED: [&str; 2] = ["run", "hop"];

/// The gaits whose posture servo may be turned off in Unloading (the biped
/// gallops keep it on: not yet separated).
const UNLOADING: [&str; 1] = ["run"];

impl Additions {
    /// The additions for `gait` from the preset's `lab_additions` (`None`:
    /// a file made before they were optional).
    #[must_use]
    pub fn for_gait(spec: Option<&LabAdditions>, gait: &str) -> Self {
        let has_trim = TRIMMED.contains(&gait);
        let has_unloading = UNLOADING.contains(&gait);
        let hop = gait == "hop";
        match spec {
            None => Self {
                speed_trim: has_trim,
                unloading_posture: has_unloading,
                speed_ramp: hop,
                tail_feedback: hop,
                legacy: true,
            },
            Some(a) => Self {
                // The biped run and the kangaroo hold their speed without
                // the trim; the gallops and the bound do not yet
                // (docs/physics.md).
                speed_trim: has_trim && a.speed_trim.unwrap_or(!PAPER_SPEED.contains(&gait)),
                unloading_posture: has_unloading && a.unloading_posture.unwrap_or(true),
                // Without either the kangaroo falls at 3.5 and 5 m/s.
                speed_ramp: hop && a.speed_ramp.unwrap_or(true),
                tail_feedback: hop && a.tail_feedback.unwrap_or(true),
                legacy: false,
            },
        }
    }

    /// The additions on, by their preset names (no allocation: the app's
    /// panel asks every frame).
    pub fn names(&self) -> impl Iterator<Item = &'static str> + Clone + use<> {
        let on = [
            (self.speed_trim, "speed_trim"),
            (self.unloading_posture, "unloading_posture"),
            (self.speed_ramp, "speed_ramp"),
            (self.tail_feedback, "tail_feedback"),
        ];
        on.into_iter().filter(|&(on, _)| on).map(|(_, name)| name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_old_file_keeps_every_addition_and_a_new_one_the_gaits_defaults() {
        let old = Additions::for_gait(None, "run");
        assert!(old.legacy && old.speed_trim && old.unloading_posture);
        let new = Additions::for_gait(Some(&LabAdditions::default()), "run");
        // The run drops the trim; Unloading's posture servo stays on until
        // the biped runs without it (docs/physics.md, "The lab's additions").
        assert!(!new.legacy && new.names().eq(["unloading_posture"]));
        let paper = LabAdditions {
            unloading_posture: Some(false),
            ..LabAdditions::default()
        };
        assert!(
            Additions::for_gait(Some(&paper), "run")
                .names()
                .next()
                .is_none()
        );
        let gallop = Additions::for_gait(Some(&LabAdditions::default()), "gallop");
        assert!(gallop.names().eq(["speed_trim"]));
        let asked = LabAdditions {
            speed_trim: Some(true),
            ..LabAdditions::default()
        };
        let run = Additions::for_gait(Some(&asked), "run");
        assert!(run.names().eq(["speed_trim", "unloading_posture"]));
        // The trot has no trim to turn on.
        assert!(
            Additions::for_gait(Some(&asked), "trot")
                .names()
                .next()
                .is_none()
        );
        // The kangaroo: its trim off, its ramp and tail feedback on.
        let hop = Additions::for_gait(Some(&LabAdditions::default()), "hop");
        assert!(hop.names().eq(["speed_ramp", "tail_feedback"]));
    }
}
