//! The lab's additions to Raibert & Hodgins 1991's control, resolved for
//! the gait that runs (`scenario.physics.lab_additions`, docs/physics.md
//! "The lab's additions"). None is in the paper; each is named, and off by
//! default wherever a gait runs by the paper's laws alone.

pub mod ground_ahead;
pub mod speed_trim;

use gaitlab_core::preset::physics::LabAdditions;

/// Which additions a gait's controller runs with. Defaults for a file with
/// `lab_additions`: the trim off for the biped run and the kangaroo hop (the
/// gallops and the bound do not hold their speed without it with the
/// controllers' own gains);
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
    /// The thrust corrected from each measured apex or flight (every gait),
    /// where eq. 2's prediction alone sets it.
    pub hop_integrator: bool,
    /// On ground that is not flat, eq. 2's hop and eq. 3's touchdown
    /// measured from the ground plane under the body
    /// ([`crate::world::ground_view::GroundView`]), where the paper's laws
    /// take the floor at height 0 (issue 45, docs/terrain.md).
    pub ground_ahead: bool,
    /// The file predates the additions being optional: every addition on
    /// and the controllers' earlier defaults, so it runs as it was made.
    pub legacy: bool,
}

/// Which of the lab's additions a controller has, each with its default
/// for a file whose `lab_additions` does not name it; `None`: the
/// controller has no such addition. The table of offers is below
/// ([`Offered::BIPED_RUN`] and its neighbours).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Offered {
    /// [`Additions::speed_trim`].
    pub speed_trim: Option<bool>,
    /// [`Additions::unloading_posture`].
    pub unloading_posture: Option<bool>,
    /// [`Additions::speed_ramp`].
    pub speed_ramp: Option<bool>,
    /// [`Additions::tail_feedback`].
    pub tail_feedback: Option<bool>,
    /// [`Additions::hop_integrator`].
    pub hop_integrator: Option<bool>,
    /// [`Additions::ground_ahead`].
    pub ground_ahead: Option<bool>,
}

/// Each controller's offer, in one table: which of the lab's additions it
/// has, and each one's default for a file that does not name it. The trot
/// holds its speed by eq. 3 alone; of the additions it has only the hop
/// integrator.
impl Offered {
    /// No addition: the controller runs the paper's laws only.
    pub const NONE: Self = Self {
        speed_trim: None,
        unloading_posture: None,
        speed_ramp: None,
        tail_feedback: None,
        hop_integrator: None,
        ground_ahead: None,
    };

    /// The biped run: the speed trim (off: eq. 3 alone holds the speed),
    /// Unloading's posture servo (on for a file that does not say, as files
    /// of 2026-12-02 ran) and the hop integrator (on for a file that does
    /// not say, as every file ran until 2026-12-06; the bundled biped turns
    /// it off: eq. 2 alone holds its speeds).
    pub const BIPED_RUN: Self = Self {
        speed_trim: Some(false),
        unloading_posture: Some(true),
        hop_integrator: Some(true),
        ground_ahead: Some(false),
        ..Self::NONE
    };

    /// The biped gallops: the speed trim, on (with the controller's own
    /// gains they miss the desired speed by 25–46 % without it; the bundled
    /// biped carries gallop gains that need none and turns it off); the hop
    /// integrator, on for a file that does not say (with the gains tuned
    /// for it the gallop blows up at 2 m/s by eq. 2 alone; the bundled biped
    /// carries gains tuned for eq. 2 and turns it off).
    pub const BIPED_GALLOP: Self = Self {
        speed_trim: Some(true),
        hop_integrator: Some(true),
        ..Self::NONE
    };

    /// The quadruped bound and gallop: the speed trim, on (without it the
    /// skip bound and gallop run 38–54 % slow); the hop integrator, on (by
    /// eq. 2 alone the bound falls at 2.8 m/s, the gallop runs 44–65 % slow).
    pub const BOUND: Self = Self {
        speed_trim: Some(true),
        hop_integrator: Some(true),
        ..Self::NONE
    };

    /// The trot and the pace: the hop integrator (on for a file that does
    /// not say, as every file ran until 2026-12-06; the bundled quadruped
    /// turns it off for both, which hold their speeds and Table 2 by eq. 2
    /// alone — the pace with gains tuned for it, docs/physics.md "Eq. 2 as
    /// written").
    pub const TROT: Self = Self {
        hop_integrator: Some(true),
        ground_ahead: Some(false),
        ..Self::NONE
    };

    /// The kangaroo hop: the speed trim (off), the speed ramp and the tail
    /// feedback (on: without them it falls at 3.5 and 5 m/s), the hop
    /// integrator (on: by eq. 2's prediction alone it runs 11 % slow at
    /// 2 m/s and 16 % slow at 5 m/s, docs/physics.md "Eq. 2 as written").
    pub const KANGAROO_HOP: Self = Self {
        speed_trim: Some(false),
        speed_ramp: Some(true),
        tail_feedback: Some(true),
        hop_integrator: Some(true),
        ground_ahead: Some(false),
        ..Self::NONE
    };
}

impl Additions {
    /// None on, and not a file from before they were optional.
    pub const NONE: Self = Self {
        speed_trim: false,
        unloading_posture: false,
        speed_ramp: false,
        tail_feedback: false,
        hop_integrator: false,
        ground_ahead: false,
        legacy: false,
    };

    /// The additions a controller offering `offered` runs with, from the
    /// preset's `lab_additions` (`None`: a file made before they were
    /// optional, every offered addition on).
    #[must_use]
    pub fn resolve(spec: Option<&LabAdditions>, offered: Offered) -> Self {
        let pick =
            |offer: Option<bool>, asked: fn(&LabAdditions) -> Option<bool>| match (offer, spec) {
                (None, _) => false,
                (Some(_), None) => true,
                (Some(default), Some(a)) => asked(a).unwrap_or(default),
            };
        Self {
            speed_trim: pick(offered.speed_trim, |a| a.speed_trim),
            unloading_posture: pick(offered.unloading_posture, |a| a.unloading_posture),
            speed_ramp: pick(offered.speed_ramp, |a| a.speed_ramp),
            tail_feedback: pick(offered.tail_feedback, |a| a.tail_feedback),
            hop_integrator: pick(offered.hop_integrator, |a| a.hop_integrator),
            // Made after terrain: a file from before the additions were
            // optional ran on the floor, and gets it off.
            ground_ahead: offered.ground_ahead.is_some()
                && spec.is_some_and(|a| a.ground_ahead.unwrap_or(false)),
            legacy: spec.is_none(),
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
            (self.hop_integrator, "hop_integrator"),
            (self.ground_ahead, "ground_ahead"),
        ];
        on.into_iter().filter(|&(on, _)| on).map(|(_, name)| name)
    }
}
