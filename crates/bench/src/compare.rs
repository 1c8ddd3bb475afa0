//! The regression check of the performance budget (issue 7, item 4): each
//! case's median µs now against the committed baseline (`bench/baseline.json`),
//! failing any case more than `tolerance_pct` slower. Cases only in the
//! baseline or only in the run are noted, not failed (presets come and go).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde_json::Value;

/// The default tolerance: a case fails when more than 25 % slower.
pub const DEFAULT_TOLERANCE_PCT: f64 = 25.0;

/// What the check concluded for one case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Within tolerance (or faster).
    Ok,
    /// Slower than the baseline by more than the tolerance, or no finite figure now.
    Regression,
    /// In the baseline, not measured by this run.
    Missing,
    /// Measured by this run, not in the baseline.
    New,
    /// The baseline's figure is not a positive finite number: nothing to compare with.
    BadBaseline,
}

impl Verdict {
    /// The word shown in the table.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Ok => "ok",
            Verdict::Regression => "SLOWER",
            Verdict::Missing => "missing (not run)",
            Verdict::New => "new (no baseline)",
            Verdict::BadBaseline => "bad baseline",
        }
    }
}

/// One case: the baseline and current medians, µs (lower is better).
#[derive(Clone, Debug, PartialEq)]
pub struct CaseComparison {
    /// The case name, e.g. `ik/human/sdls/iteration`.
    pub case: String,
    /// Baseline median, µs.
    pub baseline_us: Option<f64>,
    /// Current median, µs.
    pub current_us: Option<f64>,
    /// The conclusion.
    pub verdict: Verdict,
}

impl CaseComparison {
    /// Current over baseline (2.0: twice as slow), when both exist.
    #[must_use]
    pub fn ratio(&self) -> Option<f64> {
        Some(self.current_us? / self.baseline_us?)
    }
}

/// Every case of a baseline and a run, by name.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// One row per case in either, sorted by name.
    pub rows: Vec<CaseComparison>,
    /// Allowed slowdown, percent.
    pub tolerance_pct: f64,
}

impl Comparison {
    /// The cases that failed.
    pub fn regressions(&self) -> impl Iterator<Item = &CaseComparison> {
        self.rows
            .iter()
            .filter(|r| r.verdict == Verdict::Regression)
    }

    /// True when no case failed.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.regressions().next().is_none()
    }

    /// The table people read: case, baseline µs, current µs, ratio, verdict,
    /// then one summary line.
    #[must_use]
    pub fn table(&self) -> String {
        let mut text = String::new();
        let _ = writeln!(
            text,
            "{:<36} {:>12} {:>12} {:>7}  verdict (tolerance +{}%)",
            "case", "baseline µs", "current µs", "ratio", self.tolerance_pct
        );
        let number = |v: Option<f64>, precision: usize| {
            v.map_or_else(|| "-".to_owned(), |v| format!("{v:.precision$}"))
        };
        for row in &self.rows {
            let _ = writeln!(
                text,
                "{:<36} {:>12} {:>12} {:>7}  {}",
                row.case,
                number(row.baseline_us, 3),
                number(row.current_us, 3),
                number(row.ratio(), 2),
                row.verdict.label()
            );
        }
        let count = |v: Verdict| self.rows.iter().filter(|r| r.verdict == v).count();
        let _ = write!(
            text,
            "{} cases: {} ok, {} slower, {} missing, {} new",
            self.rows.len(),
            count(Verdict::Ok),
            count(Verdict::Regression),
            count(Verdict::Missing),
            count(Verdict::New)
        );
        if count(Verdict::BadBaseline) > 0 {
            let _ = write!(text, ", {} bad baseline", count(Verdict::BadBaseline));
        }
        text
    }
}

/// Compares `current` with `baseline` (case name → median µs): a case fails
/// when `current > baseline × (1 + tolerance_pct / 100)` or when it has no
/// finite positive figure now.
#[must_use]
pub fn compare(
    baseline: &BTreeMap<String, f64>,
    current: &BTreeMap<String, f64>,
    tolerance_pct: f64,
) -> Comparison {
    let limit = 1.0 + tolerance_pct.max(0.0) / 100.0;
    let mut names: Vec<&String> = baseline.keys().chain(current.keys()).collect();
    names.sort();
    names.dedup();
    let rows = names
        .into_iter()
        .map(|case| {
            let baseline_us = baseline.get(case).copied();
            let current_us = current.get(case).copied();
            let usable = |v: f64| v.is_finite() && v > 0.0;
            let verdict = match (baseline_us, current_us) {
                (Some(_), None) => Verdict::Missing,
                (None, _) => Verdict::New,
                (Some(b), Some(_)) if !usable(b) => Verdict::BadBaseline,
                (Some(b), Some(c)) if !usable(c) || c > b * limit => Verdict::Regression,
                (Some(_), Some(_)) => Verdict::Ok,
            };
            CaseComparison {
                case: case.clone(),
                baseline_us,
                current_us,
                verdict,
            }
        })
        .collect();
    Comparison {
        rows,
        tolerance_pct,
    }
}

