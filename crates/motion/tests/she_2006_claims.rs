//! She 2006 §5.3's statements about the four methods, as measurements on the
//! `she-2006` preset (the §5.2.2 listing, no posture pull, joint limits by
//! clamping alone as §6.1.1.1 says): 10 s of walking and of running per
//! method at 60 frames per second, 4 iterations per frame.
//! The solver runs as the thesis prints it (`gaitlab-preset/2`): §4.4.1's α,
//! §4.4.2's step clamp on pinv alone, and λ = 0.2 m from the sweep of
//! docs/she-2006.md "Choosing λ". Each statement is a test. Where gaitlab
//! measures something other than the thesis says, the test is named
//! `finding_…`, asserts what gaitlab measures, and docs/she-2006.md gives the
//! numbers (`python3 tools/she2006_table.py`). The tests named `lab_…` measure
//! the same runs with the solver as gaitlab ran it before (the clamp on every
//! method, Buss's α, λ = 0.05 m: what a `gaitlab-preset/1` file runs), the
//! other way of the comparison.

mod common;

use std::sync::OnceLock;

use gaitlab_core::driver::{Driver, IkMetrics};
use gaitlab_core::ik::{Method, TransposeAlpha};
use gaitlab_core::preset::Creature;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_motion::ThesisDriver;

const FPS: f64 = 60.0;
const SECONDS: f64 = 10.0;
const METHODS: [Method; 4] = [Method::Transpose, Method::Pinv, Method::Dls, Method::Sdls];
const FEET: [&str; 2] = ["left_foot", "right_foot"];
const HANDS: [&str; 2] = ["left_hand", "right_hand"];

/// One run's figures, averaged over a pair of effectors.
#[derive(Clone, Copy, Debug)]
struct Pair {
    reachable: f64,
    error_m: f64,
    error_reachable_m: Option<f64>,
    oscillation_hz: f64,
    jitter_rad: f64,
}

#[derive(Clone, Copy, Debug)]
struct Run {
    feet: Pair,
    hands: Pair,
}

fn pair(creature: &Creature, metrics: &IkMetrics, names: [&str; 2]) -> Pair {
    let e = names.map(|name| match creature.skeleton.effector_index(name) {
        Some(e) => e,
        None => panic!("no effector {name}"),
    });
    let mean = |f: &dyn Fn(usize) -> Option<f64>| -> f64 {
        e.iter().map(|&e| f(e).unwrap_or(f64::NAN)).sum::<f64>() / 2.0
    };
    let reachable = e
        .iter()
        .map(|&e| metrics.mean_error_reachable_m(e))
        .collect::<Option<Vec<f64>>>()
        .map(|v| v.iter().sum::<f64>() / 2.0);
    Pair {
        reachable: mean(&|e| metrics.reachable(e)),
        error_m: mean(&|e| metrics.mean_error_m(e)),
        error_reachable_m: reachable,
        oscillation_hz: mean(&|e| metrics.oscillation_hz(e)),
        jitter_rad: mean(&|e| metrics.jitter_rad(e)),
    }
}

fn run(creature: &Creature, mode: ThesisMode, method: Method) -> Run {
    let mut creature = creature.clone();
    creature.scenario.mode = mode;
    creature.scenario.method = method;
    let mut driver = match ThesisDriver::for_creature(&creature) {
        Ok(driver) => driver,
        Err(error) => panic!("driver: {error}"),
    };
    for _ in 0..(SECONDS * FPS).round() as usize {
        driver.step(1.0 / FPS);
    }
    let Some(metrics) = driver.ik_metrics() else {
        panic!("the thesis driver reports IK metrics")
    };
    Run {
        feet: pair(&creature, metrics, FEET),
        hands: pair(&creature, metrics, HANDS),
    }
}

type Runs = Vec<(Method, Run, Run)>;

/// Every method's walk and run on `creature`.
fn every_run(creature: &Creature, label: &str) -> Runs {
    METHODS
        .iter()
        .map(|&method| {
            let walk = run(creature, ThesisMode::Walk, method);
            let run = run(creature, ThesisMode::Run, method);
            println!(
                "{label} {}: walk {walk:?}\n      run {run:?}",
                method.name()
            );
            (method, walk, run)
        })
        .collect()
}

