//! Thin singular value decomposition J = Σ σᵢ uᵢ vᵢᵀ (She 2006 §4.4.4) computed
//! from the eigen-decomposition of the smaller Gram matrix: JJᵀ = U Σ² Uᵀ when
//! m ≤ n (then vᵢ = Jᵀuᵢ/σᵢ), JᵀJ = V Σ² Vᵀ otherwise (then uᵢ = Jvᵢ/σᵢ). Only
//! the r = rank(J) triplets above the rank tolerance are kept, so U and V are
//! never formed in full. Buffers are reused between calls.

use nalgebra::DMatrix;

use super::eigen::{NoConvergence, SymmetricEigen};
use crate::skeleton::TaskBlock;

/// The nonzero singular triplets of a Jacobian.
#[derive(Clone, Debug, Default)]
pub struct ThinSvd {
    rows: usize,
    cols: usize,
    rank: usize,
    gram: Vec<f64>,
    eigen: SymmetricEigen,
    sigma: Vec<f64>,
    /// Scratch for a block's gathered submatrix.
    gathered: Vec<f64>,
    /// Block of each kept singular triplet (when `by_blocks`).
    block_of: Vec<usize>,
    /// Whether the last decomposition went block by block.
    by_blocks: bool,
    /// Left singular vectors, `rows × rank`, column-major.
    u: Vec<f64>,
    /// Right singular vectors, `cols × rank`, column-major.
    v: Vec<f64>,
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

/// Gathers the block's submatrix `B = J[rows, joints]` (p×q) into `gathered`,
/// row-major (row a of B is `gathered[a*q..(a+1)*q]`), and writes its Gram
/// matrix `BBᵀ` (p×p) into `gram` as dot products of those contiguous rows.
pub(crate) fn gram_of_block(
    j: &DMatrix<f64>,
    block: &TaskBlock,
    gram: &mut [f64],
    gathered: &mut Vec<f64>,
) {
    let m = j.nrows();
    let p = block.rows.len();
    let q = block.joints.len();
    if gathered.len() < p * q {
        gathered.resize(p * q, 0.0);
    }
    let data = j.as_slice();
    for (a, &r) in block.rows.iter().enumerate() {
        let out = &mut gathered[a * q..(a + 1) * q];
        for (o, &c) in out.iter_mut().zip(&block.joints) {
            *o = data[c * m + r];
        }
    }
    let gram = &mut gram[..p * p];
    for a in 0..p {
        let row_a = &gathered[a * q..(a + 1) * q];
        for b in a..p {
            let row_b = &gathered[b * q..(b + 1) * q];
            let dot: f64 = row_a.iter().zip(row_b).map(|(x, y)| x * y).sum();
            gram[a * p + b] = dot;
            gram[b * p + a] = dot;
        }
    }
}

impl ThinSvd {
    /// Decomposes `j`, keeping singular values above `rank_tolerance · σ_max`.
    ///
    /// `blocks` are the Jacobian's independent blocks (see
    /// [`Skeleton::task_blocks`](crate::Skeleton::task_blocks); use
    /// [`TaskBlock::whole`] for a general matrix): no column has nonzeros in two
    /// blocks, so each block is decomposed on its own.
    ///
    /// # Errors
    /// [`NoConvergence`] when `j` holds non-finite values.
    pub fn compute(
        &mut self,
        j: &DMatrix<f64>,
        blocks: &[TaskBlock],
        rank_tolerance: f64,
    ) -> Result<(), NoConvergence> {
        let (m, n) = j.shape();
        self.rows = m;
        self.cols = n;
        self.rank = 0;
        if m == 0 || n == 0 {
            return Ok(());
        }
        self.by_blocks = false;
        if m > n && blocks.len() <= 1 {
            return self.compute_from_columns(j, rank_tolerance);
        }
        self.by_blocks = true;
        if self.sigma.len() < m || self.u.len() < m * m || self.v.len() < n * m {
            self.block_of.resize(m, 0);
            self.sigma.resize(m, 0.0);
            self.u.resize(m * m, 0.0);
            self.v.resize(n * m, 0.0);
        }
        // Every eigenpair of every group's JJᵀ block, uᵢ spread to full length m.
        let mut count = 0;
        let mut largest: f64 = 0.0;
        for (block_index, block) in blocks.iter().enumerate() {
            let rows = &block.rows;
            let p = rows.len();
            if self.gram.len() < p * p {
                self.gram.resize(p * p, 0.0);
            }
            gram_of_block(j, block, &mut self.gram, &mut self.gathered);
            self.eigen.compute(&self.gram, p)?;
            for i in 0..p {
                let lambda = self.eigen.values()[i].max(0.0);
                largest = largest.max(lambda);
                self.sigma[count] = lambda.sqrt();
                let u = &mut self.u[count * m..(count + 1) * m];
                u.fill(0.0);
                for (&r, &q) in rows.iter().zip(self.eigen.vector(i)) {
                    u[r] = q;
                }
                self.block_of[count] = block_index;
                count += 1;
            }
        }
        // Keep the directions above the tolerance, compacting in place.
        let threshold = (rank_tolerance * largest.sqrt()).max(1e-150);
        let mut kept = 0;
        for i in 0..count {
            if self.sigma[i] > threshold {
                if kept != i {
                    self.sigma[kept] = self.sigma[i];
                    self.block_of[kept] = self.block_of[i];
                    self.u.copy_within(i * m..(i + 1) * m, kept * m);
                }
                kept += 1;
            }
        }
        self.rank = kept;
        // vᵢ = Jᵀuᵢ/σᵢ over the rows and joints of uᵢ's block (zero elsewhere).
        let data = j.as_slice();
        self.v[..n * kept].fill(0.0);
        for i in 0..kept {
            let block = &blocks[self.block_of[i]];
            let inv = 1.0 / self.sigma[i];
            let u = &self.u[i * m..(i + 1) * m];
            let v = &mut self.v[i * n..(i + 1) * n];
            for &c in &block.joints {
                let col = &data[c * m..(c + 1) * m];
                let dot: f64 = block.rows.iter().map(|&r| col[r] * u[r]).sum();
                v[c] = dot * inv;
            }
        }
        Ok(())
    }

