//! A portable `sin_cos` for forward kinematics: Cody–Waite reduction by π/2
//! and Taylor polynomials on [−π/4, π/4], accurate to a few units in the last
//! place. It is plain arithmetic, so native and WebAssembly builds give the same
//! bits (the platform libm need not), and it is several times cheaper than a
//! libm call in the FK loop. Arguments beyond ±2²⁰ rad fall back to `libm::sincos`.

use std::f64::consts::FRAC_2_PI;

/// π/2 split into three parts whose products with a small integer are exact.
/// The high part has 33 significant bits, so `k · PIO2_HI` is exact for |k| < 2²⁰.
const PIO2_HI: f64 = f64::from_bits(0x3FF9_21FB_5440_0000);
const PIO2_MID: f64 = f64::from_bits(0x3DD0_B461_1A60_0000);
const PIO2_LO: f64 = f64::from_bits(0x3BA3_198A_2E03_7073);

/// 1.5 · 2⁵²: adding and subtracting it rounds a small double to an integer.
const ROUNDING_SHIFT: f64 = 6_755_399_441_055_744.0;

/// Largest |x| handled by the polynomial path.
const REDUCTION_LIMIT: f64 = 1_048_576.0;

/// sin and cos of `x` radians.
#[must_use]
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    // NaN fails this comparison too and goes to the fallback.
    if x.abs().partial_cmp(&REDUCTION_LIMIT) != Some(std::cmp::Ordering::Less) {
        return libm::sincos(x);
    }
    // Round to the nearest integer by the 1.5·2⁵² trick (exact for |v| < 2⁵¹);
    // `f64::round` is a library call on baseline x86-64.
    let k = (x * FRAC_2_PI + ROUNDING_SHIFT) - ROUNDING_SHIFT;
    let r = ((x - k * PIO2_HI) - k * PIO2_MID) - k * PIO2_LO;
    let (s, c) = kernel(r);
    // k mod 4 selects the quadrant; k is an exact integer below 2^21.
    match (k as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// Taylor coefficients of sin r / r in powers of z = r²: (−1)ᵏ/(2k+1)!, k = 0..=8.
const SIN_TAYLOR: [f64; 9] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
];

/// Taylor coefficients of cos r in powers of z = r²: (−1)ᵏ/(2k)!, k = 0..=9.
const COS_TAYLOR: [f64; 10] = [
    1.0,
    -0.5,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
    -1.0 / 6_402_373_705_728_000.0,
];

/// Evaluates Σ cₖ zᵏ by Horner's rule.
#[inline]
fn horner(coefficients: &[f64], z: f64) -> f64 {
    coefficients.iter().rev().fold(0.0, |acc, c| acc * z + c)
}

/// sin and cos of |r| ≤ π/4 by Taylor series (truncation error below 1e-17).
#[inline]
fn kernel(r: f64) -> (f64, f64) {
    let z = r * r;
    (r * horner(&SIN_TAYLOR, z), horner(&COS_TAYLOR, z))
}

#[cfg(test)]
#[allow(clippy::disallowed_methods)] // compares with the platform functions
mod tests {
    use super::*;

    #[test]
    fn agrees_with_the_platform_to_a_few_ulp() {
        let mut worst: f64 = 0.0;
        let mut x = -50.0;
        while x < 50.0 {
            let (s, c) = sin_cos(x);
            let (rs, rc) = x.sin_cos();
            worst = worst.max((s - rs).abs()).max((c - rc).abs());
            x += 0.000_731;
        }
        assert!(worst < 5e-16, "worst error {worst:e}");
        for x in [
            0.0,
            -0.0,
            1e-300,
            std::f64::consts::FRAC_PI_4,
            std::f64::consts::FRAC_PI_2,
            std::f64::consts::PI,
            1e5,
            -7.5e5,
        ] {
            let (s, c) = sin_cos(x);
            let (rs, rc) = x.sin_cos();
            assert!(
                (s - rs).abs() < 1e-15 * (1.0 + x.abs() * 1e-6)
                    && (c - rc).abs() < 1e-15 * (1.0 + x.abs() * 1e-6),
                "{x}"
            );
        }
    }

    #[test]
    fn non_finite_and_huge_arguments_fall_back() {
        assert!(sin_cos(f64::NAN).0.is_nan());
        assert!(sin_cos(f64::INFINITY).1.is_nan());
        let (s, c) = sin_cos(1e300);
        assert_eq!((s, c), 1e300_f64.sin_cos());
    }
}