/// The `she-2006` preset with the solver as gaitlab ran it before the
/// thesis' α and clamp became the defaults.
fn she_2006_as_before() -> Creature {
    let mut creature = common::she_2006();
    let ik = &mut creature.scenario.ik;
    ik.clamp_every_method = true;
    ik.transpose_alpha = TransposeAlpha::Buss;
    ik.lambda = 0.05;
    creature
}

/// Every method's walk and run, computed once for all the tests.
fn runs() -> &'static Runs {
    static RUNS: OnceLock<Runs> = OnceLock::new();
    RUNS.get_or_init(|| every_run(&common::she_2006(), "printed"))
}

/// The same with the solver as gaitlab ran it before (the lab's settings).
fn lab_runs() -> &'static Runs {
    static RUNS: OnceLock<Runs> = OnceLock::new();
    RUNS.get_or_init(|| every_run(&she_2006_as_before(), "lab"))
}

fn find(runs: &Runs, method: Method) -> (Run, Run) {
    match runs.iter().find(|(m, _, _)| *m == method) {
        Some((_, walk, run)) => (*walk, *run),
        None => panic!("{} was run", method.name()),
    }
}

fn walk(method: Method) -> Run {
    find(runs(), method).0
}

fn running(method: Method) -> Run {
    find(runs(), method).1
}

fn lab_walk(method: Method) -> Run {
    find(lab_runs(), method).0
}

/// §5.3: "Two leg target positions in walking cycle are reachable, while others
/// are not"; running, "four targets position were set to be unreachable".
#[test]
fn walking_feet_are_reachable_and_everything_else_is_not() {
    for method in METHODS {
        let (walk, run) = (walk(method), running(method));
        let name = method.name();
        assert_eq!(walk.feet.reachable, 1.0, "{name}: walking feet");
        assert!(
            walk.hands.reachable <= 0.05,
            "{name}: walking hands {walk:?}"
        );
        assert_eq!(run.feet.reachable, 0.0, "{name}: running feet");
        assert!(run.hands.reachable <= 0.05, "{name}: running hands {run:?}");
    }
}

/// §5.3 SDLS: "the best performance for both reachable target positions";
/// DLS: "did not have good performance when the target position was reachable"
/// compared with SDLS.
#[test]
fn sdls_tracks_reachable_targets_best() {
    let sdls = walk(Method::Sdls)
        .feet
        .error_reachable_m
        .unwrap_or(f64::NAN);
    assert!(sdls < 1e-3, "SDLS reachable feet error {sdls} m");
    for method in [Method::Transpose, Method::Pinv, Method::Dls] {
        let other = walk(method).feet.error_reachable_m.unwrap_or(f64::NAN);
        assert!(
            sdls <= other,
            "SDLS {sdls} m against {} {other} m",
            method.name()
        );
    }
}

/// §5.3 pinv: "the walking cycle had better performance" than running.
#[test]
fn pinv_walks_better_than_it_runs() {
    let (walk, run) = (walk(Method::Pinv), running(Method::Pinv));
    assert!(walk.feet.error_m < run.feet.error_m, "{walk:?} {run:?}");
    assert!(walk.hands.error_m < run.hands.error_m, "{walk:?} {run:?}");
}

/// §5.3 pinv: "the unreachable target positions caused the rigid body to
/// oscillate"; DLS is "natural and smooth"; SDLS "reduced oscillate when near
/// singularity". Issue 18's measure: on the walking hands (unreachable) pinv's
/// oscillation is at least 1.5 × DLS's and SDLS's; so is its jitter |Δ²θ|.
#[test]
fn pinv_oscillates_on_unreachable_hands_more_than_dls_and_sdls() {
    let pinv = walk(Method::Pinv).hands;
    for method in [Method::Dls, Method::Sdls] {
        let other = walk(method).hands;
        assert!(
            pinv.oscillation_hz >= 1.5 * other.oscillation_hz,
            "pinv {pinv:?} {} {other:?}",
            method.name()
        );
        assert!(
            pinv.jitter_rad >= 1.5 * other.jitter_rad,
            "pinv {pinv:?} {} {other:?}",
            method.name()
        );
    }
}

