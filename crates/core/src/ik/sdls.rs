//! Selectively damped least squares (Buss & Kim 2005, as summarised in She 2006
//! §4.4.5): each singular direction gets its own clamp γᵢ = min(1, Nᵢ/Mᵢ)·γmax,
//! where Nᵢ = Σℓ ‖uᵢ restricted to effector ℓ‖ and
//! Mᵢ = σᵢ⁻¹ Σⱼ |vⱼᵢ| Σℓ ‖∂sℓ/∂θⱼ‖; φᵢ = ClampMaxAbs(σᵢ⁻¹αᵢvᵢ, γᵢ) with
//! αᵢ = uᵢᵀe, and Δθ = ClampMaxAbs(Σφᵢ, γmax). γmax is π/4 (the thesis
//! misprints it as 4/π).

use nalgebra::DMatrix;

use super::svd::ThinSvd;

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

/// Workspace for SDLS: per-joint ρⱼ and one direction's φᵢ.
#[derive(Clone, Debug, Default)]
pub struct SdlsWorkspace {
    rho: Vec<f64>,
    phi: Vec<f64>,
}

impl SdlsWorkspace {
    /// Writes the SDLS step into `step`. The rows of `jacobian` come in 3-row
    /// blocks (one per effector position, one more per effector orientation);
    /// each block counts as one "end effector" in Nᵢ and ρⱼ.
    pub fn step(
        &mut self,
        jacobian: &DMatrix<f64>,
        svd: &ThinSvd,
        error: &[f64],
        gamma_max: f64,
        step: &mut [f64],
    ) {
        let (m, n) = jacobian.shape();
        let data = jacobian.as_slice();
        self.rho.resize(n, 0.0);
        self.phi.resize(n, 0.0);
        // ρⱼ = Σℓ ‖∂sℓ/∂θⱼ‖ over the 3-row blocks of column j.
        for (c, rho) in self.rho.iter_mut().enumerate() {
            let col = &data[c * m..(c + 1) * m];
            *rho = col
                .chunks_exact(3)
                .map(|b| (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt())
                .sum();
        }
        step.fill(0.0);
        for i in 0..svd.rank() {
            let sigma = svd.sigma(i);
            let u = svd.u(i);
            let v = svd.v(i);
            let alpha: f64 = u.iter().zip(error).map(|(x, y)| x * y).sum();
            let n_i: f64 = u
                .chunks_exact(3)
                .map(|b| (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]).sqrt())
                .sum();
            let m_i: f64 = v
                .iter()
                .zip(&self.rho)
                .map(|(x, r)| x.abs() * r)
                .sum::<f64>()
                / sigma;
            let gamma = if m_i > 0.0 {
                (n_i / m_i).min(1.0) * gamma_max
            } else {
                gamma_max
            };
            let scale = alpha / sigma;
            for (p, x) in self.phi.iter_mut().zip(v) {
                *p = scale * x;
            }
            clamp_max_abs(&mut self.phi, gamma);
            for (out, p) in step.iter_mut().zip(&self.phi) {
                *out += p;
            }
        }
        clamp_max_abs(step, gamma_max);
    }
}
