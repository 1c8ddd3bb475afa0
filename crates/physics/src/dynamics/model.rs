//! The articulated model: a tree of rigid bodies joined by revolute or
//! prismatic joints, rooted at a free-floating 6-DOF base or at the fixed
//! world (Raibert & Hodgins 1991, "Modeling": "a tree of rigid bodies, each
//! connected to its parent by rotary or sliding joints"). Immutable once
//! built; the mutable state lives in [`crate::Data`].
//!
//! Multi-DOF joints are chains of single-DOF joints through massless bodies:
//! a gimbal hip is two revolutes, a ball hip three, the kangaroo's planar base
//! two prismatics and a revolute from the world.

use glam::{DMat3, DVec3};

use crate::dynamics::spatial::{Inertia, Motion, ParentLink};

/// Which entries of a link's rotation (in its parent) are known to be
/// exactly zero, from its joint and placement ([`Model::link_shape`]); the
/// products of [`crate::dynamics::sparse`] leave them out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RotShape {
    /// The rotation is the identity (a slider with an unrotated placement).
    Identity,
    /// A rotation about coordinate axis 0, 1 or 2 (x, y, z): row and column
    /// off the diagonal are zero.
    About(usize),
    /// Nothing known.
    General,
}

/// How a body moves relative to its parent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Joint {
    /// Six degrees of freedom (only for the root body): position and
    /// orientation in the world, velocity in body coordinates.
    Free,
    /// Rotation by `q` radians about a unit axis (body coordinates).
    Revolute(DVec3),
    /// Translation by `q` metres along a unit axis (body coordinates).
    Prismatic(DVec3),
}

impl Joint {
    /// The motion subspace `S` of a single-DOF joint (body coordinates).
    #[must_use]
    pub fn subspace(&self) -> Motion {
        match *self {
            Joint::Free => Motion::ZERO,
            Joint::Revolute(axis) => Motion::new(axis, DVec3::ZERO),
            Joint::Prismatic(axis) => Motion::new(DVec3::ZERO, axis),
        }
    }
}

/// One rigid body and the joint that attaches it.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Name (unique), used by controllers, exports and errors.
    pub name: String,
    /// Parent body, or `None` for a root attached to the world.
    pub parent: Option<usize>,
    /// The joint to the parent.
    pub joint: Joint,
    /// The joint frame in the parent's frame when `q = 0`.
    pub placement: ParentLink,
    /// Mass (kg); zero for the massless links of a multi-DOF joint.
    pub mass: f64,
    /// Centre of mass in body coordinates (m).
    pub com: DVec3,
    /// Rotational inertia about the centre of mass, body axes (kg·m²).
    pub inertia_com: DMat3,
}

impl Body {
    /// The body's spatial inertia about its own origin.
    #[must_use]
    pub fn spatial_inertia(&self) -> Inertia {
        Inertia::rigid(self.mass, self.com, self.inertia_com)
    }

    /// The zero pattern of this body's rotation in its parent: the identity
    /// for a slider placed unrotated, a rotation about a coordinate axis for
    /// a hinge placed unrotated on that axis (`DMat3::from_axis_angle` gives
    /// exact zeros off the diagonal in the axis' row and column).
    #[must_use]
    pub fn link_shape(&self) -> RotShape {
        if self.placement.rot != DMat3::IDENTITY {
            return RotShape::General;
        }
        match self.joint {
            Joint::Free => RotShape::General,
            Joint::Prismatic(_) => RotShape::Identity,
            Joint::Revolute(axis) => {
                let zeros = axis.to_array().map(|c| c == 0.0);
                match zeros {
                    [false, true, true] => RotShape::About(0),
                    [true, false, true] => RotShape::About(1),
                    [true, true, false] => RotShape::About(2),
                    _ => RotShape::General,
                }
            }
        }
    }
}

/// Why a model is rejected.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelError {
    /// The offending body's name (or index).
    pub body: String,
    /// What is wrong.
    pub reason: String,
}

impl std::fmt::Display for ModelError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "body {}: {}", self.body, self.reason)
    }
}

impl std::error::Error for ModelError {}

/// An articulated model with gravity.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    bodies: Vec<Body>,
    /// Each body's spatial inertia about its origin (cached from the body).
    inertias: Vec<Inertia>,
    shapes: Vec<RotShape>,
    /// [`Model::last_children`].
    last_child: Vec<Option<usize>>,
    /// The bodies by depth in the tree, then by index ([`Model::by_depth`]).
    by_depth: Vec<usize>,
    /// Each body's joint coordinate index (`None` for the free root).
    dof: Vec<Option<usize>>,
    dof_count: usize,
    free_base: bool,
    /// Gravity in world coordinates (m/s²), `(0, −9.81, 0)` by default (y up).
    pub gravity: DVec3,
}

/// Standard gravity (m/s²).
pub const GRAVITY_MPS2: f64 = 9.81;

