//! `gaitlab bench --check`: the regression check end to end, with baselines
//! no real run can be near (a case a billion times too slow, a case a billion
//! times too fast), so the outcome does not depend on this machine's speed.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn gaitlab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(args)
        .output()
        .expect("the gaitlab binary runs")
}

fn baseline(name: &str, cases: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-bench-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, format!(r#"{{"cases": {cases}}}"#)).expect("baseline written");
    path
}

fn run_check(path: &Path) -> Output {
    let path = path.to_string_lossy();
    gaitlab(&[
        "bench",
        "--preset",
        "poda-biped",
        "--repeats",
        "1",
        "--check",
        &path,
    ])
}

#[test]
fn a_generous_baseline_passes_and_notes_cases_not_run() {
    let path = baseline(
        "generous.json",
        r#"{"poda/poda-biped/frame": 1e9, "poda/hexapod/frame": 1e9}"#,
    );
    let output = run_check(&path);
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(stdout.contains("poda/poda-biped/frame"), "{stdout}");
    assert!(stdout.contains("missing (not run)"), "{stdout}");
    assert!(
        stdout.contains("2 cases: 1 ok, 0 slower, 1 missing, 0 new"),
        "{stdout}"
    );
}

#[test]
fn an_impossible_baseline_fails_with_code_3_naming_the_case() {
    let path = baseline("tight.json", r#"{"poda/poda-biped/frame": 1e-9}"#);
    let output = run_check(&path);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("poda/poda-biped/frame"), "{stderr}");
    assert!(String::from_utf8_lossy(&output.stdout).contains("SLOWER"));
}

#[test]
fn a_baseline_that_is_not_a_report_is_bad_input() {
    let dir = std::env::temp_dir().join(format!("gaitlab-bench-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("not-a-report.json");
    std::fs::write(&path, r#"{"ik": []}"#).expect("written");
    let output = run_check(&path);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("cases: missing"));
}
