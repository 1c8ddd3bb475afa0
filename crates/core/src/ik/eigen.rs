//! Symmetric eigen-decomposition for the small Gram matrices JJᵀ (or JᵀJ) of the
//! IK solvers: Householder reduction to tridiagonal form followed by the
//! implicit QL method with Wilkinson-style shifts (the EISPACK tred2/tql2
//! scheme). Works in caller-owned buffers: no allocation after construction.
//!
//! Storage is column-major `n × n` in a flat slice, matching nalgebra's layout.

use crate::portable::hypot;

/// Reusable workspace for decompositions of size up to `capacity`.
#[derive(Clone, Debug, Default)]
pub struct SymmetricEigen {
    n: usize,
    /// Eigenvectors, column-major n×n; column i pairs with `values[i]`.
    vectors: Vec<f64>,
    /// Eigenvalues (unsorted).
    values: Vec<f64>,
    off_diagonal: Vec<f64>,
}

/// The QL iteration failed to converge (only for non-finite input in practice).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NoConvergence;

impl SymmetricEigen {
    /// Workspace for matrices up to `capacity × capacity`.
    #[must_use]
    pub fn with_capacity(capacity: usize) -> Self {
        Self {
            n: 0,
            vectors: vec![0.0; capacity * capacity],
            values: vec![0.0; capacity],
            off_diagonal: vec![0.0; capacity],
        }
    }

    /// Size of the last decomposition.
    #[must_use]
    pub fn size(&self) -> usize {
        self.n
    }

    /// Eigenvalues of the last decomposition (unsorted).
    #[must_use]
    pub fn values(&self) -> &[f64] {
        &self.values[..self.n]
    }

    /// Component `row` of eigenvector `col`.
    #[must_use]
    pub fn vector(&self, col: usize) -> &[f64] {
        &self.vectors[col * self.n..(col + 1) * self.n]
    }

    /// Decomposes the symmetric `n × n` column-major matrix `a` (only its lower
    /// triangle is read) into `Q diag(λ) Qᵀ`.
    ///
    /// # Errors
    /// [`NoConvergence`] if the QL iteration does not settle (non-finite input).
    pub fn compute(&mut self, a: &[f64], n: usize) -> Result<(), NoConvergence> {
        if self.values.len() < n {
            *self = Self::with_capacity(n);
        }
        self.n = n;
        if n == 0 {
            return Ok(());
        }
        self.vectors[..n * n].copy_from_slice(&a[..n * n]);
        self.tridiagonalize();
        self.ql_implicit()
    }

    /// Householder reduction of `vectors` (holding A) to tridiagonal form; on
    /// exit `values` holds the diagonal, `off_diagonal[1..]` the sub-diagonal and
    /// `vectors` the accumulated orthogonal transform.
    fn tridiagonalize(&mut self) {
        let n = self.n;
        let v = &mut self.vectors[..n * n];
        let d = &mut self.values[..n];
        let e = &mut self.off_diagonal[..n];
        // v[(row, col)] at row + col * n.
        let at = |row: usize, col: usize| row + col * n;
        for j in 0..n {
            d[j] = v[at(n - 1, j)];
        }
        for i in (1..n).rev() {
            let mut scale = 0.0;
            let mut h = 0.0;
            for dk in d.iter().take(i) {
                scale += dk.abs();
            }
            if scale == 0.0 {
                e[i] = d[i - 1];
                for j in 0..i {
                    d[j] = v[at(i - 1, j)];
                    v[at(i, j)] = 0.0;
                    v[at(j, i)] = 0.0;
                }
            } else {
                for dk in d.iter_mut().take(i) {
                    *dk /= scale;
                    h += *dk * *dk;
                }
                let f = d[i - 1];
                let mut g = h.sqrt();
                if f > 0.0 {
                    g = -g;
                }
                e[i] = scale * g;
                h -= f * g;
                d[i - 1] = f - g;
                e[..i].fill(0.0);
                for j in 0..i {
                    let f = d[j];
                    v[at(j, i)] = f;
                    let mut g = e[j] + v[at(j, j)] * f;
                    for k in j + 1..i {
                        g += v[at(k, j)] * d[k];
                        e[k] += v[at(k, j)] * f;
                    }
                    e[j] = g;
                }
                let mut f = 0.0;
                for j in 0..i {
                    e[j] /= h;
                    f += e[j] * d[j];
                }
                let hh = f / (h + h);
                for j in 0..i {
                    e[j] -= hh * d[j];
                }
                for j in 0..i {
                    let f = d[j];
                    let g = e[j];
                    for k in j..i {
                        v[at(k, j)] -= f * e[k] + g * d[k];
                    }
                    d[j] = v[at(i - 1, j)];
                    v[at(i, j)] = 0.0;
                }
            }
            d[i] = h;
        }
        // Accumulate the transformations.
        for i in 0..n - 1 {
            v[at(n - 1, i)] = v[at(i, i)];
            v[at(i, i)] = 1.0;
            let h = d[i + 1];
            if h != 0.0 {
                for k in 0..=i {
                    d[k] = v[at(k, i + 1)] / h;
                }
                for j in 0..=i {
                    let mut g = 0.0;
                    for k in 0..=i {
                        g += v[at(k, i + 1)] * v[at(k, j)];
                    }
                    for k in 0..=i {
                        v[at(k, j)] -= g * d[k];
                    }
                }
            }
            for k in 0..=i {
                v[at(k, i + 1)] = 0.0;
            }
        }
        for j in 0..n {
            d[j] = v[at(n - 1, j)];
            v[at(n - 1, j)] = 0.0;
        }
        v[at(n - 1, n - 1)] = 1.0;
        e[0] = 0.0;
    }

