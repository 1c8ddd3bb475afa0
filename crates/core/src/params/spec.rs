//! One row of an engine's parameter table ([`ParamSpec`]): key, unit, valid
//! range ([`Domain`]), live or not, the paper's reference and the value's
//! [`Origin`]; the range checks every reader of the value shares.

use std::f64::consts::{PI, TAU};
use std::fmt::Write as _;

use serde::Serialize;

use crate::preset::PresetError;

/// Where a parameter's value or behaviour comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// The paper's value, law or choice.
    Paper,
    /// A value the paper leaves open: the lab's pick (the row's `why` says
    /// why this value).
    Open,
    /// The lab's addition: behaviour the paper does not have, off by default
    /// unless the row's `why` names the claim it rescues.
    Lab,
}

impl Origin {
    /// The origin as `--json` and the page write it (`paper`, `open`, `lab`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Paper => "paper",
            Self::Open => "open",
            Self::Lab => "lab",
        }
    }
}

/// The values a parameter may take.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Domain {
    /// A real number from `min` to `max`; an open end excludes its bound.
    Real {
        /// Smallest value (excluded when `min_open`).
        min: f64,
        /// Largest value (excluded when `max_open`).
        max: f64,
        /// Whether `min` itself is refused.
        min_open: bool,
        /// Whether `max` itself is refused.
        max_open: bool,
    },
    /// A whole number from `min` to `max`, both included.
    Integer {
        /// Smallest value.
        min: i64,
        /// Largest value.
        max: i64,
    },
    /// On or off.
    Bool,
    /// One of these names.
    Choice {
        /// The names accepted.
        options: &'static [&'static str],
    },
    /// A list, vector or object, or a name whose choices another crate
    /// owns (the physics gaits: the engine's gait table), checked by the
    /// preset's rules for it (`shape` says what it holds).
    Structured {
        /// What the value holds, in words (`[x, y, z] m`, `list of [along, height]`).
        shape: &'static str,
    },
}

impl Domain {
    /// A closed range [`min`, `max`].
    #[must_use]
    pub const fn closed(min: f64, max: f64) -> Self {
        Self::Real {
            min,
            max,
            min_open: false,
            max_open: false,
        }
    }

    /// A range (`min`, `max`]: `min` refused.
    #[must_use]
    pub const fn above(min: f64, max: f64) -> Self {
        Self::Real {
            min,
            max,
            min_open: true,
            max_open: false,
        }
    }

    /// A range (`min`, `max`): both ends refused.
    #[must_use]
    pub const fn open(min: f64, max: f64) -> Self {
        Self::Real {
            min,
            max,
            min_open: true,
            max_open: true,
        }
    }

    /// Whether a real `value` lies in this domain (`false` for a domain
    /// that is not a number).
    #[must_use]
    pub fn contains(&self, value: f64) -> bool {
        match *self {
            Self::Real {
                min,
                max,
                min_open,
                max_open,
            } => {
                value.is_finite()
                    && (if min_open { value > min } else { value >= min })
                    && (if max_open { value < max } else { value <= max })
            }
            #[expect(
                clippy::cast_precision_loss,
                reason = "integer bounds are small (at most thousands)"
            )]
            Self::Integer { min, max } => {
                value.is_finite()
                    && value.fract() == 0.0
                    && value >= min as f64
                    && value <= max as f64
            }
            Self::Bool | Self::Choice { .. } | Self::Structured { .. } => false,
        }
    }

    /// The range in words: `(0, 10]`, `between 1 and 16`, `on or off`.
    #[must_use]
    pub fn describe(&self) -> String {
        match *self {
            Self::Real {
                min,
                max,
                min_open,
                max_open,
            } => format!(
                "{}{}, {}{}",
                if min_open { '(' } else { '[' },
                show(min),
                show(max),
                if max_open { ')' } else { ']' }
            ),
            Self::Integer { min, max } => format!("between {min} and {max}"),
            Self::Bool => "true or false".to_owned(),
            Self::Choice { options } => {
                let mut out = String::from("one of ");
                for (i, o) in options.iter().enumerate() {
                    let _ = write!(out, "{}\"{o}\"", if i == 0 { "" } else { ", " });
                }
                out
            }
            Self::Structured { shape } => shape.to_owned(),
        }
    }
}

