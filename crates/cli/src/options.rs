//! Checks of the command-line options shared by `run` and `track`: the IK
//! method, the frame rate and length of a run, and `--last`. Errors name the
//! option (`--fps: must be …`).

use gaitlab_core::ik::Method;
use gaitlab_core::preset::MAX_FPS;
use gaitlab_engine::take::frames_in;

use crate::fail::Failure;

/// Longest run the CLI accepts, simulated seconds.
pub const MAX_SECONDS: f64 = 3600.0;

/// Parses `--method`.
pub fn method(name: Option<&str>, default: Method) -> Result<Method, Failure> {
    match name {
        None => Ok(default),
        Some(name) => Method::parse(name).ok_or_else(|| {
            Failure::input(format!(
                "--method: unknown method {name:?} (use transpose, pinv, dls, sdls or ccd)"
            ))
        }),
    }
}

/// Checks `--fps` (or the preset's) and `--seconds`, returning (fps, frames).
pub fn timing(fps: Option<u32>, preset_fps: u32, seconds: f64) -> Result<(f64, usize), Failure> {
    let fps = fps.unwrap_or(preset_fps);
    if fps == 0 || fps > MAX_FPS {
        return Err(Failure::input(format!(
            "--fps: must be between 1 and {MAX_FPS}"
        )));
    }
    if !seconds.is_finite() || seconds <= 0.0 || seconds > MAX_SECONDS {
        return Err(Failure::input(format!(
            "--seconds: must be more than 0 and at most {MAX_SECONDS}"
        )));
    }
    Ok((
        f64::from(fps),
        (seconds * f64::from(fps)).round().max(1.0) as usize,
    ))
}

/// Frames written to the files when `frames` are run at `fps` and only the
/// `last` seconds are wanted: the take's rule ([`frames_in`]), at most `frames`.
pub fn written_frames(last: Option<f64>, frames: usize, fps: f64) -> Result<usize, Failure> {
    let Some(seconds) = last else {
        return Ok(frames);
    };
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= MAX_SECONDS) {
        return Err(Failure::input(format!(
            "--last: must be more than 0 and at most {MAX_SECONDS} s"
        )));
    }
    Ok(frames_in(seconds, fps).min(frames))
}
