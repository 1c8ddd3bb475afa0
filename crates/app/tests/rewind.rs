//! The history scrubber (issue 21 item 1): stepping back shows the stored
//! poses, and simulating forward again from there reproduces every stored
//! frame bit for bit — for the IK figure, a four-view comparison, a PODA
//! walker and a physics creature; a setting changed while back in time makes
//! a new future; the history reaches back at most 10 s.

use gaitlab_app::{App, Settings};

fn lab(preset: &str) -> App {
    let mut lab = App::new(Settings::default());
    if let Err(error) = lab.set_preset(preset) {
        panic!("{error}");
    }
    lab.set_paused(true);
    lab
}

fn command(lab: &mut App, json: &str) {
    if let Err(error) = lab.command(json) {
        panic!("{json}: {error}");
    }
}

/// One frame forward (as the Step button does) and the shown pose's digest.
fn step(lab: &mut App) -> String {
    lab.single_step();
    lab.advance(0.0);
    lab.rewind_state().pose_digest
}

/// Runs `frames` frames, then steps back 1 s and forward again, checking
/// every frame of that second against the digests taken the first time.
fn back_and_forth(lab: &mut App, frames: u64) {
    let fps = (1.0 / lab.frame_seconds()).round() as u64;
    let mut digests = Vec::new();
    for _ in 0..frames {
        digests.push(step(lab));
    }
    let end = lab.rewind_state().frame;
    assert_eq!(end, frames);
    command(lab, r#"{"step_back_s": 1}"#);
    let back = lab.rewind_state();
    assert_eq!(back.frame, end - fps, "one second back");
    assert!(lab.paused(), "stepping back pauses");
    // Frame k's digest is digests[k - 1].
    assert_eq!(
        back.pose_digest,
        digests[(end - fps - 1) as usize],
        "the stored pose at frame {}",
        back.frame
    );
    assert_eq!(back.newest_frame, end);
    for k in end - fps + 1..=end {
        let digest = step(lab);
        assert_eq!(
            digest,
            digests[(k - 1) as usize],
            "frame {k} simulated again"
        );
        assert_eq!(
            lab.rewind_state().pose_matches_stored,
            Some(true),
            "frame {k}"
        );
    }
    // Scrubbing to a frame between keyframes and back to the end.
    command(lab, &format!(r#"{{"rewind_to_frame": {}}}"#, end - 7));
    assert_eq!(lab.rewind_state().pose_digest, digests[(end - 8) as usize]);
    command(lab, &format!(r#"{{"rewind_to_frame": {end}}}"#));
    assert_eq!(lab.rewind_state().pose_digest, digests[(end - 1) as usize]);
}

#[test]
fn the_ik_figure_steps_back_and_replays_bit_for_bit() {
    let mut lab = lab("human");
    back_and_forth(&mut lab, 150);
}

#[test]
fn a_four_view_comparison_steps_back_and_replays_bit_for_bit() {
    let mut lab = lab("human");
    command(
        &mut lab,
        r#"{"compare":{"views":["transpose","pinv","dls","sdls"],"scenario":"singularity"}}"#,
    );
    lab.set_paused(true);
    back_and_forth(&mut lab, 130);
    // The views' figures came back with their poses: the jitter, a window
    // over the last frames, is what it was.
    let state: serde_json::Value = serde_json::from_str(&lab.state_json()).unwrap_or_default();
    let jitter = state["compare"]["metrics"][1]["jitter_rad"]
        .as_f64()
        .unwrap_or(0.0);
    assert!(jitter > 0.0, "{jitter}");
}

#[test]
fn a_poda_walker_and_a_physics_creature_step_back_and_replay_bit_for_bit() {
    for preset in ["hexapod", "raibert-biped"] {
        let mut lab = lab(preset);
        back_and_forth(&mut lab, 100);
    }
}

#[test]
fn a_change_made_back_in_time_starts_a_new_future() {
    let mut lab = lab("human");
    for _ in 0..120 {
        step(&mut lab);
    }
    command(&mut lab, r#"{"step_back_s": 1}"#);
    command(&mut lab, r#"{"method": "transpose"}"#);
    step(&mut lab);
    let state = lab.rewind_state();
    assert_eq!(state.pose_matches_stored, Some(false));
    assert_eq!(state.newest_frame, 61, "the old future is gone");
}

#[test]
fn the_history_reaches_back_ten_seconds_and_refuses_while_recording() {
    let mut lab = lab("human");
    for _ in 0..(12 * 60) {
        step(&mut lab);
    }
    command(&mut lab, r#"{"step_back_s": 10}"#);
    let state = lab.rewind_state();
    assert_eq!(state.newest_frame, 720);
    assert!(state.oldest_frame >= 720 - 600 + 1 - 30, "{state:?}");
    assert!(
        state.frame >= state.oldest_frame && state.frame <= 720 - 570,
        "{state:?}"
    );
    assert!(
        lab.command(r#"{"step_back_s": 11}"#)
            .is_err_and(|e| e.contains("step_back_s"))
    );
    lab.start_recording();
    let refused = lab.step_back(10);
    assert!(refused.is_err_and(|e| e.contains("stop recording")));
}
