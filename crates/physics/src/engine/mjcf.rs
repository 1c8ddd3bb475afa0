//! The creature as a MuJoCo model (MJCF XML): bodies with their inertias
//! (Table 3), joints, the leg springs as passive joint springs at their
//! landing rest length (eq. 1), hip motors with the controllers' torque limit,
//! and the ground springs as soft contact (`solref` with negative stiffness
//! and damping, MuJoCo's direct spring-damper form) — so people can take
//! gaitlab's creatures to MuJoCo. Axes stay gaitlab's (y up): gravity points
//! along −y and the floor plane faces +y.
//!
//! Massless links of a multi-DOF joint (a gimbal's or ball hip's inner axes,
//! the kangaroo's planar base slides) become extra joints of the next body, as
//! MuJoCo composes a body's joints in order — the same kinematic chain.

use std::fmt::Write as _;

use glam::{DMat3, DQuat, DVec3};

use crate::creatures::PhysicalCreature;
use crate::dynamics::model::{Body, Joint};
use crate::world::ground::GroundParams;

/// What to write besides the creature.
#[derive(Clone, Debug, PartialEq)]
pub struct MjcfOptions {
    /// Model name.
    pub name: String,
    /// Integration step (s).
    pub timestep_s: f64,
    /// Where body 0 (or the planar base) starts (m).
    pub root_position: DVec3,
    /// Each joint coordinate's spring: `(coordinate, stiffness, damping, rest)`.
    pub springs: Vec<(usize, f64, f64, f64)>,
    /// Largest hip torque, for the motors' control range (N·m).
    pub hip_torque_limit: f64,
    /// The ground springs, written as the feet's contact softness.
    pub ground: GroundParams,
    /// The ground's shape ([`gaitlab_core::terrain::to_mjcf`]): the floor
    /// plane, or boxes and an `hfield`.
    pub terrain: gaitlab_core::terrain::Terrain,
}

/// The foot's contact sphere's radius, metres at scale 1: gaitlab's ground
/// springs act at the foot's point, so MuJoCo's sphere is all but a point
/// (a 1 cm sphere stood the quadruped 1 cm higher on its feet:
/// `tools/stairs_mujoco_check.py`, docs/terrain.md "In MuJoCo").
const FOOT_RADIUS_M: f64 = 1e-4;

fn v3(v: DVec3) -> String {
    format!("{} {} {}", num(v.x), num(v.y), num(v.z))
}

