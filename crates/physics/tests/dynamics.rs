//! The dynamics checked against independent computations: the O(n)
//! articulated-body algorithm against the O(n³) CRBA + RNEA path on random
//! states of every model, a pendulum's period against its closed form, and a
//! free body's momentum and energy in flight.

use gaitlab_physics::creatures::{biped, kangaroo, quadruped};
use gaitlab_physics::dynamics::crba::forward_dynamics_dense;
use gaitlab_physics::dynamics::energy::{kinetic_energy, momentum, potential_energy};
use gaitlab_physics::dynamics::integrate::integrate;
use gaitlab_physics::dynamics::kinematics::kinematics;
use gaitlab_physics::{Body, Data, Force, Joint, Model, ParentLink, forward_dynamics};
use glam::{DMat3, DQuat, DVec3};

/// A small deterministic generator (xorshift64*), uniform in [-1, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    fn vec(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }
}

fn randomize(model: &Model, data: &mut Data, rng: &mut Rng) {
    data.base_position = rng.vec();
    data.base_orientation = DQuat::from_scaled_axis(rng.vec() * 2.0);
    data.base_velocity.angular = rng.vec() * 3.0;
    data.base_velocity.linear = rng.vec() * 3.0;
    for k in 0..model.joint_count() {
        data.q[k] = rng.next() * 1.5;
        data.qd[k] = rng.next() * 4.0;
        data.tau[k] = rng.next() * 50.0;
    }
    for f in &mut data.external {
        *f = Force::new(rng.vec() * 20.0, rng.vec() * 100.0);
    }
}

/// A random tree of revolute and prismatic joints on a free base.
fn random_tree(rng: &mut Rng, n: usize) -> Model {
    let mut bodies = vec![Body {
        name: "base".into(),
        parent: None,
        joint: Joint::Free,
        placement: ParentLink::default(),
        mass: 5.0,
        com: rng.vec() * 0.1,
        inertia_com: DMat3::from_diagonal(DVec3::new(0.3, 0.4, 0.5)),
    }];
    for i in 1..n {
        let parent = ((rng.next() + 1.0) * 0.5 * i as f64) as usize;
        let axis = rng.vec().normalize();
        let joint = if rng.next() > 0.0 {
            Joint::Revolute(axis)
        } else {
            Joint::Prismatic(axis)
        };
        let d = DVec3::new(
            rng.next().abs() + 0.1,
            rng.next().abs() + 0.1,
            rng.next().abs() + 0.1,
        ) * 0.05;
        bodies.push(Body {
            name: format!("b{i}"),
            parent: Some(parent.min(i - 1)),
            joint,
            placement: ParentLink {
                rot: DMat3::from_quat(DQuat::from_scaled_axis(rng.vec())),
                pos: rng.vec() * 0.4,
            },
            mass: rng.next().abs() + 0.2,
            com: rng.vec() * 0.2,
            inertia_com: DMat3::from_diagonal(d),
        });
    }
    Model::new(bodies).expect("valid random tree")
}

fn assert_aba_matches_dense(name: &str, model: &Model, rng: &mut Rng, trials: usize) {
    let mut data = Data::new(model);
    let base = if model.free_base() { 6 } else { 0 };
    for trial in 0..trials {
        randomize(model, &mut data, rng);
        forward_dynamics(model, &mut data).expect("ABA solves");
        let dense = forward_dynamics_dense(model, &mut data).expect("H is positive definite");
        let mut aba = Vec::new();
        if model.free_base() {
            let a = data.base_acceleration;
            aba.extend([
                a.angular.x,
                a.angular.y,
                a.angular.z,
                a.linear.x,
                a.linear.y,
                a.linear.z,
            ]);
        }
        aba.extend_from_slice(&data.qdd);
        let scale = dense.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
        for (k, (a, d)) in aba.iter().zip(&dense).enumerate() {
            assert!(
                (a - d).abs() <= 1e-9 * scale,
                "{name} trial {trial} coordinate {k} (base {base}): ABA {a} vs CRBA+RNEA {d}"
            );
        }
    }
}

#[test]
fn aba_equals_crba_rnea_on_random_states_of_every_model() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for l in [1.0, 2.5] {
        assert_aba_matches_dense("biped", &biped(l).expect("biped").model, &mut rng, 50);
        assert_aba_matches_dense(
            "quadruped",
            &quadruped(l).expect("quadruped").model,
            &mut rng,
            50,
        );
        assert_aba_matches_dense(
            "kangaroo",
            &kangaroo(l).expect("kangaroo").model,
            &mut rng,
            50,
        );
    }
    // 1: the free base alone, a leaf whose articulated inertia is its own.
    for n in [1, 2, 7, 20, 40] {
        let model = random_tree(&mut rng, n);
        assert_aba_matches_dense(&format!("random tree of {n}"), &model, &mut rng, 20);
    }
}

