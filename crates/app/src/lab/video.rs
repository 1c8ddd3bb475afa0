//! The video recording's status as the web front end reports it (frames
//! copied, encoder, frames skipped, seconds), for `state().video`.

/// What the video recorder reports.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VideoStatus {
    /// Whether video of the 3-D view is recording (or asked to).
    pub recording: bool,
    /// Frames the video recorder has copied.
    pub frames: u64,
    /// The encoder the video recorder uses (empty before the first recording).
    pub encoder: &'static str,
    /// Frames the video encoder skipped because it had fallen behind.
    pub skipped: u64,
    /// Seconds of video recorded so far (from the first recorded frame).
    pub seconds: f64,
}
