//! Errors from building or reconfiguring a driver: a path into the
//! parameters plus a reason, shown to people as `path: reason` (STYLE.md).

use std::fmt;

/// Why a driver could not be built or reconfigured.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DriverError {
    /// Where the problem is, e.g. `wounded[1].joint` or `walk.frequency_hz`.
    pub path: String,
    /// What is wrong.
    pub reason: String,
}

impl DriverError {
    /// An error at `path` for `reason`.
    #[must_use]
    pub fn new(path: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for DriverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.reason)
    }
}

impl std::error::Error for DriverError {}
