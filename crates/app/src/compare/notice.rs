//! "What to notice" for each comparison scenario (issue 21 item 1): a few
//! lines for a class, each one of She 2006's own statements (quoted where
//! short) with its section, so the teacher can point at the thesis. A line
//! that compares methods carries its [`Claim`], which the screen checks
//! against this run's figures and shows beside it (issue 43 item 1). The
//! singularity scenario is the lab's (the thesis has no full-reach
//! experiment); its notes say so.

use super::claim::{Claim, Figure, Rank};
use super::config::CompareScenario;
use super::method::CompareMethod;

/// One line of a note: what to look at, where She 2006 says it, and the
/// comparison it states, if any, which the screen checks against the run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoticeLine {
    /// What to look at, in plain words; a line with a claim states the
    /// thesis' finding, never this run's.
    pub text: &'static str,
    /// The thesis section it rests on.
    pub source: &'static str,
    /// The comparison the line states, checked against this run's figures.
    pub claim: Option<Claim>,
}

const fn line(text: &'static str, source: &'static str) -> NoticeLine {
    NoticeLine {
        text,
        source,
        claim: None,
    }
}

const fn claim(
    text: &'static str,
    source: &'static str,
    figure: Figure,
    method: CompareMethod,
    rank: Rank,
    among: &'static [CompareMethod],
) -> NoticeLine {
    NoticeLine {
        text,
        source,
        claim: Some(Claim {
            figure,
            method,
            rank,
            among,
        }),
    }
}

use CompareMethod::{Dls, Pinv, Sdls, Transpose};

/// §5.3 on the pseudoinverse, for the script and a recording alike.
const PINV_OSCILLATES: NoticeLine = claim(
    "On the pseudoinverse: \"the unreachable target positions caused the rigid body to \
     oscillate\" — more oscillation than DLS and SDLS.",
    "She 2006 §5.3",
    Figure::Oscillation,
    Pinv,
    Rank::Most,
    &[Dls, Sdls],
);

const SCRIPT: &[NoticeLine] = &[
    line(
        "In the walk the foot targets are always within reach and the hand targets never are \
         (in the run, none of the four is): watch the hands.",
        "She 2006 §5.3",
    ),
    claim(
        "The thesis on the transpose: the body \"looks jerky and oscillates\" — the most jitter.",
        "She 2006 §5.3",
        Figure::Jitter,
        Transpose,
        Rank::Most,
        &[],
    ),
    PINV_OSCILLATES,
    claim(
        "DLS \"worked substantially better than either the Jacobian Transpose Method or the \
         Pseudoinverse Method\" — a smaller mean error than those two.",
        "She 2006 §5.3",
        Figure::MeanError,
        Dls,
        Rank::Least,
        &[Transpose, Pinv],
    ),
    claim(
        "SDLS \"has the best performance for both reachable target positions and unreachable \
         target positions\" — on reachable targets, the smallest error …",
        "She 2006 §5.3",
        Figure::ErrorReachable,
        Sdls,
        Rank::Least,
        &[],
    ),
    claim(
        "… and on unreachable ones.",
        "She 2006 §5.3",
        Figure::ErrorUnreachable,
        Sdls,
        Rank::Least,
        &[],
    ),
];

const SINGULARITY: &[NoticeLine] = &[
    line(
        "A fully stretched limb is singular: no small change of its joints moves its end \
         further along it.",
        "She 2006 §4.3.2",
    ),
    claim(
        "Near such a pose the pseudoinverse lets effectors \"move to impossible directions or \
         oscillate\" — more oscillation than DLS and SDLS.",
        "She 2006 §4.4.2",
        Figure::Oscillation,
        Pinv,
        Rank::Most,
        &[Dls, Sdls],
    ),
    claim(
        "With its step clamp the pseudoinverse \"might have the problem which is unable to \
         effectively track targets\" — the largest mean error.",
        "She 2006 §4.4.2",
        Figure::MeanError,
        Pinv,
        Rank::Most,
        &[],
    ),
    line(
        "DLS damps every direction with one constant that \"must be chosen very carefully\" \
         (try its λ slider); SDLS damps each singular direction on its own, with no constant \
         to choose.",
        "She 2006 §4.4.3, §4.4.5",
    ),
    line(
        "This scenario is the lab's: the thesis argues it from a stretched arm but never \
         runs limbs pulled past their reach.",
        "gaitlab",
    ),
];

const RECORDED: &[NoticeLine] = &[
    line(
        "The targets come from a recording, the same for every method: where one leaves \
         its limb's reach it turns orange.",
        "gaitlab",
    ),
    PINV_OSCILLATES,
    claim(
        "SDLS \"has the best performance for both reachable target positions and unreachable \
         target positions\" — on unreachable ones, the smallest error.",
        "She 2006 §5.3",
        Figure::ErrorUnreachable,
        Sdls,
        Rank::Least,
        &[],
    ),
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
