//! A comparison a note states (She 2006 §5.3's findings: "the transpose looks
//! jerky", "SDLS has the best performance"), checked against this run's
//! figures (issue 43 item 1): the screen shows the claim and, beside it,
//! whether this run agrees, with the numbers — never a comparison on its own.

use super::method::CompareMethod;
use super::view::CompareView;

/// A figure every view measures, compared between views.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Figure {
    /// Joint-velocity jitter, mean |Δ²θ| over the last 4 s, rad per frame².
    Jitter,
    /// Sign changes of the limb joints' Δθ per second, Hz (§5.3's oscillation).
    Oscillation,
    /// Mean effector error since the reset, metres.
    MeanError,
    /// Mean error over the frames the targets were within reach, metres.
    ErrorReachable,
    /// Mean error over the frames the targets were out of reach, metres.
    ErrorUnreachable,
}

impl Figure {
    /// The figure's key in `state().compare.metrics[i]`.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Figure::Jitter => "jitter_rad",
            Figure::Oscillation => "oscillation_hz",
            Figure::MeanError => "mean_error_m",
            Figure::ErrorReachable => "mean_error_reachable_m",
            Figure::ErrorUnreachable => "mean_error_unreachable_m",
        }
    }

    /// What the figure is called on the cards.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Figure::Jitter => "jitter",
            Figure::Oscillation => "oscillation",
            Figure::MeanError => "mean error",
            Figure::ErrorReachable => "error on reachable targets",
            Figure::ErrorUnreachable => "error on unreachable targets",
        }
    }

    /// The view's value, in the unit of [`Figure::key`] (`None` where the
    /// run has not measured it).
    #[must_use]
    pub fn of(self, view: &CompareView) -> Option<f64> {
        match self {
            Figure::Jitter => Some(view.metrics.jitter_rad()),
            Figure::Oscillation => view.oscillation_hz(),
            Figure::MeanError => Some(view.mean_error_m()),
            Figure::ErrorReachable => view.mean_error_reachable_m(),
            Figure::ErrorUnreachable => view.mean_error_unreachable_m(),
        }
    }

    /// `value` as the cards show it, with its unit.
    #[must_use]
    pub fn format(self, value: f64) -> String {
        match self {
            Figure::Jitter => format!("{value:.2e} rad/frame²"),
            Figure::Oscillation => format!("{value:.2} Hz"),
            Figure::MeanError | Figure::ErrorReachable | Figure::ErrorUnreachable => {
                format!("{:.1} mm", value * 1e3)
            }
        }
    }
}

/// Which end of the ranking the claim puts its method at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rank {
    /// The largest figure of those compared.
    Most,
    /// The smallest.
    Least,
}

impl Rank {
    /// `"most"` or `"least"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Rank::Most => "most",
            Rank::Least => "least",
        }
    }
}

/// "`method` has the `rank` `figure` of `among`" (every other view when
/// `among` is empty).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Claim {
    /// What is compared.
    pub figure: Figure,
    /// The method the claim is about.
    pub method: CompareMethod,
    /// Largest or smallest.
    pub rank: Rank,
    /// The methods it is compared with; empty: every other view.
    pub among: &'static [CompareMethod],
}

/// Figures closer than this fraction of the larger are level.
pub const LEVEL_FRACTION: f64 = 0.05;

/// Frames a run needs before its figures are compared (1 s at 60 fps).
pub const MIN_FRAMES: u64 = 60;

/// What this run says of a claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The method ranks where the claim puts it, by more than [`LEVEL_FRACTION`].
    Holds,
    /// The method and the closest rival are level (within [`LEVEL_FRACTION`]).
    Level,
    /// A rival ranks where the claim puts the method.
    Fails,
    /// The method, or every rival, is not among this run's views.
    NotInRun,
    /// The run is too short, or did not measure the figure.
    NotMeasured,
}

