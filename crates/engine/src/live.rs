//! Live changes to a running driver — a gait switch, a gait-value edit and
//! a push (Girard & Maciejewski 1985's eq. 7–8 gait values and eq. 12–13 leg force;
//! Raibert & Hodgins 1991's desired speed and hop height) — in one place for
//! the page's commands and the CLI's `--switch T:GAIT` / `--edit T:KEY=VALUE`
//! / `--push T:VX,VZ`.
//! The drivers validate; this module routes and words the errors.

use crate::AnyDriver;
use crate::apply::{Applied, EngineCommand};

/// The gait-value keys [`edit_value`] takes, with their units.
pub const EDIT_KEYS: &[&str] = &[
    "period_s",
    "duty_factor",
    "speed_mps",
    "stroke_m",
    "leg_force_n",
    "hop_height_m",
];

/// Switches the gait of a PODA or physics driver ([`AnyDriver::apply`]'s
/// [`EngineCommand::Gait`]).
///
/// # Errors
/// `gait: reason` when the engine has no gaits or the name is unknown for
/// the creature; nothing changes.
pub fn switch_gait(driver: &mut AnyDriver, name: &str) -> Result<(), String> {
    driver.apply(EngineCommand::Gait(name)).map(drop)
}

/// Sets one gait value ([`EngineCommand::Value`]): PODA's `period_s`,
/// `duty_factor`, `speed_mps`, `stroke_m` (the gait model derives the others
/// so that eq. 7–8 stay true) or `leg_force_n` (each leg's upward force during
/// support, eq. 12–13); the physics controllers' `speed_mps` and
/// `hop_height_m`. Returns the names of the values the gait model derived.
///
/// # Errors
/// `key: reason` when the engine has no gait, the key is unknown, or the
/// value (or one derived from it) is out of range; nothing changes.
pub fn edit_value(
    driver: &mut AnyDriver,
    key: &str,
    value: f64,
) -> Result<Vec<&'static str>, String> {
    match driver.apply(EngineCommand::Value { key, value })? {
        Applied::Derived(derived) => Ok(derived),
        _ => Ok(Vec::new()),
    }
}

/// The name of the PODA gait `driver` runs now (after a switch, or a speed
/// edit that picked one: `scenario.poda.gait_by_speed`); `None` for the
/// other engines.
#[must_use]
pub fn poda_gait(driver: &AnyDriver) -> Option<&str> {
    match driver {
        AnyDriver::Poda(poda) => Some(poda.gait_name()),
        _ => None,
    }
}

/// What a scheduled change does.
#[derive(Clone, Debug, PartialEq)]
pub enum Change {
    /// Switch to this gait.
    Switch(String),
    /// Set this gait value ([`EDIT_KEYS`]).
    Edit {
        /// The key, e.g. `period_s`.
        key: String,
        /// The new value, in the key's unit.
        value: f64,
    },
    /// Push the physics creature's trunk by `[x, z]` m/s
    /// ([`EngineCommand::Push`]).
    Push([f64; 2]),
}

/// A change at a time of the run.
#[derive(Clone, Debug, PartialEq)]
pub struct TimedChange {
    /// Simulated seconds from the start; applied before the first frame
    /// stepped at or after this time.
    pub at_s: f64,
    /// What changes.
    pub change: Change,
}

impl TimedChange {
    /// Reads `T:GAIT` (`--switch`).
    ///
    /// # Errors
    /// What is wrong with the text: no `:`, a time that is not a finite
    /// number ≥ 0, or an empty gait name.
    pub fn switch(text: &str) -> Result<Self, String> {
        let (at_s, rest) = time_and_rest(text, "T:GAIT")?;
        let name = rest.trim();
        if name.is_empty() {
            return Err(format!("{text:?}: the gait name is empty (T:GAIT)"));
        }
        Ok(Self {
            at_s,
            change: Change::Switch(name.to_owned()),
        })
    }

    /// Reads `T:KEY=VALUE` (`--edit`).
    ///
    /// # Errors
    /// What is wrong with the text: the shape, the time, an unknown key or a
    /// value that is not a number.
    pub fn edit(text: &str) -> Result<Self, String> {
        let (at_s, rest) = time_and_rest(text, "T:KEY=VALUE")?;
        let Some((key, value)) = rest.split_once('=') else {
            return Err(format!("{text:?}: expected T:KEY=VALUE"));
        };
        let key = key.trim();
        if !EDIT_KEYS.contains(&key) {
            return Err(format!(
                "{text:?}: {key:?} is not a gait value ({})",
                EDIT_KEYS.join(", ")
            ));
        }
        let value: f64 = value
            .trim()
            .parse()
            .ok()
            .filter(|v: &f64| v.is_finite())
            .ok_or_else(|| format!("{text:?}: {key} must be a finite number"))?;
        Ok(Self {
            at_s,
            change: Change::Edit {
                key: key.to_owned(),
                value,
            },
        })
    }

