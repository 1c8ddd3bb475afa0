//! Pseudoinverse step Δθ = J⁺e = Σᵢ σᵢ⁻¹ vᵢ uᵢᵀ e over the singular values above
//! the rank tolerance (She 2006 §4.4.2 and §4.4.4; PODA eq. 4–5: for a full-rank
//! J with m < n this equals Jᵀ(JJᵀ)⁻¹e), and the damped variant of DLS
//! written in the same basis, Σᵢ σᵢ/(σᵢ² + λ²) vᵢ uᵢᵀ e (§4.4.4).

use super::svd::ThinSvd;

/// Writes Σᵢ f(σᵢ) vᵢ (uᵢᵀ e) into `step`, where f is `filter`.
pub fn filtered_step(svd: &ThinSvd, error: &[f64], step: &mut [f64], filter: impl Fn(f64) -> f64) {
    step.fill(0.0);
    for i in 0..svd.rank() {
        let alpha: f64 = svd.u(i).iter().zip(error).map(|(x, y)| x * y).sum();
        let scale = filter(svd.sigma(i)) * alpha;
        for (out, v) in step.iter_mut().zip(svd.v(i)) {
            *out += scale * v;
        }
    }
}

/// The pseudoinverse step J⁺e.
pub fn pinv_step(svd: &ThinSvd, error: &[f64], step: &mut [f64]) {
    filtered_step(svd, error, step, |sigma| 1.0 / sigma);
}
