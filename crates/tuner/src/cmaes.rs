//! CMA-ES, the covariance matrix adaptation evolution strategy (Hansen,
//! "The CMA Evolution Strategy: A Tutorial", 2016): (μ/μ_w, λ) selection,
//! cumulative step-size adaptation, rank-one and rank-μ covariance updates,
//! with the tutorial's default constants.
//!
//! Written here rather than taken from a crate: the maintained ones
//! (`cmaes`, `argmin`'s) draw normals and decompose the covariance with the
//! platform's maths and threads, and a seeded tune must give the same bits
//! natively and in wasm. This one uses the portable `ln`, `exp` and
//! `sin_cos`, and samples through the Cholesky factor `A` of the covariance
//! (`C = A·Aᵀ`) in place of its eigen-decomposition: only `+ − × ÷ √`, exact
//! on every IEEE platform. The step-size path then uses `A⁻¹·y = z`, which
//! is N(0, I) under random selection just as the tutorial's `C^{-½}·y` is.

use gaitlab_core::portable::Portable;

use crate::rng::Rng;

/// The strategy's state: mean, step size, paths and covariance.
#[derive(Clone, Debug)]
pub struct Cmaes {
    n: usize,
    /// Offspring per generation λ.
    pub lambda: usize,
    mu: usize,
    weights: Vec<f64>,
    mu_eff: f64,
    c_sigma: f64,
    d_sigma: f64,
    c_c: f64,
    c_1: f64,
    c_mu: f64,
    chi_n: f64,
    mean: Vec<f64>,
    sigma: f64,
    p_sigma: Vec<f64>,
    p_c: Vec<f64>,
    /// Covariance, row-major n × n.
    cov: Vec<f64>,
    /// Its lower Cholesky factor, row-major.
    chol: Vec<f64>,
    generation: u32,
    rng: Rng,
    /// Last generation's standard-normal draws `z` and steps `y = A·z`.
    z: Vec<Vec<f64>>,
    y: Vec<Vec<f64>>,
}

impl Cmaes {
    /// A strategy around `mean` with step size `sigma`, drawing from `seed`.
    ///
    /// # Panics
    /// Never for `mean` non-empty; an empty `mean` is a programming error.
    #[must_use]
    pub fn new(mean: &[f64], sigma: f64, seed: u64) -> Self {
        let n = mean.len().max(1);
        let nf = n as f64;
        let lambda = 4 + (3.0 * nf.pln()).floor() as usize;
        let mu = lambda / 2;
        let raw: Vec<f64> = (1..=mu)
            .map(|i| (mu as f64 + 0.5).pln() - (i as f64).pln())
            .collect();
        let total: f64 = raw.iter().sum();
        let weights: Vec<f64> = raw.iter().map(|w| w / total).collect();
        let mu_eff = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
        let c_sigma = (mu_eff + 2.0) / (nf + mu_eff + 5.0);
        let d_sigma = 1.0 + 2.0 * (((mu_eff - 1.0) / (nf + 1.0)).sqrt() - 1.0).max(0.0) + c_sigma;
        let c_c = (4.0 + mu_eff / nf) / (nf + 4.0 + 2.0 * mu_eff / nf);
        let c_1 = 2.0 / ((nf + 1.3).powi(2) + mu_eff);
        let c_mu =
            (1.0 - c_1).min(2.0 * (mu_eff - 2.0 + 1.0 / mu_eff) / ((nf + 2.0).powi(2) + mu_eff));
        let chi_n = nf.sqrt() * (1.0 - 1.0 / (4.0 * nf) + 1.0 / (21.0 * nf * nf));
        let mut identity = vec![0.0; n * n];
        for i in 0..n {
            identity[i * n + i] = 1.0;
        }
        Self {
            n,
            lambda,
            mu,
            weights,
            mu_eff,
            c_sigma,
            d_sigma,
            c_c,
            c_1,
            c_mu,
            chi_n,
            mean: mean.to_vec(),
            sigma,
            p_sigma: vec![0.0; n],
            p_c: vec![0.0; n],
            cov: identity.clone(),
            chol: identity,
            generation: 0,
            rng: Rng::new(seed),
            z: Vec::new(),
            y: Vec::new(),
        }
    }

    /// The current mean (the best estimate of the optimum).
    #[must_use]
    pub fn mean(&self) -> &[f64] {
        &self.mean
    }

    /// The current step size σ.
    #[must_use]
    pub fn sigma(&self) -> f64 {
        self.sigma
    }

    /// Generations told so far.
    #[must_use]
    pub fn generation(&self) -> u32 {
        self.generation
    }

    /// The next generation's λ candidates `x = m + σ·A·z`.
    pub fn ask(&mut self) -> Vec<Vec<f64>> {
        let n = self.n;
        self.z = (0..self.lambda)
            .map(|_| (0..n).map(|_| self.rng.normal()).collect())
            .collect();
        self.y = self
            .z
            .iter()
            .map(|z| {
                (0..n)
                    .map(|i| (0..=i).map(|j| self.chol[i * n + j] * z[j]).sum())
                    .collect()
            })
            .collect();
        self.y
            .iter()
            .map(|y: &Vec<f64>| {
                self.mean
                    .iter()
                    .zip(y)
                    .map(|(m, yi)| m + self.sigma * yi)
                    .collect()
            })
            .collect()
    }