    /// Reads `T:VX,VZ` (`--push`): a change of the trunk's velocity, m/s,
    /// world x (sideways) and z (forward at heading 0).
    ///
    /// # Errors
    /// What is wrong with the text: the shape, the time, or a speed that is
    /// not a finite number.
    pub fn push(text: &str) -> Result<Self, String> {
        let (at_s, rest) = time_and_rest(text, "T:VX,VZ")?;
        let Some((vx, vz)) = rest.split_once(',') else {
            return Err(format!(
                "{text:?}: expected T:VX,VZ (m/s sideways, forward)"
            ));
        };
        let speed = |name: &str, v: &str| {
            v.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("{text:?}: {name} must be a finite number of m/s"))
        };
        Ok(Self {
            at_s,
            change: Change::Push([speed("VX", vx)?, speed("VZ", vz)?]),
        })
    }

    /// Applies the change to `driver`; returns the derived values' names.
    ///
    /// # Errors
    /// As [`switch_gait`] and [`edit_value`].
    pub fn apply(&self, driver: &mut AnyDriver) -> Result<Vec<&'static str>, String> {
        match &self.change {
            Change::Switch(name) => switch_gait(driver, name).map(|()| Vec::new()),
            Change::Edit { key, value } => edit_value(driver, key, *value),
            Change::Push(dv) => driver.apply(EngineCommand::Push(*dv)).map(|_| Vec::new()),
        }
    }

    /// The change as the command line writes it (`3:trot`, `5:period_s=0.8`).
    #[must_use]
    pub fn describe(&self) -> String {
        match &self.change {
            Change::Switch(name) => format!("{}:{name}", self.at_s),
            Change::Edit { key, value } => format!("{}:{key}={value}", self.at_s),
            Change::Push([vx, vz]) => format!("{}:push {vx},{vz}", self.at_s),
        }
    }
}

fn time_and_rest<'a>(text: &'a str, shape: &str) -> Result<(f64, &'a str), String> {
    let Some((time, rest)) = text.split_once(':') else {
        return Err(format!("{text:?}: expected {shape}, T in seconds"));
    };
    let at_s: f64 = time
        .trim()
        .parse()
        .ok()
        .filter(|t: &f64| t.is_finite() && *t >= 0.0)
        .ok_or_else(|| format!("{text:?}: the time must be seconds ≥ 0 ({shape})"))?;
    Ok((at_s, rest))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn switches_and_edits_read_and_name_what_is_wrong() {
        assert_eq!(
            TimedChange::switch("2.5:trot"),
            Ok(TimedChange {
                at_s: 2.5,
                change: Change::Switch("trot".to_owned())
            })
        );
        assert_eq!(
            TimedChange::edit("3:period_s=0.8"),
            Ok(TimedChange {
                at_s: 3.0,
                change: Change::Edit {
                    key: "period_s".to_owned(),
                    value: 0.8
                }
            })
        );
        for (text, part) in [
            ("trot", "expected T:GAIT"),
            ("-1:trot", "seconds ≥ 0"),
            ("NaN:trot", "seconds ≥ 0"),
            ("1:", "gait name is empty"),
        ] {
            let error = TimedChange::switch(text).err().unwrap_or_default();
            assert!(error.contains(part), "{text}: {error}");
        }
        for (text, part) in [
            ("1:period_s", "expected T:KEY=VALUE"),
            ("1:colour=2", "not a gait value"),
            ("1:period_s=fast", "finite number"),
            ("1:period_s=inf", "finite number"),
        ] {
            let error = TimedChange::edit(text).err().unwrap_or_default();
            assert!(error.contains(part), "{text}: {error}");
        }
        assert_eq!(
            TimedChange::push("6:-0.3, 0.25"),
            Ok(TimedChange {
                at_s: 6.0,
                change: Change::Push([-0.3, 0.25])
            })
        );
        for (text, part) in [
            ("6:0.3", "expected T:VX,VZ"),
            ("6:x,0", "VX must be"),
            ("6:0,inf", "VZ must be"),
            ("x:0,0", "seconds ≥ 0"),
        ] {
            let error = TimedChange::push(text).err().unwrap_or_default();
            assert!(error.contains(part), "{text}: {error}");
        }
    }

    #[test]
    fn the_engines_take_what_they_have_and_refuse_the_rest() {
        let load = |name: &str| match gaitlab_core::preset::load_bundled(name) {
            Some(Ok(creature)) => {
                match crate::driver_for(&creature, &crate::Overrides::default()) {
                    Ok(driver) => driver,
                    Err(error) => panic!("{name}: {error}"),
                }
            }
            other => panic!("{name}: {other:?}"),
        };
        let mut poda = load("poda-quadruped");
        assert_eq!(switch_gait(&mut poda, "trot"), Ok(()));
        let derived = edit_value(&mut poda, "period_s", 0.8).unwrap_or_default();
        assert!(!derived.is_empty(), "a period edit derives another value");
        assert_eq!(poda.poda().map(|p| p.gait().period_s()), Some(0.8));
        let error = edit_value(&mut poda, "period_s", -1.0)
            .err()
            .unwrap_or_default();
        assert!(error.starts_with("period_s"), "{error}");
        assert_eq!(poda.poda().map(|p| p.gait().period_s()), Some(0.8));

        let mut human = load("human");
        assert_eq!(
            switch_gait(&mut human, "trot"),
            Err("gait: engine ik has no gaits (use mode)".to_owned())
        );
        assert_eq!(
            edit_value(&mut human, "speed_mps", 1.0),
            Err("speed_mps: engine ik has no gait".to_owned())
        );

        let mut biped = load("raibert-biped");
        assert_eq!(edit_value(&mut biped, "speed_mps", 1.0), Ok(Vec::new()));
        let error = edit_value(&mut biped, "stroke_m", 1.0)
            .err()
            .unwrap_or_default();
        assert!(error.contains("no such gait value"), "{error}");
    }
}
