//! The base's equation of the articulated-body algorithm, `I^A a = −p^A`
//! (Featherstone 2008 §9.3): a 6×6 Cholesky solve of a spatial inertia,
//! unrolled by the column index so every loop has a fixed length.
//!
//! The arithmetic is the textbook in-place Cholesky, `L Lᵀ = I`, then
//! forward and back substitution, each sum taken in ascending index order:
//! a fixed order, so the result is the same bits on every platform
//! (`tests::same_bits_as_textbook` holds it to the loop form).
#![expect(
    clippy::needless_range_loop,
    reason = "the factorisation reads best in matrix indices, and the indices fix the order of each sum"
)]

use glam::DVec3;

use crate::dynamics::spatial::{Force, Inertia, Motion};

/// The lower triangle of the inertia, rows and columns `[angular; linear]`
/// (the upper triangle is left zero: the factorisation never reads it).
#[inline(always)]
fn lower(i: &Inertia) -> [[f64; 6]; 6] {
    let mut m = [[0.0; 6]; 6];
    for row in 0..3 {
        for col in 0..=row {
            m[row][col] = i.a.col(col)[row];
            m[row + 3][col + 3] = i.c.col(col)[row];
        }
        for col in 0..3 {
            // The lower-left block is bᵀ: entry (row, col) is b's (col, row).
            m[row + 3][col] = i.b.col(row)[col];
        }
    }
    m
}

/// Column `J` of the factor `L`, in place; false when the pivot is not
/// positive and finite.
#[inline(always)]
fn factor_column<const J: usize>(m: &mut [[f64; 6]; 6]) -> bool {
    let mut d = m[J][J];
    for k in 0..J {
        d -= m[J][k] * m[J][k];
    }
    if d <= 0.0 || !d.is_finite() {
        return false;
    }
    let d = d.sqrt();
    m[J][J] = d;
    for i in J + 1..6 {
        let mut s = m[i][J];
        for k in 0..J {
            s -= m[i][k] * m[J][k];
        }
        m[i][J] = s / d;
    }
    true
}

/// Row `I` of the forward substitution `L y = r`.
#[inline(always)]
fn forward<const I: usize>(m: &[[f64; 6]; 6], y: &mut [f64; 6], rhs: &[f64; 6]) {
    let mut s = rhs[I];
    for k in 0..I {
        s -= m[I][k] * y[k];
    }
    y[I] = s / m[I][I];
}

/// Row `I` of the back substitution `Lᵀ x = y`.
#[inline(always)]
fn backward<const I: usize>(m: &[[f64; 6]; 6], x: &mut [f64; 6], y: &[f64; 6]) {
    let mut s = y[I];
    for k in I + 1..6 {
        s -= m[k][I] * x[k];
    }
    x[I] = s / m[I][I];
}