    /// Update from the costs of the candidates [`Cmaes::ask`] gave, in the
    /// same order (lower is better; a NaN ranks last).
    pub fn tell(&mut self, costs: &[f64]) {
        let n = self.n;
        let mut order: Vec<usize> = (0..self.z.len().min(costs.len())).collect();
        let key = |i: usize| {
            if costs[i].is_nan() {
                f64::INFINITY
            } else {
                costs[i]
            }
        };
        order.sort_by(|&a, &b| key(a).total_cmp(&key(b)).then(a.cmp(&b)));
        let best = &order[..self.mu.min(order.len())];
        let weighted = |v: &[Vec<f64>]| -> Vec<f64> {
            (0..n)
                .map(|i| {
                    best.iter()
                        .zip(&self.weights)
                        .map(|(&k, w)| w * v[k][i])
                        .sum()
                })
                .collect()
        };
        let y_w = weighted(&self.y);
        let z_w = weighted(&self.z);
        for (m, y) in self.mean.iter_mut().zip(&y_w) {
            *m += self.sigma * y;
        }
        let cs = (self.c_sigma * (2.0 - self.c_sigma) * self.mu_eff).sqrt();
        for (p, z) in self.p_sigma.iter_mut().zip(&z_w) {
            *p = (1.0 - self.c_sigma) * *p + cs * z;
        }
        self.generation += 1;
        let norm = self.p_sigma.iter().map(|p| p * p).sum::<f64>().sqrt();
        let decay = 1.0 - (1.0 - self.c_sigma).powi(2 * self.generation as i32);
        let h_sigma = norm / decay.sqrt() < (1.4 + 2.0 / (n as f64 + 1.0)) * self.chi_n;
        let h = if h_sigma { 1.0 } else { 0.0 };
        let cc = (self.c_c * (2.0 - self.c_c) * self.mu_eff).sqrt();
        for (p, y) in self.p_c.iter_mut().zip(&y_w) {
            *p = (1.0 - self.c_c) * *p + h * cc * y;
        }
        let lost = (1.0 - h) * self.c_c * (2.0 - self.c_c);
        for i in 0..n {
            for j in 0..=i {
                let rank_mu: f64 = best
                    .iter()
                    .zip(&self.weights)
                    .map(|(&k, w)| w * self.y[k][i] * self.y[k][j])
                    .sum();
                let c = (1.0 - self.c_1 - self.c_mu) * self.cov[i * n + j]
                    + self.c_1 * (self.p_c[i] * self.p_c[j] + lost * self.cov[i * n + j])
                    + self.c_mu * rank_mu;
                self.cov[i * n + j] = c;
                self.cov[j * n + i] = c;
            }
        }
        self.sigma *= ((self.c_sigma / self.d_sigma) * (norm / self.chi_n - 1.0)).pexp();
        if !cholesky(&self.cov, n, &mut self.chol) {
            // Numerically lost positive definiteness: start the shape afresh.
            self.cov.fill(0.0);
            self.chol.fill(0.0);
            for i in 0..n {
                self.cov[i * n + i] = 1.0;
                self.chol[i * n + i] = 1.0;
            }
        }
    }
}

/// The lower Cholesky factor of the symmetric `a` (row-major n × n) into
/// `l`; `false` when `a` is not positive definite.
fn cholesky(a: &[f64], n: usize, l: &mut [f64]) -> bool {
    l.fill(0.0);
    for i in 0..n {
        for j in 0..=i {
            let s: f64 = (0..j).map(|k| l[i * n + k] * l[j * n + k]).sum();
            if i == j {
                let d = a[i * n + i] - s;
                if !(d > 0.0 && d.is_finite()) {
                    return false;
                }
                l[i * n + i] = d.sqrt();
            } else {
                l[i * n + j] = (a[i * n + j] - s) / l[j * n + j];
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cholesky_factors_a_positive_matrix_and_refuses_others() {
        let a = [4.0, 2.0, 2.0, 3.0];
        let mut l = [0.0; 4];
        assert!(cholesky(&a, 2, &mut l));
        assert_eq!(l, [2.0, 0.0, 1.0, 2.0_f64.sqrt()]);
        assert!(!cholesky(&[1.0, 2.0, 2.0, 1.0], 2, &mut l));
    }

    #[test]
    fn the_default_constants_are_the_tutorials() {
        // n = 10: λ = 4 + ⌊3 ln 10⌋ = 10, μ = 5, weights sum to 1.
        let es = Cmaes::new(&[0.0; 10], 0.5, 1);
        assert_eq!((es.lambda, es.mu), (10, 5));
        assert!((es.weights.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        assert!(es.weights.windows(2).all(|w| w[0] > w[1]));
        assert!((es.mu_eff - 3.1672).abs() < 1e-3, "{}", es.mu_eff);
    }
}
