//! `--switch T:GAIT`, `--edit T:KEY=VALUE` and `--push T:VX,VZ`: the live
//! changes of a headless run (a gait switch, a gait-value edit, as the
//! page's commands make them, and a push of a physics creature's trunk), applied through the engine layer's [`TimedChange`] when the
//! run's clock reaches them, each with what happened.

use gaitlab_engine::{AnyDriver, TimedChange};
use serde::Serialize;

use crate::fail::Failure;

/// What one change did.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Outcome {
    /// The change as written on the command line (`3:trot`, `5:period_s=0.8`).
    pub change: String,
    /// Simulated seconds at which it was applied (the first frame at or
    /// after its time).
    pub applied_at_s: f64,
    /// The values the gait model derived from an edit (eq. 7–8, 13).
    pub derived: Vec<&'static str>,
    /// The engine's refusal, `key: reason`; the run went on unchanged.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub refused: Option<String>,
    /// The PODA gait after the change (a switch, or a speed edit with
    /// `scenario.poda.gait_by_speed`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gait: Option<String>,
}

/// The run's changes in time order, and what each did.
#[derive(Debug, Default)]
pub struct Schedule {
    changes: Vec<TimedChange>,
    next: usize,
    /// One entry per applied change, in order.
    pub outcomes: Vec<Outcome>,
}

impl Schedule {
    /// Reads the `--switch`, `--edit` and `--push` arguments; changes at the
    /// same time apply in the order given, switches first, pushes last.
    ///
    /// # Errors
    /// `--switch TEXT: reason` / `--edit TEXT: reason` for a malformed one.
    pub fn parse(
        switches: &[String],
        edits: &[String],
        pushes: &[String],
    ) -> Result<Self, Failure> {
        let mut changes = Vec::with_capacity(switches.len() + edits.len() + pushes.len());
        for text in switches {
            changes.push(
                TimedChange::switch(text).map_err(|e| Failure::input(format!("--switch {e}")))?,
            );
        }
        for text in edits {
            changes
                .push(TimedChange::edit(text).map_err(|e| Failure::input(format!("--edit {e}")))?);
        }
        for text in pushes {
            changes
                .push(TimedChange::push(text).map_err(|e| Failure::input(format!("--push {e}")))?);
        }
        changes.sort_by(|a, b| a.at_s.total_cmp(&b.at_s));
        Ok(Self {
            outcomes: Vec::with_capacity(changes.len()),
            changes,
            next: 0,
        })
    }

    /// Whether there is nothing scheduled.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.changes.is_empty()
    }

    /// Applies every change due at the driver's time `now_s` (within half a
    /// frame of `dt_s`, so `3:trot` at 60 fps lands on frame 180).
    pub fn apply_due(&mut self, driver: &mut AnyDriver, now_s: f64, dt_s: f64) {
        while let Some(change) = self.changes.get(self.next) {
            if change.at_s > now_s + 0.5 * dt_s {
                break;
            }
            let result = change.apply(driver);
            if let Err(reason) = &result {
                eprintln!("warning: {}: refused: {reason}", change.describe());
            }
            self.outcomes.push(Outcome {
                change: change.describe(),
                applied_at_s: now_s,
                derived: result.as_ref().map_or_else(|_| Vec::new(), Clone::clone),
                refused: result.err(),
                gait: gaitlab_engine::poda_gait(driver).map(str::to_owned),
            });
            self.next += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn changes_are_read_and_sorted_by_time() {
        let schedule = Schedule::parse(
            &["5:trot".to_owned(), "1:walk".to_owned()],
            &["3:period_s=0.8".to_owned()],
            &["4:0.3,0".to_owned()],
        );
        let Ok(schedule) = schedule else {
            panic!("parses")
        };
        let times: Vec<f64> = schedule.changes.iter().map(|c| c.at_s).collect();
        assert_eq!(times, [1.0, 3.0, 4.0, 5.0]);
        let error = Schedule::parse(&[], &["x".to_owned()], &[]).err();
        assert!(
            error.is_some_and(|e| e.message.starts_with("--edit \"x\"")),
            "a malformed edit names the flag"
        );
    }
}