impl Model {
    /// Build and check a model: bodies in topological order (parents first),
    /// a free joint only on body 0, unit joint axes, finite non-negative
    /// masses, symmetric positive semi-definite inertias, unique names.
    ///
    /// # Errors
    /// The first body that breaks a rule, and which rule.
    pub fn new(bodies: Vec<Body>) -> Result<Self, ModelError> {
        let mut dof = Vec::with_capacity(bodies.len());
        let mut count = 0;
        for (i, b) in bodies.iter().enumerate() {
            let err = |reason: String| ModelError {
                body: b.name.clone(),
                reason,
            };
            if bodies[..i].iter().any(|o| o.name == b.name) {
                return Err(err("duplicate name".into()));
            }
            if let Some(p) = b.parent
                && p >= i
            {
                return Err(err(format!("parent {p} must come before the body ({i})")));
            }
            match b.joint {
                Joint::Free if i != 0 || b.parent.is_some() => {
                    return Err(err(
                        "only the first body, with no parent, may be free".into()
                    ));
                }
                Joint::Free => dof.push(None),
                Joint::Revolute(a) | Joint::Prismatic(a) => {
                    if !a.is_finite() || (a.length() - 1.0).abs() > 1e-9 {
                        return Err(err("joint axis must be a unit vector".into()));
                    }
                    dof.push(Some(count));
                    count += 1;
                }
            }
            if !(b.mass.is_finite() && b.mass >= 0.0) {
                return Err(err("mass must be finite and ≥ 0".into()));
            }
            let m = b.inertia_com;
            let sym = (m - m.transpose())
                .to_cols_array()
                .iter()
                .all(|x| x.abs() < 1e-12);
            let diag_ok = [m.x_axis.x, m.y_axis.y, m.z_axis.z]
                .iter()
                .all(|d| d.is_finite() && *d >= 0.0);
            if !sym || !diag_ok || !b.com.is_finite() {
                return Err(err(
                    "inertia must be finite and symmetric with a non-negative diagonal".into(),
                ));
            }
            if !b.placement.pos.is_finite() || !b.placement.rot.is_finite() {
                return Err(err("placement must be finite".into()));
            }
        }
        if bodies.is_empty() {
            return Err(ModelError {
                body: "-".into(),
                reason: "a model needs a body".into(),
            });
        }
        let free_base = bodies[0].joint == Joint::Free;
        let inertias = bodies.iter().map(Body::spatial_inertia).collect();
        let shapes = bodies.iter().map(Body::link_shape).collect();
        let mut last_child = vec![None; bodies.len()];
        let mut depth = vec![0_usize; bodies.len()];
        for (i, b) in bodies.iter().enumerate() {
            if let Some(p) = b.parent {
                last_child[p] = Some(i);
                depth[i] = depth[p] + 1;
            }
        }
        let mut by_depth: Vec<usize> = (0..bodies.len()).collect();
        by_depth.sort_by_key(|&i| (depth[i], i));
        Ok(Self {
            inertias,
            shapes,
            last_child,
            by_depth,
            bodies,
            dof,
            dof_count: count,
            free_base,
            gravity: DVec3::new(0.0, -GRAVITY_MPS2, 0.0),
        })
    }

    /// The bodies, parents first.
    #[must_use]
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// Body `i`'s spatial inertia about its origin (body coordinates).
    #[must_use]
    pub fn inertia(&self, body: usize) -> &Inertia {
        &self.inertias[body]
    }

    /// Which entries of body `body`'s rotation in its parent are exactly
    /// zero at every joint coordinate ([`crate::dynamics::sparse`]).
    #[must_use]
    pub fn link_shape(&self, body: usize) -> RotShape {
        self.shapes[body]
    }

    /// The bodies ordered by their depth in the tree, then by index: every
    /// parent before its children, as in body order, but the legs' chains
    /// interleaved (hip, hip, knee, knee, …), so the recursive passes give
    /// the processor independent work side by side. Reversed, it reaches a
    /// body's children in decreasing index order, as the reversed body
    /// order does, so every sum into a parent keeps its order and its bits.
    #[must_use]
    pub fn by_depth(&self) -> &[usize] {
        &self.by_depth
    }

    /// Every body's spatial inertia, [`Model::inertia`] in body order.
    #[must_use]
    pub fn inertias(&self) -> &[Inertia] {
        &self.inertias
    }

    /// Every body's [`Model::link_shape`], in body order.
    #[must_use]
    pub fn link_shapes(&self) -> &[RotShape] {
        &self.shapes
    }

    /// Every body's child of highest index (`None` for a leaf), in body
    /// order: the first child the articulated-body algorithm's
    /// leaves-to-root pass reaches.
    #[must_use]
    pub fn last_children(&self) -> &[Option<usize>] {
        &self.last_child
    }

    /// Every body's [`Model::dof_of`], in body order.
    #[must_use]
    pub fn dofs(&self) -> &[Option<usize>] {
        &self.dof
    }

    /// Body `body`'s joint coordinate index, `None` for the free root.
    #[must_use]
    pub fn dof_of(&self, body: usize) -> Option<usize> {
        self.dof[body]
    }

    /// Number of single-DOF joint coordinates (the free base not counted).
    #[must_use]
    pub fn joint_count(&self) -> usize {
        self.dof_count
    }

    /// Whether body 0 floats freely.
    #[must_use]
    pub fn free_base(&self) -> bool {
        self.free_base
    }

    /// Degrees of freedom of the velocity: 6 for a free base plus one per joint.
    #[must_use]
    pub fn nv(&self) -> usize {
        self.dof_count + if self.free_base { 6 } else { 0 }
    }

    /// The index of the body called `name`.
    #[must_use]
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }

    /// Total mass (kg).
    #[must_use]
    pub fn total_mass(&self) -> f64 {
        self.bodies.iter().map(|b| b.mass).sum()
    }
}
