//! Deprecated preset values (DESIGN.md "Versions"): what presets made before
//! a change may still say. They are read and run as before; each one found
//! is named by a warning that says what changed, for the CLI's stderr and the
//! page's message line.

use std::fmt;

use super::Creature;

/// One deprecated value in a preset.
#[derive(Clone, Debug, PartialEq)]
pub struct Deprecation {
    /// JSON path of the value, e.g. `scenario.poda.vertical_gain`.
    pub path: String,
    /// What is deprecated and what runs instead.
    pub message: String,
}

impl fmt::Display for Deprecation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

impl Creature {
    /// The deprecated values this creature's preset uses (none for the
    /// bundled presets).
    #[must_use]
    pub fn deprecations(&self) -> Vec<Deprecation> {
        let mut out = Vec::new();
        if let Some(poda) = &self.scenario.poda
            && poda.vertical_gain != 1.0
        {
            out.push(Deprecation {
                path: "scenario.poda.vertical_gain".to_owned(),
                message: format!(
                    "{} is deprecated: Girard & Maciejewski's eq. 12–13 scale the body's \
                     vertical motion by nothing (a smaller bob comes from the leg force and the \
                     body's mass); this preset still runs with it, as it was made",
                    poda.vertical_gain
                ),
            });
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use crate::preset::{bundled, load_bundled};

    #[test]
    fn the_bundled_presets_use_nothing_deprecated() {
        for (name, _) in bundled() {
            let creature = match load_bundled(name) {
                Some(Ok(creature)) => creature,
                other => panic!("{name}: {other:?}"),
            };
            assert_eq!(creature.deprecations(), Vec::new(), "{name}");
        }
    }

    #[test]
    fn a_vertical_gain_is_named() {
        let Some(Ok(mut creature)) = load_bundled("hexapod") else {
            panic!("hexapod")
        };
        if let Some(poda) = creature.scenario.poda.as_mut() {
            poda.vertical_gain = 0.3;
        }
        let found = creature.deprecations();
        assert_eq!(found.len(), 1);
        let text = found[0].to_string();
        assert!(
            text.starts_with("scenario.poda.vertical_gain: 0.3 is deprecated"),
            "{text}"
        );
    }
}
