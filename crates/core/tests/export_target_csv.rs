//! The effector-target CSV of `gaitlab track`: a good file's counts and linear
//! interpolation, an exact writer → reader round trip, the line/column error of
//! every malformed case, the size and row limits, and no panic on any prefix or
//! garbage input.

use gaitlab_core::export::{
    CsvError, MAX_TARGET_CSV_BYTES, MAX_TARGET_ROWS, TargetCsvWriter, TargetTrack, WriteError,
    parse_target_csv, write_target_csv,
};
use gaitlab_core::portable::Portable;
use glam::DVec3;

/// Two effectors, CRLF ends, a quoted and padded header, a blank line.
const GOOD: &str = "t, \"left, foot_x\",left_foot_y,left_foot_z,a,b,c\r\n0,0,0,0,1,1,1\r\n\r\n1.0, 2,0,0, 1,3,1\r\n3,2,4,0,1,3,5\r\n";

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-12
}

#[test]
fn good_file_parses_with_the_right_counts() {
    let track = parse_target_csv(GOOD, 2).expect("valid");
    assert_eq!(track.effector_count(), 2);
    assert_eq!(track.row_count(), 3);
    assert_eq!(track.times(), &[0.0, 1.0, 3.0]);
    assert_eq!(track.positions().len(), 6);
    assert_eq!(
        track.row(1),
        Some(&[DVec3::new(2.0, 0.0, 0.0), DVec3::new(1.0, 3.0, 1.0)][..])
    );
    assert_eq!(track.row(3), None);
    assert_eq!((track.start_time(), track.end_time()), (0.0, 3.0));
}

#[test]
fn sampling_is_linear_between_rows_and_clamped_at_the_ends() {
    let track = parse_target_csv(GOOD, 2).expect("valid");
    let mut out = [DVec3::ZERO; 2];
    track.sample(0.5, &mut out);
    assert!(
        close(out[0], DVec3::new(1.0, 0.0, 0.0)) && close(out[1], DVec3::new(1.0, 2.0, 1.0)),
        "{out:?}"
    );
    track.sample(2.0, &mut out);
    assert!(
        close(out[0], DVec3::new(2.0, 2.0, 0.0)) && close(out[1], DVec3::new(1.0, 3.0, 3.0)),
        "{out:?}"
    );
    // A quarter of the way from t = 1 to t = 3.
    track.sample(1.5, &mut out);
    assert!(
        close(out[0], DVec3::new(2.0, 1.0, 0.0)) && close(out[1], DVec3::new(1.0, 3.0, 2.0)),
        "{out:?}"
    );
    track.sample(1.0, &mut out);
    assert_eq!(
        out,
        [DVec3::new(2.0, 0.0, 0.0), DVec3::new(1.0, 3.0, 1.0)],
        "exact at a row time"
    );
    track.sample(-5.0, &mut out);
    assert_eq!(out, [DVec3::ZERO, DVec3::ONE], "clamped before the start");
    track.sample(99.0, &mut out);
    assert_eq!(
        out,
        [DVec3::new(2.0, 4.0, 0.0), DVec3::new(1.0, 3.0, 5.0)],
        "clamped after the end"
    );
    track.sample(f64::NAN, &mut out);
    assert_eq!(out, [DVec3::ZERO, DVec3::ONE], "NaN reads as the start");
    let mut one = [DVec3::NEG_ONE; 1];
    track.sample(0.5, &mut one);
    assert!(
        close(one[0], DVec3::new(1.0, 0.0, 0.0)),
        "a short buffer gets the first effectors"
    );
}

#[test]
fn writer_and_reader_round_trip_exactly() {
    let times: Vec<f64> = (0..200).map(|i| f64::from(i) / 60.0 + 1e-3).collect();
    let positions: Vec<DVec3> = (0..200 * 3)
        .map(|i| {
            let x = f64::from(i);
            DVec3::new((0.37 * x).psin(), 1e-9 * x, -(x / 7.0).pcos() * 1e6)
        })
        .collect();
    let track = TargetTrack::new(times, positions, 3).expect("valid track");
    let mut text = String::new();
    write_target_csv(&mut text, &["left_foot", "right_foot", "pelvis"], &track).expect("writes");
    assert!(text.starts_with("t,left_foot_x,left_foot_y,left_foot_z,right_foot_x,"));
    let back = parse_target_csv(&text, 3).expect("reads back");
    assert_eq!(back, track, "bit-exact");
}

