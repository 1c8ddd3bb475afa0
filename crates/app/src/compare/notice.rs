//! "What to notice" for each comparison scenario (issue 21 item 1): a few
//! lines for a class, each one of She 2006's own statements (quoted where
//! short) with its section, so the teacher can point at the thesis. The
//! singularity scenario is the lab's (the thesis has no full-reach
//! experiment); its notes say so.

use super::config::CompareScenario;

/// One line of a note: what to look at, and where She 2006 says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoticeLine {
    /// What to look at, in plain words.
    pub text: &'static str,
    /// The thesis section it rests on.
    pub source: &'static str,
}

const SCRIPT: &[NoticeLine] = &[
    NoticeLine {
        text: "In the walk the foot targets are always within reach and the hand targets never are \
               (in the run, none of the four is): watch the hands.",
        source: "She 2006 §5.3",
    },
    NoticeLine {
        text: "The thesis found the Jacobian transpose jerky, and the pseudoinverse worst where \
               targets are out of reach: they \"caused the rigid body to oscillate\". Compare \
               pinv's error plot and oscillation row with the others.",
        source: "She 2006 §5.3",
    },
    NoticeLine {
        text: "DLS looked \"natural and smooth\"; SDLS did best on reachable and unreachable \
               targets alike.",
        source: "She 2006 §5.3, §7.1",
    },
];

const SINGULARITY: &[NoticeLine] = &[
    NoticeLine {
        text: "A fully stretched limb is singular: no small change of its joints moves its end \
               further along it.",
        source: "She 2006 §4.3.2",
    },
    NoticeLine {
        text: "Near such a pose the pseudoinverse lets effectors \"move to impossible directions \
               or oscillate\": watch pinv's jitter, limit hits and error spikes.",
        source: "She 2006 §4.4.2",
    },
    NoticeLine {
        text: "DLS stays stable with one damping constant that \"must be chosen very carefully\" \
               (try its λ slider); SDLS damps each singular direction on its own, with no \
               constant to choose.",
        source: "She 2006 §4.4.3, §4.4.5",
    },
    NoticeLine {
        text: "This scenario is the lab's: the thesis argues it from a stretched arm but never \
               runs limbs pulled past their reach.",
        source: "gaitlab",
    },
];

const RECORDED: &[NoticeLine] = &[
    NoticeLine {
        text: "The targets come from a recording, the same for every method: where one leaves \
               its limb's reach it turns orange, and the methods part.",
        source: "gaitlab",
    },
    NoticeLine {
        text: "On targets out of reach the thesis found the pseudoinverse made \"the rigid body to \
               oscillate\" and SDLS did best: see whether the recording agrees.",
        source: "She 2006 §5.3",
    },
];

/// The notes for `scenario`, or for a recording (`recorded`: the thesis'
/// scenarios do not apply).
#[must_use]
pub fn notice(scenario: CompareScenario, recorded: bool) -> &'static [NoticeLine] {
    match (recorded, scenario) {
        (true, _) => RECORDED,
        (false, CompareScenario::Script) => SCRIPT,
        (false, CompareScenario::Singularity) => SINGULARITY,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every line of She 2006 names a section the thesis has, and every
    /// quotation in it is the thesis' wording.
    #[test]
    fn every_line_cites_the_thesis_and_quotes_it_verbatim() {
        let thesis = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../../shared/papers/she-2006-realtime-walking-running-ik.txt"
        ));
        for (scenario, recorded) in [
            (CompareScenario::Script, false),
            (CompareScenario::Singularity, false),
            (CompareScenario::Script, true),
        ] {
            let lines = notice(scenario, recorded);
            assert!(lines.len() >= 2, "{scenario:?}");
            for line in lines {
                assert!(
                    line.source == "gaitlab" || line.source.starts_with("She 2006 §"),
                    "{}",
                    line.source
                );
                let Ok(thesis) = &thesis else { continue };
                // The thesis' text runs its lines together; compare with single spaces.
                let flat: String = thesis.split_whitespace().collect::<Vec<_>>().join(" ");
                for quote in line.text.split('"').skip(1).step_by(2) {
                    assert!(flat.contains(quote), "not in the thesis: {quote:?}");
                }
            }
        }
    }
}
