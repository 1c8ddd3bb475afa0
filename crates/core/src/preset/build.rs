//! From a validated [`Preset`] to a [`Creature`]: joints in topological order,
//! DH limbs expanded with [`DhLimb::append_to`] (PODA), effectors resolved by
//! name, and the [`Skeleton`] built (She 2006 §3.1–3.2). A map from each built
//! joint and effector back to its place in the file turns any [`SkeletonError`]
//! path (`joints[3].axis`) into a JSON path (`skeleton.joints[7].axis`).

use std::collections::HashMap;

use glam::{DMat3, DQuat, DVec3};

use super::limits::MAX_PRESET_BYTES;
use super::poda::PodaLegSpec;
use super::scenario::{Engine, Scenario};
use super::schema::Preset;
use super::validate::{self, Purpose, Unit};
use super::{PresetError, ROOT_PATH};
use crate::skeleton::{DhJoint, DhLimb};
use crate::{Effector, Joint, Pose, RootTransform, Skeleton, SkeletonError};

/// An immutable creature built from a preset, plus the preset's default scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Creature {
    /// The preset's name.
    pub name: String,
    /// The preset's description.
    pub description: String,
    /// The joint tree and effectors.
    pub skeleton: Skeleton,
    /// World position of the root at reset, metres.
    pub root_position: DVec3,
    /// What runs on the creature by default.
    pub scenario: Scenario,
}

impl Creature {
    /// Parses, validates and builds a preset in one step.
    ///
    /// # Errors
    /// The first [`PresetError`] found, with the JSON path of the offending value.
    pub fn from_json(json: &str) -> Result<Self, PresetError> {
        Preset::from_json(json)?.build()
    }

    /// Parses, validates and builds a preset for `purpose`: [`Purpose::Scenario`]
    /// is [`Creature::from_json`]; [`Purpose::Tracking`] skips the rules only the
    /// scenario's own motion needs (the thesis roles).
    ///
    /// # Errors
    /// The first [`PresetError`] found, with the JSON path of the offending value.
    pub fn from_json_for(json: &str, purpose: Purpose) -> Result<Self, PresetError> {
        Preset::from_json_for(json, purpose)?.build_for(purpose)
    }

    /// The reset pose: the root at `root_position`, unrotated, every joint at its rest value.
    #[must_use]
    pub fn rest_pose(&self) -> Pose {
        Pose {
            root: RootTransform {
                position: self.root_position,
                rotation: DMat3::IDENTITY,
            },
            joints: self.skeleton.rest_values(),
        }
    }
}

impl Preset {
    /// Parses and validates a preset. The size limit ([`MAX_PRESET_BYTES`]) is checked on
    /// the raw text first; syntax errors name the path reached and the line and column.
    ///
    /// # Errors
    /// A [`PresetError`] naming the JSON path: too large, malformed, an unknown or
    /// missing field, a wrong type, or any rule of [`Preset::validate`].
    pub fn from_json(json: &str) -> Result<Self, PresetError> {
        Self::from_json_for(json, Purpose::Scenario)
    }

    /// [`Preset::from_json`], validated for `purpose` (see [`Preset::validate_for`]).
    ///
    /// # Errors
    /// As [`Preset::from_json`], less the rules `purpose` does not need.
    pub fn from_json_for(json: &str, purpose: Purpose) -> Result<Self, PresetError> {
        if json.len() > MAX_PRESET_BYTES {
            return Err(PresetError::new(
                ROOT_PATH,
                format!(
                    "preset is {} bytes, more than the limit of {MAX_PRESET_BYTES} bytes (256 KiB)",
                    json.len()
                ),
            ));
        }
        let start = json.trim_start().chars().next();
        if start.is_some_and(|c| c != '{') {
            return Err(PresetError::new(
                ROOT_PATH,
                "a preset must be a JSON object ({ … })",
            ));
        }
        let mut deserializer = serde_json::Deserializer::from_str(json);
        let mut preset: Preset = serde_path_to_error::deserialize(&mut deserializer)
            .map_err(|e| PresetError::from_serde(&e).with_non_finite_hint(json, e.inner()))?;
        deserializer
            .end()
            .map_err(|e| PresetError::new(ROOT_PATH, e.to_string()))?;
        preset.scenario.ik.method = preset.scenario.method;
        super::versions::write_in_old_defaults(&mut preset, json);
        preset.validate_for(purpose)?;
        Ok(preset)
    }