impl Verdict {
    /// The verdict as the state names it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Level => "level",
            Verdict::Fails => "does not hold",
            Verdict::NotInRun => "not in this run",
            Verdict::NotMeasured => "not measured",
        }
    }
}

/// A claim checked against the views: the verdict and the figures behind it.
#[derive(Clone, Debug, PartialEq)]
pub struct Checked {
    /// The verdict.
    pub verdict: Verdict,
    /// The method's own figure.
    pub own: Option<f64>,
    /// The rival that ranks furthest toward the claim's end, and its figure.
    pub rival: Option<(CompareMethod, f64)>,
    /// How many views were compared, the method's included.
    pub compared: usize,
}

impl Claim {
    /// Checks the claim against `views`.
    #[must_use]
    pub fn check(&self, views: &[CompareView]) -> Checked {
        let in_claim = |m: CompareMethod| {
            m != self.method && (self.among.is_empty() || self.among.contains(&m))
        };
        let own_view = views.iter().find(|v| v.method == self.method);
        let rivals = || views.iter().filter(|v| in_claim(v.method));
        let count = rivals().count();
        let mut checked = Checked {
            verdict: Verdict::NotInRun,
            own: None,
            rival: None,
            compared: count + usize::from(own_view.is_some()),
        };
        let Some(own_view) = own_view else {
            return checked;
        };
        if count == 0 {
            return checked;
        }
        checked.verdict = Verdict::NotMeasured;
        if own_view.metrics.frames < MIN_FRAMES {
            return checked;
        }
        let Some(own) = self.figure.of(own_view) else {
            return checked;
        };
        checked.own = Some(own);
        // The rival furthest toward the claimed end.
        let better = |a: f64, b: f64| match self.rank {
            Rank::Most => a > b,
            Rank::Least => a < b,
        };
        let mut rival: Option<(CompareMethod, f64)> = None;
        for view in rivals() {
            let Some(value) = self.figure.of(view) else {
                return checked;
            };
            if rival.is_none_or(|(_, r)| better(value, r)) {
                rival = Some((view.method, value));
            }
        }
        let Some((_, r)) = rival else {
            return checked;
        };
        checked.rival = rival;
        let scale = own.abs().max(r.abs());
        checked.verdict = if scale == 0.0 || (own - r).abs() <= LEVEL_FRACTION * scale {
            Verdict::Level
        } else if better(own, r) {
            Verdict::Holds
        } else {
            Verdict::Fails
        };
        checked
    }
}

impl Checked {
    /// "here: holds — pinv 2.1e-4 rad/frame², the most of 4 views (next: dls 1.0e-4 …)".
    #[must_use]
    pub fn sentence(&self, claim: &Claim) -> String {
        let name = claim.method.name();
        let figure = claim.figure;
        let of = if self.compared > 2 {
            format!(" of {} views", self.compared)
        } else {
            String::new()
        };
        match (self.verdict, self.own, self.rival) {
            (Verdict::Holds, Some(own), Some((rival, r))) => format!(
                "here: holds — {name} has the {} {}{of} ({} against {}'s {})",
                claim.rank.name(),
                figure.label(),
                figure.format(own),
                rival.name(),
                figure.format(r)
            ),
            (Verdict::Level, Some(own), Some((rival, r))) => format!(
                "here: level — {name}'s {} {} and {}'s {} are within {:.0} %",
                figure.label(),
                figure.format(own),
                rival.name(),
                figure.format(r),
                LEVEL_FRACTION * 100.0
            ),
            (Verdict::Fails, Some(own), Some((rival, r))) => format!(
                "here: does not hold — {} has the {} {} ({} against {name}'s {})",
                rival.name(),
                claim.rank.name(),
                figure.label(),
                figure.format(r),
                figure.format(own)
            ),
            (Verdict::NotInRun, ..) => {
                format!("here: not in this run — {name} or its rivals are not among the views")
            }
            _ => format!(
                "here: not measured — no {} in this run so far",
                figure.label()
            ),
        }
    }
}