#[test]
fn a_pendulum_swings_with_its_closed_form_period() {
    // A rod of 0.8 m, 2 kg, pivoting about the world x axis; mass centre 0.4 m
    // below the pivot. Small-angle period 2π √(I_pivot / (m g d)).
    let (mass, d, i_com) = (2.0, 0.4, 2.0 * 0.8 * 0.8 / 12.0);
    let model = Model::new(vec![Body {
        name: "rod".into(),
        parent: None,
        joint: Joint::Revolute(DVec3::X),
        placement: ParentLink::default(),
        mass,
        com: DVec3::new(0.0, -d, 0.0),
        inertia_com: DMat3::from_diagonal(DVec3::splat(i_com)),
    }])
    .expect("pendulum");
    let mut data = Data::new(&model);
    let amplitude = 0.01;
    data.q[0] = amplitude;
    let dt = 0.0004;
    let expected = 2.0 * std::f64::consts::PI * ((i_com + mass * d * d) / (mass * 9.81 * d)).sqrt();
    // Interpolated downward zero crossings of q, over ten periods.
    let mut crossings = Vec::new();
    let mut t = 0.0;
    let mut prev = data.q[0];
    while crossings.len() < 11 {
        forward_dynamics(&model, &mut data).expect("pendulum dynamics");
        integrate(&model, &mut data, dt);
        t += dt;
        let q = data.q[0];
        if prev > 0.0 && q <= 0.0 {
            crossings.push(t - dt * q / (q - prev));
        }
        prev = q;
    }
    let period = (crossings[10] - crossings[0]) / 10.0;
    let rel = (period - expected).abs() / expected;
    assert!(
        rel < 1e-4,
        "period {period} s vs {expected} s (relative error {rel:e})"
    );
    // Symplectic Euler keeps the amplitude: no growth, no decay beyond 0.1 %.
    assert!((data.q[0].abs().max(prev.abs())) < amplitude * 1.001);
}

#[test]
fn a_free_body_in_flight_keeps_its_momentum_and_energy() {
    // The quadruped thrown tumbling, joints free and unactuated: linear
    // momentum changes by exactly m·g·t, angular momentum about the centre of
    // mass and total energy stay constant.
    let creature = quadruped(1.0).expect("quadruped");
    let model = &creature.model;
    let mut data = Data::new(model);
    data.base_position = DVec3::new(0.0, 5.0, 0.0);
    data.base_velocity.angular = DVec3::new(1.5, -2.0, 0.7);
    data.base_velocity.linear = DVec3::new(0.5, 4.0, 1.0);
    for k in 0..model.joint_count() {
        data.qd[k] = 0.3 * (k as f64 - 4.0);
    }
    let dt = 0.0004;
    let mass = model.total_mass();
    kinematics(model, &mut data);
    let (p0, _) = momentum(model, &data);
    let com_momentum = |data: &Data| {
        let (p, l) = momentum(model, data);
        let c = gaitlab_physics::dynamics::energy::center_of_mass(model, data);
        l - c.cross(p)
    };
    let l0 = com_momentum(&data);
    let e0 = kinetic_energy(model, &data) + potential_energy(model, &data);
    let steps = 2500; // 1 s
    for _ in 0..steps {
        forward_dynamics(model, &mut data).expect("flight dynamics");
        integrate(model, &mut data, dt);
    }
    kinematics(model, &mut data);
    let (p1, _) = momentum(model, &data);
    let expected = p0 + model.gravity * mass * (steps as f64 * dt);
    let dp = (p1 - expected).length() / (mass * 9.81);
    let dl = (com_momentum(&data) - l0).length() / l0.length();
    let e1 = kinetic_energy(model, &data) + potential_energy(model, &data);
    let de = (e1 - e0).abs() / e0.abs();
    eprintln!(
        "flight 1 s: momentum error {dp:e} (× m·g·1 s), angular momentum {dl:e}, energy {de:e}"
    );
    assert!(dp < 1e-3, "linear momentum off by {dp:e} of m·g·1 s");
    assert!(
        dl < 1e-2,
        "angular momentum about the centre of mass drifted by {dl:e}"
    );
    assert!(de < 1e-2, "energy drifted by {de:e}");
}

#[test]
fn the_depth_order_keeps_every_parent_first_and_siblings_in_index_order() {
    // `Model::by_depth` is the order of the recursive passes: a parent before
    // its children (the passes' dependencies), and a parent's children in
    // increasing index, so that the leaves-to-root pass, which runs it
    // backwards, adds each child's inertia into its parent in the same
    // order as the reversed body order (the same bits).
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let mut models: Vec<Model> = [2, 7, 20, 40]
        .iter()
        .map(|&n| random_tree(&mut rng, n))
        .collect();
    models.push(biped(1.0).expect("biped").model);
    models.push(quadruped(1.0).expect("quadruped").model);
    models.push(kangaroo(1.0).expect("kangaroo").model);
    for model in &models {
        let order = model.by_depth();
        let n = model.bodies().len();
        let mut at = vec![usize::MAX; n];
        for (k, &i) in order.iter().enumerate() {
            assert_eq!(at[i], usize::MAX, "body {i} appears twice");
            at[i] = k;
        }
        assert!(at.iter().all(|&k| k < n), "every body appears");
        for (i, body) in model.bodies().iter().enumerate() {
            if let Some(p) = body.parent {
                assert!(at[p] < at[i], "parent {p} after its child {i}");
            }
            for (j, other) in model.bodies().iter().enumerate().skip(i + 1) {
                if other.parent == body.parent {
                    assert!(at[i] < at[j], "siblings {i} and {j} out of index order");
                }
            }
        }
    }
    // The biped's legs interleave: trunk, both hips' outer axes, both inner
    // axes, both upper legs, both lower legs.
    let biped = biped(1.0).expect("biped").model;
    let names: Vec<&str> = biped
        .by_depth()
        .iter()
        .map(|&i| biped.bodies()[i].name.as_str())
        .collect();
    assert_eq!(names[0], "trunk");
    assert_eq!(
        names[7..],
        ["left-lower-leg", "right-lower-leg"],
        "order: {names:?}"
    );
}