    /// Checks every rule without building anything: counts, finite numbers, positive
    /// sizes, ordered limits with rest and center inside, gains in [0, 1], unique
    /// names, parents that exist and form no cycle, effectors on existing joints,
    /// sane IK options and thesis parameters.
    ///
    /// # Errors
    /// The first [`PresetError`] found.
    pub fn validate(&self) -> Result<(), PresetError> {
        self.validate_for(Purpose::Scenario)
    }

    /// Checks the rules that apply when the preset is loaded for `purpose`:
    /// [`Purpose::Scenario`] is [`Preset::validate`]; [`Purpose::Tracking`] leaves
    /// out the thesis roles, which only the target script reads.
    ///
    /// # Errors
    /// The first [`PresetError`] found.
    pub fn validate_for(&self, purpose: Purpose) -> Result<(), PresetError> {
        validate::check(self, purpose).map(drop)
    }

    /// Validates and builds the creature.
    ///
    /// Joint order: parents before children, otherwise the file's order (listed joints
    /// and limbs interleaved as the parents require). Effector order: `skeleton.effectors`
    /// in file order, then limb effectors in limb order.
    ///
    /// # Errors
    /// Any [`PresetError`] of [`Preset::validate`].
    pub fn build(&self) -> Result<Creature, PresetError> {
        self.build_for(Purpose::Scenario)
    }

    /// Validates for `purpose` (see [`Preset::validate_for`]) and builds the creature.
    ///
    /// # Errors
    /// Any [`PresetError`] of [`Preset::validate_for`].
    pub fn build_for(&self, purpose: Purpose) -> Result<Creature, PresetError> {
        let plan = validate::check(self, purpose)?;
        let spec = &self.skeleton;
        let joint_total =
            spec.joints.len() + spec.limbs.iter().map(|l| l.joints.len()).sum::<usize>();
        let mut joints: Vec<Joint> = Vec::with_capacity(joint_total);
        let mut joint_sources: Vec<JointSource> = Vec::with_capacity(joint_total);
        let mut index: HashMap<&str, usize> = HashMap::new();
        let mut limb_effectors: Vec<(usize, Effector)> = Vec::new();
        let parent_index =
            |index: &HashMap<&str, usize>, parent: Option<&str>, path: String| match parent {
                None => Ok(None),
                Some(name) => index
                    .get(name)
                    .copied()
                    .map(Some)
                    .ok_or_else(|| PresetError::new(path, format!("no joint named {name:?}"))),
            };
        for unit in plan.order {
            match unit {
                Unit::Joint(i) => {
                    let Some(joint) = spec.joints.get(i) else {
                        continue;
                    };
                    let parent = parent_index(
                        &index,
                        joint.parent.as_deref(),
                        format!("skeleton.joints[{i}].parent"),
                    )?;
                    let axis = validate::normalized(joint.axis).ok_or_else(|| {
                        PresetError::new(
                            format!("skeleton.joints[{i}].axis"),
                            "must be a non-zero vector",
                        )
                    })?;
                    index.insert(joint.name.as_str(), joints.len());
                    joint_sources.push(JointSource::Joint(i));
                    joints.push(Joint {
                        name: joint.name.clone(),
                        parent,
                        kind: joint.kind.into(),
                        axis,
                        offset: joint.offset,
                        frame: rotation(joint.frame_rotation),
                        limits: joint.limits,
                        rest: joint.rest,
                        center: joint.center.unwrap_or(joint.rest),
                        gain: joint.gain,
                        size: joint.size,
                    });
                }
                Unit::Limb(l) => {
                    let Some(limb) = spec.limbs.get(l) else {
                        continue;
                    };
                    let parent = parent_index(
                        &index,
                        limb.parent.as_deref(),
                        format!("skeleton.limbs[{l}].parent"),
                    )?;
                    let dh = DhLimb {
                        parent,
                        base_offset: limb.base_offset,
                        base_frame: rotation(limb.base_rotation),
                        joints: limb
                            .joints
                            .iter()
                            .map(|row| DhJoint {
                                name: row.name.clone(),
                                kind: row.kind.into(),
                                a: row.a,
                                alpha: row.alpha,
                                d: row.d,
                                theta: row.theta,
                                limits: row.limits,
                                center: row.center.unwrap_or_else(|| row.rest()),
                                gain: row.gain,
                            })
                            .collect(),
                        effector: limb.effector.clone(),
                    };
                    let first = joints.len();
                    let mut effectors = Vec::new();
                    dh.append_to(&mut joints, &mut effectors);
                    for (r, row) in limb.joints.iter().enumerate() {
                        index.insert(row.name.as_str(), first + r);
                        joint_sources.push(JointSource::LimbRow(l, r));
                    }
                    limb_effectors.extend(effectors.into_iter().map(|e| (l, e)));
                }
            }
        }
        let mut effectors = Vec::with_capacity(spec.effectors.len() + limb_effectors.len());
        let mut effector_sources = Vec::with_capacity(effectors.capacity());
        for (e, effector) in spec.effectors.iter().enumerate() {
            let joint = index.get(effector.joint.as_str()).copied().ok_or_else(|| {
                PresetError::new(
                    format!("skeleton.effectors[{e}].joint"),
                    format!("no joint named {:?}", effector.joint),
                )
            })?;
            effectors.push(Effector {
                name: effector.name.clone(),
                joint,
                offset: effector.offset,
                orientation: effector.orientation,
            });
            effector_sources.push(EffectorSource::Effector(e));
        }
        for (l, effector) in limb_effectors {
            effectors.push(effector);
            effector_sources.push(EffectorSource::Limb(l));
        }
        let skeleton = Skeleton::new(joints, effectors)
            .map_err(|e| translate(&e, self, &joint_sources, &effector_sources))?;
        Ok(Creature {
            name: self.name.clone(),
            description: self.description.clone(),
            skeleton,
            root_position: spec.root.position,
            scenario: self.built_scenario(),
        })
    }

