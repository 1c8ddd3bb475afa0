//! The Jacobian's singular values and each method's gain along them
//! ([`Spectrum`], She 2006 §4.4 read through the SVD): the singular values
//! agree with nalgebra's SVD of the same J, and each method's gain at σᵢ is
//! what its solver actually does to an error along uᵢ.

mod common;

use common::{Rng, random_tree};
use gaitlab_core::ik::{GainLaw, IkOptions, IkSolver, Method, Spectrum, Targets, TransposeAlpha};
use gaitlab_core::preset::load_bundled;
use gaitlab_core::{Kinematics, Pose, RootTransform, Skeleton};
use glam::{DMat3, DVec3};

/// The she-2006 human and three random trees (one and several Jacobian
/// blocks), each at a random pose within ±0.8 rad of rest.
fn cases() -> Vec<(String, Skeleton, Vec<f64>)> {
    let mut rng = Rng::new(11);
    let human = load_bundled("she-2006")
        .expect("bundled")
        .expect("valid")
        .skeleton
        .clone();
    let mut out = vec![];
    let values = |rng: &mut Rng, s: &Skeleton| -> Vec<f64> {
        s.joints()
            .iter()
            .map(|j| j.clamp(j.rest + rng.range(-0.8, 0.8)))
            .collect()
    };
    let pose = values(&mut rng, &human);
    out.push(("she-2006 human".to_owned(), human, pose));
    for (n, k) in [(12, 3), (20, 4), (9, 1)] {
        let tree = random_tree(&mut rng, n, k, None, false);
        let pose = values(&mut rng, &tree);
        out.push((format!("random tree {n} joints {k} effectors"), tree, pose));
    }
    out
}

fn effectors(skeleton: &Skeleton, values: &[f64]) -> Vec<DVec3> {
    Kinematics::of(
        skeleton,
        &Pose {
            root: RootTransform::default(),
            joints: values.to_vec(),
        },
    )
    .effector_position
}

/// Targets at the effectors moved by `shift` (3 rows per effector).
fn targets_shifted(at: &[DVec3], shift: &[f64]) -> Targets {
    Targets {
        position: at
            .iter()
            .zip(shift.chunks_exact(3))
            .map(|(p, d)| *p + DVec3::new(d[0], d[1], d[2]))
            .collect(),
        rotation: vec![DMat3::IDENTITY; at.len()],
    }
}

#[test]
fn singular_values_equal_nalgebras_svd_of_the_same_jacobian() {
    for (name, skeleton, values) in cases() {
        assert!(
            skeleton.effectors().iter().all(|e| !e.orientation),
            "{name}"
        );
        let at = effectors(&skeleton, &values);
        let mut solver = IkSolver::new(&skeleton, IkOptions::default());
        let mut pose = values.clone();
        let shift = vec![0.01; skeleton.task_rows()];
        solver.iterate(
            &skeleton,
            &RootTransform::default(),
            &mut pose,
            &targets_shifted(&at, &shift),
        );
        let mut spectrum = Spectrum::default();
        solver.spectrum(0.01, &mut spectrum).expect("finite");
        let mut reference: Vec<f64> = solver
            .jacobian()
            .clone()
            .svd(false, false)
            .singular_values
            .iter()
            .copied()
            .collect();
        reference.sort_by(|a, b| b.total_cmp(a));
        let ours: Vec<f64> = spectrum.directions().iter().map(|d| d.sigma).collect();
        assert_eq!(
            ours.len() + spectrum.zero_count(),
            reference.len(),
            "{name}"
        );
        for (a, b) in ours.iter().zip(&reference) {
            assert!((a - b).abs() < 1e-9, "{name}: σ {a} against nalgebra's {b}");
        }
        for b in &reference[ours.len()..] {
            assert!(*b < 1e-7 * reference[0], "{name}: a dropped σ {b}");
        }
        let condition = spectrum.condition().expect("nonempty");
        if spectrum.zero_count() == 0 {
            let expected = reference[0] / reference[reference.len() - 1];
            assert!(
                (condition - expected).abs() <= 1e-9 * expected,
                "{name}: {condition} against {expected}"
            );
        } else {
            assert!(condition.is_infinite(), "{name}");
        }
        println!(
            "{name}: {} singular values, σ {:.4e} … {:.4e}, condition {condition:.3e}",
            reference.len(),
            reference[0],
            reference[reference.len() - 1]
        );
    }
}

