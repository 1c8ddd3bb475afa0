//! Preset validation before anything is built (DESIGN.md input limits): counts,
//! finite numbers, positive sizes, ordered limits, rest and center values inside
//! their limits, gains in [0, 1], unique names, resolvable parents without
//! cycles, effectors on existing joints, sane thesis parameters (She 2006
//! §5.1.1, §5.2.3) and IK options (She 2006 §4.4). Every error names the JSON path.
//!
//! The result is a [`Plan`]: the joints and limbs in a parent-before-child order
//! that keeps the file's order wherever the parents allow it.

use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::f64::consts::{PI, TAU};

use glam::DVec3;

use super::PresetError;
use super::poda::PodaParams;
use super::scenario::{Engine, MAX_FPS};
use super::schema::{
    DhJointSpec, JointType, MAX_EFFECTORS, MAX_JOINTS, MAX_LIMBS, MAX_NAME_CHARS, Preset,
    SkeletonSpec,
};
use super::thesis::{CycleShape, ThesisParams};
use crate::ik::IkOptions;

/// Lowest thesis `slowdown` (1 = real time).
pub const MIN_SLOWDOWN: f64 = 1.0;
/// Highest thesis `slowdown`.
pub const MAX_SLOWDOWN: f64 = 100.0;
/// Highest gait-cycle frequency, Hz.
pub const MAX_FREQUENCY_HZ: f64 = 10.0;
/// Highest forward speed, m/s.
pub const MAX_SPEED_MPS: f64 = 20.0;
/// Most IK iterations per frame a preset may ask for.
pub const MAX_ITERATIONS_PER_FRAME: usize = 100;
/// Largest wounded `multiply` factor.
pub const MAX_WOUNDED_MULTIPLY: f64 = 10.0;
/// Largest magnitude of a wounded `add` term, radians per iteration.
pub const MAX_WOUNDED_ADD: f64 = 0.5;
/// Longest thesis start ramp, seconds.
pub const MAX_START_RAMP_S: f64 = 10.0;
/// Effectors a skeleton needs before the four thesis roles are checked.
pub const THESIS_ROLE_COUNT: usize = 4;

/// What a preset is loaded for. A rule is checked where the loaded preset uses
/// what it checks: the thesis roles (`scenario.thesis.roles`) only where the
/// She 2006 target script will drive them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Purpose {
    /// Running the preset's scenario (the app, `gaitlab run`, `gaitlab validate`):
    /// every rule. The roles are checked when the engine is `ik` and the skeleton
    /// has at least [`THESIS_ROLE_COUNT`] effectors, since every thesis mode
    /// (walk, run, wounded walk, wounded run) drives the four role effectors.
    #[default]
    Scenario,
    /// Following recorded effector targets with the skeleton (`gaitlab track`):
    /// the target script never runs, so the roles are not checked; every other
    /// rule is (tracking reads the skeleton, `scenario.ik`, `method`, `fps` and
    /// `thesis.iterations_per_frame`).
    Tracking,
}

/// A joint or a limb: the units the topological sort orders.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Unit {
    /// `skeleton.joints[i]`.
    Joint(usize),
    /// `skeleton.limbs[l]` (all its rows, in order).
    Limb(usize),
}

/// Where a joint name is declared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum NamePlace {
    Joint(usize),
    LimbRow(usize, usize),
}

impl NamePlace {
    fn unit(self) -> Unit {
        match self {
            NamePlace::Joint(i) => Unit::Joint(i),
            NamePlace::LimbRow(l, _) => Unit::Limb(l),
        }
    }

    fn path(self) -> String {
        match self {
            NamePlace::Joint(i) => format!("skeleton.joints[{i}].name"),
            NamePlace::LimbRow(l, r) => format!("skeleton.limbs[{l}].joints[{r}].name"),
        }
    }
}

/// The outcome of validation: a build order.
#[derive(Clone, Debug)]
pub(crate) struct Plan {
    /// Joints and limbs, every parent before its children.
    pub order: Vec<Unit>,
}

