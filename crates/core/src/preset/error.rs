//! The one error type of preset parsing, validation and building:
//! `PresetError { path, reason }`, shown to people as `path: reason`, where
//! `path` is a JSON path into the preset (`skeleton.joints[3].axis`).

use std::fmt;

/// JSON path used when an error concerns the whole document (JSONPath's root).
pub const ROOT_PATH: &str = "$";

/// Why a preset was rejected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PresetError {
    /// JSON path of the offending value, e.g. `skeleton.joints[3].axis`; [`ROOT_PATH`] (`$`)
    /// for the document as a whole (too large, empty, trailing characters).
    pub path: String,
    /// What is wrong, in words. Syntax and type errors end with `at line L column C`.
    pub reason: String,
}

impl PresetError {
    /// An error at `path` because of `reason`.
    #[must_use]
    pub fn new(path: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            reason: reason.into(),
        }
    }

    /// Converts a typed serde error into a path error. serde reports a missing
    /// field at the enclosing object; its name is appended so that the path
    /// points at the field itself (an unknown key is already on the path).
    pub(crate) fn from_serde(error: &serde_path_to_error::Error<serde_json::Error>) -> Self {
        let path = json_path(error.path());
        let reason = error.inner().to_string();
        let missing = reason
            .strip_prefix("missing field `")
            .and_then(|rest| rest.split_once('`'))
            .map(|(field, _)| field);
        let path = match (missing, path.is_empty()) {
            (Some(field), true) => field.to_owned(),
            (Some(field), false) => format!("{path}.{field}"),
            (None, true) => ROOT_PATH.to_owned(),
            (None, false) => path,
        };
        Self { path, reason }
    }
}

impl PresetError {
    /// JSON has no NaN or Infinity: when serde stops at such a token, say so
    /// instead of the bare "expected value".
    pub(crate) fn with_non_finite_hint(mut self, json: &str, error: &serde_json::Error) -> Self {
        let (line, column) = (error.line(), error.column());
        let token = json
            .lines()
            .nth(line.saturating_sub(1))
            .and_then(|text| text.get(column.saturating_sub(1)..))
            .unwrap_or("")
            .trim_start_matches(['-', '+']);
        if ["NaN", "nan", "Infinity", "inf"]
            .iter()
            .any(|t| token.starts_with(t))
        {
            self.reason = format!(
                "every number must be finite: NaN and Infinity are not JSON numbers ({})",
                self.reason
            );
        }
        self
    }
}

/// Writes a serde path as `a.b[3].c`, stopping at the first segment serde could
/// not name (after the last key of an object, for example). Empty for the root.
pub fn json_path(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for segment in path.iter() {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } | Segment::Enum { variant: key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
            }
            Segment::Unknown => break,
        }
    }
    out
}

impl fmt::Display for PresetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.reason)
    }
}

impl std::error::Error for PresetError {}
