//! Selectively damped least squares (Buss & Kim 2005, as summarised in She 2006
//! §4.4.5): each singular direction gets its own clamp γᵢ = min(1, Nᵢ/Mᵢ)·γmax,
//! where Nᵢ = Σℓ ‖uᵢ restricted to effector ℓ‖ and
//! Mᵢ = σᵢ⁻¹ Σⱼ |vⱼᵢ| Σℓ ‖∂sℓ/∂θⱼ‖; φᵢ = ClampMaxAbs(σᵢ⁻¹αᵢvᵢ, γᵢ) with
//! αᵢ = uᵢᵀe, and Δθ = ClampMaxAbs(Σφᵢ, γmax). γmax is π/4 (the thesis
//! misprints it as 4/π).

use nalgebra::DMatrix;

use super::svd::ThinSvd;
use crate::skeleton::TaskBlock;

/// Scales `values` so that its largest magnitude is at most `limit`.
pub fn clamp_max_abs(values: &mut [f64], limit: f64) {
    let largest = values.iter().fold(0.0_f64, |acc, x| acc.max(x.abs()));
    if largest > limit && largest > 0.0 {
        let scale = limit / largest;
        for x in values.iter_mut() {
            *x *= scale;
        }
    }
}

/// SDLS's clamp γᵢ = min(1, Nᵢ/Mᵢ)·γmax of direction i, from Nᵢ, σᵢ and
/// `m_sigma` = Mᵢσᵢ = Σⱼ |vⱼᵢ| ρⱼ (γmax when Mᵢ is 0).
#[must_use]
pub(crate) fn direction_clamp(n_i: f64, m_sigma: f64, sigma: f64, gamma_max: f64) -> f64 {
    let m_i = m_sigma / sigma;
    if m_i > 0.0 {
        (n_i / m_i).min(1.0) * gamma_max
    } else {
        gamma_max
    }
}

/// Σℓ ‖xℓ‖ over the 3-row blocks of `x` (one block per effector position or
/// orientation): Nᵢ for x = uᵢ, ρⱼ for x = column j of J.
#[must_use]
pub(crate) fn block_norm_sum(x: &[f64]) -> f64 {
    x.chunks_exact(3)
        .map(|b| (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt())
        .sum()
}

/// Writes ρⱼ = Σℓ ‖∂sℓ/∂θⱼ‖ for every column j of `jacobian` into `rho`.
pub(crate) fn fill_rho(jacobian: &DMatrix<f64>, rho: &mut Vec<f64>) {
    let (m, n) = jacobian.shape();
    rho.resize(n, 0.0);
    for (col, out) in jacobian
        .as_slice()
        .chunks_exact(m.max(1))
        .zip(rho.iter_mut())
    {
        *out = block_norm_sum(col);
    }
}

/// One singular direction's contribution φᵢ.
struct Direction<'a> {
    v: &'a [f64],
    sigma: f64,
    alpha: f64,
    n_i: f64,
    gamma_max: f64,
}

impl Direction<'_> {
    /// Adds φᵢ = ClampMaxAbs(σᵢ⁻¹αᵢvᵢ, γᵢ) to `step`, visiting only `joints`
    /// (vᵢ is zero elsewhere).
    fn add_to(&self, joints: impl Iterator<Item = usize> + Clone, rho: &[f64], step: &mut [f64]) {
        // One pass for Mᵢσᵢ = Σⱼ |vⱼᵢ| ρⱼ and max |vⱼᵢ|.
        let mut m_sigma = 0.0;
        let mut v_max: f64 = 0.0;
        for j in joints.clone() {
            let x = self.v[j].abs();
            m_sigma += x * rho[j];
            v_max = v_max.max(x);
        }
        let gamma = direction_clamp(self.n_i, m_sigma, self.sigma, self.gamma_max);
        // ClampMaxAbs of a scaled vector is one scale factor.
        let mut scale = self.alpha / self.sigma;
        let largest = scale.abs() * v_max;
        if largest > gamma {
            scale *= gamma / largest;
        }
        for j in joints {
            step[j] += scale * self.v[j];
        }
    }
}

/// Workspace for SDLS: per-joint ρⱼ.
#[derive(Clone, Debug, Default)]
pub struct SdlsWorkspace {
    rho: Vec<f64>,
}

impl SdlsWorkspace {
    /// Writes the SDLS step into `step`. The rows of `jacobian` come in 3-row
    /// blocks (one per effector position, one more per effector orientation);
    /// each block counts as one "end effector" in Nᵢ and ρⱼ.
    pub fn step(
        &mut self,
        jacobian: &DMatrix<f64>,
        svd: &ThinSvd,
        blocks: &[TaskBlock],
        error: &[f64],
        gamma_max: f64,
        step: &mut [f64],
    ) {
        let n = jacobian.ncols();
        fill_rho(jacobian, &mut self.rho);
        step.fill(0.0);
        for i in 0..svd.rank() {
            let sigma = svd.sigma(i);
            let u = svd.u(i);
            let v = svd.v(i);
            let alpha: f64 = u.iter().zip(error).map(|(x, y)| x * y).sum();
            let n_i = block_norm_sum(u);
            let direction = Direction {
                v,
                sigma,
                alpha,
                n_i,
                gamma_max,
            };
            match svd.support(i, blocks) {
                Some(joints) => direction.add_to(joints.iter().copied(), &self.rho, step),
                None => direction.add_to(0..n, &self.rho, step),
            }
        }
        clamp_max_abs(step, gamma_max);
    }
}