/// Checks every rule that applies to `purpose` and returns the build order.
pub(crate) fn check(preset: &Preset, purpose: Purpose) -> Result<Plan, PresetError> {
    check_name("name", &preset.name)?;
    let skeleton = &preset.skeleton;
    check_counts(skeleton)?;
    check_vector("skeleton.root.position", skeleton.root.position)?;
    for (i, joint) in skeleton.joints.iter().enumerate() {
        let at = |field: &str| format!("skeleton.joints[{i}].{field}");
        check_name(&at("name"), &joint.name)?;
        let axis = joint.axis;
        if !axis.is_finite() || normalized(axis).is_none() {
            return Err(PresetError::new(at("axis"), "must be a non-zero vector"));
        }
        check_vector(&at("offset"), joint.offset)?;
        check_rotation_vector(&at("frame_rotation"), joint.frame_rotation)?;
        check_value(&at("rest"), joint.rest)?;
        let center = joint.center.unwrap_or(joint.rest);
        check_value(&at("center"), center)?;
        check_variable_range(
            &at(""),
            joint.kind,
            joint.limits,
            ("rest", joint.rest),
            ("center", center),
        )?;
        check_gain(&at("gain"), joint.gain)?;
        if !(joint.size.is_finite() && joint.size > 0.0) {
            return Err(PresetError::new(
                at("size"),
                "must be a positive number of metres",
            ));
        }
    }
    for (l, limb) in skeleton.limbs.iter().enumerate() {
        let at = |field: &str| format!("skeleton.limbs[{l}].{field}");
        check_name(&at("name"), &limb.name)?;
        check_vector(&at("base_offset"), limb.base_offset)?;
        check_rotation_vector(&at("base_rotation"), limb.base_rotation)?;
        if limb.joints.is_empty() {
            return Err(PresetError::new(
                at("joints"),
                "a limb needs at least one joint",
            ));
        }
        for (r, row) in limb.joints.iter().enumerate() {
            check_dh_row(&format!("skeleton.limbs[{l}].joints[{r}]"), row)?;
        }
        if let Some(effector) = &limb.effector {
            check_name(&at("effector"), effector)?;
        }
    }
    let names = joint_names(skeleton)?;
    let order = topological_order(skeleton, &names)?;
    check_effectors(skeleton, &names)?;
    check_scenario(preset, &names, purpose)?;
    Ok(Plan { order })
}

/// Total joints (listed plus limb rows) and effectors (listed plus limb effectors).
fn totals(skeleton: &SkeletonSpec) -> (usize, usize) {
    let limb_joints: usize = skeleton
        .limbs
        .iter()
        .fold(0, |sum, limb| sum.saturating_add(limb.joints.len()));
    let limb_effectors = skeleton
        .limbs
        .iter()
        .filter(|l| l.effector.is_some())
        .count();
    (
        skeleton.joints.len().saturating_add(limb_joints),
        skeleton.effectors.len().saturating_add(limb_effectors),
    )
}

fn check_counts(skeleton: &SkeletonSpec) -> Result<(), PresetError> {
    let (joints, effectors) = totals(skeleton);
    let joints_path = if skeleton.joints.len() > MAX_JOINTS || skeleton.limbs.is_empty() {
        "skeleton.joints"
    } else {
        "skeleton.limbs"
    };
    if joints == 0 {
        return Err(PresetError::new(
            "skeleton.joints",
            "a skeleton needs at least one joint",
        ));
    }
    if joints > MAX_JOINTS {
        return Err(PresetError::new(
            joints_path,
            format!("{joints} joints is more than the limit of {MAX_JOINTS}"),
        ));
    }
    if skeleton.limbs.len() > MAX_LIMBS {
        return Err(PresetError::new(
            "skeleton.limbs",
            format!(
                "{} limbs is more than the limit of {MAX_LIMBS}",
                skeleton.limbs.len()
            ),
        ));
    }
    if effectors > MAX_EFFECTORS {
        let path = if skeleton.effectors.len() > MAX_EFFECTORS || skeleton.limbs.is_empty() {
            "skeleton.effectors"
        } else {
            "skeleton.limbs"
        };
        return Err(PresetError::new(
            path,
            format!("{effectors} effectors is more than the limit of {MAX_EFFECTORS}"),
        ));
    }
    Ok(())
}

