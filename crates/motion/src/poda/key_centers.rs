//! Centre angles and gains carried by PODA's key leg positions (Girard &
//! Maciejewski 1985, "Leg Support and Transfer Trajectories": "a key
//! position records the position of the foot (as a control point in the
//! spline) and the center angles and gains that are associated with that
//! position"; the centres and gains are eq. 6's `θcᵢ`, `αᵢ`, which "may
//! change dynamically").
//!
//! `scenario.poda.transfer_key_centers` gives, per key position, centres and
//! gains for joints of the legs, by a joint's place in its leg (every leg) or
//! by its name ([`gaitlab_core::preset::poda::KeyCenters`]). [`resolve`]
//! turns them into, per leg, the joints some key names and each key's value
//! (`None` where a key leaves the joint its own).
//!
//! The reading: the centre and gain are a second curve on the foot's own
//! spline parameter `u` — the transfer's share of its time, the control
//! points lift-off, the keys, touchdown evenly spaced in it — through the
//! same kind of curve, a Catmull-Rom, with the joint's own (skeleton)
//! centre and gain at lift-off and touchdown and wherever a key leaves it
//! unnamed. The joint's centre then reaches a key's value at the moment the
//! foot passes that key's point (the paper's key position holds both), its
//! rate of change has no corner at a key (a linear blend would kink there,
//! and the IK's null-space step would follow the kink), and it equals the
//! joint's own at lift-off and touchdown, so the support's own centres take
//! over without a jump. A Catmull-Rom may overshoot between keys: the gain
//! is kept in [0, 1] and the centre within the joint's limits.

use gaitlab_core::Skeleton;
use gaitlab_core::preset::poda::{KeyCenters, key_center_place};
use glam::DVec3;

use super::leg_ik::LegIk;
use super::spline::eval_open;
use crate::DriverError;

/// One leg joint that some key position gives a centre and gain.
#[derive(Clone, Debug, PartialEq)]
pub struct KeyCenterJoint {
    /// The joint's place in its leg (the hip 0).
    pub place: usize,
    /// Per key position, its `[center, gain]`; `None`: the joint's own there.
    pub keys: Vec<Option<[f64; 2]>>,
}

/// One leg's joints that key positions give centres and gains (empty: none).
pub type LegKeyCenters = Vec<KeyCenterJoint>;

/// Resolves the key positions' `centers` (one object per key) against the
/// legs, each `(name, joints hip first)`: per leg, in leg order, the joints
/// some key names with each key's value (a joint's name over its place).
/// `at` is the field's path; errors name `{at}[i].{key}`.
///
/// # Errors
/// A [`DriverError`] at `{at}[i].{key}` for a place some leg lacks, a name
/// that is no joint or belongs to no leg, or a centre outside a joint's
/// limits (naming the joint).
pub fn resolve<'a>(
    skeleton: &Skeleton,
    legs: impl Iterator<Item = (&'a str, &'a [usize])> + Clone,
    centers: &[KeyCenters],
    at: &str,
) -> Result<Vec<LegKeyCenters>, DriverError> {
    for (i, object) in centers.iter().enumerate() {
        for key in object.keys() {
            let path = || format!("{at}[{i}].{key}");
            if let Some(place) = key_center_place(key) {
                if let Some((name, joints)) = legs.clone().find(|(_, j)| j.len() <= place) {
                    return Err(DriverError::new(
                        path(),
                        format!(
                            "leg {name:?} has no joint at place {place} (its {} joints are places 0 to {})",
                            joints.len(),
                            joints.len().saturating_sub(1)
                        ),
                    ));
                }
            } else {
                let Some(j) = skeleton.joint_index(key) else {
                    return Err(DriverError::new(path(), format!("no joint called {key:?}")));
                };
                if !legs.clone().any(|(_, joints)| joints.contains(&j)) {
                    return Err(DriverError::new(
                        path(),
                        format!("{key:?} belongs to no leg"),
                    ));
                }
            }
        }
    }
    let all = skeleton.joints();
    let mut out = Vec::new();
    for (_, joints) in legs {
        let mut leg = LegKeyCenters::new();
        for (place, &j) in joints.iter().enumerate() {
            let joint = &all[j];
            let place_key = place.to_string();
            let by_name = key_center_place(&joint.name).is_none();
            let mut keys = Vec::with_capacity(centers.len());
            for (i, object) in centers.iter().enumerate() {
                let entry = by_name
                    .then(|| object.get_key_value(joint.name.as_str()))
                    .flatten()
                    .or_else(|| object.get_key_value(place_key.as_str()));
                let Some((key, &[center, gain])) = entry else {
                    keys.push(None);
                    continue;
                };
                if joint.clamp(center) != center {
                    let (lo, hi) = joint.limits.unwrap_or((f64::NAN, f64::NAN));
                    return Err(DriverError::new(
                        format!("{at}[{i}].{key}"),
                        format!(
                            "the centre {center} is outside {:?}'s limits [{lo}, {hi}]",
                            joint.name
                        ),
                    ));
                }
                keys.push(Some([center, gain]));
            }
            if keys.iter().any(Option::is_some) {
                leg.push(KeyCenterJoint { place, keys });
            }
        }
        out.push(leg);
    }
    Ok(out)
}

