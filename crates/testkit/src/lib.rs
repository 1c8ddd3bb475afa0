//! Helpers shared by the test suites of `gaitlab-core`, `gaitlab-motion`,
//! `gaitlab-physics` and `gaitlab-cli` (a dev-dependency only; see
//! `docs/property-tests.md`): the property tests' configuration and a
//! preset with more leg pairs.

mod more_legs;

pub use more_legs::with_extra_leg_pairs;

use proptest::test_runner::{Config, RngSeed};

/// The seed the property tests run with in CI (any fixed value; chosen once).
pub const PROP_SEED: u64 = 0x6a17_1ab5_0000_0007;

/// A proptest configuration running `cases` cases, times `GAITLAB_PROP_SCALE`
/// (an integer ≥ 1, default 1), from the fixed [`PROP_SEED`] unless
/// `PROPTEST_RNG_SEED` is set.
#[must_use]
pub fn prop_config(cases: u32) -> Config {
    let scale = std::env::var("GAITLAB_PROP_SCALE")
        .ok()
        .and_then(|s| s.parse::<u32>().ok())
        .unwrap_or(1)
        .max(1);
    let mut config = Config::with_cases(cases.saturating_mul(scale));
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(PROP_SEED);
    }
    config
}
