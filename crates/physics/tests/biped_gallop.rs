//! Biped galloping (Raibert & Hodgins 1991, "Gaits"): both styles hold 60 s
//! at several speeds, the stride is a gallop (the legs land separated in time
//! and share a double support), the alternate-swing style pitches less than
//! the together-swing style, and the controller scales with L (Table 1).
//! Run with `--nocapture` to see the Table-2-like figures.

use gaitlab_physics::control::gaits::biped_gallop::{
    BipedGallop, BipedGallopParams, GallopPhase, GallopStyle,
};
use gaitlab_physics::creatures::biped;
use gaitlab_physics::engine::metrics::{GaitRecorder, GaitSummary};
use gaitlab_physics::world::ground::GroundParams;
use gaitlab_physics::{Sim, SimOptions};

const SETTLE_S: f64 = 3.0;

struct Run {
    summary: GaitSummary,
    trail: usize,
    phases_seen: [bool; 4],
}

/// Gallop the biped at scale `l` for `secs` (both in the paper's units, so
/// time is stretched by √L); a blow-up counts as a fall.
fn gallop(style: GallopStyle, speed: f64, secs: f64, l: f64) -> Run {
    let mut sim = Sim::new(
        biped(l).expect("biped"),
        GroundParams::default().scaled(l),
        SimOptions::default(),
    );
    sim.data.base_position.y = 0.9 * l;
    sim.data.base_velocity.linear.z = speed * l.sqrt();
    sim.commands.speed_mps = speed;
    let params = BipedGallopParams {
        style,
        ..BipedGallopParams::default()
    };
    let mut ctl = BipedGallop::new(params, &sim.creature);
    let mut rec = GaitRecorder::new(2, speed * l.sqrt(), 0.0, SETTLE_S * l.sqrt());
    let mut phases_seen = [false; 4];
    let mut blew_up = false;
    while sim.time < secs * l.sqrt() {
        if sim.step(&mut ctl).is_err() {
            blew_up = true;
            break;
        }
        rec.record(&sim);
        phases_seen[ctl.phase.index()] = true;
    }
    let mut summary = rec.summary();
    summary.fell |= blew_up;
    Run {
        summary,
        trail: ctl.trail(),
        phases_seen,
    }
}

/// Per stride (each trailing-leg stance): whether the leading leg landed
/// during it, the touchdown lag and the double-support time.
struct GallopFigures {
    strides: usize,
    galloped: usize,
    lag_s: f64,
    double_s: f64,
    min_lag_s: f64,
}

fn gallop_figures(s: &GaitSummary, trail: usize) -> GallopFigures {
    let lead = 1 - trail;
    let mut f = GallopFigures {
        strides: 0,
        galloped: 0,
        lag_s: 0.0,
        double_s: 0.0,
        min_lag_s: f64::INFINITY,
    };
    for t in &s.stances[trail] {
        f.strides += 1;
        if let Some(d) = s.stances[lead]
            .iter()
            .find(|d| d.start_s > t.start_s && d.start_s < t.end_s)
        {
            f.galloped += 1;
            let lag = d.start_s - t.start_s;
            f.lag_s += lag;
            f.min_lag_s = f.min_lag_s.min(lag);
            f.double_s += t.end_s.min(d.end_s) - d.start_s;
        }
    }
    let n = f.galloped.max(1) as f64;
    f.lag_s /= n;
    f.double_s /= n;
    f
}

fn report(style: GallopStyle, s: &GaitSummary, f: &GallopFigures) {
    eprintln!(
        "{:15} {:.2} m/s: mean {:.3} m/s, stride {:.3} m / {:.3} s, flight {:.3} s, stance {:.3} s \
         (legs {:.3}/{:.3}), lag {:.3} s, double support {:.3} s, pitch {:.1}°, roll {:.1}°, \
         leg Δ {:.3} m, friction {:.2}, peak {:.1} g, strides {}/{} galloped",
        style.name(),
        s.speed_desired_mps,
        s.speed_mean_mps,
        s.stride_length_m,
        s.stride_duration_s,
        s.flight_duration_s,
        s.stance_duration_s,
        s.leg_stance_s[0],
        s.leg_stance_s[1],
        f.lag_s,
        f.double_s,
        s.pitch_magnitude_deg,
        s.roll_magnitude_deg,
        s.leg_length_change_m,
        s.friction_needed_max,
        s.peak_vertical_accel_g,
        f.galloped,
        f.strides,
    );
}

