//! Physics creatures from presets and back: a preset's skeleton gives the
//! bodies' geometry (each joint moves one body; the root is the trunk of a
//! free base, or the fixed world of a planar one) and `scenario.physics` their
//! mass properties (Raibert & Hodgins 1991, Table 3), legs, tail and neck.
//! [`to_preset`] writes a [`PhysicalCreature`] as such a preset (the bundled ones are
//! made this way from [`crate::creatures`]).

use gaitlab_core::JointKind;
use gaitlab_core::preset::{
    Creature as PresetCreature, EffectorSpec, Engine, Format, JointSpec, JointType, MassSpec,
    PhysicsBase, PhysicsBodySpec, PhysicsLegSpec, PhysicsModel, PhysicsParams, Preset, PresetError,
    RootSpec, Scenario, SkeletonSpec,
};
use glam::{DMat3, DVec3};

use crate::creatures::{Leg, PhysicalCreature, Species};
use crate::dynamics::model::{Body, Joint, Model};
use crate::dynamics::spatial::ParentLink;

fn species(model: PhysicsModel) -> Species {
    match model {
        PhysicsModel::Biped => Species::Biped,
        PhysicsModel::Quadruped => Species::Quadruped,
        PhysicsModel::Kangaroo => Species::Kangaroo,
    }
}

fn inertia(spec: &MassSpec, l: f64) -> (f64, DVec3, DMat3) {
    let [ix, iy, iz] = spec.inertia_kgm2;
    (
        spec.mass_kg * l.powi(3),
        DVec3::from_array(spec.com_m) * l,
        DMat3::from_diagonal(DVec3::new(ix, iy, iz)) * l.powi(5),
    )
}

/// The physics creature of a built preset whose engine is `physics`, at the
/// preset's dynamic scale L (lengths ×L, masses ×L³, inertias ×L⁵).
///
/// # Errors
/// A [`PresetError`] naming `scenario.physics` (or a field of it) when the
/// section is missing or the structure does not make a model.
pub fn creature_from_preset(preset: &PresetCreature) -> Result<PhysicalCreature, PresetError> {
    let err =
        |path: &str, reason: String| PresetError::new(format!("scenario.physics{path}"), reason);
    let params = preset.scenario.physics.as_ref().ok_or_else(|| {
        err(
            "",
            "engine \"physics\" needs the creature's physical model".into(),
        )
    })?;
    let l = params.scale;
    let skeleton = &preset.skeleton;
    let free = params.base == PhysicsBase::Free;
    let offset = usize::from(free);
    let mut bodies = Vec::with_capacity(skeleton.joint_count() + offset);
    if free {
        let trunk = params
            .trunk
            .as_ref()
            .ok_or_else(|| err(".trunk", "a free base needs the trunk".into()))?;
        let (mass, com, i) = inertia(trunk, l);
        bodies.push(Body {
            name: "trunk".into(),
            parent: None,
            joint: Joint::Free,
            placement: ParentLink::default(),
            mass,
            com,
            inertia_com: i,
        });
    }
    for joint in skeleton.joints() {
        let spec = params.bodies.iter().find(|b| b.joint == joint.name);
        let (mass, com, i) = spec.map_or((0.0, DVec3::ZERO, DMat3::ZERO), |b| inertia(&b.mass, l));
        let mut pos = joint.offset * l;
        if !free && joint.parent.is_none() {
            pos += preset.root_position * l;
        }
        let parent = match joint.parent {
            Some(p) => Some(p + offset),
            None if free => Some(0),
            None => None,
        };
        bodies.push(Body {
            name: joint.name.clone(),
            parent,
            joint: match joint.kind {
                JointKind::Revolute => Joint::Revolute(joint.axis),
                JointKind::Prismatic => Joint::Prismatic(joint.axis),
            },
            placement: ParentLink {
                rot: joint.frame,
                pos,
            },
            mass,
            com,
            inertia_com: i,
        });
    }
    let model = Model::new(bodies).map_err(|e| err(".bodies", e.to_string()))?;
    let joint = |path: String, name: &str| {
        skeleton
            .joint_index(name)
            .ok_or_else(|| PresetError::new(path, format!("no joint named \"{name}\"")))
    };
    let mut legs = Vec::with_capacity(params.legs.len());
    for (i, spec) in params.legs.iter().enumerate() {
        let at = |f: &str| format!("scenario.physics.legs[{i}].{f}");
        let hip = spec
            .hip
            .iter()
            .enumerate()
            .map(|(k, h)| joint(format!("{}[{k}]", at("hip")), h))
            .collect::<Result<Vec<_>, _>>()?;
        let first_hip = *hip
            .first()
            .ok_or_else(|| PresetError::new(at("hip"), "needs a joint"))?;
        let hip_body = &model.bodies()[first_hip + offset];
        legs.push(Leg {
            name: spec.name.clone(),
            spring: joint(at("spring"), &spec.spring)?,
            knee: spec
                .knee
                .as_deref()
                .map(|k| joint(at("knee"), k))
                .transpose()?,
            foot_body: joint(at("foot"), &spec.foot)? + offset,
            foot_point: DVec3::from_array(spec.foot_point_m) * l,
            hip_in_trunk: hip_body.placement.pos,
            hip,
            length_m: 0.0,
        });
    }
    let trunk = if free {
        0
    } else {
        let first = legs
            .first()
            .and_then(|leg| leg.hip.first())
            .copied()
            .unwrap_or(0);
        model.bodies()[first].parent.ok_or_else(|| {
            err(
                ".legs[0].hip[0]",
                "a planar leg's hip must hang from the trunk".into(),
            )
        })?
    };
    let tail = params
        .tail
        .iter()
        .enumerate()
        .map(|(k, t)| joint(format!("scenario.physics.tail[{k}]"), t))
        .collect::<Result<Vec<_>, _>>()?;
    let neck = params
        .neck
        .as_deref()
        .map(|n| joint("scenario.physics.neck".into(), n))
        .transpose()?;
    Ok(PhysicalCreature::new(
        species(params.model),
        l,
        model,
        trunk,
        legs,
        tail,
        neck,
    ))
}