/// Sets `ik`'s centres and gains for one leg: while it transfers
/// (`transfer` = `Some(u)`, the foot spline's parameter in [0, 1]) each
/// joint of `leg` on its Catmull-Rom through its own value, the keys' and its
/// own again (module docs); while it supports (`None`) its own. `scratch`
/// holds the control points (no allocation once it holds the keys plus two).
pub fn apply(
    skeleton: &Skeleton,
    leg: &[KeyCenterJoint],
    ik: &mut LegIk,
    transfer: Option<f64>,
    scratch: &mut Vec<DVec3>,
) {
    let Some(u) = transfer else {
        ik.clear_center_overrides();
        return;
    };
    for key_joint in leg {
        let Some(&j) = ik.joints().get(key_joint.place) else {
            continue;
        };
        let joint = &skeleton.joints()[j];
        let own = DVec3::new(joint.center, joint.gain, 0.0);
        scratch.clear();
        scratch.push(own);
        scratch.extend(
            key_joint
                .keys
                .iter()
                .map(|key| key.map_or(own, |[center, gain]| DVec3::new(center, gain, 0.0))),
        );
        scratch.push(own);
        let at = eval_open(scratch, u);
        ik.set_center_override(
            key_joint.place,
            Some([joint.clamp(at.x), at.y.clamp(0.0, 1.0)]),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use gaitlab_core::Joint;

    /// Two three-joint legs: `a_hip`, `a_knee` (limits [0, 2]), `a_ankle`;
    /// `b_…` the same, and a tail joint on no leg.
    fn two_legs() -> Skeleton {
        let mut joints = Vec::new();
        for side in ["a", "b"] {
            let base = joints.len();
            joints.push(Joint::revolute(
                &format!("{side}_hip"),
                None,
                DVec3::ZERO,
                DVec3::X,
            ));
            joints.push(
                Joint::revolute(
                    &format!("{side}_knee"),
                    Some(base),
                    DVec3::new(0.0, -0.4, 0.0),
                    DVec3::X,
                )
                .with_limits(0.0, 2.0),
            );
            joints.push(Joint::revolute(
                &format!("{side}_ankle"),
                Some(base + 1),
                DVec3::new(0.0, -0.4, 0.0),
                DVec3::X,
            ));
        }
        joints.push(Joint::revolute("tail", None, DVec3::ZERO, DVec3::Y));
        joints[1].center = 0.5;
        joints[1].gain = 0.2;
        Skeleton::new(joints, Vec::new()).expect("valid")
    }

    const LEGS: [(&str, &[usize]); 2] = [("a", &[0, 1, 2]), ("b", &[3, 4, 5])];

    fn object(entries: &[(&str, [f64; 2])]) -> KeyCenters {
        entries.iter().map(|(k, v)| ((*k).to_owned(), *v)).collect()
    }

    #[test]
    fn places_apply_to_every_leg_and_names_override_them() {
        let skeleton = two_legs();
        let centers = [
            object(&[]),
            object(&[("1", [1.5, 1.0]), ("b_knee", [0.3, 0.6])]),
        ];
        let legs = resolve(&skeleton, LEGS.into_iter(), &centers, "k").expect("valid");
        assert_eq!(
            legs[0],
            vec![KeyCenterJoint {
                place: 1,
                keys: vec![None, Some([1.5, 1.0])]
            }]
        );
        assert_eq!(legs[1][0].keys, vec![None, Some([0.3, 0.6])]);
    }

    #[test]
    fn bad_entries_are_refused_naming_the_key() {
        let skeleton = two_legs();
        for (entry, path, words) in [
            (("3", [0.0, 0.5]), "k[0].3", "no joint at place 3"),
            (("knee", [0.0, 0.5]), "k[0].knee", "no joint called"),
            (("tail", [0.0, 0.5]), "k[0].tail", "belongs to no leg"),
            (
                ("1", [2.5, 0.5]),
                "k[0].1",
                "outside \"a_knee\"'s limits [0, 2]",
            ),
        ] {
            let error = resolve(&skeleton, LEGS.into_iter(), &[object(&[entry])], "k")
                .expect_err("refused");
            assert_eq!(error.path, path);
            assert!(error.reason.contains(words), "{error}");
        }
    }

    #[test]
    fn the_centre_follows_the_keys_and_is_its_own_at_both_ends() {
        let skeleton = two_legs();
        let centers = [object(&[]), object(&[("1", [1.5, 1.0])]), object(&[])];
        let legs = resolve(&skeleton, LEGS.into_iter(), &centers, "k").expect("valid");
        let mut ik = LegIk::new(vec![0, 1, 2], usize::MAX);
        let mut scratch = Vec::new();
        let mut at = |u: Option<f64>| {
            apply(&skeleton, &legs[0], &mut ik, u, &mut scratch);
            ik.center_of(&skeleton, 1).expect("knee")
        };
        // Control points at u = 0, ¼, ½, ¾, 1: own, own, key, own, own.
        assert_eq!(at(Some(0.0)), [0.5, 0.2]);
        assert_eq!(at(Some(0.5)), [1.5, 1.0]);
        assert_eq!(at(Some(1.0)), [0.5, 0.2]);
        assert_eq!(at(None), [0.5, 0.2]);
        // Smooth (a step of u = 0.01 changes the centre by under 0.08 rad,
        // and the change by under 0.01), and the Catmull-Rom's undershoot
        // before the key is 4/54 of the key's step: 0.074 rad below 0.5.
        let (mut last, mut last_step, mut lowest) = (at(Some(0.0)), 0.0_f64, 0.5_f64);
        for k in 1..=100 {
            let now = at(Some(f64::from(k) / 100.0));
            let step = now[0] - last[0];
            assert!(step.abs() < 0.08, "smooth at {k}: {step}");
            assert!((step - last_step).abs() < 0.01, "no corner at {k}");
            assert!((0.0..=1.0).contains(&now[1]));
            lowest = lowest.min(now[0]);
            (last, last_step) = (now, step);
        }
        assert!((lowest - (0.5 - 4.0 / 54.0)).abs() < 1e-3, "{lowest}");
    }
}
