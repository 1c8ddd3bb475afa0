//! The error of the target CSV reader and of [`super::TargetTrack::new`]: a reason, with the line
//! and column it is on when it came from text.

use std::fmt;

/// Why a target CSV (or a [`super::TargetTrack`]) was refused. Shown as
/// `line 7, column 4: reason`, `line 7: reason` or just `reason`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CsvError {
    /// 1-based line of the problem, if it is on one line.
    pub line: Option<usize>,
    /// 1-based column (field) of the problem, if it is in one field.
    pub column: Option<usize>,
    /// What is wrong.
    pub reason: String,
}

impl CsvError {
    pub(super) fn at(line: usize, column: usize, reason: impl Into<String>) -> Self {
        Self {
            line: Some(line),
            column: Some(column),
            reason: reason.into(),
        }
    }

    pub(super) fn on_line(line: usize, reason: impl Into<String>) -> Self {
        Self {
            line: Some(line),
            column: None,
            reason: reason.into(),
        }
    }

    pub(crate) fn detached(reason: impl Into<String>) -> Self {
        Self {
            line: None,
            column: None,
            reason: reason.into(),
        }
    }
}

impl fmt::Display for CsvError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(line), Some(column)) => {
                write!(f, "line {line}, column {column}: {}", self.reason)
            }
            (Some(line), None) => write!(f, "line {line}: {}", self.reason),
            _ => f.write_str(&self.reason),
        }
    }
}

impl std::error::Error for CsvError {}