/// Solve `inertia · a = f` for the motion `a`; `None` when the inertia is
/// not positive definite.
#[must_use]
pub fn solve(inertia: &Inertia, f: Force) -> Option<Motion> {
    let mut m = lower(inertia);
    let factored = factor_column::<0>(&mut m)
        && factor_column::<1>(&mut m)
        && factor_column::<2>(&mut m)
        && factor_column::<3>(&mut m)
        && factor_column::<4>(&mut m)
        && factor_column::<5>(&mut m);
    if !factored {
        return None;
    }
    let rhs = [
        f.moment.x, f.moment.y, f.moment.z, f.force.x, f.force.y, f.force.z,
    ];
    let mut y = [0.0; 6];
    forward::<0>(&m, &mut y, &rhs);
    forward::<1>(&m, &mut y, &rhs);
    forward::<2>(&m, &mut y, &rhs);
    forward::<3>(&m, &mut y, &rhs);
    forward::<4>(&m, &mut y, &rhs);
    forward::<5>(&m, &mut y, &rhs);
    let mut x = [0.0; 6];
    backward::<5>(&m, &mut x, &y);
    backward::<4>(&m, &mut x, &y);
    backward::<3>(&m, &mut x, &y);
    backward::<2>(&m, &mut x, &y);
    backward::<1>(&m, &mut x, &y);
    backward::<0>(&m, &mut x, &y);
    Some(Motion::new(
        DVec3::new(x[0], x[1], x[2]),
        DVec3::new(x[3], x[4], x[5]),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DMat3;

    /// The loop form of the same factorisation and substitutions, on the full
    /// 6×6 matrix: the reference the unrolled form must match bit for bit.
    fn textbook(i: &Inertia, f: Force) -> Option<[f64; 6]> {
        let mut m = i.to_array();
        for j in 0..6 {
            let mut d = m[j][j];
            for k in 0..j {
                d -= m[j][k] * m[j][k];
            }
            if d <= 0.0 || !d.is_finite() {
                return None;
            }
            let d = d.sqrt();
            m[j][j] = d;
            for r in j + 1..6 {
                let mut s = m[r][j];
                for k in 0..j {
                    s -= m[r][k] * m[j][k];
                }
                m[r][j] = s / d;
            }
        }
        let rhs = [
            f.moment.x, f.moment.y, f.moment.z, f.force.x, f.force.y, f.force.z,
        ];
        let mut y = [0.0; 6];
        for r in 0..6 {
            let mut s = rhs[r];
            for k in 0..r {
                s -= m[r][k] * y[k];
            }
            y[r] = s / m[r][r];
        }
        let mut x = [0.0; 6];
        for r in (0..6).rev() {
            let mut s = y[r];
            for k in r + 1..6 {
                s -= m[k][r] * x[k];
            }
            x[r] = s / m[r][r];
        }
        Some(x)
    }

    /// A deterministic spread of values in (−1, 1).
    fn value(seed: &mut u64) -> f64 {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }

    #[test]
    fn same_bits_as_textbook() {
        let mut seed = 7;
        for _ in 0..500 {
            let com = DVec3::new(value(&mut seed), value(&mut seed), value(&mut seed)) * 0.3;
            let rot = DMat3::from_euler(
                glam::EulerRot::XYZ,
                value(&mut seed),
                value(&mut seed),
                value(&mut seed),
            );
            let diag = DVec3::new(value(&mut seed), value(&mut seed), value(&mut seed)).abs()
                + DVec3::splat(0.01);
            let mass = 1.0 + value(&mut seed).abs() * 20.0;
            let inertia = Inertia::rigid(
                mass,
                com,
                rot * DMat3::from_diagonal(diag) * rot.transpose(),
            );
            // Articulated inertias are not bit-symmetric: perturb one side.
            let mut inertia = inertia;
            inertia.a.x_axis.y += 1e-13 * value(&mut seed);
            inertia.b.y_axis.z += 1e-3 * value(&mut seed);
            let f = Force::new(
                DVec3::new(value(&mut seed), value(&mut seed), value(&mut seed)),
                DVec3::new(value(&mut seed), value(&mut seed), value(&mut seed)) * 50.0,
            );
            let want = textbook(&inertia, f).expect("positive definite");
            let got = solve(&inertia, f).expect("positive definite");
            let got = [
                got.angular.x,
                got.angular.y,
                got.angular.z,
                got.linear.x,
                got.linear.y,
                got.linear.z,
            ];
            for k in 0..6 {
                assert_eq!(got[k].to_bits(), want[k].to_bits(), "entry {k}");
            }
        }
    }

    #[test]
    fn inverts_the_inertia_product() {
        let i = Inertia::rigid(
            1.7,
            DVec3::new(0.1, 0.3, -0.2),
            DMat3::from_diagonal(DVec3::new(0.04, 0.02, 0.03)),
        );
        let a = Motion::new(DVec3::new(0.3, -0.2, 0.9), DVec3::new(1.0, 2.0, -0.5));
        let back = solve(&i, i.mul(a)).expect("positive definite");
        assert!((back - a).angular.length() < 1e-9 && (back - a).linear.length() < 1e-9);
    }

    #[test]
    fn refuses_what_is_not_positive_definite() {
        assert!(solve(&Inertia::ZERO, Force::ZERO).is_none());
        let mut i = Inertia::rigid(2.0, DVec3::ZERO, DMat3::from_diagonal(DVec3::splat(0.1)));
        i.c.z_axis.z = -1.0;
        assert!(solve(&i, Force::ZERO).is_none());
        i.c.z_axis.z = f64::NAN;
        assert!(solve(&i, Force::ZERO).is_none());
    }
}
