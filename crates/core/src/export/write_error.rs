//! The one error type of the export writers (BVH, pose CSV, target CSV).

use std::fmt;

/// Why a writer refused to write. Writers check a frame completely before
/// writing any of it, so after an error other than [`WriteError::Sink`] the
/// output still ends at a line boundary.
#[derive(Clone, Debug, PartialEq)]
pub enum WriteError {
    /// The output sink ([`std::fmt::Write`]) reported an error.
    Sink,
    /// A constructor argument or option is out of range.
    InvalidOption {
        /// Which argument, e.g. `fps`.
        name: &'static str,
        /// What is wrong with it.
        reason: String,
    },
    /// A slice has the wrong length (joint values, effector positions, names).
    ValueCount {
        /// What was counted, e.g. `joint values`.
        what: &'static str,
        /// How many the skeleton or header needs.
        expected: usize,
        /// How many were given.
        found: usize,
    },
    /// A value to be written is NaN or infinite (the readers would reject the file).
    NonFinite {
        /// What holds the value, e.g. `pose`.
        what: &'static str,
        /// Zero-based frame or row index.
        row: usize,
    },
    /// Times of a target CSV must increase strictly from row to row.
    TimeNotIncreasing {
        /// Zero-based row index.
        row: usize,
        /// The offending time, seconds.
        time: f64,
        /// The previous row's time, seconds.
        previous: f64,
    },
    /// Calls made in the wrong order: a frame before the header, a second header.
    Order(&'static str),
    /// A BVH stream ended with a different number of frames than its header declared.
    FrameCount {
        /// `Frames:` written in the header.
        declared: usize,
        /// Frames actually written.
        written: usize,
    },
}

impl From<fmt::Error> for WriteError {
    fn from(_: fmt::Error) -> Self {
        Self::Sink
    }
}

impl fmt::Display for WriteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Sink => write!(f, "the output refused the text"),
            Self::InvalidOption { name, reason } => write!(f, "{name}: {reason}"),
            Self::ValueCount {
                what,
                expected,
                found,
            } => {
                write!(f, "expected {expected} {what}, found {found}")
            }
            Self::NonFinite { what, row } => {
                write!(f, "row {row}: {what} holds a NaN or infinite value")
            }
            Self::TimeNotIncreasing {
                row,
                time,
                previous,
            } => {
                write!(
                    f,
                    "row {row}: time {time} is not after the previous time {previous}"
                )
            }
            Self::Order(reason) => f.write_str(reason),
            Self::FrameCount { declared, written } => {
                write!(
                    f,
                    "the header declared {declared} frames but {written} were written"
                )
            }
        }
    }
}

impl std::error::Error for WriteError {}
