//! Recorded effector targets (`gaitlab track --targets FILE.csv`): any text and
//! effector count give a track or a `CsvError` naming the line, never a panic;
//! every accepted value is finite and times increase.
#![no_main]

use gaitlab_core::export::parse_target_csv;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&count, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let effectors = usize::from(count % 8) + 1;
    if let Ok(track) = parse_target_csv(text, effectors) {
        assert_eq!(track.effector_count(), effectors);
        assert_eq!(track.positions().len(), track.row_count() * effectors);
        assert!(track.times().windows(2).all(|w| w[0] < w[1]), "times increase");
        assert!(track.times().iter().all(|t| t.is_finite()));
        assert!(track.positions().iter().all(|p| p.is_finite()));
    }
});
