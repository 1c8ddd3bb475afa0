//! Damped least squares (She 2006 §4.4.3): Δθ = Jᵀ(JJᵀ + λ²I)⁻¹e, solved with a
//! Cholesky factorisation of the m×m damped Gram matrix (or of JᵀJ + λ²I when
//! m > n: Δθ = (JᵀJ + λ²I)⁻¹Jᵀe, the same vector), without forming an inverse.

use nalgebra::DMatrix;

use super::svd::{gram_cols, gram_of_block};
use crate::skeleton::TaskBlock;

/// Workspace for the DLS solve.
#[derive(Clone, Debug, Default)]
pub struct DlsWorkspace {
    gram: Vec<f64>,
    rhs: Vec<f64>,
    gathered: Vec<f64>,
}

/// In-place Cholesky factorisation of the symmetric positive definite column-major
/// `n × n` matrix `a` (lower triangle). Returns false if it is not positive definite.
fn cholesky(a: &mut [f64], n: usize) -> bool {
    for j in 0..n {
        let mut diagonal = a[j + j * n];
        for k in 0..j {
            diagonal -= a[j + k * n] * a[j + k * n];
        }
        if diagonal <= 0.0 || !diagonal.is_finite() {
            return false;
        }
        let root = diagonal.sqrt();
        a[j + j * n] = root;
        for i in j + 1..n {
            let mut sum = a[i + j * n];
            for k in 0..j {
                sum -= a[i + k * n] * a[j + k * n];
            }
            a[i + j * n] = sum / root;
        }
    }
    true
}

/// Solves L Lᵀ x = b in place (`b` becomes x) with the factor from [`cholesky`].
fn cholesky_solve(l: &[f64], n: usize, b: &mut [f64]) {
    for i in 0..n {
        let mut sum = b[i];
        for k in 0..i {
            sum -= l[i + k * n] * b[k];
        }
        b[i] = sum / l[i + i * n];
    }
    for i in (0..n).rev() {
        let mut sum = b[i];
        for k in i + 1..n {
            sum -= l[k + i * n] * b[k];
        }
        b[i] = sum / l[i + i * n];
    }
}

impl DlsWorkspace {
    /// Writes the DLS step with damping `lambda` into `step`. `blocks` are the
    /// Jacobian's independent blocks; each is solved on its own, which gives the
    /// same step since no column spans two blocks.
    /// Returns false (and a zero step) if a damped system could not be factored
    /// (non-finite input).
    pub fn step(
        &mut self,
        jacobian: &DMatrix<f64>,
        blocks: &[TaskBlock],
        error: &[f64],
        lambda: f64,
        step: &mut [f64],
    ) -> bool {
        let (m, n) = jacobian.shape();
        let lambda2 = lambda * lambda;
        step.fill(0.0);
        if m == 0 || n == 0 {
            return true;
        }
        if m > n && blocks.len() <= 1 {
            return self.step_from_columns(jacobian, error, lambda2, step);
        }
        for block in blocks {
            let rows = &block.rows;
            let p = rows.len();
            if self.gram.len() < p * p {
                self.gram.resize(p * p, 0.0);
            }
            if self.rhs.len() < p {
                self.rhs.resize(p, 0.0);
            }
            gram_of_block(jacobian, block, &mut self.gram, &mut self.gathered);
            for i in 0..p {
                self.gram[i + i * p] += lambda2;
            }
            if !cholesky(&mut self.gram[..p * p], p) {
                step.fill(0.0);
                return false;
            }
            let rhs = &mut self.rhs[..p];
            for (out, &r) in rhs.iter_mut().zip(rows) {
                *out = error[r];
            }
            cholesky_solve(&self.gram[..p * p], p, rhs);
            // Δθ += J[rows, :]ᵀ y.
            // Δθ[joints] = Bᵀy with B row-major in `gathered`.
            let q = block.joints.len();
            for &c in &block.joints {
                step[c] = 0.0;
            }
            for (row, &y) in self.gathered[..p * q]
                .chunks_exact(q.max(1))
                .zip(rhs.iter())
            {
                for (&c, &x) in block.joints.iter().zip(row) {
                    step[c] += x * y;
                }
            }
        }
        true
    }

    /// The m > n form: Δθ = (JᵀJ + λ²I)⁻¹Jᵀe.
    fn step_from_columns(
        &mut self,
        jacobian: &DMatrix<f64>,
        error: &[f64],
        lambda2: f64,
        step: &mut [f64],
    ) -> bool {
        let (m, n) = jacobian.shape();
        if self.gram.len() < n * n {
            self.gram.resize(n * n, 0.0);
        }
        gram_cols(jacobian, &mut self.gram);
        for i in 0..n {
            self.gram[i + i * n] += lambda2;
        }
        if !cholesky(&mut self.gram[..n * n], n) {
            step.fill(0.0);
            return false;
        }
        let data = jacobian.as_slice();
        for (c, out) in step.iter_mut().enumerate() {
            *out = data[c * m..(c + 1) * m]
                .iter()
                .zip(error)
                .map(|(x, y)| x * y)
                .sum();
        }
        cholesky_solve(&self.gram[..n * n], n, step);
        true
    }
}