/// Every method, with and without `max_step` clamping transpose and DLS, at an
/// error of 1 cm and of 1 m along each direction (the clamps bind at 1 m).
fn settings() -> Vec<IkOptions> {
    let mut out = vec![];
    for method in [Method::Transpose, Method::Pinv, Method::Dls, Method::Sdls] {
        for clamp_every_method in [false, true] {
            for transpose_alpha in TransposeAlpha::ALL {
                if method != Method::Transpose && transpose_alpha != TransposeAlpha::Thesis {
                    continue;
                }
                out.push(IkOptions {
                    method,
                    clamp_every_method,
                    transpose_alpha,
                    enforce_limits: false,
                    ..IkOptions::default()
                });
            }
        }
    }
    out
}

#[test]
fn each_methods_gain_is_its_solvers_response_along_each_direction() {
    let mut checked = 0;
    let mut clamped = 0;
    for (name, skeleton, values) in cases() {
        let at = effectors(&skeleton, &values);
        let root = RootTransform::default();
        // The directions of J at this pose (the same for every method).
        let mut probe = IkSolver::new(&skeleton, IkOptions::default());
        probe.iterate(
            &skeleton,
            &root,
            &mut values.clone(),
            &targets_shifted(&at, &vec![0.0; skeleton.task_rows()]),
        );
        let mut directions = Spectrum::default();
        probe.spectrum(1.0, &mut directions).expect("finite");
        for options in settings() {
            for amplitude in [0.01, 1.0] {
                for i in 0..directions.directions().len() {
                    let u = directions.u(i).expect("direction");
                    let shift: Vec<f64> = u.iter().map(|x| x * amplitude).collect();
                    let mut solver = IkSolver::new(&skeleton, options.clone());
                    let mut pose = values.clone();
                    solver.iterate(&skeleton, &root, &mut pose, &targets_shifted(&at, &shift));
                    let step = solver.last_step().to_vec();
                    let mut spectrum = Spectrum::default();
                    solver.spectrum(amplitude, &mut spectrum).expect("finite");
                    let sigma = spectrum.directions()[i].sigma;
                    let v = spectrum.v(i).expect("direction");
                    // The same decomposition: the same direction i.
                    let same: f64 = spectrum
                        .u(i)
                        .expect("direction")
                        .iter()
                        .zip(u)
                        .map(|(a, b)| a * b)
                        .sum();
                    assert!((same.abs() - 1.0).abs() < 1e-9, "{name}: uᵢ moved");
                    let sign = same.signum();
                    let response: f64 =
                        sign * v.iter().zip(&step).map(|(a, b)| a * b).sum::<f64>() / amplitude;
                    let gain = spectrum.gain(i, sigma).expect("a Jacobian method");
                    let scale = gain.abs().max(1e-6);
                    assert!(
                        (response - gain).abs() <= 1e-7 * scale,
                        "{name}, {:?} clamp {} α {:?}, a {amplitude} m, direction {i} σ {sigma:.4e}: \
                         solver {response:.9e} against the curve's {gain:.9e}",
                        options.method,
                        options.clamp_every_method,
                        options.transpose_alpha,
                    );
                    // The step lies along vᵢ alone.
                    let off: f64 = step
                        .iter()
                        .zip(v)
                        .map(|(s, x)| (s - sign * response * amplitude * x).powi(2))
                        .sum::<f64>()
                        .sqrt();
                    let size: f64 = step.iter().map(|s| s * s).sum::<f64>().sqrt();
                    assert!(off <= 1e-7 * size.max(1e-9), "{name}: off vᵢ by {off:.3e}");
                    let formula = spectrum
                        .law()
                        .and_then(|law| law.formula(sigma))
                        .expect("formula");
                    if gain < formula * (1.0 - 1e-9) {
                        clamped += 1;
                    }
                    checked += 1;
                }
            }
        }
    }
    println!("{checked} directions checked, {clamped} of them clamped");
    assert!(checked > 300, "{checked}");
    assert!(clamped > 20, "the clamps were exercised: {clamped}");
}

#[test]
fn the_laws_formulas_are_the_textbook_curves() {
    let sigma: f64 = 0.05;
    let t = GainLaw::Transpose { alpha: 3.0 };
    assert_eq!(t.formula(sigma), Some(0.15000000000000002));
    let p = GainLaw::Pinv { cutoff: 0.1 };
    assert_eq!(p.formula(sigma), Some(0.0), "below the rank tolerance");
    assert_eq!(p.formula(0.5), Some(2.0));
    let d = GainLaw::Dls { lambda: 0.2 };
    let expected = 0.05 / (0.0025 + 0.04);
    assert!((d.formula(sigma).expect("dls") - expected).abs() < 1e-15);
    // DLS's gain peaks at σ = λ with 1/(2λ).
    assert!((d.formula(0.2).expect("dls") - 2.5).abs() < 1e-12);
    assert_eq!(GainLaw::None.formula(sigma), None);
    assert_eq!(d.formula(0.0), None);
    assert_eq!(d.formula(f64::NAN), None);
}