/// What a preset written by [`to_preset`] says beyond the creature itself.
#[derive(Clone, Debug, PartialEq)]
pub struct PresetMeta {
    /// Preset name.
    pub name: String,
    /// One or two sentences for people.
    pub description: String,
    /// Where the root (trunk, or the planar base's origin) starts (m).
    pub root_position: DVec3,
    /// Starting value of every joint coordinate.
    pub rest: Vec<f64>,
    /// Gait name.
    pub gait: String,
    /// Desired speed (m/s).
    pub speed_mps: f64,
    /// Run the controller every this many 0.4 ms steps: 5 (2 ms, the
    /// paper's "few ms") where the creature's gaits hold at that interval.
    pub control_every: u32,
}

fn mass_spec(b: &Body) -> MassSpec {
    let d = b.inertia_com;
    MassSpec {
        mass_kg: b.mass,
        com_m: b.com.to_array(),
        inertia_kgm2: [d.x_axis.x, d.y_axis.y, d.z_axis.z],
    }
}

/// Write a creature built at scale 1 as a preset.
#[must_use]
pub fn to_preset(creature: &PhysicalCreature, meta: &PresetMeta) -> Preset {
    let bodies = creature.model.bodies();
    let free = creature.model.free_base();
    let offset = usize::from(free);
    let name_of = |i: usize| bodies[i].name.clone();
    let mut joints = Vec::new();
    let mut masses = Vec::new();
    for (i, b) in bodies.iter().enumerate().skip(offset) {
        let (kind, axis) = match b.joint {
            Joint::Revolute(a) => (JointType::Revolute, a),
            Joint::Prismatic(a) => (JointType::Prismatic, a),
            Joint::Free => continue,
        };
        let parent = b.parent.filter(|&p| !(free && p == 0)).map(name_of);
        let rot = glam::DQuat::from_mat3(&b.placement.rot);
        joints.push(JointSpec {
            name: b.name.clone(),
            parent,
            kind,
            axis,
            offset: b.placement.pos,
            frame_rotation: rot.to_scaled_axis(),
            limits: None,
            rest: meta.rest.get(i - offset).copied().unwrap_or(0.0),
            center: None,
            gain: 0.0,
            size: if b.mass > 0.0 { 0.03 } else { 0.02 },
        });
        if b.mass > 0.0 {
            masses.push(PhysicsBodySpec {
                joint: b.name.clone(),
                mass: mass_spec(b),
            });
        }
    }
    let dof_name = |k: usize| bodies[k + offset].name.clone();
    let legs: Vec<PhysicsLegSpec> = creature
        .legs
        .iter()
        .map(|leg| PhysicsLegSpec {
            name: leg.name.clone(),
            hip: leg.hip.iter().map(|&k| dof_name(k)).collect(),
            spring: dof_name(leg.spring),
            knee: leg.knee.map(dof_name),
            foot: name_of(leg.foot_body),
            foot_point_m: leg.foot_point.to_array(),
        })
        .collect();
    let effectors = creature
        .legs
        .iter()
        .map(|leg| EffectorSpec {
            name: format!("{}-foot", leg.name),
            joint: name_of(leg.foot_body),
            offset: leg.foot_point,
            orientation: false,
        })
        .collect();
    let model = match creature.species {
        Species::Biped => PhysicsModel::Biped,
        Species::Quadruped => PhysicsModel::Quadruped,
        Species::Kangaroo => PhysicsModel::Kangaroo,
    };
    let physics = PhysicsParams {
        model,
        base: if free {
            PhysicsBase::Free
        } else {
            PhysicsBase::Planar
        },
        trunk: free.then(|| mass_spec(&bodies[0])),
        bodies: masses,
        legs,
        tail: creature.tail.iter().map(|&k| dof_name(k)).collect(),
        neck: creature.neck.map(dof_name),
        gait: Some(meta.gait.clone()),
        speed_mps: meta.speed_mps,
        hop_height_m: None,
        scale: 1.0,
        dt_s: 0.0004,
        control_every: meta.control_every,
        ground: None,
        controller: std::collections::BTreeMap::new(),
        controller_by_gait: std::collections::BTreeMap::new(),
        lab_additions_by_gait: std::collections::BTreeMap::new(),
        obstacles: Vec::new(),
        waypoints: Vec::new(),
        lab_additions: Some(gaitlab_core::preset::physics::LabAdditions::default()),
        start: gaitlab_core::preset::physics::PhysicsStart::default(),
        switch_to_start: Vec::new(),
    };
    Preset {
        schema: None,
        format: Format::V2,
        name: meta.name.clone(),
        description: meta.description.clone(),
        skeleton: SkeletonSpec {
            root: RootSpec {
                position: meta.root_position,
            },
            joints,
            limbs: Vec::new(),
            effectors,
        },
        scenario: Scenario {
            engine: Engine::Physics,
            physics: Some(physics),
            ..Scenario::default()
        },
    }
}
