//! The kangaroo's leg as a planar hip–knee–ankle chain (Raibert & Hodgins
//! 1991, "Kangaroo control": the toe placed for eq. 3 through the hip and
//! knee, the ankle held at its spring's rest; in stance the knee kept on the
//! thrust line from the toe through the centre of mass). Angles are absolute
//! in the sagittal plane (rad about +x, 0 hanging down).

use gaitlab_core::portable::Portable;
use glam::{DVec2, DVec3};

use crate::creatures::PhysicalCreature;

/// The leg's link lengths (m), read from the model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LegGeometry {
    /// Hip to knee (m).
    pub(crate) thigh: f64,
    /// Knee to ankle (m).
    pub(crate) shin: f64,
    /// Ankle to toe (m).
    pub(crate) foot: f64,
}

/// The kangaroo's leg geometry: thigh and shin from the model's body
/// placements, the foot from its contact point; `None` without a leg.
pub(crate) fn leg_geometry(creature: &PhysicalCreature) -> Option<LegGeometry> {
    let leg = creature.legs.first()?;
    let bodies = creature.model.bodies();
    let shin_body = bodies.get(leg.foot_body)?.parent?;
    Some(LegGeometry {
        thigh: bodies.get(shin_body)?.placement.pos.length(),
        shin: bodies.get(leg.foot_body)?.placement.pos.length(),
        foot: leg.foot_point.length(),
    })
}

/// Unit direction (forward, up) of a link at absolute angle `a` (rad about +x,
/// 0 hanging down, positive swinging back).
pub(crate) fn dir(a: f64) -> DVec2 {
    DVec2::new(-a.psin(), -a.pcos())
}

/// Absolute angle of the direction `v` (forward, up).
pub(crate) fn angle_of(v: DVec2) -> f64 {
    (-v.x).patan2(-v.y)
}

/// A world point in the sagittal plane (forward, up).
pub(crate) fn planar(p: DVec3) -> DVec2 {
    DVec2::new(p.z, p.y)
}

/// Hip and knee angles (relative, rad) putting the toe at `toe` from the hip
/// (forward, up) with the ankle at `ankle` and the trunk at pitch `pitch`;
/// the knee bends forward.
pub(crate) fn leg_ik(g: &LegGeometry, toe: DVec2, ankle: f64, pitch: f64) -> (f64, f64) {
    // Knee-to-toe as one link in the shin's frame.
    let v = g.shin * dir(0.0) + g.foot * dir(ankle);
    let s = v.length();
    let delta = angle_of(v);
    let l1 = g.thigh;
    let d = toe
        .length()
        .clamp((l1 - s).abs() + 1e-6 * (l1 + s), 0.999 * (l1 + s));
    let gamma = angle_of(toe);
    let alpha = ((l1 * l1 + d * d - s * s) / (2.0 * l1 * d))
        .clamp(-1.0, 1.0)
        .pacos();
    let a1 = gamma - alpha;
    let knee = l1 * dir(a1);
    let toe_at = d * dir(gamma);
    let b = angle_of(toe_at - knee);
    let a2 = b - delta;
    (a1 - pitch, a2 - a1)
}

/// The thigh's absolute angle (rad) that puts the knee on the thrust line
/// from `toe` through `com` (both in the sagittal plane, as is `hip`): of the
/// two knees on that line at thigh length from the hip, the one nearer the
/// thigh's angle now (`now`); the knee nearest the line when none reaches it.
pub(crate) fn thigh_on_thrust_line(
    g: &LegGeometry,
    hip: DVec2,
    toe: DVec2,
    com: DVec2,
    now: f64,
) -> f64 {
    let u = (com - toe).normalize_or(DVec2::Y);
    let th = toe - hip;
    let b = u.dot(th);
    let disc = b * b - (th.length_squared() - g.thigh * g.thigh);
    if disc >= 0.0 {
        let r = disc.sqrt();
        let k1 = toe + (-b + r) * u - hip;
        let k2 = toe + (-b - r) * u - hip;
        let (c1, c2) = (angle_of(k1), angle_of(k2));
        if (c1 - now).abs() <= (c2 - now).abs() {
            c1
        } else {
            c2
        }
    } else {
        angle_of(toe + (-b) * u - hip)
    }
}