/// Names: non-empty, at most [`MAX_NAME_CHARS`] characters, no whitespace or
/// control characters (BVH and the CLI treat names as single tokens).
fn check_name(path: &str, name: &str) -> Result<(), PresetError> {
    if name.is_empty() {
        return Err(PresetError::new(path, "must not be empty"));
    }
    if name.chars().count() > MAX_NAME_CHARS {
        return Err(PresetError::new(
            path,
            format!("must be at most {MAX_NAME_CHARS} characters"),
        ));
    }
    if name.chars().any(|c| c.is_whitespace() || c.is_control()) {
        return Err(PresetError::new(
            path,
            format!("{name:?} must not contain spaces or control characters"),
        ));
    }
    Ok(())
}

fn check_value(path: &str, value: f64) -> Result<(), PresetError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(PresetError::new(path, "must be a finite number"))
    }
}

fn check_vector(path: &str, v: DVec3) -> Result<(), PresetError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(PresetError::new(path, "must be three finite numbers"))
    }
}

/// Rotation vectors (axis × angle) must be finite and at most one turn long:
/// anything longer is almost surely degrees written where radians belong.
fn check_rotation_vector(path: &str, v: DVec3) -> Result<(), PresetError> {
    check_vector(path, v)?;
    if v.length() > TAU + 1e-9 {
        return Err(PresetError::new(
            path,
            "a rotation vector longer than 2π (one turn); angles are in radians",
        ));
    }
    Ok(())
}

fn check_gain(path: &str, gain: f64) -> Result<(), PresetError> {
    if (0.0..=1.0).contains(&gain) {
        Ok(())
    } else {
        Err(PresetError::new(path, "must be between 0 and 1"))
    }
}

/// Limits finite and ordered, a revolute range at most two turns wide, and the
/// named values (rest, center) inside. `prefix` ends with `.`.
fn check_variable_range(
    prefix: &str,
    kind: JointType,
    limits: Option<(f64, f64)>,
    rest: (&str, f64),
    center: (&str, f64),
) -> Result<(), PresetError> {
    let Some((lo, hi)) = limits else {
        return Ok(());
    };
    let path = format!("{prefix}limits");
    if !lo.is_finite() || !hi.is_finite() {
        return Err(PresetError::new(path, "must be two finite numbers"));
    }
    if lo > hi {
        return Err(PresetError::new(
            path,
            format!("minimum {lo} is greater than maximum {hi}"),
        ));
    }
    if kind == JointType::Revolute && hi - lo > 2.0 * TAU {
        return Err(PresetError::new(
            path,
            "a revolute range wider than two turns (4π) is not a limit; angles are in radians",
        ));
    }
    for (field, value) in [rest, center] {
        if value < lo || value > hi {
            return Err(PresetError::new(
                format!("{prefix}{field}"),
                format!("{value} is outside the limits [{lo}, {hi}]"),
            ));
        }
    }
    Ok(())
}

fn check_dh_row(prefix: &str, row: &DhJointSpec) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    check_name(&at("name"), &row.name)?;
    for (field, value) in [
        ("a", row.a),
        ("alpha", row.alpha),
        ("d", row.d),
        ("theta", row.theta),
    ] {
        check_value(&at(field), value)?;
    }
    if row.alpha.abs() > TAU {
        return Err(PresetError::new(
            at("alpha"),
            "a twist beyond ±2π; angles are in radians",
        ));
    }
    let rest = row.rest();
    let center = row.center.unwrap_or(rest);
    check_value(&at("center"), center)?;
    check_variable_range(
        &at(""),
        row.kind,
        row.limits,
        (row.rest_field(), rest),
        ("center", center),
    )?;
    check_gain(&at("gain"), row.gain)
}

