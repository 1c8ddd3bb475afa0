//! The CLI's error type: a message printed as `error: <message>` and an exit
//! code (2 for bad input — a preset, a target file, an argument — 1 for I/O,
//! 3 for a check that ran and failed).

use std::fmt::Display;

/// Why a command stopped.
#[derive(Debug)]
pub struct Failure {
    /// What went wrong, e.g. `skeleton.joints[3].axis: must be a non-zero vector`.
    pub message: String,
    /// Process exit code.
    pub code: u8,
}

impl Failure {
    /// Bad input from the user (exit code 2).
    pub fn input(message: impl Display) -> Self {
        Self {
            message: message.to_string(),
            code: 2,
        }
    }

    /// A check ran and failed, e.g. `gaitlab bench --check` found a slower case (exit code 3).
    pub fn check(message: impl Display) -> Self {
        Self {
            message: message.to_string(),
            code: 3,
        }
    }

    /// A file could not be read or written (exit code 1).
    pub fn io(path: &str, error: impl Display) -> Self {
        Self {
            message: format!("{path}: {error}"),
            code: 1,
        }
    }
}