/// §5.3 DLS: "Walking and running animation is natural and smooth": on the
/// stretched arms its jitter is within 1.5 × SDLS's and under a third of
/// pinv's, walking and running.
#[test]
fn dls_is_smooth_on_the_unreachable_hands() {
    for (motion, dls, sdls, pinv) in [
        (
            "walk",
            walk(Method::Dls),
            walk(Method::Sdls),
            walk(Method::Pinv),
        ),
        (
            "run",
            running(Method::Dls),
            running(Method::Sdls),
            running(Method::Pinv),
        ),
    ] {
        let (dls, sdls, pinv) = (dls.hands, sdls.hands, pinv.hands);
        assert!(
            dls.jitter_rad <= 1.5 * sdls.jitter_rad,
            "{motion}: DLS {dls:?} SDLS {sdls:?}"
        );
        if motion == "walk" {
            assert!(
                dls.jitter_rad * 3.0 <= pinv.jitter_rad,
                "{motion}: DLS {dls:?} pinv {pinv:?}"
            );
        }
    }
}

/// §5.3 DLS: "worked substantially better than … the Pseudoinverse Method" —
/// on the walking feet (reachable), its error is under three quarters of
/// pinv's; and "compared with SDLS … did not have good performance when the
/// target position was reachable": it misses them, SDLS does not. With λ =
/// 0.2 m the gap is small (2.0 mm against 0.0); with the lab's λ = 0.05 m and
/// clamp it was 45.6 mm (`lab_…` below).
#[test]
fn dls_tracks_the_walking_feet_between_pinv_and_sdls() {
    let (dls, pinv, sdls) = (
        walk(Method::Dls).feet,
        walk(Method::Pinv).feet,
        walk(Method::Sdls).feet,
    );
    assert!(
        dls.error_m <= 0.75 * pinv.error_m,
        "DLS {dls:?} pinv {pinv:?}"
    );
    assert!(
        dls.error_m >= sdls.error_m + 0.001,
        "DLS {dls:?} SDLS {sdls:?}"
    );
}

/// §5.3 DLS "worked substantially better than either the Jacobian Transpose
/// Method or …": on the walking feet DLS misses by under half the
/// transpose's error (2.0 against 16.0 mm).
#[test]
fn dls_tracks_the_walking_feet_better_than_transpose() {
    let (dls, transpose) = (walk(Method::Dls).feet, walk(Method::Transpose).feet);
    assert!(
        dls.error_m < 0.5 * transpose.error_m,
        "DLS {dls:?} transpose {transpose:?}"
    );
}

/// §5.3 transpose: "looks jerky and oscillates"; issue 18's measure: on the
/// walking hands (unreachable) its oscillation and its jitter are each at
/// least 1.5 × DLS's and SDLS's.
#[test]
fn transpose_oscillates_on_the_walking_hands_more_than_dls_and_sdls() {
    let transpose = walk(Method::Transpose).hands;
    for method in [Method::Dls, Method::Sdls] {
        let other = walk(method).hands;
        assert!(
            transpose.oscillation_hz >= 1.5 * other.oscillation_hz,
            "transpose {transpose:?} {} {other:?}",
            method.name()
        );
        assert!(
            transpose.jitter_rad >= 1.5 * other.jitter_rad,
            "transpose {transpose:?} {} {other:?}",
            method.name()
        );
    }
}

/// Running, the transpose's hands are not the roughest: its oscillation is
/// below DLS's and SDLS's and its jitter between theirs, so §5.3's "jerky"
/// holds for walking only.
#[test]
fn finding_running_transpose_hands_are_no_rougher_than_dls_and_sdls() {
    let transpose = running(Method::Transpose).hands;
    for method in [Method::Dls, Method::Sdls] {
        let other = running(method).hands;
        assert!(
            transpose.oscillation_hz < 1.5 * other.oscillation_hz,
            "transpose {transpose:?} {} {other:?}",
            method.name()
        );
        assert!(
            transpose.jitter_rad < 1.5 * other.jitter_rad,
            "transpose {transpose:?} {} {other:?}",
            method.name()
        );
    }
}

/// §5.3 pinv "performs a little bit better than Jacobian transpose method in
/// giving a smooth visual result"; gaitlab measures it far less smooth on the
/// listing (walking hand jitter more than 5 × transpose's) and tracking worse
/// (the walking feet miss by more than 5 × transpose's error: the 0.2 rad step
/// clamp scales the whole Δθ down when the stretched arms ask for large steps).
#[test]
fn finding_pinv_is_rougher_and_tracks_worse_than_transpose() {
    let (pinv, transpose) = (walk(Method::Pinv), walk(Method::Transpose));
    assert!(
        pinv.hands.jitter_rad > 5.0 * transpose.hands.jitter_rad,
        "pinv {pinv:?} transpose {transpose:?}"
    );
    assert!(
        pinv.feet.error_m > 5.0 * transpose.feet.error_m,
        "pinv {pinv:?} transpose {transpose:?}"
    );
}