/// Every joint name (listed and limb rows) with where it is declared; duplicates are errors.
fn joint_names(skeleton: &SkeletonSpec) -> Result<HashMap<&str, NamePlace>, PresetError> {
    let mut names: HashMap<&str, NamePlace> = HashMap::new();
    let listed = skeleton
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| (j.name.as_str(), NamePlace::Joint(i)));
    let rows = skeleton.limbs.iter().enumerate().flat_map(|(l, limb)| {
        limb.joints
            .iter()
            .enumerate()
            .map(move |(r, row)| (row.name.as_str(), NamePlace::LimbRow(l, r)))
    });
    for (name, place) in listed.chain(rows) {
        match names.entry(name) {
            Entry::Occupied(first) => {
                return Err(PresetError::new(
                    place.path(),
                    format!(
                        "duplicate joint name {name:?} (first at {})",
                        first.get().path()
                    ),
                ));
            }
            Entry::Vacant(slot) => {
                slot.insert(place);
            }
        }
    }
    let mut limb_names: HashMap<&str, usize> = HashMap::new();
    for (l, limb) in skeleton.limbs.iter().enumerate() {
        if let Some(first) = limb_names.insert(limb.name.as_str(), l) {
            return Err(PresetError::new(
                format!("skeleton.limbs[{l}].name"),
                format!(
                    "duplicate limb name {:?} (first at skeleton.limbs[{first}].name)",
                    limb.name
                ),
            ));
        }
    }
    Ok(names)
}

/// Orders joints and limbs parents first. Walks each unit's parent chain up to
/// an already placed unit, so a file already in order keeps its order; a unit met
/// twice on one walk closes a cycle.
fn topological_order(
    skeleton: &SkeletonSpec,
    names: &HashMap<&str, NamePlace>,
) -> Result<Vec<Unit>, PresetError> {
    let joint_count = skeleton.joints.len();
    let units: Vec<Unit> = (0..joint_count)
        .map(Unit::Joint)
        .chain((0..skeleton.limbs.len()).map(Unit::Limb))
        .collect();
    let slot = |unit: Unit| match unit {
        Unit::Joint(i) => i,
        Unit::Limb(l) => joint_count + l,
    };
    let describe = |unit: Unit| match unit {
        Unit::Joint(i) => skeleton
            .joints
            .get(i)
            .map_or_else(String::new, |j| format!("{:?}", j.name)),
        Unit::Limb(l) => skeleton
            .limbs
            .get(l)
            .map_or_else(String::new, |limb| format!("limb {:?}", limb.name)),
    };
    let parent_path = |unit: Unit| match unit {
        Unit::Joint(i) => format!("skeleton.joints[{i}].parent"),
        Unit::Limb(l) => format!("skeleton.limbs[{l}].parent"),
    };
    // Resolve every parent name first, so an unknown name is reported before any cycle.
    let mut parents: Vec<Option<Unit>> = Vec::with_capacity(units.len());
    for &unit in &units {
        let parent_name = match unit {
            Unit::Joint(i) => skeleton.joints.get(i).and_then(|j| j.parent.as_deref()),
            Unit::Limb(l) => skeleton
                .limbs
                .get(l)
                .and_then(|limb| limb.parent.as_deref()),
        };
        let parent = match parent_name {
            None => None,
            Some(name) => match names.get(name) {
                Some(place) => Some(place.unit()),
                None => {
                    return Err(PresetError::new(
                        parent_path(unit),
                        format!("no joint named {name:?}"),
                    ));
                }
            },
        };
        parents.push(parent);
    }

    const NEW: u8 = 0;
    const ON_WALK: u8 = 1;
    const PLACED: u8 = 2;
    let mut state = vec![NEW; units.len()];
    let mut order = Vec::with_capacity(units.len());
    let mut walk: Vec<Unit> = Vec::new();
    for &start in &units {
        walk.clear();
        let mut cursor = Some(start);
        while let Some(unit) = cursor {
            let s = slot(unit);
            match state.get(s).copied() {
                Some(NEW) => {
                    if let Some(flag) = state.get_mut(s) {
                        *flag = ON_WALK;
                    }
                    walk.push(unit);
                    cursor = parents.get(s).copied().flatten();
                }
                Some(ON_WALK) => {
                    let from = walk.iter().position(|&u| u == unit).unwrap_or(0);
                    let cycle = walk.get(from..).unwrap_or(&[]);
                    // Report at the cycle member listed first in the file.
                    let first = cycle
                        .iter()
                        .copied()
                        .min_by_key(|&u| slot(u))
                        .unwrap_or(unit);
                    let reason = if cycle.len() == 1 {
                        format!("{} is its own parent", describe(unit))
                    } else {
                        let at = cycle.iter().position(|&u| u == first).unwrap_or(0);
                        let mut chain: Vec<String> = cycle
                            .iter()
                            .cycle()
                            .skip(at)
                            .take(cycle.len())
                            .map(|&u| describe(u))
                            .collect();
                        chain.push(describe(first));
                        format!("parents form a cycle: {}", chain.join(" → "))
                    };
                    return Err(PresetError::new(parent_path(first), reason));
                }
                _ => break,
            }
        }
        for &unit in walk.iter().rev() {
            if let Some(flag) = state.get_mut(slot(unit)) {
                *flag = PLACED;
            }
            order.push(unit);
        }
    }
    Ok(order)
}

