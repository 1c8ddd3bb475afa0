//! Kangaroo hopping (Raibert & Hodgins 1991, "Kangaroo control", Table 2):
//! hopping without falling, speed regulation, Table-2 figures and dynamic
//! scaling. Figures that the controller does not yet meet are measured and
//! printed (`cargo test -- --nocapture`), and asserted only loosely.
//!
//! Every run starts hopping at 2 m/s (or slower) with the desired speed set
//! once; the controller ramps its commanded speed up to it. Speeds and
//! Table-2 figures are measured from 3 s after the ramp ends.

use gaitlab_physics::control::additions::Additions;
use gaitlab_physics::control::gaits::kangaroo_hop;
use gaitlab_physics::control::gaits::kangaroo_hop::{
    KangarooHop, KangarooHopParams, kangaroo_ground,
};
use gaitlab_physics::creatures::kangaroo;
use gaitlab_physics::engine::metrics::{GaitRecorder, GaitSummary};
use gaitlab_physics::{Sim, SimOptions};

struct Run {
    summary: GaitSummary,
    blew_up: Option<String>,
    tail_wag_deg: f64,
    /// (time, forward, up, pitch) of the trunk every 10 ms × √L.
    trace: Vec<(f64, f64, f64, f64)>,
}

/// Start speed of every run (m/s at scale 1).
const START_MPS: f64 = 2.0;

/// Seconds (at scale 1) from the start until the commanded speed has
/// ramped to `speed`, plus 3 s of settling.
fn settle_s(speed: f64) -> f64 {
    let ramp = KangarooHopParams::default().speed_ramp_mps2;
    3.0 + (speed - START_MPS).abs() / ramp
}

fn run(speed: f64, l: f64, secs: f64) -> Run {
    let options = SimOptions {
        dt: 0.0004 * l.sqrt(),
        ..Default::default()
    };
    let mut sim = Sim::new(
        kangaroo(l).expect("kangaroo"),
        kangaroo_ground().scaled(l),
        options,
    );
    kangaroo_hop::start::start(&mut sim, speed.min(START_MPS), Additions::NONE);
    sim.commands.speed_mps = speed;
    let mut ctl = KangarooHop::new(KangarooHopParams::default());
    let settle = settle_s(speed) * l.sqrt();
    let mut rec = GaitRecorder::new(1, speed * l.sqrt(), 0.0, settle);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut wags = Vec::new();
    let mut was = false;
    let mut trace = Vec::new();
    let mut blew_up = None;
    let every = (0.01 * l.sqrt() / options.dt).round() as u64;
    while sim.time < secs * l.sqrt() {
        if let Err(e) = sim.step(&mut ctl) {
            blew_up = Some(e.to_string());
            break;
        }
        rec.record(&sim);
        let q = &sim.data.q;
        lo = lo.min(q[6]);
        hi = hi.max(q[6]);
        let touching = sim.contacts[0].touching;
        if touching && !was {
            if sim.time > settle {
                wags.push((hi - lo).to_degrees());
            }
            lo = f64::INFINITY;
            hi = f64::NEG_INFINITY;
        }
        was = touching;
        if sim.steps.is_multiple_of(every) {
            trace.push((sim.time, q[0], q[1], q[2]));
        }
    }
    let tail_wag_deg = if wags.is_empty() {
        0.0
    } else {
        wags.iter().sum::<f64>() / wags.len() as f64
    };
    Run {
        summary: rec.summary(),
        blew_up,
        tail_wag_deg,
        trace,
    }
}

#[test]
fn hops_at_2_mps_without_falling_and_holds_speed() {
    let r = run(2.0, 1.0, 30.0);
    let s = &r.summary;
    println!(
        "2 m/s: speed {:.3} wag {:.1}",
        s.speed_mean_mps, r.tail_wag_deg
    );
    assert!(r.blew_up.is_none(), "{:?}", r.blew_up);
    assert!(!s.fell);
    assert!(
        (s.speed_mean_mps - 2.0).abs() < 0.2,
        "mean speed {:.3}",
        s.speed_mean_mps
    );
}