/// The `cases` map of a suite report (name → median µs).
///
/// # Errors
/// The report has no `cases` object, or a case's figure is not a number
/// (`cases.<name>: …`).
pub fn cases_of(report: &Value) -> Result<BTreeMap<String, f64>, String> {
    let cases = report
        .get("cases")
        .and_then(Value::as_object)
        .ok_or("cases: missing (not a `gaitlab bench --json` report?)")?;
    cases
        .iter()
        .map(|(name, value)| {
            value
                .as_f64()
                .map(|us| (name.clone(), us))
                .ok_or_else(|| format!("cases.{name}: expected a number of µs"))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cases(pairs: &[(&str, f64)]) -> BTreeMap<String, f64> {
        pairs.iter().map(|(k, v)| ((*k).to_owned(), *v)).collect()
    }

    #[test]
    fn only_cases_beyond_the_tolerance_fail() {
        let baseline = cases(&[("a", 10.0), ("b", 10.0), ("c", 10.0), ("d", 4.0)]);
        // a: 24 % slower, b: 26 % slower, c: faster, d: exactly at the limit.
        let current = cases(&[("a", 12.4), ("b", 12.6), ("c", 5.0), ("d", 5.0)]);
        let result = compare(&baseline, &current, 25.0);
        let verdicts: Vec<(&str, Verdict)> = result
            .rows
            .iter()
            .map(|r| (r.case.as_str(), r.verdict))
            .collect();
        assert_eq!(
            verdicts,
            [
                ("a", Verdict::Ok),
                ("b", Verdict::Regression),
                ("c", Verdict::Ok),
                ("d", Verdict::Ok),
            ]
        );
        assert!(!result.passed());
        let failed: Vec<&str> = result.regressions().map(|r| r.case.as_str()).collect();
        assert_eq!(failed, ["b"]);
        assert!((result.rows[1].ratio().unwrap_or(0.0) - 1.26).abs() < 1e-12);
    }

    #[test]
    fn a_tighter_tolerance_catches_smaller_slowdowns() {
        let baseline = cases(&[("a", 10.0)]);
        let current = cases(&[("a", 11.0)]);
        assert!(compare(&baseline, &current, 25.0).passed());
        assert!(!compare(&baseline, &current, 5.0).passed());
    }

    #[test]
    fn missing_and_new_cases_are_noted_not_failed() {
        let baseline = cases(&[("gone", 1.0), ("kept", 2.0)]);
        let current = cases(&[("kept", 2.0), ("added", 3.0)]);
        let result = compare(&baseline, &current, 25.0);
        assert!(result.passed());
        let verdict = |name: &str| {
            result
                .rows
                .iter()
                .find(|r| r.case == name)
                .map(|r| r.verdict)
        };
        assert_eq!(verdict("gone"), Some(Verdict::Missing));
        assert_eq!(verdict("added"), Some(Verdict::New));
        assert_eq!(verdict("kept"), Some(Verdict::Ok));
        let table = result.table();
        assert!(table.contains("missing (not run)"), "{table}");
        assert!(
            table.ends_with("3 cases: 1 ok, 0 slower, 1 missing, 1 new"),
            "{table}"
        );
    }

    #[test]
    fn a_non_finite_figure_now_fails_and_a_bad_baseline_is_skipped() {
        let baseline = cases(&[("nan-now", 1.0), ("zero-before", 0.0)]);
        let current = cases(&[("nan-now", f64::NAN), ("zero-before", 5.0)]);
        let result = compare(&baseline, &current, 25.0);
        assert_eq!(result.rows[0].verdict, Verdict::Regression);
        assert_eq!(result.rows[1].verdict, Verdict::BadBaseline);
    }

    #[test]
    fn the_table_names_each_slower_case_with_its_ratio() {
        let result = compare(
            &cases(&[("ik/human/sdls/iteration", 8.0)]),
            &cases(&[("ik/human/sdls/iteration", 16.0)]),
            25.0,
        );
        let line = result
            .table()
            .lines()
            .find(|l| l.starts_with("ik/human/sdls/iteration"))
            .map(str::to_owned)
            .unwrap_or_default();
        assert!(line.contains("8.000") && line.contains("16.000"), "{line}");
        assert!(line.contains("2.00") && line.contains("SLOWER"), "{line}");
    }

    #[test]
    fn cases_are_read_from_a_report_and_bad_ones_named() {
        let report = serde_json::json!({"cases": {"a": 1.5, "b": 2}});
        assert_eq!(cases_of(&report), Ok(cases(&[("a", 1.5), ("b", 2.0)])));
        let error = cases_of(&serde_json::json!({"cases": {"a": "fast"}})).expect_err("string");
        assert!(error.starts_with("cases.a:"), "{error}");
        assert!(cases_of(&serde_json::json!({"ik": []})).is_err());
    }
}