    /// The scenario with defaults that depend on the skeleton filled in: a
    /// PODA scenario without listed legs gets one leg per limb with an
    /// effector (hip = the limb's first joint), in limb order.
    fn built_scenario(&self) -> Scenario {
        let mut scenario = self.scenario.clone();
        if scenario.engine == Engine::Poda {
            let mut poda = scenario.poda_params();
            if poda.legs.is_empty() {
                poda.legs = self
                    .skeleton
                    .limbs
                    .iter()
                    .filter_map(|limb| {
                        Some(PodaLegSpec {
                            name: Some(limb.name.clone()),
                            effector: limb.effector.clone()?,
                            hip: limb.joints.first()?.name.clone(),
                        })
                    })
                    .collect();
            }
            scenario.poda = Some(poda);
        }
        scenario
    }
}

/// Rotation matrix of a rotation vector (axis × angle, radians).
fn rotation(v: DVec3) -> DMat3 {
    DMat3::from_quat(DQuat::from_scaled_axis(v))
}

/// Where a built joint came from.
#[derive(Clone, Copy, Debug)]
enum JointSource {
    /// `skeleton.joints[i]`.
    Joint(usize),
    /// `skeleton.limbs[l].joints[r]`.
    LimbRow(usize, usize),
}

/// Where a built effector came from.
#[derive(Clone, Copy, Debug)]
enum EffectorSource {
    /// `skeleton.effectors[e]`.
    Effector(usize),
    /// The effector of `skeleton.limbs[l]`.
    Limb(usize),
}

