//! Printing a run's [`RunMetrics`]: one JSON line (`--json`), or a short
//! human-readable summary per engine.

use crate::schedule::Outcome;
use crate::stdout::outln;
use gaitlab_engine::RunMetrics;
use gaitlab_engine::metrics::{GaitRunMetrics, IkRunMetrics, PhysicsRunMetrics};

/// Prints `metrics` as one JSON line (with the live `changes`, if any, under
/// `changes`), or as a short table.
pub fn print(metrics: &RunMetrics, changes: &[Outcome], as_json: bool) {
    if as_json {
        let line = serde_json::to_value(metrics).and_then(|mut value| {
            if let (false, Some(map)) = (changes.is_empty(), value.as_object_mut()) {
                map.insert("changes".to_owned(), serde_json::to_value(changes)?);
            }
            serde_json::to_string(&value)
        });
        match line {
            Ok(line) => outln!("{line}"),
            // Plain structs of numbers and strings always serialize.
            Err(error) => eprintln!("error: metrics: {error}"),
        }
        return;
    }
    match metrics {
        RunMetrics::Ik(ik) => print_ik(ik),
        RunMetrics::Gait(gait) => print_gait(gait),
        RunMetrics::Physics(physics) => print_physics(physics),
    }
    for outcome in changes {
        match &outcome.refused {
            None => outln!(
                "  change {} at {:.3} s{}",
                outcome.change,
                outcome.applied_at_s,
                if outcome.derived.is_empty() {
                    String::new()
                } else {
                    format!(" (derived {})", outcome.derived.join(", "))
                }
            ),
            Some(reason) => outln!(
                "  change {} at {:.3} s refused: {reason}",
                outcome.change,
                outcome.applied_at_s
            ),
        }
    }
}

fn mm(metres: Option<f64>) -> String {
    metres.map_or("-".to_owned(), |m| format!("{:.2}", m * 1e3))
}

fn print_ik(m: &IkRunMetrics) {
    outln!(
        "{} · engine {} · method {} · {} frames ({:.2} s simulated) in {:.1} ms · {:.2} µs per IK iteration",
        m.preset,
        m.engine,
        m.method,
        m.frames,
        m.sim_seconds,
        m.wall_ms,
        m.us_per_iteration,
    );
    outln!(
        "  {:<14} {:>12} {:>12}",
        "effector",
        "mean err mm",
        "max err mm"
    );
    for effector in &m.effectors {
        outln!(
            "  {:<20} {:>12} {:>12}",
            effector.name,
            mm(effector.mean_error_m),
            mm(effector.max_error_m)
        );
    }
}

fn print_gait(m: &GaitRunMetrics) {
    let or_nan = |v: Option<f64>| v.unwrap_or(f64::NAN);
    outln!(
        "{} · engine poda · gait {} · {} frames ({:.2} s simulated) in {:.1} ms · {:.1} µs per frame",
        m.preset,
        m.gait,
        m.frames,
        m.sim_seconds,
        m.wall_ms,
        m.us_per_frame,
    );
    outln!(
        "  foot slip max {:.3} mm · period {:.3} s · stride {:.3} m · body speed {:.3} m/s",
        m.foot_slip_max_m * 1e3,
        or_nan(m.period_s),
        or_nan(m.stride_length_m),
        m.body_speed_mps,
    );
    if let Some(t) = &m.terrain {
        outln!(
            "  terrain {} · made good {:.3} m · climbed {:.3} m · deepest foot below ground {:.3} mm · footholds moved off uneven spots: {} · body eased toward the ground: {} frames (least kept {:.3})",
            t.kind,
            t.made_good_m,
            t.climbed_m,
            t.foot_below_ground_max_m.max(0.0) * 1e3,
            t.footholds_moved,
            t.body_eased_frames,
            t.body_eased_least_kept,
        );
    }
    outln!(
        "  {:<14} {:>10} {:>10} {:>10} {:>10}",
        "leg",
        "duty",
        "(set)",
        "phase",
        "(set)"
    );
    let value = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v:.3}"));
    for leg in &m.legs {
        outln!(
            "  {:<14} {:>10} {:>10} {:>10} {:>10}",
            leg.name,
            value(leg.duty_factor),
            value(Some(leg.duty_factor_set)),
            value(leg.relative_phase),
            value(Some(leg.relative_phase_set)),
        );
    }
}