#[test]
fn effectorless_tracks_have_only_times() {
    let track = parse_target_csv("t\n0\n0.5\n", 0).expect("valid");
    assert_eq!(track.row_count(), 2);
    assert!(track.positions().is_empty());
    let mut out: [DVec3; 0] = [];
    track.sample(0.2, &mut out);
}

fn error(text: &str, effectors: usize) -> String {
    match parse_target_csv(text, effectors) {
        Ok(track) => panic!("accepted {text:?} as {track:?}"),
        Err(error) => error.to_string(),
    }
}

#[test]
fn every_bad_input_names_its_line_and_column() {
    let cases: [(&str, usize, &str); 20] = [
        (
            "",
            1,
            "empty input: expected a header row (t, then x,y,z for each effector)",
        ),
        (
            " \n\r\n\n",
            1,
            "empty input: expected a header row (t, then x,y,z for each effector)",
        ),
        (
            "t,x,y\n0,1,2\n",
            1,
            "line 1: the header has 3 columns; expected 4 (t, then x,y,z for each of 1 effectors)",
        ),
        (
            "t,x,y,z\n0,1,2,3\n",
            2,
            "line 1: the header has 4 columns; expected 7 (t, then x,y,z for each of 2 effectors)",
        ),
        (
            "0,1,2,3\n1,1,2,3\n",
            1,
            "line 1: the first row must be a header (t, then x,y,z for each effector), not numbers",
        ),
        ("t,x,y,z\n", 1, "line 1: no data rows after the header"),
        (
            "t,x,y,z\n0,1,2,3\n0.5,1,2\n",
            1,
            "line 3: expected 4 columns, found 3",
        ),
        (
            "t,x,y,z\n0,1,2,3\n0.5,1,2,3,4\n",
            1,
            "line 3: expected 4 columns, found 5",
        ),
        (
            "t,a_x,a_y,a_z\n0,0,0,0\n0.1,0,0,0\n0.2,0,0,0\n\n0.3,0,0,0\n0.4,0,0,abc\n",
            1,
            "line 7, column 4: not a number \"abc\"",
        ),
        (
            "t,x,y,z\n0,1,inf,3\n",
            1,
            "line 2, column 3: not a finite number \"inf\"",
        ),
        (
            "t,x,y,z\n0,1,2,NaN\n",
            1,
            "line 2, column 4: not a finite number \"NaN\"",
        ),
        (
            "t,x,y,z\n1e999,1,2,3\n",
            1,
            "line 2, column 1: not a finite number \"1e999\"",
        ),
        ("t,x,y,z\n0,,2,3\n", 1, "line 2, column 2: empty value"),
        (
            "t,x,y,z\n0,1,2,3\n0,1,2,3\n",
            1,
            "line 3, column 1: time 0 is not after the previous time 0 (times must increase strictly)",
        ),
        (
            "t,x,y,z\n1,1,2,3\n0.5,1,2,3\n",
            1,
            "line 3, column 1: time 0.5 is not after the previous time 1 (times must increase strictly)",
        ),
        (
            "t,\"x,y,z\n0,1,2,3\n",
            1,
            "line 1, column 2: unterminated quoted field",
        ),
        (
            "t,x,y,z\n0,1,\"2\"3,3\n",
            1,
            "line 2, column 3: text after a closing quote",
        ),
        (
            "t,x,y,z\n\n0,1,2,3\n\nfoo,1,2,3\n",
            1,
            "line 5, column 1: not a number \"foo\"",
        ),
        (
            "t,x,y,z\n0,1,2,3\n1,1,0x10,3\n",
            1,
            "line 3, column 3: not a number \"0x10\"",
        ),
        (
            "t,x,y,z\n0,1,2,3\n1,1, 2 5 ,3\n",
            1,
            "line 3, column 3: not a number \"2 5\"",
        ),
    ];
    for (text, effectors, expected) in cases {
        assert_eq!(error(text, effectors), expected, "for {text:?}");
    }
    let parsed: CsvError = parse_target_csv("t,x,y,z\n0,1,2,abc\n", 1).expect_err("bad");
    assert_eq!((parsed.line, parsed.column), (Some(2), Some(4)));
}

