//! A legged preset with more leg pairs (issue 19's "a user who adds a pair of
//! legs to the hexapod"): copies of its last pair, each further back.

use serde_json::Value;

/// `preset_json` with `extra` more pairs behind the pair named `L{last}` and
/// `R{last}` (limbs copied with their joints and effectors renamed to pair
/// `last + 1`, `last + 2`, …), each `spacing_m` further along −z.
///
/// # Panics
/// If the text is not a preset with limbs `L{last}` and `R{last}` (a test's
/// own fixture, never user input).
#[must_use]
pub fn with_extra_leg_pairs(
    preset_json: &str,
    last: usize,
    extra: usize,
    spacing_m: f64,
) -> String {
    let mut preset: Value = serde_json::from_str(preset_json).expect("preset JSON");
    let limbs = preset["skeleton"]["limbs"]
        .as_array_mut()
        .expect("skeleton.limbs");
    let (left, right) = (format!("L{last}"), format!("R{last}"));
    let pair: Vec<Value> = limbs
        .iter()
        .filter(|l| l["name"] == left.as_str() || l["name"] == right.as_str())
        .cloned()
        .collect();
    assert_eq!(pair.len(), 2, "the preset's pair {last}");
    for k in 1..=extra {
        for limb in &pair {
            let side = &limb["name"].as_str().expect("limb name")[..1];
            let text = limb
                .to_string()
                .replace(&format!("\"{side}{last}"), &format!("\"{side}{}", last + k));
            let mut limb: Value = serde_json::from_str(&text).expect("limb JSON");
            let z = limb["base_offset"][2].as_f64().expect("base offset z");
            #[expect(clippy::cast_precision_loss, reason = "a handful of pairs")]
            let back = spacing_m * k as f64;
            limb["base_offset"][2] = Value::from(z - back);
            limbs.push(limb);
        }
    }
    preset.to_string()
}