fn check_effectors(
    skeleton: &SkeletonSpec,
    names: &HashMap<&str, NamePlace>,
) -> Result<(), PresetError> {
    let mut seen: HashMap<&str, String> = HashMap::new();
    for (e, effector) in skeleton.effectors.iter().enumerate() {
        let at = |field: &str| format!("skeleton.effectors[{e}].{field}");
        check_name(&at("name"), &effector.name)?;
        if !names.contains_key(effector.joint.as_str()) {
            return Err(PresetError::new(
                at("joint"),
                format!("no joint named {:?}", effector.joint),
            ));
        }
        check_vector(&at("offset"), effector.offset)?;
        if let Some(first) = seen.insert(effector.name.as_str(), at("name")) {
            return Err(PresetError::new(
                at("name"),
                format!(
                    "duplicate effector name {:?} (first at {first})",
                    effector.name
                ),
            ));
        }
    }
    for (l, limb) in skeleton.limbs.iter().enumerate() {
        if let Some(name) = &limb.effector {
            let path = format!("skeleton.limbs[{l}].effector");
            if let Some(first) = seen.insert(name.as_str(), path.clone()) {
                return Err(PresetError::new(
                    path,
                    format!("duplicate effector name {name:?} (first at {first})"),
                ));
            }
        }
    }
    Ok(())
}

fn check_scenario(
    preset: &Preset,
    names: &HashMap<&str, NamePlace>,
    purpose: Purpose,
) -> Result<(), PresetError> {
    let scenario = &preset.scenario;
    if !(1..=MAX_FPS).contains(&scenario.fps) {
        return Err(PresetError::new(
            "scenario.fps",
            format!("must be between 1 and {MAX_FPS}"),
        ));
    }
    check_ik_options("scenario.ik", &scenario.ik)?;
    if scenario.physics.is_some() && scenario.engine != Engine::Physics {
        return Err(PresetError::new(
            "scenario.physics",
            format!(
                "belongs to engine \"physics\"; this scenario's engine is \"{}\"",
                scenario.engine.name()
            ),
        ));
    }
    match scenario.engine {
        Engine::Ik => {
            if scenario.poda.is_some() {
                return Err(PresetError::new(
                    "scenario.poda",
                    "belongs to engine \"poda\"; this scenario's engine is \"ik\"",
                ));
            }
            check_thesis(names, &scenario.thesis)?;
            // The thesis script, the one reader of the roles, runs only for this
            // engine and only when the scenario itself is run.
            if purpose == Purpose::Scenario {
                check_thesis_roles(&preset.skeleton, &scenario.thesis)?;
            }
            Ok(())
        }
        Engine::Poda => check_poda(&preset.skeleton, names, &scenario.poda_params()),
        Engine::Physics => {
            let Some(physics) = &scenario.physics else {
                return Err(PresetError::new(
                    "scenario.physics",
                    "engine \"physics\" needs the creature's physical model",
                ));
            };
            let known = |n: &str| matches!(names.get(n), Some(NamePlace::Joint(_)));
            physics.check("scenario.physics", &known)
        }
    }
}

