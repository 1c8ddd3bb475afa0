//! Thin singular value decomposition J = Σ σᵢ uᵢ vᵢᵀ (She 2006 §4.4.4) computed
//! from the eigen-decomposition of the smaller Gram matrix: JJᵀ = U Σ² Uᵀ when
//! m ≤ n (then vᵢ = Jᵀuᵢ/σᵢ), JᵀJ = V Σ² Vᵀ otherwise (then uᵢ = Jvᵢ/σᵢ). Only
//! the r = rank(J) triplets above the rank tolerance are kept, so U and V are
//! never formed in full. Buffers are reused between calls.

use nalgebra::DMatrix;

use super::eigen::{NoConvergence, SymmetricEigen};

/// The nonzero singular triplets of a Jacobian.
#[derive(Clone, Debug, Default)]
pub struct ThinSvd {
    rows: usize,
    cols: usize,
    rank: usize,
    gram: Vec<f64>,
    eigen: SymmetricEigen,
    sigma: Vec<f64>,
    /// Left singular vectors, `rows × rank`, column-major.
    u: Vec<f64>,
    /// Right singular vectors, `cols × rank`, column-major.
    v: Vec<f64>,
}

/// Writes the lower triangle (and mirrors it) of `JJᵀ` (m×m) into `gram`.
pub(crate) fn gram_rows(j: &DMatrix<f64>, gram: &mut [f64]) {
    let m = j.nrows();
    let gram = &mut gram[..m * m];
    gram.fill(0.0);
    for col in j.column_iter() {
        let col = col.as_slice();
        for a in 0..m {
            let ca = col[a];
            if ca == 0.0 {
                continue;
            }
            let target = &mut gram[a * m..(a + 1) * m];
            for b in a..m {
                target[b] += ca * col[b];
            }
        }
    }
    mirror_lower(gram, m);
}

/// Writes `JᵀJ` (n×n) into `gram`.
pub(crate) fn gram_cols(j: &DMatrix<f64>, gram: &mut [f64]) {
    let n = j.ncols();
    let m = j.nrows();
    let data = j.as_slice();
    for a in 0..n {
        let ca = &data[a * m..(a + 1) * m];
        for b in a..n {
            let cb = &data[b * m..(b + 1) * m];
            let dot: f64 = ca.iter().zip(cb).map(|(x, y)| x * y).sum();
            gram[b + a * n] = dot;
            gram[a + b * n] = dot;
        }
    }
}

fn mirror_lower(gram: &mut [f64], m: usize) {
    for a in 0..m {
        for b in a + 1..m {
            gram[a + b * m] = gram[b + a * m];
        }
    }
}

impl ThinSvd {
    /// Decomposes `j`, keeping singular values above `rank_tolerance · σ_max`.
    ///
    /// # Errors
    /// [`NoConvergence`] when `j` holds non-finite values.
    pub fn compute(&mut self, j: &DMatrix<f64>, rank_tolerance: f64) -> Result<(), NoConvergence> {
        let (m, n) = j.shape();
        self.rows = m;
        self.cols = n;
        self.rank = 0;
        let side = m.min(n);
        if self.gram.len() < side * side {
            self.gram.resize(side * side, 0.0);
            self.eigen = SymmetricEigen::with_capacity(side);
        }
        if self.sigma.len() < side || self.u.len() < m * side || self.v.len() < n * side {
            self.sigma.resize(side, 0.0);
            self.u.resize(m * side, 0.0);
            self.v.resize(n * side, 0.0);
        }
        if side == 0 {
            return Ok(());
        }
        let rows_side = m <= n;
        if rows_side {
            gram_rows(j, &mut self.gram);
        } else {
            gram_cols(j, &mut self.gram);
        }
        self.eigen.compute(&self.gram, side)?;
        let largest = self.eigen.values().iter().fold(0.0_f64, |acc, &x| acc.max(x));
        let sigma_max = largest.max(0.0).sqrt();
        let threshold = (rank_tolerance * sigma_max).max(1e-150);
        let data = j.as_slice();
        // Keep the eigenpairs above the threshold; record their σ.
        let mut kept = 0;
        for i in 0..side {
            let sigma = self.eigen.values()[i].max(0.0).sqrt();
            if sigma > threshold {
                self.sigma[kept] = sigma;
                let q = self.eigen.vector(i);
                if rows_side {
                    self.u[kept * m..(kept + 1) * m].copy_from_slice(q);
                } else {
                    self.v[kept * n..(kept + 1) * n].copy_from_slice(q);
                }
                kept += 1;
            }
        }
        self.rank = kept;
        if rows_side {
            // vᵢ = Jᵀuᵢ/σᵢ, skipping the (many) zero entries of each column.
            self.v[..n * kept].fill(0.0);
            for c in 0..n {
                let col = &data[c * m..(c + 1) * m];
                for (a, &x) in col.iter().enumerate() {
                    if x == 0.0 {
                        continue;
                    }
                    for i in 0..kept {
                        self.v[i * n + c] += x * self.u[i * m + a];
                    }
                }
            }
            for i in 0..kept {
                let inv = 1.0 / self.sigma[i];
                for x in &mut self.v[i * n..(i + 1) * n] {
                    *x *= inv;
                }
            }
        } else {
            // uᵢ = Jvᵢ/σᵢ.
            self.u[..m * kept].fill(0.0);
            for i in 0..kept {
                let inv = 1.0 / self.sigma[i];
                let (v, u) = (&self.v[i * n..(i + 1) * n], &mut self.u[i * m..(i + 1) * m]);
                for (c, &vc) in v.iter().enumerate() {
                    if vc == 0.0 {
                        continue;
                    }
                    for (out, x) in u.iter_mut().zip(&data[c * m..(c + 1) * m]) {
                        *out += x * vc;
                    }
                }
                for out in u.iter_mut() {
                    *out *= inv;
                }
            }
        }
        Ok(())
    }

