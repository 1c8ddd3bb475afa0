//! The one place a driver is built: [`driver_for`] turns a preset's creature,
//! with a front end's [`Overrides`] (a motion, a method, a gait, a path, a
//! speed, recorded targets), into the [`AnyDriver`] of its engine — She 2006's
//! thesis motions (engine `ik`), Girard & Maciejewski 1985's PODA gaits
//! (`poda`), Raibert & Hodgins 1991's simulation (`physics`), or recorded
//! targets followed by the thesis IK (`gaitlab track`).

use gaitlab_core::RootTransform;
use gaitlab_core::driver::Driver;
use gaitlab_core::export::TargetTrack;
use gaitlab_core::ik::{IkOptions, Method};
use gaitlab_core::preset::physics::check_speed_mps;
use gaitlab_core::preset::thesis::ThesisMode;
use gaitlab_core::preset::{
    Creature, Engine, PathSpec, PresetError, THESIS_ROLE_COUNT, check_ik_options,
};
use gaitlab_motion::{DriverError, PodaDriver, ThesisDriver, TrackDriver, TrackOptions};
use gaitlab_physics::PhysicsDriver;
use glam::DMat3;

use crate::AnyDriver;

/// Recorded effector targets to follow instead of the engine's own motion
/// (`gaitlab track`).
#[derive(Clone, Debug)]
pub struct Tracking {
    /// One target per effector per sample, world metres.
    pub targets: TargetTrack,
    /// IK iterations per frame (`None`: the preset's thesis setting).
    pub iterations_per_frame: Option<usize>,
}

/// What a front end changes from the preset when it builds a driver. Every
/// field is optional: `Overrides::default()` gives the preset's own driver.
/// Fields that do not apply to the creature's engine are not used (the
/// thesis motion and method mean nothing to the physics engine).
#[derive(Clone, Debug, Default)]
pub struct Overrides {
    /// Thesis motion (engine `ik`; default: the preset's).
    pub mode: Option<ThesisMode>,
    /// IK method (engine `ik` and tracking; default: the preset's).
    pub method: Option<Method>,
    /// IK options in place of the preset's (engine `ik`; `method` above, when
    /// set, still wins over the options' own).
    pub ik: Option<IkOptions>,
    /// The figure's heading, degrees about +y (engine `ik`; default 0, facing +z).
    pub heading_deg: Option<f64>,
    /// Gait name (engines `poda` and `physics`; default: the preset's).
    pub gait: Option<String>,
    /// Body path (engine `poda`; default: the preset's).
    pub path: Option<PathSpec>,
    /// Desired speed, m/s (engine `physics`; default: the preset's).
    pub speed_mps: Option<f64>,
    /// Follow recorded targets with the thesis IK, whatever the engine.
    pub tracking: Option<Tracking>,
}

/// The driver of `creature`'s engine with `overrides` applied, at time 0.
///
/// # Errors
/// A [`PresetError`] whose path names the value that cannot be used: a
/// scenario value (`scenario.thesis.…`, `scenario.poda.gait`,
/// `scenario.physics.…`, `scenario.terrain` when it is not flat and the
/// engine is the IK's, or the physics' on ground or in a gait it does not
/// run on yet: [`PHYSICS_ON_TERRAIN`]), or for
/// tracking `targets` / `iterations` (the
/// recorded targets do not fit the skeleton).
pub fn driver_for(creature: &Creature, overrides: &Overrides) -> Result<AnyDriver, PresetError> {
    if !creature.scenario.terrain.is_flat() && creature.scenario.engine == Engine::Ik {
        return Err(PresetError::new(
            "scenario.terrain",
            format!(
                "the {} engine walks on flat ground only in this version (PODA creatures walk \
                 on a plane, stairs or a height field; physics creatures run on a plane or \
                 rough ground)",
                creature.scenario.engine.name()
            ),
        ));
    }
    if let Some(tracking) = &overrides.tracking {
        return track_driver(creature, overrides, tracking);
    }
    match creature.scenario.engine {
        Engine::Ik => thesis_driver(creature, overrides),
        Engine::Poda => {
            let mut params = creature.scenario.poda_params();
            if let Some(gait) = &overrides.gait {
                params.gait = Some(gait.clone());
            }
            if let Some(path) = &overrides.path {
                params.path = Some(path.clone());
            }
            PodaDriver::with_params(creature, params)
                .map(|driver| AnyDriver::Poda(Box::new(driver)))
                .map_err(preset_error)
        }
        Engine::Physics => {
            let Some(mut params) = creature.scenario.physics.clone() else {
                return Err(PresetError::new(
                    "scenario.physics",
                    "engine \"physics\" needs the creature's physical model",
                ));
            };
            if let Some(gait) = &overrides.gait {
                params.gait = Some(gait.clone());
            }
            if let Some(speed) = overrides.speed_mps {
                check_speed_mps("scenario.physics.speed_mps", speed)?;
                params.speed_mps = speed;
            }
            let driver = PhysicsDriver::with_params(creature, params)?;
            physics_on_terrain(&creature.scenario.terrain, driver.gait())?;
            Ok(AnyDriver::Physics(Box::new(driver)))
        }
    }
}