/// Why the creature fell or was put back, in the text output too (the
/// `--json` output lists the put-backs, the first 100, under `put_backs`).
fn print_put_backs(m: &PhysicsRunMetrics) {
    match (m.put_backs.first(), m.put_backs.last()) {
        (Some(first), Some(last)) => {
            let count = m.put_backs.len();
            let times = if count == 1 {
                "once".to_owned()
            } else {
                format!("{count} times")
            };
            outln!(
                "put back {times}; the first at {:.3} s: {}",
                first.run_time_s,
                first.why
            );
            if count > 1 && last.why != first.why {
                outln!("the last at {:.3} s: {}", last.run_time_s, last.why);
            }
        }
        _ if m.fell => outln!(
            "fell: the trunk tipped past 60° or sank below 40 % of its leg's reach (a headless run reports the fall and runs on)"
        ),
        _ => {}
    }
}

fn print_physics(m: &PhysicsRunMetrics) {
    outln!(
        "{} · engine physics · gait {} · {:.1} s simulated · fell {} · speed {:.2} of {:.2} m/s · stride {:.2} m in {:.2} s · flight {:.3} s · stance {:.3} s · pitch {:.1}° · roll {:.1}° · friction needed {:.2} (mid-support {:.2}, first and last 10 ms {:.2}) · cost of transport {:.2} · {:.0} steps/s ({:.0}× real time)",
        m.preset,
        m.gait,
        m.sim_seconds,
        m.fell,
        m.speed_mean_mps,
        m.speed_desired_mps,
        m.stride_length_m,
        m.stride_duration_s,
        m.flight_duration_s,
        m.stance_duration_s,
        m.pitch_magnitude_deg,
        m.roll_magnitude_deg,
        m.friction_needed_max,
        m.friction_needed_mid,
        m.friction_needed_edges,
        m.cost_of_transport,
        m.steps_per_second,
        m.realtime_factor,
    );
    print_put_backs(m);
    if let Some(t) = &m.terrain {
        let [low, high] = t.trunk_height_range_m.unwrap_or([f64::NAN; 2]);
        outln!(
            "  terrain {} · made good {:.3} m · climbed {:.3} m · trunk {:.3}–{:.3} m above the ground · deepest foot in the ground springs {:.1} mm",
            t.kind,
            t.made_good_m,
            t.climbed_m,
            low,
            high,
            t.foot_below_ground_max_m.max(0.0) * 1e3,
        );
    }
    for p in &m.pushes {
        let verdict = match p.recovered {
            Some(true) => "recovered",
            Some(false) if p.fell => "fell",
            Some(false) => "did not recover its speed",
            None => "no verdict: the run ended within 5 s of it",
        };
        let after = p.speed_after_mps.map_or_else(String::new, |v| {
            format!(" (speed {v:.2} of {:.2} m/s after 5 s)", p.desired_mps)
        });
        outln!(
            "push at {:.2} s of ({:+.2}, {:+.2}) m/s: {verdict}{after}",
            p.at_s,
            p.dv_mps[0],
            p.dv_mps[1]
        );
    }
    if m.table2.is_empty() {
        return;
    }
    outln!("Table 2 (Raibert & Hodgins 1991, animation column) beside this run:");
    for row in &m.table2 {
        let measured = row
            .measured
            .map_or_else(|| "—".to_owned(), |v| format!("{v:.3}"));
        let diff = match (row.input, row.diff_pct) {
            (true, _) => "input".to_owned(),
            (false, Some(d)) => format!("{d:+.0} %"),
            (false, None) => String::new(),
        };
        outln!(
            "  {:<40} paper {:>6} · run {:>7} {}",
            row.quantity,
            row.paper,
            measured,
            diff
        );
    }
}