fn num(x: f64) -> String {
    let s = format!("{x:.9}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

fn quat(m: DMat3) -> String {
    let q = DQuat::from_mat3(&m).normalize();
    format!("{} {} {} {}", num(q.w), num(q.x), num(q.y), num(q.z))
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Whether body `i` is a massless link whose joint can ride on its only child.
fn merges_into_child(bodies: &[Body], i: usize) -> Option<usize> {
    let b = &bodies[i];
    if b.mass > 0.0 || b.joint == Joint::Free {
        return None;
    }
    let mut children = bodies
        .iter()
        .enumerate()
        .filter(|(_, c)| c.parent == Some(i));
    let (c, child) = children.next()?;
    let aligned = child.placement.pos.length() < 1e-12
        && child.placement.rot.abs_diff_eq(DMat3::IDENTITY, 1e-12);
    (children.next().is_none() && aligned && child.joint != Joint::Free).then_some(c)
}

/// The MJCF text of `creature`.
#[must_use]
pub fn to_mjcf(creature: &PhysicalCreature, options: &MjcfOptions) -> String {
    let model = &creature.model;
    let bodies = model.bodies();
    let mut x = String::new();
    let g = model.gravity;
    let _ = writeln!(x, "<mujoco model=\"{}\">", escape(&options.name));
    let _ = writeln!(
        x,
        "  <!-- Written by gaitlab from Raibert & Hodgins 1991, Table 3 (scale L = {}). Axes: y up. -->",
        num(creature.scale)
    );
    let _ = writeln!(x, "  <compiler angle=\"radian\" autolimits=\"true\"/>");
    let _ = writeln!(
        x,
        "  <option timestep=\"{}\" gravity=\"{}\" integrator=\"Euler\"/>",
        num(options.timestep_s),
        v3(g)
    );
    let gp = &options.ground;
    let _ = writeln!(x, "  <default>");
    let _ = writeln!(
        x,
        "    <geom contype=\"0\" conaffinity=\"0\" rgba=\"0.7 0.72 0.78 1\"/>"
    );
    let _ = writeln!(x, "  </default>");
    let ground = gaitlab_core::terrain::to_mjcf(&options.terrain);
    if !ground.asset.is_empty() {
        let _ = writeln!(x, "  <asset>");
        x.push_str(&ground.asset);
        let _ = writeln!(x, "  </asset>");
    }
    let _ = writeln!(x, "  <worldbody>");
    x.push_str(&ground.geoms);
    // Which bodies carry their parents' merged joints.
    let mut carried: Vec<Vec<usize>> = vec![Vec::new(); bodies.len()];
    let mut skipped = vec![false; bodies.len()];
    for i in 0..bodies.len() {
        if let Some(c) = merges_into_child(bodies, i) {
            skipped[i] = true;
            let mut chain = std::mem::take(&mut carried[i]);
            chain.push(i);
            carried[c] = chain;
        }
    }
    let feet: Vec<(usize, DVec3, &str)> = creature
        .legs
        .iter()
        .map(|l| (l.foot_body, l.foot_point, l.name.as_str()))
        .collect();
    let solref = format!(
        "{} {}",
        num(-gp.vertical_stiffness),
        num(-gp.vertical_damping)
    );
    let mut joint_names: Vec<(usize, String)> = Vec::new();
    // Recursive writer over the kept bodies.
    fn write_body(
        x: &mut String,
        i: usize,
        depth: usize,
        ctx: &Ctx<'_>,
        joint_names: &mut Vec<(usize, String)>,
    ) {
        let bodies = ctx.bodies;
        let pad = "  ".repeat(depth + 2);
        let first = ctx.carried[i].first().copied().unwrap_or(i);
        let placement = bodies[first].placement;
        let pos = if bodies[first].parent.is_none() {
            placement.pos + ctx.root
        } else {
            placement.pos
        };
        let b = &bodies[i];
        let _ = writeln!(
            x,
            "{pad}<body name=\"{}\" pos=\"{}\" quat=\"{}\">",
            escape(&b.name),
            v3(pos),
            quat(placement.rot)
        );
        for &k in ctx.carried[i].iter().chain(std::iter::once(&i)) {
            let body = &bodies[k];
            match body.joint {
                Joint::Free => {
                    let _ = writeln!(x, "{pad}  <freejoint name=\"root\"/>");
                }
                Joint::Revolute(a) | Joint::Prismatic(a) => {
                    let kind = if matches!(body.joint, Joint::Revolute(_)) {
                        "hinge"
                    } else {
                        "slide"
                    };
                    let dof = ctx.dof_of(k);
                    let spring = dof.and_then(|d| ctx.springs.iter().find(|s| s.0 == d));
                    let spring_attrs = spring.map_or(String::new(), |s| {
                        format!(
                            " stiffness=\"{}\" damping=\"{}\" springref=\"{}\"",
                            num(s.1),
                            num(s.2),
                            num(s.3)
                        )
                    });
                    let _ = writeln!(
                        x,
                        "{pad}  <joint name=\"{}\" type=\"{kind}\" axis=\"{}\"{spring_attrs}/>",
                        escape(&body.name),
                        v3(a)
                    );
                    if let Some(d) = dof {
                        joint_names.push((d, body.name.clone()));
                    }
                }
            }
        }
        if b.mass > 0.0 {
            let d = b.inertia_com;
            let _ = writeln!(
                x,
                "{pad}  <inertial pos=\"{}\" mass=\"{}\" diaginertia=\"{}\"/>",
                v3(b.com),
                num(b.mass),
                v3(DVec3::new(d.x_axis.x, d.y_axis.y, d.z_axis.z).max(DVec3::splat(1e-9)))
            );
            let r = 0.02 * ctx.scale;
            let _ = writeln!(
                x,
                "{pad}  <geom type=\"sphere\" size=\"{}\" pos=\"{}\" mass=\"0\"/>",
                num(r),
                v3(b.com)
            );
        }
        for (foot, point, name) in ctx.feet {
            if *foot == i {
                let _ = writeln!(
                    x,
                    "{pad}  <geom name=\"{}-foot\" type=\"sphere\" size=\"{}\" pos=\"{}\" mass=\"0\" contype=\"1\" conaffinity=\"1\" condim=\"3\" friction=\"2 0.005 0.0001\" solref=\"{}\"/>",
                    escape(name),
                    num(FOOT_RADIUS_M * ctx.scale),
                    v3(*point),
                    ctx.solref
                );
            }
        }
        for c in 0..bodies.len() {
            if !ctx.skipped[c] && ctx.kept_parent_of(c) == Some(i) {
                write_body(x, c, depth + 1, ctx, joint_names);
            }
        }
        let _ = writeln!(x, "{pad}</body>");
    }
    struct Ctx<'a> {
        bodies: &'a [Body],
        carried: &'a [Vec<usize>],
        skipped: &'a [bool],
        springs: &'a [(usize, f64, f64, f64)],
        feet: &'a [(usize, DVec3, &'a str)],
        root: DVec3,
        scale: f64,
        solref: String,
        model: &'a crate::dynamics::model::Model,
    }
    impl Ctx<'_> {
        fn dof_of(&self, body: usize) -> Option<usize> {
            self.model.dof_of(body)
        }
        /// The kept body a kept body hangs from: the parent of the first link
        /// of the chain it carries (or its own parent).
        fn kept_parent_of(&self, c: usize) -> Option<usize> {
            let first = self.carried[c].first().copied().unwrap_or(c);
            self.bodies[first].parent
        }
    }
    let ctx = Ctx {
        bodies,
        carried: &carried,
        skipped: &skipped,
        springs: &options.springs,
        feet: &feet,
        root: options.root_position,
        scale: creature.scale,
        solref,
        model,
    };
    let roots: Vec<usize> = (0..bodies.len())
        .filter(|&i| !skipped[i] && ctx.kept_parent_of(i).is_none())
        .collect();
    for i in roots {
        write_body(&mut x, i, 0, &ctx, &mut joint_names);
    }
    let _ = writeln!(x, "  </worldbody>");
    let _ = writeln!(x, "  <actuator>");
    let limit = options.hip_torque_limit;
    for leg in &creature.legs {
        for &k in &leg.hip {
            if let Some((_, name)) = joint_names.iter().find(|(d, _)| *d == k) {
                let _ = writeln!(
                    x,
                    "    <motor name=\"{0}-motor\" joint=\"{0}\" ctrlrange=\"{1} {2}\" gear=\"1\"/>",
                    escape(name),
                    num(-limit),
                    num(limit)
                );
            }
        }
    }
    let _ = writeln!(x, "  </actuator>");
    let _ = writeln!(x, "</mujoco>");
    x
}