/// The physics gaits made to run on ground that is not flat (issue 45 item
/// 3, docs/terrain.md "Physics on terrain"): the biped's run, the
/// quadruped's trot and the kangaroo's hop, on a plane, a height field or
/// rough ground.
pub const PHYSICS_ON_TERRAIN: [&str; 3] = ["run", "trot", "hop"];

/// Refuses a physics run on `terrain` that the controllers do not plan for
/// yet: stairs (their risers), or a gait not in [`PHYSICS_ON_TERRAIN`].
fn physics_on_terrain(
    terrain: &gaitlab_core::terrain::Terrain,
    gait: &str,
) -> Result<(), PresetError> {
    if terrain.is_flat() {
        return Ok(());
    }
    let kind = terrain.kind_name();
    if kind == "stairs" {
        return Err(PresetError::new(
            "scenario.terrain",
            "the physics engine does not climb stairs in this version (it runs the biped, \
             the quadruped's trot and the kangaroo's hop on a plane or rough ground; PODA \
             creatures climb stairs)",
        ));
    }
    if !PHYSICS_ON_TERRAIN.contains(&gait) {
        return Err(PresetError::new(
            "scenario.terrain",
            format!(
                "the physics engine runs the {gait} on flat ground only in this version (on \
                 a {kind}: the biped's run, the quadruped's trot, the kangaroo's hop)"
            ),
        ));
    }
    Ok(())
}

/// The IK options a thesis or tracking driver gets; options given in
/// `overrides` are checked by the preset's own rule (the one range check).
fn ik_options(creature: &Creature, overrides: &Overrides) -> Result<IkOptions, PresetError> {
    let mut options = match &overrides.ik {
        Some(options) => {
            check_ik_options("ik", options)?;
            options.clone()
        }
        None => creature.scenario.ik_options(),
    };
    if let Some(method) = overrides.method {
        options.method = method;
    }
    Ok(options)
}

fn thesis_driver(creature: &Creature, overrides: &Overrides) -> Result<AnyDriver, PresetError> {
    let mode = overrides.mode.unwrap_or(creature.scenario.mode);
    let options = ik_options(creature, overrides)?;
    if overrides.heading_deg.is_some_and(|h| !h.is_finite()) {
        return Err(PresetError::new("heading_deg", "must be finite"));
    }
    let mut driver = ThesisDriver::new(
        creature.skeleton.clone(),
        creature.scenario.thesis.clone(),
        mode,
        options,
    )
    .map_err(|e| PresetError::new(format!("scenario.thesis.{}", e.path), e.reason))?;
    if let Some(heading_deg) = overrides.heading_deg {
        driver.set_origin(RootTransform {
            rotation: DMat3::from_rotation_y(heading_deg.to_radians()),
            ..RootTransform::default()
        });
        driver.reset();
    }
    Ok(AnyDriver::Thesis(Box::new(driver)))
}

fn track_driver(
    creature: &Creature,
    overrides: &Overrides,
    tracking: &Tracking,
) -> Result<AnyDriver, PresetError> {
    let options = TrackOptions {
        ik: ik_options(creature, overrides)?,
        iterations_per_frame: tracking
            .iterations_per_frame
            .unwrap_or(creature.scenario.thesis.iterations_per_frame),
        root: RootTransform {
            position: creature.root_position,
            ..RootTransform::default()
        },
    };
    TrackDriver::new(creature.skeleton.clone(), tracking.targets.clone(), options)
        .map(|driver| AnyDriver::Track(Box::new(driver)))
        .map_err(preset_error)
}

fn preset_error(error: DriverError) -> PresetError {
    PresetError::new(error.path, error.reason)
}

/// The engine layer's own check of a preset, after the preset's: the driver
/// `gaitlab run` would build, so that a preset that validates is one that
/// runs. `None` for an IK figure with fewer effectors than the thesis has
/// roles (two feet, two hands): it has no motion of its own and is for
/// following recorded targets (`gaitlab track`).
///
/// # Errors
/// As [`driver_for`] with no overrides.
pub fn check(creature: &Creature) -> Result<Option<AnyDriver>, PresetError> {
    let tracking_only = creature.scenario.engine == Engine::Ik
        && creature.skeleton.effector_count() < THESIS_ROLE_COUNT;
    if tracking_only {
        return Ok(None);
    }
    driver_for(creature, &Overrides::default()).map(Some)
}