/// 60 s at 3.5 and at the paper's 5 m/s (Figure 6, Table 2) without a fall,
/// the mean speed within the paper's 10 % once the ramp has ended.
#[test]
fn hops_at_higher_speeds() {
    for speed in [3.5, 5.0] {
        let r = run(speed, 1.0, 60.0);
        let s = &r.summary;
        println!(
            "{speed} m/s: blew_up {:?} fell {} speed {:.3} stride {:.3} m {:.3} s pitch {:.1} wag {:.1} peak {:.2} g",
            r.blew_up,
            s.fell,
            s.speed_mean_mps,
            s.stride_length_m,
            s.stride_duration_s,
            s.pitch_magnitude_deg,
            r.tail_wag_deg,
            s.peak_vertical_accel_g
        );
        assert!(r.blew_up.is_none() && !s.fell);
        assert!((s.speed_mean_mps - speed).abs() < 0.1 * speed);
    }
}

/// Table 2's kangaroo column (animation, 5 m/s desired) beside ours at 5 m/s.
/// Printed; the asserts hold the figures within ±35 % of the paper's, except
/// the peak vertical acceleration and the stance duration, which the stiff
/// ankle misses (a stance of about 0.065 s instead of 0.11 s, so the ground
/// carries the body weight in a shorter, higher pulse); those are only
/// bounded.
#[test]
fn table_2_figures() {
    let r = run(5.0, 1.0, settle_s(5.0) + 12.0);
    let s = &r.summary;
    let rows = [
        (
            "peak vertical acceleration (g)",
            4.6,
            s.peak_vertical_accel_g,
        ),
        ("pitch magnitude (deg)", 12.0, s.pitch_magnitude_deg),
        ("tail wag relative to trunk (deg)", 31.0, r.tail_wag_deg),
        ("stride length (m)", 1.5, s.stride_length_m),
        ("stride duration (s)", 0.35, s.stride_duration_s),
        ("flight duration (s)", 0.24, s.flight_duration_s),
        ("stance duration (s)", 0.11, s.stance_duration_s),
    ];
    for (name, paper, ours) in rows {
        let ok = (ours - paper).abs() <= 0.35 * paper;
        println!("{name:36} paper {paper:6.2} ours {ours:6.3} within35% {ok}");
    }
    assert!(r.blew_up.is_none() && !s.fell);
    let within = |ours: f64, paper: f64| (ours - paper).abs() <= 0.35 * paper;
    assert!(within(s.pitch_magnitude_deg, 12.0));
    assert!(within(r.tail_wag_deg, 31.0));
    assert!(within(s.stride_length_m, 1.5));
    assert!(within(s.stride_duration_s, 0.35));
    assert!(within(s.flight_duration_s, 0.24));
    assert!(s.stance_duration_s > 0.04, "stance {}", s.stance_duration_s);
    assert!(
        s.peak_vertical_accel_g < 12.0,
        "peak {}",
        s.peak_vertical_accel_g
    );
}

/// Table 1: at L = 2 with speed ×√2 and the step ×√2, the trunk's path is
/// the L = 1 path with positions ×L and time ×√L.
#[test]
fn dynamic_scaling_matches() {
    let secs = 3.0;
    let a = run(2.0, 1.0, secs);
    let b = run(2.0, 2.0, secs);
    assert!(a.blew_up.is_none() && b.blew_up.is_none());
    let l: f64 = 2.0;
    let n = a.trace.len().min(b.trace.len());
    assert!(n > 200, "{n} samples");
    let mut worst_pos: f64 = 0.0;
    let mut worst_pitch: f64 = 0.0;
    for (x, y) in a.trace.iter().zip(&b.trace).take(n) {
        assert!((y.0 - x.0 * l.sqrt()).abs() < 1e-6, "{} vs {}", y.0, x.0);
        worst_pos = worst_pos
            .max((y.1 / l - x.1).abs())
            .max((y.2 / l - x.2).abs());
        worst_pitch = worst_pitch.max((y.3 - x.3).abs());
    }
    println!(
        "scaling over {secs} s: worst position error {worst_pos:.2e} m (L=1 units), pitch {worst_pitch:.2e} rad"
    );
    assert!(worst_pos < 1e-6, "position error {worst_pos}");
    assert!(worst_pitch < 1e-6, "pitch error {worst_pitch}");
}