/// A bound as people write it: π and 2π by name, other numbers plainly.
fn show(x: f64) -> String {
    if (x - PI).abs() < 1e-12 {
        "π".to_owned()
    } else if (x - TAU).abs() < 1e-12 {
        "2π".to_owned()
    } else if (x + PI).abs() < 1e-12 {
        "−π".to_owned()
    } else {
        format!("{x}")
    }
}

/// One settable value of an engine.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ParamSpec {
    /// Its path in a preset, as `--set` and the preset's errors name it
    /// (`scenario.ik.lambda`).
    pub key: &'static str,
    /// The page's command key and `--edit` key that set it while running
    /// (`lambda`), where there is one.
    pub command: Option<&'static str>,
    /// What it is, in a few words for people.
    pub label: &'static str,
    /// Unit (`m`, `s`, `rad`, `m/s`, `N`; empty for a pure number).
    pub unit: &'static str,
    /// The values it may take.
    pub domain: Domain,
    /// Whether it changes while running (command or `--edit`); otherwise it
    /// takes effect when the preset is loaded or the run restarts.
    pub live: bool,
    /// Where the paper speaks of it (section, equation, table), or where
    /// the lab's docs explain it.
    pub reference: &'static str,
    /// The paper's, a value the paper leaves open, or the lab's addition.
    pub origin: Origin,
    /// Why this value or this addition (the origin's reason), one line.
    pub why: &'static str,
}

impl ParamSpec {
    /// The unit after a number (` m`); empty for a pure number.
    fn unit_suffix(&self) -> String {
        if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        }
    }

    /// Checks a real value against the domain.
    ///
    /// # Errors
    /// `path: must be in (0, 10] m` (the domain's words and the unit) for a
    /// value outside it.
    pub fn check_real(&self, path: &str, value: f64) -> Result<(), PresetError> {
        if self.domain.contains(value) {
            return Ok(());
        }
        let unit = self.unit_suffix();
        Err(PresetError::new(
            path,
            match self.domain {
                Domain::Integer { .. } => format!("must be {}", self.domain.describe()),
                Domain::Real {
                    min,
                    max,
                    min_open: false,
                    max_open: false,
                } => format!("must be between {} and {}{unit}", show(min), show(max)),
                _ => format!("must be in {}{unit}", self.domain.describe()),
            },
        ))
    }

    /// Checks a value a command gives for this row, with the command's
    /// wording: `lambda: -1 is outside (0, 10] m`.
    ///
    /// # Errors
    /// `key: value is outside range unit` for a value outside the domain.
    pub fn check_command(&self, key: &str, value: f64) -> Result<f64, String> {
        if self.domain.contains(value) {
            Ok(value)
        } else {
            let unit = self.unit_suffix();
            Err(format!(
                "{key}: {value} is outside {}{unit}",
                self.domain.describe()
            ))
        }
    }

    /// Checks a whole number against the domain (see [`Self::check_real`]).
    ///
    /// # Errors
    /// `path: must be between 1 and 16` for a value outside it.
    #[expect(
        clippy::cast_precision_loss,
        reason = "a count far past the bounds stays far past them as f64"
    )]
    pub fn check_integer(&self, path: &str, value: usize) -> Result<(), PresetError> {
        self.check_real(path, value as f64)
    }
}

/// The row with key `key` of `table`.
///
/// # Panics
/// When `table` has no such row: the tables are constants, and a test walks
/// every lookup.
#[must_use]
pub fn row(table: &'static [ParamSpec], key: &str) -> &'static ParamSpec {
    match table.iter().find(|p| p.key == key) {
        Some(p) => p,
        None => panic!("parameter table has no row {key}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn domains_check_their_ends_and_say_them() {
        let d = Domain::above(0.0, 10.0);
        assert!(!d.contains(0.0) && d.contains(1e-9) && d.contains(10.0) && !d.contains(10.5));
        assert!(!d.contains(f64::NAN));
        assert_eq!(d.describe(), "(0, 10]");
        assert_eq!(Domain::open(0.0, PI).describe(), "(0, π)");
        let i = Domain::Integer { min: 1, max: 16 };
        assert!(i.contains(1.0) && i.contains(16.0) && !i.contains(17.0) && !i.contains(2.5));
        assert_eq!(i.describe(), "between 1 and 16");
    }
}
