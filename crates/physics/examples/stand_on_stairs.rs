//! Development aid for issue 45 item 5 (`tools/stairs_mujoco_check.py`): a
//! physics creature standing on a tread of a flight of stairs, held still —
//! its leg springs as the gait set them at the start, its hips servoed to
//! their start angles (the same servo the check gives MuJoCo's joints), no
//! thrust — settles in gaitlab's simulation; the same creature on the
//! floor too. Writes the MJCF of the creature on the stairs and prints, as
//! JSON, both settled trunk heights and what MuJoCo needs to hold it the same
//! way. `-- PRESET OUT_DIR`
use gaitlab_core::preset::load_bundled;
use gaitlab_core::terrain::{Stairs, Terrain};
use gaitlab_physics::{ControlInput, Controller, Drive, PhysicsDriver};

/// The hips' servo: stiffness (N·m/rad) and damping (N·m·s/rad).
const HIP_KP: f64 = 400.0;
const HIP_KV: f64 = 20.0;
/// How long the creature settles, seconds.
const SETTLE_S: f64 = 3.0;
/// The tread the creature stands on: the third of five 0.1 m steps, 1.5 m
/// deep, centred on the start (the first riser 3.75 m behind it).
const RISE_M: f64 = 0.1;
const TREAD_M: f64 = 3.0 * RISE_M;

/// Holds every coordinate's drive as set once: the passive stand.
struct Hold(Vec<Drive>);

impl Controller for Hold {
    fn control(&mut self, _input: &ControlInput<'_>, drives: &mut [Drive]) {
        drives.clone_from_slice(&self.0);
    }
}

/// A creature settled held still.
struct Settled {
    /// The trunk's height, metres.
    height_m: f64,
    /// Each foot's height above the ground under it, metres.
    feet_m: Vec<f64>,
    /// The coordinates servoed (hips and knees).
    held: Vec<usize>,
    /// Every coordinate's start value.
    q0: Vec<f64>,
}

/// Settles `driver`'s creature held still.
fn settle(driver: &PhysicsDriver) -> Result<Settled, String> {
    let mut sim = driver.sim().clone();
    let creature = sim.creature.clone();
    let q0 = sim.data.q.clone();
    let mut hold: Vec<Drive> = sim
        .drives
        .iter()
        .map(|d| Drive {
            stops: d.stops,
            ..Drive::default()
        })
        .collect();
    let mut hips = Vec::new();
    for leg in &creature.legs {
        hold[leg.spring].spring = sim.drives[leg.spring].spring;
        for &k in &leg.hip {
            hold[k].spring.stiffness = HIP_KP;
            hold[k].spring.damping = HIP_KV;
            hold[k].spring.rest = q0[k];
            hips.push(k);
        }
        if let Some(k) = leg.knee {
            hold[k].spring.stiffness = HIP_KP;
            hold[k].spring.damping = HIP_KV;
            hold[k].spring.rest = q0[k];
            hips.push(k);
        }
    }
    let mut controller = Hold(hold);
    let steps = (SETTLE_S / sim.options.dt).round() as u64;
    for _ in 0..steps {
        sim.step(&mut controller).map_err(|e| format!("{e:?}"))?;
    }
    let feet = creature
        .legs
        .iter()
        .map(|leg| {
            let p = sim.data.point_world(leg.foot_body, leg.foot_point);
            p.y - sim.terrain.height(p.x, p.z)
        })
        .collect();
    Ok(Settled {
        height_m: sim.data.base_position.y,
        feet_m: feet,
        held: hips,
        q0,
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let name = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "raibert-quadruped".into());
    let out = std::env::args().nth(2).unwrap_or_else(|| ".".into());
    let floor = load_bundled(&name).ok_or("no such preset")??;
    let mut on_stairs = floor.clone();
    on_stairs.scenario.terrain = Terrain::Stairs(Stairs {
        rise_m: RISE_M,
        run_m: 1.5,
        count: 5,
        direction_deg: 90.0,
        start_m: -3.75,
    });
    let mut driver = PhysicsDriver::new(&on_stairs)?;
    // One step: the gait sets its leg springs (the export takes them so).
    driver.run_steps(1).map_err(|e| format!("{e:?}"))?;
    let xml = driver.mjcf(&name);
    let path = std::path::Path::new(&out).join(format!("{name}-on-stairs.xml"));
    std::fs::write(&path, xml)?;
    let stand = settle(&driver)?;
    let mut flat = PhysicsDriver::new(&floor)?;
    flat.run_steps(1).map_err(|e| format!("{e:?}"))?;
    let flat_height = settle(&flat)?.height_m;
    let start = driver.sim().data.base_position;
    let turn = driver.sim().data.base_orientation;
    println!(
        "{}",
        serde_json::json!({
            "xml": path,
            "tread_m": TREAD_M,
            "settle_s": SETTLE_S,
            "hip_kp": HIP_KP,
            "hip_kv": HIP_KV,
            "held": stand.held,
            "q0": stand.q0,
            "start_base_m": start.to_array(),
            "start_quat_wxyz": [turn.w, turn.x, turn.y, turn.z],
            "gaitlab_rest_height_m": stand.height_m,
            "gaitlab_feet_above_ground_m": stand.feet_m,
            "gaitlab_flat_rest_height_m": flat_height,
        })
    );
    Ok(())
}
