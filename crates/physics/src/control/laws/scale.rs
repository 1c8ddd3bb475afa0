//! Table 1 of Raibert & Hodgins 1991 ("Dynamic Scaling"): the factors by
//! which a creature scaled L times in every length scales each mechanical
//! and control quantity, gravity unchanged. Every controller states its
//! gains at scale 1 and multiplies by these, so a scaled creature runs the
//! scaled motion (L = 2: hops twice as high, √2 as fast, steps ×√2 as long).

use gaitlab_core::portable::Portable;

/// The dynamic scale factor L and the Table-1 factor of each quantity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    /// L: how many times the scale-1 creature's lengths.
    pub l: f64,
}

impl Scale {
    /// The factors for scale `l`.
    #[must_use]
    pub fn new(l: f64) -> Self {
        Self { l }
    }

    /// A linear servo's or spring's gains `(k, b)` at scale 1, scaled.
    #[must_use]
    pub fn linear_gains(self, k: f64, b: f64) -> (f64, f64) {
        (k * self.stiffness(), b * self.damping())
    }

    /// A torsional servo's gains `(kp, kv)` at scale 1, scaled.
    #[must_use]
    pub fn torsional_gains(self, kp: f64, kv: f64) -> (f64, f64) {
        (
            kp * self.torsional_stiffness(),
            kv * self.torsional_damping(),
        )
    }
}

/// Declares one method of [`Scale`] per row of Table 1: `name = |l| factor`,
/// the factor as an expression in L.
macro_rules! table_1 {
    ($($(#[$doc:meta])* $name:ident = |$l:ident| $factor:expr;)*) => {
        impl Scale {
            $(
                $(#[$doc])*
                #[must_use]
                pub fn $name(self) -> f64 {
                    let $l = self.l;
                    $factor
                }
            )*
        }
    };
}

table_1! {
    /// Length and displacement (m): L.
    length = |l| l;
    /// Time (s): L^½.
    time = |l| l.sqrt();
    /// Force (N): L³.
    force = |l| l.powi(3);
    /// Velocity (m/s): L^½.
    velocity = |l| l.sqrt();
    /// Linear stiffness (N/m): L².
    stiffness = |l| l * l;
    /// Torque (N·m): L⁴.
    torque = |l| l.powi(4);
    /// Linear damping (N·s/m): L^{5/2}.
    damping = |l| l.ppowf(2.5);
    /// Torsional stiffness (N·m/rad): L⁴.
    torsional_stiffness = |l| l.powi(4);
    /// Torsional damping (N·m·s/rad): L^{9/2}.
    torsional_damping = |l| l.ppowf(4.5);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_factors_follow_from_length_time_and_force() {
        // Table 1's basic variables: length L, time L^½, force L³; every
        // other row is a product of their powers.
        let s = Scale::new(2.0);
        let (l, t, f) = (s.length(), s.time(), s.force());
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12 * b.abs().max(1.0);
        assert!(close(s.velocity(), l / t));
        assert!(close(s.torque(), f * l));
        assert!(close(s.stiffness(), f / l));
        assert!(close(s.damping(), f * t / l));
        assert!(close(s.torsional_stiffness(), f * l));
        assert!(close(s.torsional_damping(), f * l * t));
        assert_eq!(Scale::new(1.0).torsional_gains(3.0, 4.0), (3.0, 4.0));
    }
}
