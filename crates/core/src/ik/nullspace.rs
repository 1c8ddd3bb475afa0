//! PODA's redundancy resolution (Girard & Maciejewski 1985, eq. 6):
//! Δθ = J⁺Δx + (I − J⁺J)z with z = −k∇H, H = Σᵢ αᵢ(θᵢ − θcᵢ)², the center
//! angles θc and gains α the animator sets. (I − J⁺J) = I − Σᵢ vᵢvᵢᵀ projects z
//! onto the null space, so the term moves joints toward their centers without
//! moving the effectors, to first order.

use super::svd::ThinSvd;

/// Adds (I − Σᵢ vᵢvᵢᵀ) z to `step`, where z is in `gradient` (it is overwritten
/// with the projected vector).
pub fn add_null_space(svd: &ThinSvd, gradient: &mut [f64], step: &mut [f64]) {
    for i in 0..svd.rank() {
        let v = svd.v(i);
        let dot: f64 = v.iter().zip(gradient.iter()).map(|(x, y)| x * y).sum();
        for (g, x) in gradient.iter_mut().zip(v) {
            *g -= dot * x;
        }
    }
    for (out, g) in step.iter_mut().zip(gradient.iter()) {
        *out += g;
    }
}
