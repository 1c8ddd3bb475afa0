//! Damped least squares (She 2006 §4.4.3): Δθ = Jᵀ(JJᵀ + λ²I)⁻¹e, solved with a
//! Cholesky factorisation of the m×m damped Gram matrix (or of JᵀJ + λ²I when
//! m > n: Δθ = (JᵀJ + λ²I)⁻¹Jᵀe, the same vector), without forming an inverse.

use nalgebra::DMatrix;

use super::svd::{gram_cols, gram_rows};

/// Workspace for the DLS solve.
#[derive(Clone, Debug, Default)]
pub struct DlsWorkspace {
    gram: Vec<f64>,
    rhs: Vec<f64>,
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
    /// Writes the DLS step with damping `lambda` into `step`. Returns false (and a
    /// zero step) if the damped system could not be factored (non-finite input).
    pub fn step(&mut self, jacobian: &DMatrix<f64>, error: &[f64], lambda: f64, step: &mut [f64]) -> bool {
        let (m, n) = jacobian.shape();
        let data = jacobian.as_slice();
        let side = m.min(n);
        if self.gram.len() < side * side {
            self.gram.resize(side * side, 0.0);
        }
        if self.rhs.len() < side {
            self.rhs.resize(side, 0.0);
        }
        let lambda2 = lambda * lambda;
        let rhs = &mut self.rhs[..side];
        if m <= n {
            gram_rows(jacobian, &mut self.gram);
            rhs.copy_from_slice(&error[..m]);
        } else {
            gram_cols(jacobian, &mut self.gram);
            for (c, out) in rhs.iter_mut().enumerate() {
                *out = data[c * m..(c + 1) * m].iter().zip(error).map(|(x, y)| x * y).sum();
            }
        }
        for i in 0..side {
            self.gram[i + i * side] += lambda2;
        }
        if !cholesky(&mut self.gram[..side * side], side) {
            step.fill(0.0);
            return false;
        }
        cholesky_solve(&self.gram[..side * side], side, rhs);
        if m <= n {
            for (c, out) in step.iter_mut().enumerate() {
                *out = data[c * m..(c + 1) * m].iter().zip(rhs.iter()).map(|(x, y)| x * y).sum();
            }
        } else {
            step[..n].copy_from_slice(rhs);
        }
        true
    }
}