#[test]
fn oversized_inputs_are_refused() {
    let mut huge = String::with_capacity(MAX_TARGET_CSV_BYTES + 16);
    huge.push_str("t,x,y,z\n");
    while huge.len() <= MAX_TARGET_CSV_BYTES {
        huge.push_str("                                                               \n");
    }
    let message = error(&huge, 1);
    assert!(
        message.contains("more than the limit of 67108864 (64 MiB)"),
        "{message}"
    );

    let mut many = String::from("t,x,y,z\n");
    for row in 0..=MAX_TARGET_ROWS {
        many.push_str(&format!("{row},0,0,0\n"));
    }
    assert_eq!(
        error(&many, 1),
        format!("line {}: more than 1000000 data rows", MAX_TARGET_ROWS + 2)
    );
}

#[test]
fn writer_refuses_what_the_reader_would_refuse() {
    let mut writer = TargetCsvWriter::new(1);
    let mut out = String::new();
    assert!(matches!(
        writer.write_row(&mut out, 0.0, &[DVec3::ZERO]),
        Err(WriteError::Order(_))
    ));
    assert!(matches!(
        writer.write_header(&mut out, &["a", "b"]),
        Err(WriteError::ValueCount {
            expected: 1,
            found: 2,
            ..
        })
    ));
    writer.write_header(&mut out, &["foot"]).expect("header");
    writer.write_row(&mut out, 0.0, &[DVec3::ONE]).expect("row");
    assert_eq!(
        writer.write_row(&mut out, 0.0, &[DVec3::ONE]),
        Err(WriteError::TimeNotIncreasing {
            row: 1,
            time: 0.0,
            previous: 0.0
        })
    );
    assert_eq!(
        writer.write_row(&mut out, 1.0, &[DVec3::new(f64::INFINITY, 0.0, 0.0)]),
        Err(WriteError::NonFinite {
            what: "target row",
            row: 1
        })
    );
    assert!(matches!(
        writer.write_row(&mut out, 1.0, &[]),
        Err(WriteError::ValueCount { .. })
    ));
    assert_eq!(
        out, "t,foot_x,foot_y,foot_z\n0,1,1,1\n",
        "refused rows write nothing"
    );
    assert!(TargetTrack::new(vec![0.0, 0.0], vec![DVec3::ZERO; 2], 1).is_err());
    assert!(TargetTrack::new(vec![], vec![], 1).is_err());
    assert!(TargetTrack::new(vec![0.0], vec![DVec3::ZERO; 2], 1).is_err());
    assert_eq!(
        TargetTrack::new(vec![0.0, 1.0], vec![DVec3::ZERO, DVec3::NAN], 1)
            .expect_err("NaN")
            .to_string(),
        "row 1: a target position is not finite"
    );
}

#[test]
fn no_prefix_or_garbage_input_panics() {
    for end in 0..=GOOD.len() {
        let Some(prefix) = GOOD.get(..end) else {
            continue;
        };
        if let Ok(track) = parse_target_csv(prefix, 2) {
            assert!(
                track.row_count() >= 1 && track.row_count() <= 3,
                "prefix of {end} bytes"
            );
        }
        let _ = parse_target_csv(prefix, 0);
        let _ = parse_target_csv(prefix, 32);
    }
    let alphabet: Vec<char> = "0123456789.,-+eE\"\n\r \ttinfaNxé\u{feff}"
        .chars()
        .collect();
    let mut state = 0x9E37_79B9_u64;
    let mut accepted = 0;
    for _ in 0..5000 {
        let mut text = String::new();
        for _ in 0..(state >> 60) as usize * 4 + 4 {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            text.push(alphabet[(state >> 33) as usize % alphabet.len()]);
        }
        for k in 0..3 {
            if let Ok(track) = parse_target_csv(&text, k) {
                accepted += 1;
                let mut out = vec![DVec3::ZERO; k];
                track.sample(0.5, &mut out);
                assert!(out.iter().all(|p| p.is_finite()));
            }
        }
    }
    assert!(accepted < 5000 * 3);
}