/// PODA parameters: values in range, and every leg an effector on a chain
/// that passes through its hip joint.
fn check_poda(
    skeleton: &SkeletonSpec,
    names: &HashMap<&str, NamePlace>,
    poda: &PodaParams,
) -> Result<(), PresetError> {
    poda.check_values("scenario.poda")?;
    let limb_legs = skeleton
        .limbs
        .iter()
        .filter(|l| l.effector.is_some())
        .count();
    if poda.legs.is_empty() && limb_legs == 0 {
        return Err(PresetError::new(
            "scenario.poda.legs",
            "name the legs (effector and hip joint): the skeleton has no limbs with effectors",
        ));
    }
    let parents = joint_parents(skeleton);
    let effector_joint = |name: &str| -> Option<&str> {
        skeleton
            .effectors
            .iter()
            .find(|e| e.name == name)
            .map(|e| e.joint.as_str())
            .or_else(|| {
                skeleton.limbs.iter().find_map(|l| {
                    (l.effector.as_deref() == Some(name))
                        .then(|| l.joints.last().map(|row| row.name.as_str()))
                        .flatten()
                })
            })
    };
    for (i, leg) in poda.legs.iter().enumerate() {
        let at = |field: &str| format!("scenario.poda.legs[{i}].{field}");
        if let Some(name) = &leg.name {
            check_name(&at("name"), name)?;
        }
        let Some(mut joint) = effector_joint(&leg.effector) else {
            return Err(PresetError::new(
                at("effector"),
                format!("no effector called {:?}", leg.effector),
            ));
        };
        if !names.contains_key(leg.hip.as_str()) {
            return Err(PresetError::new(
                at("hip"),
                format!("no joint called {:?}", leg.hip),
            ));
        }
        let mut steps = 0;
        while joint != leg.hip {
            steps += 1;
            match parents.get(joint) {
                Some(Some(parent)) if steps <= MAX_JOINTS => joint = parent,
                _ => {
                    return Err(PresetError::new(
                        at("hip"),
                        format!(
                            "joint {:?} is not on the chain of effector {:?}",
                            leg.hip, leg.effector
                        ),
                    ));
                }
            }
        }
        if let Some(first) = poda.legs[..i]
            .iter()
            .position(|l| l.effector == leg.effector)
        {
            return Err(PresetError::new(
                at("effector"),
                format!("effector {:?} is already leg {first}", leg.effector),
            ));
        }
    }
    if let Some(phases) = &poda.phases {
        let legs = if poda.legs.is_empty() {
            limb_legs
        } else {
            poda.legs.len()
        };
        if phases.len() != legs {
            return Err(PresetError::new(
                "scenario.poda.phases",
                format!("needs one phase per leg ({legs}), got {}", phases.len()),
            ));
        }
    }
    Ok(())
}

/// Parent joint name of every joint name (`None` for joints on the root).
fn joint_parents(skeleton: &SkeletonSpec) -> HashMap<&str, Option<&str>> {
    let mut parents = HashMap::new();
    for joint in &skeleton.joints {
        parents.insert(joint.name.as_str(), joint.parent.as_deref());
    }
    for limb in &skeleton.limbs {
        let mut parent = limb.parent.as_deref();
        for row in &limb.joints {
            parents.insert(row.name.as_str(), parent);
            parent = Some(row.name.as_str());
        }
    }
    parents
}

