//! Jacobian transpose (She 2006 §4.4.1): Δθ = α Jᵀe. Buss 2004's step length
//! α = ⟨e, JJᵀe⟩ / ‖JJᵀe‖² brings the predicted change J Δθ closest to e; the
//! thesis prints α = Δs·Δt / (2|Δt|²) with Δs = e and Δt = JJᵀe, half of it.
//! The caller picks the factor on Buss's α ([`TransposeAlpha`](super::TransposeAlpha)).

use nalgebra::DMatrix;

/// Writes the transpose step for `jacobian` and task error `error` into `step`,
/// with α = `alpha_factor` · ⟨e, JJᵀe⟩ / ‖JJᵀe‖² (½ the thesis', 1 Buss's),
/// using `scratch` (length m) for JJᵀe.
pub fn transpose_step(
    jacobian: &DMatrix<f64>,
    error: &[f64],
    alpha_factor: f64,
    scratch: &mut [f64],
    step: &mut [f64],
) {
    let alpha = transpose_alpha(jacobian, error, alpha_factor, scratch, step);
    for g in step.iter_mut() {
        *g *= alpha;
    }
}

/// The transpose method's α = `alpha_factor` · ⟨e, JJᵀe⟩ / ‖JJᵀe‖² for
/// `error` (0 when JJᵀe vanishes), leaving Jᵀe in `gradient` (length n) and
/// JJᵀe in `scratch` (length m).
pub fn transpose_alpha(
    jacobian: &DMatrix<f64>,
    error: &[f64],
    alpha_factor: f64,
    scratch: &mut [f64],
    gradient: &mut [f64],
) -> f64 {
    let step = gradient;
    let m = jacobian.nrows();
    let data = jacobian.as_slice();
    // g = Jᵀ e
    for (c, out) in step.iter_mut().enumerate() {
        let col = &data[c * m..(c + 1) * m];
        *out = col.iter().zip(error).map(|(x, y)| x * y).sum();
    }
    // h = J g
    let scratch = &mut scratch[..m];
    scratch.fill(0.0);
    for (c, &g) in step.iter().enumerate() {
        if g == 0.0 {
            continue;
        }
        let col = &data[c * m..(c + 1) * m];
        for (out, x) in scratch.iter_mut().zip(col) {
            *out += x * g;
        }
    }
    let numerator: f64 = error.iter().zip(scratch.iter()).map(|(x, y)| x * y).sum();
    let denominator: f64 = scratch.iter().map(|x| x * x).sum();
    if denominator > 1e-300 {
        alpha_factor * numerator / denominator
    } else {
        0.0
    }
}
