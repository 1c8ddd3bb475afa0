//! `drag_target` in `command(json)`: the JS API's grab and pull —
//! `{"drag_target": {"name": EFFECTOR, "position": [x, y, z] | null,
//! "pin": BOOL}}` holds the effector's target at a world point (metres), lets
//! go of it (`null`), and pins or unpins it (a pinned target stays where it
//! is left). Keys other than `name` may be left out.

use gaitlab_core::Skeleton;
use glam::DVec3;
use serde::{Deserialize, Deserializer};

use super::hand::{Grab, GrabEvent};

/// The largest |coordinate| a dragged target may have, metres.
pub const MAX_DRAG_M: f64 = 100.0;

/// `drag_target`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct DragTargetCommand {
    /// The effector whose target moves (`state().views[0].effectors` names them).
    pub name: String,
    /// Where to hold the target, world `[x, y, z]` metres; `null` lets go
    /// (the script takes it back, blended, unless it is pinned).
    #[serde(default, deserialize_with = "present")]
    #[cfg_attr(feature = "schema", schemars(with = "Option<[f64; 3]>"))]
    pub position: Option<Option<[f64; 3]>>,
    /// Pin (true) or unpin (false) the target.
    pub pin: Option<bool>,
}

/// A present key, `null` included, as `Some`.
fn present<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Option<[f64; 3]>>, D::Error> {
    Ok(Some(Option::deserialize(d)?))
}

impl Grab {
    /// Turns a `drag_target` command into the hand's events for the figure
    /// `skeleton` (the lab applies them as it applies a drag's).
    ///
    /// # Errors
    /// `drag_target.name: …` for an effector the figure lacks,
    /// `drag_target.position: …` for a point beyond ±[`MAX_DRAG_M`].
    pub fn command(&mut self, c: &DragTargetCommand, skeleton: &Skeleton) -> Result<(), String> {
        let effector = skeleton.effector_index(&c.name).ok_or_else(|| {
            let names: Vec<&str> = skeleton
                .effectors()
                .iter()
                .map(|e| e.name.as_str())
                .collect();
            format!(
                "drag_target.name: no effector named {:?} (this figure has {})",
                c.name,
                names.join(", ")
            )
        })?;
        let position = match c.position {
            Some(Some(p)) => {
                if let Some(x) = p.iter().find(|x| x.is_nan() || x.abs() > MAX_DRAG_M) {
                    return Err(format!(
                        "drag_target.position: {x} is outside ±{MAX_DRAG_M} m"
                    ));
                }
                Some(Some(DVec3::from_array(p)))
            }
            other => other.map(|_| None),
        };
        if let Some(on) = c.pin {
            self.events.push(GrabEvent::Pin { effector, on });
        }
        match position {
            Some(Some(at)) => self.events.push(GrabEvent::Hold { effector, at }),
            Some(None) => self.events.push(GrabEvent::Release { effector }),
            None => {}
        }
        self.note_moved();
        Ok(())
    }
}