/// A jump over a 0.25 m × 0.3 m box at 2 m/s: the toe never enters the box,
/// the trunk passes it, and hopping goes on without a fall.
#[test]
fn jumps_over_an_obstacle() {
    use gaitlab_physics::world::ground::Obstacle;
    let params = KangarooHopParams {
        jump_at_m: Some(5.0),
        ..Default::default()
    };
    let mut sim = Sim::new(
        kangaroo(1.0).expect("kangaroo"),
        kangaroo_ground(),
        SimOptions::default(),
    );
    let box_ = Obstacle {
        min_xz: [-1.0, 5.0],
        max_xz: [1.0, 5.0 + params.obstacle_depth_m],
        height_m: params.obstacle_height_m,
    };
    sim.terrain.obstacles.push(box_);
    kangaroo_hop::start::start(&mut sim, 2.0, Additions::NONE);
    sim.commands.speed_mps = 2.0;
    let mut ctl = KangarooHop::new(params);
    let mut rec = GaitRecorder::new(1, 2.0, 0.0, 1.0);
    let mut min_clearance = f64::INFINITY;
    while sim.time < 10.0 {
        sim.step(&mut ctl).expect("no blow-up");
        rec.record(&sim);
        let toe = sim.contacts[0].position;
        if box_.covers(toe.x, toe.z) {
            min_clearance = min_clearance.min(toe.y - box_.height_m);
        }
    }
    println!("jump: toe clearance over the box {min_clearance:.3} m");
    assert!(min_clearance > 0.0, "toe inside the box");
    assert!(sim.data.q[0] > 5.0 + 2.0, "trunk at {}", sim.data.q[0]);
    assert!(!rec.summary().fell);
}

/// The desired speed changed while running (the speed command): up to 5
/// m/s, then back down to 2 m/s; the commanded speed ramps both ways and the
/// mean speed settles on each. Also checks `phase_name` is live.
#[test]
fn changes_speed_while_running() {
    let mut sim = Sim::new(
        kangaroo(1.0).expect("kangaroo"),
        kangaroo_ground(),
        SimOptions::default(),
    );
    kangaroo_hop::start::start(&mut sim, START_MPS, Additions::NONE);
    let mut ctl = KangarooHop::new(KangarooHopParams::default());
    sim.commands.speed_mps = 5.0;
    sim.commands.hop_height_m = Some(0.07);
    let mean_speed = |sim: &mut Sim, ctl: &mut KangarooHop, from: f64, to: f64| {
        while sim.time < from {
            sim.step(ctl).expect("no blow-up");
        }
        let z0 = sim.data.q[0];
        while sim.time < to {
            sim.step(ctl).expect("no blow-up");
            assert!(
                sim.data.q[2].abs() < 1.0,
                "pitch {} at {}",
                sim.data.q[2],
                sim.time
            );
        }
        (sim.data.q[0] - z0) / (to - from)
    };
    let fast = mean_speed(&mut sim, &mut ctl, settle_s(5.0), settle_s(5.0) + 5.0);
    assert!(!ctl.phase_name().is_empty());
    sim.commands.speed_mps = 2.0;
    let t = sim.time;
    let slow = mean_speed(
        &mut sim,
        &mut ctl,
        t + settle_s(5.0),
        t + settle_s(5.0) + 5.0,
    );
    println!("speed change: {fast:.3} m/s at 5, then {slow:.3} m/s at 2");
    assert!((fast - 5.0).abs() < 0.5, "fast {fast}");
    assert!((slow - 2.0).abs() < 0.2, "slow {slow}");
}
