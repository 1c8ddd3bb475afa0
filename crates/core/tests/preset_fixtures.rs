//! The bad preset files in `tests/fixtures/` (shared with the CLI tests) are
//! rejected with exactly the documented `path: reason`.

use gaitlab_core::preset::Preset;

fn error_of(json: &str) -> String {
    match Preset::from_json(json) {
        Ok(_) => panic!("a bad fixture was accepted"),
        Err(error) => error.to_string(),
    }
}

#[test]
fn bad_axis_names_the_zero_axis() {
    assert_eq!(
        error_of(include_str!("fixtures/bad-axis.json")),
        "skeleton.joints[3].axis: must be a non-zero vector"
    );
}

#[test]
fn bad_nan_names_the_token_and_its_line() {
    assert_eq!(
        error_of(include_str!("fixtures/bad-nan.json")),
        "skeleton.joints[2].rest: every number must be finite: NaN and Infinity are not JSON numbers (expected value at line 10 column 152)"
    );
}

#[test]
fn bad_cycle_names_the_first_joint_of_the_cycle() {
    assert_eq!(
        error_of(include_str!("fixtures/bad-cycle.json")),
        r#"skeleton.joints[0].parent: parents form a cycle: "upper" → "foot" → "lower" → "upper""#
    );
}

#[test]
fn bad_truncated_names_where_the_file_ends() {
    assert_eq!(
        error_of(include_str!("fixtures/bad-truncated.json")),
        "skeleton.joints[6].name: EOF while parsing a string at line 14 column 19"
    );
}

#[test]
fn bad_limits_names_the_unordered_limits() {
    assert_eq!(
        error_of(include_str!("fixtures/bad-limits.json")),
        "skeleton.joints[2].limits: minimum 2.4 is greater than maximum 0"
    );
}

#[test]
fn bad_huge_joints_is_refused_for_its_joint_count() {
    let json = include_str!("fixtures/bad-huge-joints.json");
    assert!(json.len() < 300 * 1024);
    assert_eq!(
        error_of(json),
        "skeleton.joints: 600 joints is more than the limit of 512"
    );
}