/// IK options: λ in (0, 10], γmax and max_step in (0, π], rank tolerance in
/// (0, 1), null-space gain in [0, 10], 1..=16 limit passes. Shared by presets
/// and by settings restored from storage.
///
/// # Errors
/// A [`PresetError`] naming the first value out of range under `prefix`.
pub fn check_ik_options(prefix: &str, ik: &IkOptions) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    if !(ik.lambda > 0.0 && ik.lambda <= 10.0) {
        return Err(PresetError::new(at("lambda"), "must be in (0, 10] metres"));
    }
    if !(ik.gamma_max > 0.0 && ik.gamma_max <= PI) {
        return Err(PresetError::new(
            at("gamma_max"),
            "must be in (0, π] radians",
        ));
    }
    if !(ik.max_step > 0.0 && ik.max_step <= PI) {
        return Err(PresetError::new(at("max_step"), "must be in (0, π]"));
    }
    if !(ik.rank_tolerance > 0.0 && ik.rank_tolerance < 1.0) {
        return Err(PresetError::new(at("rank_tolerance"), "must be in (0, 1)"));
    }
    if !(0.0..=10.0).contains(&ik.null_space_gain) {
        return Err(PresetError::new(
            at("null_space_gain"),
            "must be in [0, 10]",
        ));
    }
    if !(1..=16).contains(&ik.limit_passes) {
        return Err(PresetError::new(
            at("limit_passes"),
            "must be between 1 and 16",
        ));
    }
    Ok(())
}

fn check_cycle(prefix: &str, shape: &CycleShape) -> Result<(), PresetError> {
    let at = |field: &str| format!("{prefix}.{field}");
    if !(shape.frequency_hz > 0.0 && shape.frequency_hz <= MAX_FREQUENCY_HZ) {
        return Err(PresetError::new(
            at("frequency_hz"),
            format!("must be in (0, {MAX_FREQUENCY_HZ}] Hz"),
        ));
    }
    for (field, v) in [
        ("front_foot", shape.front_foot),
        ("back_foot", shape.back_foot),
        ("front_hand", shape.front_hand),
        ("back_hand", shape.back_hand),
    ] {
        check_vector(&at(field), v)?;
    }
    if !(shape.root_height_m.is_finite() && shape.root_height_m > 0.0) {
        return Err(PresetError::new(
            at("root_height_m"),
            "must be a positive number of metres",
        ));
    }
    for (field, value) in [
        ("step_height_m", shape.step_height_m),
        ("bounce_m", shape.bounce_m),
    ] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(PresetError::new(
                at(field),
                "must be a finite number of metres ≥ 0",
            ));
        }
    }
    Ok(())
}

/// Thesis parameters and wounded joints (engine `ik`); the roles are checked
/// apart, by [`check_thesis_roles`], where the script will run.
fn check_thesis(
    names: &HashMap<&str, NamePlace>,
    thesis: &ThesisParams,
) -> Result<(), PresetError> {
    check_thesis_values("scenario.thesis", thesis)?;
    let mut wounded_seen: HashMap<&str, usize> = HashMap::new();
    for (i, wounded) in thesis.wounded.iter().enumerate() {
        let at = |field: &str| format!("scenario.thesis.wounded[{i}].{field}");
        if !names.contains_key(wounded.joint.as_str()) {
            return Err(PresetError::new(
                at("joint"),
                format!("no joint named {:?}", wounded.joint),
            ));
        }
        if let Some(first) = wounded_seen.insert(wounded.joint.as_str(), i) {
            return Err(PresetError::new(
                at("joint"),
                format!(
                    "joint {:?} is already listed at scenario.thesis.wounded[{first}]",
                    wounded.joint
                ),
            ));
        }
    }
    Ok(())
}

