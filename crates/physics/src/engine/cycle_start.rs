//! The start on the gait's cycle (`scenario.physics.start: "on_cycle"`).
//! Raibert & Hodgins 1991 leave the start to the animator ("the animator
//! must also initialize the state of the model", Figure 2's text); this is
//! the lab's way of doing it for the kangaroo, whose hop started straight
//! at 5 m/s tumbles (docs/physics.md, "The start on the cycle"). Before
//! t = 0, out of sight and on open ground, the lab runs the hop from its own
//! start with its speed ramp, lets it hop [`SETTLE_S`] at the desired speed,
//! and hands the state at the next flight apex — the creature's and the
//! controller's — to the run, at t = 0 and z = 0.

use glam::DVec3;

use crate::control::additions::Additions;
use crate::control::gaits::controller::GaitController;
use crate::control::gaits::kangaroo_hop::KangarooHop;
use crate::control::gaits::kangaroo_hop::start as hop_start;
use crate::control::laws::phase::Phase;
use crate::control::laws::scale::Scale;
use crate::engine::metrics::GaitRecorder;
use crate::world::sim::Sim;

/// How long the hop runs at the desired speed before the start (s at scale
/// 1): about 18 hops, time for the stance estimate and the thrust's learned
/// correction to reach the cycle.
pub const SETTLE_S: f64 = 6.0;

/// The longest the lab runs out of sight before giving up (s at scale 1).
pub const MAX_SETTLE_S: f64 = 60.0;

/// The most integration steps the run-up may take: 60 s at the paper's
/// 0.4 ms. A preset with a much finer step (`dt_s` down to 1e-5) would
/// otherwise hold the page for minutes before its first frame.
pub const MAX_SETTLE_STEPS: u64 = 150_000;

/// `sim` and `controller` moved onto the gait's cycle at `speed_mps` (m/s at
/// scale 1), as the module describes; for a controller without a cycle
/// start (every gait but the kangaroo's hop), `None`.
///
/// # Errors
/// Why no start on the cycle was found: the hop fell or blew up on its
/// way, or did not reach the speed within [`MAX_SETTLE_S`] or
/// [`MAX_SETTLE_STEPS`].
pub fn on_cycle(
    sim: &Sim,
    controller: &GaitController,
    speed_mps: f64,
) -> Option<Result<(Sim, GaitController), String>> {
    let hop = controller.get::<KangarooHop>()?;
    let root_l = Scale::new(sim.creature.scale).time();
    let mut run = sim.clone();
    run.terrain.obstacles.clear();
    run.time = 0.0;
    run.steps = 0;
    let mut settling = hop.for_settling();
    // The gait's own start for a hop with the ramp on (at most 2 m/s).
    let ramped = Additions {
        speed_ramp: true,
        ..controller.additions()
    };
    hop_start::start(&mut run, speed_mps, ramped);
    crate::dynamics::kinematics::kinematics(&run.creature.model, &mut run.data);
    let legs = run.creature.legs.len();
    let mut recorder = GaitRecorder::new(legs, speed_mps * root_l, 0.0, 0.0);
    let target = speed_mps * root_l;
    let mut at_speed_since: Option<f64> = None;
    let mut rose = false;
    loop {
        if let Err(e) = run.step(&mut settling) {
            return Some(Err(format!("the hop blew up on its way up to speed: {e}")));
        }
        recorder.record(&run);
        if recorder.fell() {
            let t = run.time / root_l;
            return Some(Err(format!(
                "the hop fell on its way up to speed, {t:.1} s into it"
            )));
        }
        if at_speed_since.is_none() && (settling.speed_command_mps - target).abs() < 1e-9 {
            at_speed_since = Some(run.time);
        }
        let settled = at_speed_since.is_some_and(|t0| run.time - t0 >= SETTLE_S * root_l);
        // The planar base: slides forward (q[0], +z) and up (q[1]), pitch q[2].
        let vy = run.data.qd[1];
        let flight = settling.phase == Phase::Flight;
        rose = flight && (rose || vy > 0.0);
        if settled && rose && vy <= 0.0 {
            break;
        }
        if run.time > MAX_SETTLE_S * root_l {
            return Some(Err(format!(
                "the hop did not settle at {speed_mps} m/s within {MAX_SETTLE_S} s"
            )));
        }
        if run.steps >= MAX_SETTLE_STEPS {
            return Some(Err(format!(
                "the run-up to {speed_mps} m/s needs more than {MAX_SETTLE_STEPS} steps \
                 of {} s",
                run.options.dt
            )));
        }
    }
    let advanced = run.data.q[0];
    let mut start = sim.clone();
    start.data = run.data.clone();
    start.data.q[0] = 0.0;
    crate::dynamics::kinematics::kinematics(&start.creature.model, &mut start.data);
    start.drives.clone_from(&run.drives);
    start.contacts.clone_from(&run.contacts);
    let back = DVec3::new(0.0, 0.0, advanced);
    for c in &mut start.contacts {
        c.anchor -= back;
        c.position -= back;
    }
    start.time = 0.0;
    let mut resumed = hop.clone();
    resumed.resume_from(&settling, run.time, advanced);
    Some(Ok((start, controller.with_inner(Box::new(resumed)))))
}
