//! A terrain that cannot be used: the field (a path inside the terrain
//! object, such as `heights_m[12]`) and what is wrong with it.

/// A bad terrain value: where inside the terrain object, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TerrainError {
    /// The field inside the terrain object (`rise_m`, `heights_m[3]`; empty
    /// for the terrain as a whole).
    pub field: String,
    /// What is wrong, in words.
    pub reason: String,
}

impl TerrainError {
    /// An error at `field` for `reason`.
    #[must_use]
    pub fn new(field: impl Into<String>, reason: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            reason: reason.into(),
        }
    }

    /// The full path under `prefix` (`scenario.terrain` → `scenario.terrain.rise_m`).
    #[must_use]
    pub fn path(&self, prefix: &str) -> String {
        if self.field.is_empty() {
            prefix.to_owned()
        } else if self.field.starts_with('[') {
            format!("{prefix}{}", self.field)
        } else {
            format!("{prefix}.{}", self.field)
        }
    }
}

impl std::fmt::Display for TerrainError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.path("terrain"), self.reason)
    }
}

impl std::error::Error for TerrainError {}

/// `value` is finite and within ±`limit`, or an error at `field`.
pub(super) fn finite_within(field: &str, value: f64, limit: f64) -> Result<(), TerrainError> {
    if !value.is_finite() {
        return Err(TerrainError::new(
            field,
            format!("{value} is not a finite number"),
        ));
    }
    if value.abs() > limit {
        return Err(TerrainError::new(
            field,
            format!("{value} is outside ±{limit}"),
        ));
    }
    Ok(())
}