    /// The m > n path: eigen-decompose JᵀJ = V Σ² Vᵀ, then uᵢ = Jvᵢ/σᵢ.
    fn compute_from_columns(
        &mut self,
        j: &DMatrix<f64>,
        rank_tolerance: f64,
    ) -> Result<(), NoConvergence> {
        let (m, n) = j.shape();
        if self.gram.len() < n * n {
            self.gram.resize(n * n, 0.0);
        }
        if self.sigma.len() < n || self.u.len() < m * n || self.v.len() < n * n {
            self.sigma.resize(n, 0.0);
            self.u.resize(m * n, 0.0);
            self.v.resize(n * n, 0.0);
        }
        gram_cols(j, &mut self.gram);
        self.eigen.compute(&self.gram, n)?;
        let largest = self
            .eigen
            .values()
            .iter()
            .fold(0.0_f64, |acc, &x| acc.max(x));
        let threshold = (rank_tolerance * largest.max(0.0).sqrt()).max(1e-150);
        let data = j.as_slice();
        let mut kept = 0;
        for i in 0..n {
            let sigma = self.eigen.values()[i].max(0.0).sqrt();
            if sigma <= threshold {
                continue;
            }
            self.sigma[kept] = sigma;
            self.v[kept * n..(kept + 1) * n].copy_from_slice(self.eigen.vector(i));
            let (v, u) = (
                &self.v[kept * n..(kept + 1) * n],
                &mut self.u[kept * m..(kept + 1) * m],
            );
            u.fill(0.0);
            for (c, &vc) in v.iter().enumerate() {
                if vc == 0.0 {
                    continue;
                }
                for (out, x) in u.iter_mut().zip(&data[c * m..(c + 1) * m]) {
                    *out += x * vc;
                }
            }
            for out in u.iter_mut() {
                *out /= sigma;
            }
            kept += 1;
        }
        self.rank = kept;
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

    /// The joints (columns) where vᵢ can be nonzero, given the `blocks` passed to
    /// the last [`ThinSvd::compute`]; `None` means every joint.
    #[must_use]
    pub fn support<'b>(&self, i: usize, blocks: &'b [TaskBlock]) -> Option<&'b [usize]> {
        if !self.by_blocks {
            return None;
        }
        blocks.get(*self.block_of.get(i)?).map(|b| &b.joints[..])
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
            *seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
    }

    #[test]
    fn reconstructs_the_matrix_and_matches_nalgebra_singular_values() {
        let mut seed = 7;
        for &(m, n) in &[(3, 7), (12, 20), (9, 4), (15, 63), (1, 1)] {
            let j = random(m, n, &mut seed);
            let mut svd = ThinSvd::default();
            svd.compute(&j, &[TaskBlock::whole(m, n)], 1e-9)
                .expect("converges");
            assert_eq!(svd.rank(), m.min(n));
            let mut rebuilt = DMatrix::zeros(m, n);
            for i in 0..svd.rank() {
                let u = nalgebra::DVector::from_column_slice(svd.u(i));
                let v = nalgebra::DVector::from_column_slice(svd.v(i));
                rebuilt += &u * v.transpose() * svd.sigma(i);
            }
            assert!(
                (&rebuilt - &j).norm() < 1e-9,
                "{m}x{n}: {}",
                (&rebuilt - &j).norm()
            );
            let mut ours: Vec<f64> = (0..svd.rank()).map(|i| svd.sigma(i)).collect();
            let mut reference: Vec<f64> = j
                .clone()
                .svd(false, false)
                .singular_values
                .iter()
                .copied()
                .collect();
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
        svd.compute(&j, &[TaskBlock::whole(3, 4)], 1e-6)
            .expect("converges");
        assert_eq!(svd.rank(), 2);
    }
}