/// The ranges of every thesis parameter that does not depend on the skeleton
/// (cycle shapes, slowdown, speed, iterations, posture gain, start ramp and the
/// wounded weights), shared by presets and by live edits of a running driver.
/// Paths start with `prefix` (e.g. `scenario.thesis`; empty for none).
///
/// # Errors
/// A [`PresetError`] naming the first value out of range.
pub fn check_thesis_values(prefix: &str, thesis: &ThesisParams) -> Result<(), PresetError> {
    let at = |field: &str| {
        if prefix.is_empty() {
            field.to_owned()
        } else {
            format!("{prefix}.{field}")
        }
    };
    check_cycle(&at("walk"), &thesis.walk)?;
    check_cycle(&at("run"), &thesis.run)?;
    if !(MIN_SLOWDOWN..=MAX_SLOWDOWN).contains(&thesis.slowdown) {
        return Err(PresetError::new(
            at("slowdown"),
            format!("must be between {MIN_SLOWDOWN} and {MAX_SLOWDOWN}"),
        ));
    }
    if let Some(speed) = thesis.speed_mps
        && !(0.0..=MAX_SPEED_MPS).contains(&speed)
    {
        return Err(PresetError::new(
            at("speed_mps"),
            format!("must be between 0 and {MAX_SPEED_MPS} m/s"),
        ));
    }
    if !(1..=MAX_ITERATIONS_PER_FRAME).contains(&thesis.iterations_per_frame) {
        return Err(PresetError::new(
            at("iterations_per_frame"),
            format!("must be between 1 and {MAX_ITERATIONS_PER_FRAME}"),
        ));
    }
    if !(0.0..=1.0).contains(&thesis.posture_gain) {
        return Err(PresetError::new(
            at("posture_gain"),
            "must be between 0 and 1",
        ));
    }
    if !(0.0..=MAX_START_RAMP_S).contains(&thesis.start_ramp_s) {
        return Err(PresetError::new(
            at("start_ramp_s"),
            format!("must be between 0 and {MAX_START_RAMP_S} seconds"),
        ));
    }
    for (i, wounded) in thesis.wounded.iter().enumerate() {
        let at = |field: &str| at(&format!("wounded[{i}].{field}"));
        if !(0.0..=MAX_WOUNDED_MULTIPLY).contains(&wounded.multiply) {
            return Err(PresetError::new(
                at("multiply"),
                format!("must be between 0 and {MAX_WOUNDED_MULTIPLY}"),
            ));
        }
        if !(wounded.add.is_finite() && wounded.add.abs() <= MAX_WOUNDED_ADD) {
            return Err(PresetError::new(
                at("add"),
                format!("must be between -{MAX_WOUNDED_ADD} and {MAX_WOUNDED_ADD} radians"),
            ));
        }
    }
    Ok(())
}

/// Roles: the thesis script drives four effectors, so when the skeleton has at
/// least [`THESIS_ROLE_COUNT`] effectors each role must name a distinct existing
/// effector; a skeleton with fewer effectors cannot run the script (it can still
/// track recorded targets) and its roles are not checked. Called for engine `ik`
/// and [`Purpose::Scenario`] only.
fn check_thesis_roles(skeleton: &SkeletonSpec, thesis: &ThesisParams) -> Result<(), PresetError> {
    let (_, effector_count) = totals(skeleton);
    if effector_count >= THESIS_ROLE_COUNT {
        let effector_names: Vec<&str> = skeleton
            .effectors
            .iter()
            .map(|e| e.name.as_str())
            .chain(skeleton.limbs.iter().filter_map(|l| l.effector.as_deref()))
            .collect();
        let roles = &thesis.roles;
        let mut used: HashMap<&str, &str> = HashMap::new();
        for (role, name) in [
            ("left_foot", &roles.left_foot),
            ("right_foot", &roles.right_foot),
            ("left_hand", &roles.left_hand),
            ("right_hand", &roles.right_hand),
        ] {
            let path = format!("scenario.thesis.roles.{role}");
            if !effector_names.contains(&name.as_str()) {
                return Err(PresetError::new(
                    path,
                    format!("no effector named {name:?}"),
                ));
            }
            if let Some(other) = used.insert(name.as_str(), role) {
                return Err(PresetError::new(
                    path,
                    format!(
                        "effector {name:?} already plays {other}; each role needs its own effector"
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The unit vector along `v`, robust to very small and very large components;
/// `None` for a zero or non-finite vector.
pub(crate) fn normalized(v: DVec3) -> Option<DVec3> {
    let scale = v.abs().max_element();
    if !(scale.is_finite() && scale > 0.0) {
        return None;
    }
    (v / scale).try_normalize()
}
