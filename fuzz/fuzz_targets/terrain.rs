//! Terrain JSON (`scenario.terrain`, issue 45) → parse, check, then heights,
//! normals and the MJCF of an accepted one. Any input must give `Ok` or an
//! error naming the field, never a panic; an accepted terrain's heights and
//! normals are finite wherever they are asked, and its normals unit length.
#![no_main]

use gaitlab_core::terrain::{Terrain, to_mjcf};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(terrain) = serde_json::from_str::<Terrain>(text) else {
        return;
    };
    if let Err(error) = terrain.check() {
        assert!(!error.reason.is_empty());
        return;
    }
    for (x, z) in [
        (0.0, 0.0),
        (0.37, -1.2),
        (-2.5, 3.75),
        (1e3, -1e3),
        (0.049_999, 0.05),
    ] {
        let h = terrain.height_m(x, z);
        assert!(h.is_finite(), "height at ({x}, {z}) is {h}");
        let n = terrain.normal(x, z);
        assert!(
            n.is_finite() && (n.length() - 1.0).abs() < 1e-9,
            "normal at ({x}, {z}) is {n}"
        );
    }
    let mjcf = to_mjcf(&terrain);
    assert!(mjcf.geoms.contains("<geom"));
});