/// The other way: with the lab's clamp on every method, Buss's α and λ =
/// 0.05 m, two of §5.3's statements fail. DLS's walking feet miss by more than
/// twice the transpose's error (its knee stops at the limit and the clamp
/// keeps the other joints from making up the rest), and the transpose's
/// walking hands are about as calm as DLS's and SDLS's (under 1.5 × each).
#[test]
fn lab_settings_make_the_transpose_track_better_and_calmer_than_dls() {
    let (dls, transpose) = (lab_walk(Method::Dls), lab_walk(Method::Transpose));
    assert!(
        dls.feet.error_m > 2.0 * transpose.feet.error_m,
        "DLS {dls:?} transpose {transpose:?}"
    );
    for method in [Method::Dls, Method::Sdls] {
        let other = lab_walk(method).hands;
        assert!(
            transpose.hands.oscillation_hz < 1.5 * other.oscillation_hz,
            "transpose {transpose:?} {} {other:?}",
            method.name()
        );
        assert!(
            transpose.hands.jitter_rad < 1.5 * other.jitter_rad,
            "transpose {transpose:?} {} {other:?}",
            method.name()
        );
    }
}

/// The other way, DLS without the clamp but with λ = 0.05 m: the walking feet
/// are tracked (under 1 mm) but the unreachable hands shake, at more than
/// 1.5 × SDLS's oscillation and 100 × its jitter: the λ the clamp hid.
#[test]
fn lab_lambda_without_the_clamp_makes_dls_shake_on_the_stretched_arms() {
    let mut creature = common::she_2006();
    creature.scenario.ik.lambda = 0.05;
    let dls = run(&creature, ThesisMode::Walk, Method::Dls);
    let sdls = walk(Method::Sdls);
    assert!(dls.feet.error_m < 1e-3, "λ 0.05: DLS {dls:?}");
    assert!(
        dls.hands.oscillation_hz > 1.5 * sdls.hands.oscillation_hz,
        "λ 0.05: DLS {dls:?} SDLS {sdls:?}"
    );
    assert!(
        dls.hands.jitter_rad > 100.0 * sdls.hands.jitter_rad,
        "λ 0.05: DLS {dls:?} SDLS {sdls:?}"
    );
}

/// The lab's limit handling, measured against the thesis' clamp with the lab's
/// solver settings: with `limit_passes` 4 (clamp, then re-solve without the
/// clamped joints: the lab's default elsewhere) DLS's stretched arms reverse
/// most often and shake most of the four on the walking hands, and DLS tracks
/// the walking feet closer than the transpose. The thesis' clamp is what makes
/// DLS smooth there.
#[test]
fn the_labs_limit_resolve_makes_dls_shake_on_the_stretched_arms() {
    let mut creature = she_2006_as_before();
    creature.scenario.ik.limit_passes = 4;
    let resolved: Vec<(Method, Run)> = METHODS
        .iter()
        .map(|&m| (m, run(&creature, ThesisMode::Walk, m)))
        .collect();
    let dls = resolved[2].1;
    for (method, other) in resolved.iter().filter(|(m, _)| *m != Method::Dls) {
        let name = method.name();
        assert!(
            dls.hands.oscillation_hz > other.hands.oscillation_hz,
            "re-solve: DLS {dls:?} {name} {other:?}"
        );
        assert!(
            dls.hands.jitter_rad > other.hands.jitter_rad,
            "re-solve: DLS {dls:?} {name} {other:?}"
        );
    }
    let transpose = resolved[0].1;
    assert!(
        dls.feet.error_m < transpose.feet.error_m,
        "re-solve: DLS {dls:?} transpose {transpose:?}"
    );
    // Against the thesis' clamp: DLS's walking hand jitter falls by 10 × or more.
    assert!(
        lab_walk(Method::Dls).hands.jitter_rad * 10.0 < dls.hands.jitter_rad,
        "clamp {:?} re-solve {dls:?}",
        lab_walk(Method::Dls)
    );
}