/// Turns a skeleton path (`joints[3].axis`, `effectors[1].joint`, `joints`) into a JSON path.
fn translate(
    error: &SkeletonError,
    preset: &Preset,
    joints: &[JointSource],
    effectors: &[EffectorSource],
) -> PresetError {
    let (head, field) = match error.path.split_once('.') {
        Some((head, field)) => (head, Some(field)),
        None => (error.path.as_str(), None),
    };
    let indexed = head.split_once('[').and_then(|(list, rest)| {
        rest.strip_suffix(']')
            .map(|n| (list, n.parse::<usize>().ok()))
    });
    let path = match indexed {
        Some(("joints", Some(j))) => match joints.get(j) {
            Some(JointSource::Joint(i)) => {
                format!(
                    "skeleton.joints[{i}]{}",
                    field.map_or_else(String::new, json_joint_field)
                )
            }
            Some(JointSource::LimbRow(l, r)) => {
                let row = preset
                    .skeleton
                    .limbs
                    .get(*l)
                    .and_then(|limb| limb.joints.get(*r));
                let field = match (field, row) {
                    (Some("rest"), Some(row)) => format!(".{}", row.rest_field()),
                    (Some(f @ ("name" | "limits" | "center" | "gain")), _) => format!(".{f}"),
                    _ => String::new(),
                };
                format!("skeleton.limbs[{l}].joints[{r}]{field}")
            }
            None => "skeleton.joints".to_owned(),
        },
        Some(("effectors", Some(e))) => match effectors.get(e) {
            Some(EffectorSource::Effector(i)) => {
                format!(
                    "skeleton.effectors[{i}]{}",
                    field.map_or_else(String::new, |f| format!(".{f}"))
                )
            }
            Some(EffectorSource::Limb(l)) => format!("skeleton.limbs[{l}].effector"),
            None => "skeleton.effectors".to_owned(),
        },
        _ => format!("skeleton.{}", error.path),
    };
    PresetError::new(path, error.reason.clone())
}

/// A `Joint` field name as written in JSON (`frame` is `frame_rotation` there).
fn json_joint_field(field: &str) -> String {
    match field {
        "frame" => ".frame_rotation".to_owned(),
        other => format!(".{other}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Skeleton paths are mapped back through the build order to file indices.
    #[test]
    fn skeleton_paths_become_json_paths() {
        let preset = Preset::from_json(
            r#"{"format": "gaitlab-preset/1", "name": "t",
                "skeleton": {"root": {"position": [0, 0, 0]},
                  "joints": [{"name": "child", "parent": "base", "axis": [1, 0, 0], "offset": [0, 1, 0]},
                             {"name": "base", "axis": [0, 1, 0], "offset": [0, 0, 0]}],
                  "limbs": [{"name": "arm", "parent": "child",
                             "joints": [{"name": "r0", "a": 0.1}, {"name": "r1", "type": "prismatic", "d": 0.1}],
                             "effector": "tip"}],
                  "effectors": [{"name": "top", "joint": "child"}]},
                "scenario": {"engine": "ik"}}"#,
        )
        .expect("valid");
        let joints = [
            JointSource::Joint(1),
            JointSource::Joint(0),
            JointSource::LimbRow(0, 0),
            JointSource::LimbRow(0, 1),
        ];
        let effectors = [EffectorSource::Effector(0), EffectorSource::Limb(0)];
        let path = |skeleton_path: &str| {
            let error = SkeletonError {
                path: skeleton_path.to_owned(),
                reason: "r".to_owned(),
            };
            translate(&error, &preset, &joints, &effectors).path
        };
        assert_eq!(path("joints[0].axis"), "skeleton.joints[1].axis");
        assert_eq!(path("joints[1].frame"), "skeleton.joints[0].frame_rotation");
        assert_eq!(
            path("joints[2].limits"),
            "skeleton.limbs[0].joints[0].limits"
        );
        assert_eq!(path("joints[2].rest"), "skeleton.limbs[0].joints[0].theta");
        assert_eq!(path("joints[3].rest"), "skeleton.limbs[0].joints[1].d");
        assert_eq!(path("joints[3].axis"), "skeleton.limbs[0].joints[1]");
        assert_eq!(path("effectors[0].offset"), "skeleton.effectors[0].offset");
        assert_eq!(path("effectors[1].name"), "skeleton.limbs[0].effector");
        assert_eq!(path("joints"), "skeleton.joints");
        assert_eq!(path("joints[9].axis"), "skeleton.joints");
        let creature = preset.build().expect("builds");
        let names: Vec<&str> = creature
            .skeleton
            .joints()
            .iter()
            .map(|j| j.name.as_str())
            .collect();
        assert_eq!(names, ["base", "child", "r0", "r1"]);
    }
}