fn holds_a_minute(style: GallopStyle) {
    for speed in [1.0, 1.5, 2.0] {
        let run = gallop(style, speed, 60.0, 1.0);
        let s = &run.summary;
        report(style, s, &gallop_figures(s, run.trail));
        assert!(!s.fell, "{} at {speed} m/s fell", style.name());
        let error = (s.speed_mean_mps - speed).abs() / speed;
        assert!(
            error < 0.10,
            "{} at {speed} m/s: mean speed {:.3} m/s",
            style.name(),
            s.speed_mean_mps
        );
    }
}

#[test]
fn together_swing_gallops_a_minute_at_three_speeds() {
    holds_a_minute(GallopStyle::TogetherSwing);
}

#[test]
fn alternate_swing_gallops_a_minute_at_three_speeds() {
    holds_a_minute(GallopStyle::AlternateSwing);
}

#[test]
fn stride_is_a_gallop_and_alternate_swing_pitches_less() {
    let mut pitch = [0.0; 2];
    for (k, style) in [GallopStyle::TogetherSwing, GallopStyle::AlternateSwing]
        .into_iter()
        .enumerate()
    {
        let run = gallop(style, 1.5, 15.0, 1.0);
        let s = &run.summary;
        let f = gallop_figures(s, run.trail);
        report(style, s, &f);
        assert!(!s.fell, "{} fell", style.name());
        assert!(
            run.phases_seen.iter().all(|&seen| seen),
            "{}: phases seen {:?} of {:?}",
            style.name(),
            run.phases_seen,
            GallopPhase::ALL.map(GallopPhase::name)
        );
        // Both feet have a stance every stride, the leading foot landing
        // during the trailing foot's stance.
        assert!(f.strides >= 20, "{}: {} strides", style.name(), f.strides);
        let lead = 1 - run.trail;
        assert!(
            s.stances[lead].len().abs_diff(f.strides) <= 1,
            "{}: {} trailing and {} leading stances",
            style.name(),
            f.strides,
            s.stances[lead].len()
        );
        assert!(
            f.galloped + 1 >= f.strides,
            "{}: {} of {} strides galloped",
            style.name(),
            f.galloped,
            f.strides
        );
        // Separated in time: the lag exceeds 15 % of a stance in every stride.
        assert!(
            f.min_lag_s > 0.15 * s.stance_duration_s,
            "{}: lag {:.3} s (least {:.3} s) against stance {:.3} s",
            style.name(),
            f.lag_s,
            f.min_lag_s,
            s.stance_duration_s
        );
        // The two stances share a double support, and a flight follows.
        assert!(
            f.double_s > 0.02,
            "{}: double support {:.3} s",
            style.name(),
            f.double_s
        );
        assert!(
            s.flight_duration_s > 0.1,
            "{}: flight {:.3} s",
            style.name(),
            s.flight_duration_s
        );
        pitch[k] = s.pitch_magnitude_deg;
    }
    assert!(
        pitch[1] < 0.6 * pitch[0],
        "alternate swing pitches {:.1}°, together swing {:.1}°",
        pitch[1],
        pitch[0]
    );
}

#[test]
fn gallop_scales_with_size() {
    // Table 1: at scale L the same gallop runs √L faster with times √L
    // longer; dimensionless figures such as pitch stay put.
    let base = gallop(GallopStyle::AlternateSwing, 1.5, 12.0, 1.0).summary;
    for l in [0.5, 2.0] {
        let s = gallop(GallopStyle::AlternateSwing, 1.5, 12.0, l).summary;
        assert!(!s.fell, "L = {l} fell");
        let speed = s.speed_mean_mps / l.sqrt();
        assert!(
            (speed - 1.5).abs() < 0.15,
            "L = {l}: speed {speed:.3} (scaled)"
        );
        let duration = s.stride_duration_s / l.sqrt();
        assert!(
            (duration - base.stride_duration_s).abs() < 0.1 * base.stride_duration_s,
            "L = {l}: stride {duration:.3} s (scaled) against {:.3} s",
            base.stride_duration_s
        );
        assert!(
            (s.pitch_magnitude_deg - base.pitch_magnitude_deg).abs() < 3.0,
            "L = {l}: pitch {:.1}° against {:.1}°",
            s.pitch_magnitude_deg,
            base.pitch_magnitude_deg
        );
    }
}