    /// Numerical rank r.
    #[must_use]
    pub fn rank(&self) -> usize {
        self.rank
    }

    /// Singular value σᵢ, i < r (unsorted).
    #[must_use]
    pub fn sigma(&self, i: usize) -> f64 {
        self.sigma[i]
    }

    /// Left singular vector uᵢ (length m).
    #[must_use]
    pub fn u(&self, i: usize) -> &[f64] {
        &self.u[i * self.rows..(i + 1) * self.rows]
    }

    /// Right singular vector vᵢ (length n).
    #[must_use]
    pub fn v(&self, i: usize) -> &[f64] {
        &self.v[i * self.cols..(i + 1) * self.cols]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn random(m: usize, n: usize, seed: &mut u64) -> DMatrix<f64> {
        DMatrix::from_fn(m, n, |_, _| {
            *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
    }

    #[test]
    fn reconstructs_the_matrix_and_matches_nalgebra_singular_values() {
        let mut seed = 7;
        for &(m, n) in &[(3, 7), (12, 20), (9, 4), (15, 63), (1, 1)] {
            let j = random(m, n, &mut seed);
            let mut svd = ThinSvd::default();
            svd.compute(&j, 1e-9).expect("converges");
            assert_eq!(svd.rank(), m.min(n));
            let mut rebuilt = DMatrix::zeros(m, n);
            for i in 0..svd.rank() {
                let u = nalgebra::DVector::from_column_slice(svd.u(i));
                let v = nalgebra::DVector::from_column_slice(svd.v(i));
                rebuilt += &u * v.transpose() * svd.sigma(i);
            }
            assert!((&rebuilt - &j).norm() < 1e-9, "{m}x{n}: {}", (&rebuilt - &j).norm());
            let mut ours: Vec<f64> = (0..svd.rank()).map(|i| svd.sigma(i)).collect();
            let mut reference: Vec<f64> = j.clone().svd(false, false).singular_values.iter().copied().collect();
            ours.sort_by(f64::total_cmp);
            reference.sort_by(f64::total_cmp);
            for (a, b) in ours.iter().zip(&reference) {
                assert!((a - b).abs() < 1e-9, "{a} vs {b}");
            }
        }
    }

    #[test]
    fn drops_directions_below_the_rank_tolerance() {
        // Rank 2: third row is the sum of the first two.
        let mut j = DMatrix::zeros(3, 4);
        j[(0, 0)] = 1.0;
        j[(0, 1)] = 2.0;
        j[(1, 2)] = 3.0;
        j[(1, 3)] = -1.0;
        for c in 0..4 {
            j[(2, c)] = j[(0, c)] + j[(1, c)];
        }
        let mut svd = ThinSvd::default();
        svd.compute(&j, 1e-6).expect("converges");
        assert_eq!(svd.rank(), 2);
    }
}