    /// Implicit QL iterations on the tridiagonal matrix, rotating `vectors`.
    fn ql_implicit(&mut self) -> Result<(), NoConvergence> {
        let n = self.n;
        let v = &mut self.vectors[..n * n];
        let d = &mut self.values[..n];
        let e = &mut self.off_diagonal[..n];
        for i in 1..n {
            e[i - 1] = e[i];
        }
        e[n - 1] = 0.0;
        let mut f = 0.0;
        let mut tst1: f64 = 0.0;
        let eps = f64::EPSILON;
        for l in 0..n {
            tst1 = tst1.max(d[l].abs() + e[l].abs());
            let mut m = l;
            while m < n - 1 && e[m].abs() > eps * tst1 {
                m += 1;
            }
            if m > l {
                let mut iterations = 0;
                loop {
                    iterations += 1;
                    if iterations > 60 || !tst1.is_finite() {
                        return Err(NoConvergence);
                    }
                    let g = d[l];
                    let mut p = (d[l + 1] - g) / (2.0 * e[l]);
                    // hypot, not sqrt(p² + 1): p is huge when e[l] is tiny
                    // beside the gap d[l+1] − d[l], and p² would overflow.
                    let mut r = hypot(p, 1.0);
                    if p < 0.0 {
                        r = -r;
                    }
                    d[l] = e[l] / (p + r);
                    d[l + 1] = e[l] * (p + r);
                    let dl1 = d[l + 1];
                    let h = g - d[l];
                    for di in d.iter_mut().skip(l + 2) {
                        *di -= h;
                    }
                    f += h;
                    p = d[m];
                    let mut c = 1.0;
                    let mut c2 = c;
                    let mut c3 = c;
                    let el1 = e[l + 1];
                    let mut s = 0.0;
                    let mut s2 = 0.0;
                    for i in (l..m).rev() {
                        c3 = c2;
                        c2 = c;
                        s2 = s;
                        let g = c * e[i];
                        let h = c * p;
                        r = hypot(p, e[i]);
                        e[i + 1] = s * r;
                        s = e[i] / r;
                        c = p / r;
                        p = c * d[i] - s * g;
                        d[i + 1] = h + s * (c * g + s * d[i]);
                        let (left, right) = v.split_at_mut((i + 1) * n);
                        let col_i = &mut left[i * n..];
                        let col_next = &mut right[..n];
                        for k in 0..n {
                            let h = col_next[k];
                            col_next[k] = s * col_i[k] + c * h;
                            col_i[k] = c * col_i[k] - s * h;
                        }
                    }
                    p = -s * s2 * c3 * el1 * e[l] / dl1;
                    e[l] = s * p;
                    d[l] = c * p;
                    if e[l].abs() <= eps * tst1 {
                        break;
                    }
                }
            }
            d[l] += f;
            e[l] = 0.0;
        }
        if d.iter().all(|x| x.is_finite()) {
            Ok(())
        } else {
            Err(NoConvergence)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(a: &nalgebra::DMatrix<f64>) {
        let n = a.nrows();
        let mut eig = SymmetricEigen::with_capacity(n);
        eig.compute(a.as_slice(), n).expect("converges");
        // A q = λ q for every pair, and Q is orthonormal.
        for i in 0..n {
            let q = nalgebra::DVector::from_column_slice(eig.vector(i));
            let residual = a * &q - &q * eig.values()[i];
            assert!(
                residual.norm() < 1e-10 * (1.0 + a.norm()),
                "residual {}",
                residual.norm()
            );
            assert!((q.norm() - 1.0).abs() < 1e-12);
            for j in 0..i {
                let other = nalgebra::DVector::from_column_slice(eig.vector(j));
                assert!(q.dot(&other).abs() < 1e-10);
            }
        }
        let mut ours: Vec<f64> = eig.values().to_vec();
        let mut reference: Vec<f64> = a
            .clone()
            .symmetric_eigen()
            .eigenvalues
            .iter()
            .copied()
            .collect();
        ours.sort_by(f64::total_cmp);
        reference.sort_by(f64::total_cmp);
        for (x, y) in ours.iter().zip(&reference) {
            assert!((x - y).abs() < 1e-10 * (1.0 + a.norm()), "{x} vs {y}");
        }
    }

    #[test]
    fn matches_nalgebra_on_gram_matrices() {
        let mut seed = 12345_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        for &(m, n) in &[(1, 1), (2, 5), (3, 3), (12, 20), (15, 63), (6, 4)] {
            let j = nalgebra::DMatrix::from_fn(m, n, |_, _| next());
            check(&(&j * j.transpose()));
        }
    }

    #[test]
    fn handles_rank_deficient_and_diagonal_matrices() {
        let mut j = nalgebra::DMatrix::zeros(6, 6);
        j[(0, 0)] = 2.0;
        j[(1, 1)] = 2.0; // repeated eigenvalue
        j[(2, 3)] = 1.0;
        check(&(&j * j.transpose()));
        check(&nalgebra::DMatrix::zeros(4, 4));
        check(&nalgebra::DMatrix::identity(5, 5));
    }

    /// Regression (found by tests/prop_ik.rs): a zero diagonal entry coupled
    /// to the rest by a tiny off-diagonal ε (a Jacobian row that is zero up to
    /// rounding) made the QL shift p = (d₁ − d₀)/2ε so large that p² overflowed:
    /// below ε ≈ 1e-155 the eigenvalues came back NaN with `Ok`, and the IK
    /// iteration failed without a step. The eigenvalues are known in closed
    /// form (ε² is below rounding): {0, 1} and {0, 1 − √2, 1 + √2}.
    #[test]
    fn a_tiny_coupling_beside_a_zero_diagonal_does_not_overflow() {
        let root2 = std::f64::consts::SQRT_2;
        for eps in [1e-100, 1e-160, 1e-200, 1e-250, 1e-300] {
            let cases: [(usize, &[f64], &[f64]); 2] = [
                (2, &[0.0, eps, eps, 1.0], &[0.0, 1.0]),
                (
                    3,
                    &[0.0, eps, 0.0, eps, 0.0, 1.0, 0.0, 1.0, 2.0],
                    &[1.0 - root2, 0.0, 1.0 + root2],
                ),
            ];
            for (n, a, expected) in cases {
                let mut eig = SymmetricEigen::with_capacity(n);
                assert_eq!(eig.compute(a, n), Ok(()), "n = {n}, ε = {eps:e}");
                let mut values = eig.values().to_vec();
                values.sort_by(f64::total_cmp);
                for (x, y) in values.iter().zip(expected) {
                    assert!((x - y).abs() < 1e-14, "ε = {eps:e}: {values:?}");
                }
                for i in 0..n {
                    let q = eig.vector(i);
                    assert!(q.iter().all(|x| x.is_finite()), "ε = {eps:e}: {q:?}");
                    let norm: f64 = q.iter().map(|x| x * x).sum();
                    assert!((norm - 1.0).abs() < 1e-14, "ε = {eps:e}: |q| = {norm}");
                }
            }
        }
    }
}
