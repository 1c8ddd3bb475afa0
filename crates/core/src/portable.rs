//! Transcendental functions that give the same bits on every platform.
//!
//! `f64::sin`, `powf`, `atan2` and friends call the platform's C library
//! natively (glibc, Apple's libm, the MSVC runtime) and a Rust port of musl's
//! libm in WebAssembly; they may differ in the last place. Those last-place
//! differences grow step by step in a simulation, so a motion replayed from a
//! link, or exported from the browser and from the CLI (issue 6), would not be
//! the same. Every transcendental call in `gaitlab-core`, `gaitlab-motion` and
//! `gaitlab-physics` goes through [`Portable`], which calls the `libm` crate
//! (the same code on every target). The crates' `clippy.toml` disallows the
//! `f64` methods so a new call cannot slip past. `sqrt`, `abs`, `floor`,
//! `mul_add` and the like are exactly rounded everywhere and need no wrapper;
//! the forward-kinematics loop uses the cheaper [`crate::trig::sin_cos`].

/// √(a² + b²) without overflow or underflow in the squares: the smaller
/// magnitude is scaled by the larger. Only basic IEEE 754 operations and the
/// correctly rounded square root, so every platform gets the same bits, and
/// the browser gets wasm's `f64.sqrt` instruction (the `libm` crate's hypot
/// and square root are software there on stable Rust, and the IK's QL
/// eigen-solver calls this for every rotation).
#[inline]
#[must_use]
pub fn hypot(a: f64, b: f64) -> f64 {
    let (a, b) = (a.abs(), b.abs());
    if a.is_infinite() || b.is_infinite() {
        return f64::INFINITY;
    }
    let (big, small) = if a >= b { (a, b) } else { (b, a) };
    if big == 0.0 {
        return 0.0;
    }
    let ratio = small / big;
    big * (1.0 + ratio * ratio).sqrt()
}

/// Platform-independent transcendental functions on `f64` (each the `libm`
/// function of the same name, except `phypot`: [`hypot`]; angles in radians).
pub trait Portable: Sized {
    /// Sine.
    #[must_use]
    fn psin(self) -> f64;
    /// Cosine.
    #[must_use]
    fn pcos(self) -> f64;
    /// `(sin, cos)`.
    #[must_use]
    fn psin_cos(self) -> (f64, f64);
    /// Tangent.
    #[must_use]
    fn ptan(self) -> f64;
    /// Arcsine, in [−π/2, π/2].
    #[must_use]
    fn pasin(self) -> f64;
    /// Arccosine, in [0, π].
    #[must_use]
    fn pacos(self) -> f64;
    /// Four-quadrant arctangent of `self / x`, in [−π, π].
    #[must_use]
    fn patan2(self, x: f64) -> f64;
    /// `self` raised to `exponent`.
    #[must_use]
    fn ppowf(self, exponent: f64) -> f64;
    /// `√(self² + y²)` without overflow.
    #[must_use]
    fn phypot(self, y: f64) -> f64;
    /// `e^self`.
    #[must_use]
    fn pexp(self) -> f64;
    /// Natural logarithm.
    #[must_use]
    fn pln(self) -> f64;
}

impl Portable for f64 {
    #[inline]
    fn psin(self) -> f64 {
        libm::sin(self)
    }
    #[inline]
    fn pcos(self) -> f64 {
        libm::cos(self)
    }
    #[inline]
    fn psin_cos(self) -> (f64, f64) {
        libm::sincos(self)
    }
    #[inline]
    fn ptan(self) -> f64 {
        libm::tan(self)
    }
    #[inline]
    fn pasin(self) -> f64 {
        libm::asin(self)
    }
    #[inline]
    fn pacos(self) -> f64 {
        libm::acos(self)
    }
    #[inline]
    fn patan2(self, x: f64) -> f64 {
        libm::atan2(self, x)
    }
    #[inline]
    fn ppowf(self, exponent: f64) -> f64 {
        libm::pow(self, exponent)
    }
    #[inline]
    fn phypot(self, y: f64) -> f64 {
        hypot(self, y)
    }
    #[inline]
    fn pexp(self) -> f64 {
        libm::exp(self)
    }
    #[inline]
    fn pln(self) -> f64 {
        libm::log(self)
    }
}

#[cfg(test)]
#[allow(clippy::disallowed_methods)] // compares with the platform functions
mod tests {
    use super::{Portable, hypot};

    #[test]
    fn hypot_agrees_with_libm_within_an_ulp_and_never_overflows() {
        let mut worst = 0.0_f64;
        let mut x = 1.234_567e-300_f64;
        while x < 1e300 {
            for y in [0.0, 1.0, -3.5, x * 0.7, -x * 1e-9, x * 1e6] {
                let ours = hypot(x, y);
                let reference = libm::hypot(x, y);
                assert!(ours.is_finite(), "hypot({x}, {y}) = {ours}");
                worst = worst.max((ours - reference).abs() / reference);
            }
            x *= 37.3;
        }
        // The scaled form rounds twice more than libm's; ≤ 2 ulp (2.2e-16 each).
        assert!(worst <= 4.5e-16, "worst relative difference {worst:e}");
        assert_eq!(hypot(1e300, 1e300), 1e300 * 2.0_f64.sqrt());
        assert_eq!(hypot(3e-300, 4e-300), 5e-300);
        assert_eq!(hypot(0.0, -0.0), 0.0);
        assert_eq!(hypot(f64::INFINITY, f64::NAN), f64::INFINITY);
        assert!(hypot(f64::NAN, 1.0).is_nan());
    }

    /// The wrappers agree with the platform's functions to a few ulp (they
    /// compute the same mathematical function; only the last bits may differ).
    #[test]
    fn agrees_with_the_platform_to_a_few_ulp() {
        let close =
            |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(1.0);
        for i in -200..=200 {
            let x = f64::from(i) * 0.0173;
            assert!(close(x.psin(), x.sin()), "sin {x}");
            assert!(close(x.pcos(), x.cos()), "cos {x}");
            let (s, c) = x.psin_cos();
            assert!(close(s, x.sin()) && close(c, x.cos()), "sin_cos {x}");
            assert!(close((0.4 * x).ptan(), (0.4 * x).tan()), "tan {x}");
            let u = x / 3.5;
            assert!(
                close(u.pasin(), u.asin()) && close(u.pacos(), u.acos()),
                "asin/acos {u}"
            );
            assert!(close(x.patan2(0.7), x.atan2(0.7)), "atan2 {x}");
            assert!(close(x.abs().ppowf(1.5), x.abs().powf(1.5)), "pow {x}");
            assert!(close(x.phypot(2.0), x.hypot(2.0)), "hypot {x}");
            assert!(close(x.pexp(), x.exp()), "exp {x}");
            assert!(close((x.abs() + 0.1).pln(), (x.abs() + 0.1).ln()), "ln {x}");
        }
    }

    /// sin 1 correctly rounded (0.8414709848078965): the libm algorithm, not
    /// the platform, decides the bits.
    #[test]
    fn sine_of_one_is_correctly_rounded() {
        assert_eq!(1.0_f64.psin().to_bits(), 0x3FEA_ED54_8F09_0CEE);
    }
}
