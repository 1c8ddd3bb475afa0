//! Development aid: a bundled physics creature in a random state with our
//! forward dynamics, as JSON, for comparison with an independent engine
//! (the MJCF export loaded in MuJoCo). `-- PRESET SEED`
use gaitlab_core::preset::load_bundled;
use gaitlab_physics::engine::preset::creature_from_preset;
use gaitlab_physics::{Data, forward_dynamics};
use glam::{DQuat, DVec3};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let name = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "raibert-biped".into());
    let mut seed: u64 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(7);
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let preset = load_bundled(&name).ok_or("no such preset")??;
    let creature = creature_from_preset(&preset)?;
    let model = &creature.model;
    let mut data = Data::new(model);
    data.base_position = DVec3::new(rnd(), 3.0 + rnd(), rnd());
    data.base_orientation = DQuat::from_scaled_axis(DVec3::new(rnd(), rnd(), rnd()) * 0.8);
    data.base_velocity.angular = DVec3::new(rnd(), rnd(), rnd()) * 2.0;
    data.base_velocity.linear = DVec3::new(rnd(), rnd(), rnd()) * 2.0;
    for k in 0..model.joint_count() {
        data.q[k] = rnd() * 0.7;
        data.qd[k] = rnd() * 2.0;
    }
    if !model.free_base() {
        data.q[1] += 3.0;
    }
    forward_dynamics(model, &mut data)?;
    let q = data.base_orientation;
    let a = data.base_acceleration;
    let ke = gaitlab_physics::dynamics::energy::kinetic_energy(model, &data);
    println!(
        "{}",
        serde_json::json!({
            "free": model.free_base(),
            "pos": data.base_position.to_array(),
            "quat": [q.w, q.x, q.y, q.z],
            "v_body": data.base_velocity.linear.to_array(),
            "w_body": data.base_velocity.angular.to_array(),
            "q": data.q, "qd": data.qd, "qdd": data.qdd,
            "w_dot": a.angular.to_array(),
            "mass": model.total_mass(),
            "ke": ke,
        })
    );
    Ok(())
}
