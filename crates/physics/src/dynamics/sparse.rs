//! The joint transforms of a link that turns about, or slides along, a
//! coordinate axis, with the products of their exact zeros left out: the
//! sparsity of joint transforms that speeds the recursive algorithms
//! (Featherstone 2008, ch. 10). Used by [`crate::dynamics::kinematics`] and
//! [`crate::dynamics::aba`]; [`ParentLink`]'s dense products stay the
//! reference the tests hold these to.
//!
//! Every product here adds the same non-zero terms in the same order as the
//! dense product of [`ParentLink`] it stands for, so the result is the same
//! bit for bit; only the sign of an entry that is exactly zero can differ
//! (`-0.0` against `0.0`). Added to a non-zero term the two give the same
//! bits, and every run's figures stay the same to the bit (the golden and
//! replay tests).
//! A rotation about axis `k` built by `DMat3::from_axis_angle` has exact
//! zeros in row and column `k` off the diagonal; a skew matrix `[p]×` has a
//! zero diagonal, and zeros where `p` has zero components.

use glam::{DMat3, DVec3};

use crate::dynamics::model::RotShape;
use crate::dynamics::spatial::{Force, Inertia, Motion, ParentLink};

/// Bit of entry (row `i`, column `l`) in a zero mask.
const fn bit(i: usize, l: usize) -> u16 {
    1 << (3 * i + l)
}

/// The zero mask of a rotation about coordinate axis `k`.
const fn about_mask(k: usize) -> u16 {
    let mut m = 0;
    let mut i = 0;
    while i < 3 {
        if i != k {
            m |= bit(i, k) | bit(k, i);
        }
        i += 1;
    }
    m
}

/// The mask of the transpose.
const fn transposed(mask: u16) -> u16 {
    let mut m = 0;
    let mut i = 0;
    while i < 3 {
        let mut l = 0;
        while l < 3 {
            if mask & bit(i, l) != 0 {
                m |= bit(l, i);
            }
            l += 1;
        }
        i += 1;
    }
    m
}

/// The zero mask of `[p]×` when `p`'s components marked in `zero_xyz`
/// (bit 0 x, 1 y, 2 z) are zero; its diagonal is always zero.
const fn skew_mask(zero_xyz: u16) -> u16 {
    let mut m = bit(0, 0) | bit(1, 1) | bit(2, 2);
    if zero_xyz & 1 != 0 {
        m |= bit(2, 1) | bit(1, 2);
    }
    if zero_xyz & 2 != 0 {
        m |= bit(2, 0) | bit(0, 2);
    }
    if zero_xyz & 4 != 0 {
        m |= bit(1, 0) | bit(0, 1);
    }
    m
}

/// The rows of `a · b` that are zero because `a`'s row is all zero.
const fn zero_rows_of_product(za: u16) -> u16 {
    let mut m = 0;
    let mut i = 0;
    while i < 3 {
        let row = bit(i, 0) | bit(i, 1) | bit(i, 2);
        if za & row == row {
            m |= row;
        }
        i += 1;
    }
    m
}

/// `x · y` added to the running sum (`None` before the first term), or
/// the sum unchanged where a factor is known to be zero (`keep` false).
#[inline(always)]
fn term(sum: Option<f64>, keep: bool, x: f64, y: f64) -> Option<f64> {
    if !keep {
        return sum;
    }
    let t = x * y;
    Some(match sum {
        None => t,
        Some(s) => s + t,
    })
}

/// `Σ_l a[i][l] · b[l][j]` in glam's order, `(t0 + t1) + t2`, leaving out
/// the terms whose factor is marked zero in `za` (of `a`) or `zb` (of `b`).
#[inline(always)]
fn entry(a: &DMat3, za: u16, b: &DMat3, zb: u16, i: usize, j: usize) -> f64 {
    let keep = |l: usize| za & bit(i, l) == 0 && zb & bit(l, j) == 0;
    let bj = b.col(j);
    let s = term(None, keep(0), a.x_axis[i], bj.x);
    let s = term(s, keep(1), a.y_axis[i], bj.y);
    let s = term(s, keep(2), a.z_axis[i], bj.z);
    s.unwrap_or(0.0)
}

/// Column `j` of `a · b`.
#[inline(always)]
fn column(a: &DMat3, za: u16, b: &DMat3, zb: u16, j: usize) -> DVec3 {
    DVec3::new(
        entry(a, za, b, zb, 0, j),
        entry(a, za, b, zb, 1, j),
        entry(a, za, b, zb, 2, j),
    )
}

/// `a · b` with the products of known zeros left out (glam's `a * b` to the bit).
#[inline(always)]
fn mul(a: &DMat3, za: u16, b: &DMat3, zb: u16) -> DMat3 {
    DMat3::from_cols(
        column(a, za, b, zb, 0),
        column(a, za, b, zb, 1),
        column(a, za, b, zb, 2),
    )
}

/// `a · v` with the products of `a`'s known zeros left out (glam's `a * v`).
#[inline(always)]
fn mul_vec(a: &DMat3, za: u16, v: DVec3) -> DVec3 {
    let m = DMat3::from_cols(v, DVec3::ZERO, DVec3::ZERO);
    let zero_cols = bit(0, 1) | bit(1, 1) | bit(2, 1) | bit(0, 2) | bit(1, 2) | bit(2, 2);
    DVec3::new(
        entry(a, za, &m, zero_cols, 0, 0),
        entry(a, za, &m, zero_cols, 1, 0),
        entry(a, za, &m, zero_cols, 2, 0),
    )
}

/// `r · m · rᵀ` for a rotation about axis `K`, as `r * m * r.transpose()`.
#[inline(always)]
fn sandwich<const K: usize>(r: &DMat3, m: &DMat3) -> DMat3 {
    let z = about_mask(K);
    let rm = mul(r, z, m, 0);
    mul(&rm, 0, &r.transpose(), transposed(z))
}

/// `r · v` for a link's rotation of the given shape (`r * v`).
#[must_use]
#[inline(always)]
pub fn rot_mul_vec(shape: RotShape, r: &DMat3, v: DVec3) -> DVec3 {
    match shape {
        RotShape::Identity => v,
        RotShape::About(0) => mul_vec(r, about_mask(0), v),
        RotShape::About(1) => mul_vec(r, about_mask(1), v),
        RotShape::About(2) => mul_vec(r, about_mask(2), v),
        _ => *r * v,
    }
}

/// `rᵀ · v` for a link's rotation of the given shape (`r.transpose() * v`;
/// the transpose of a rotation about an axis has the same zeros).
#[must_use]
pub fn rot_t_mul_vec(shape: RotShape, r: &DMat3, v: DVec3) -> DVec3 {
    rot_mul_vec(shape, &r.transpose(), v)
}

/// `p · r` for any `p` and a link's rotation `r` of the given shape (`p * r`).
#[must_use]
pub fn mul_rot(p: &DMat3, shape: RotShape, r: &DMat3) -> DMat3 {
    match shape {
        RotShape::Identity => *p,
        RotShape::About(0) => mul(p, 0, r, about_mask(0)),
        RotShape::About(1) => mul(p, 0, r, about_mask(1)),
        RotShape::About(2) => mul(p, 0, r, about_mask(2)),
        _ => *p * *r,
    }
}

/// [`ParentLink::motion_to_child`] for a link of the given shape.
#[must_use]
#[inline(always)]
pub fn motion_to_child(link: &ParentLink, shape: RotShape, m: Motion) -> Motion {
    Motion {
        angular: rot_t_mul_vec(shape, &link.rot, m.angular),
        linear: rot_t_mul_vec(shape, &link.rot, m.linear + m.angular.cross(link.pos)),
    }
}

/// [`ParentLink::force_to_parent`] for a link of the given shape.
#[must_use]
pub fn force_to_parent(link: &ParentLink, shape: RotShape, f: Force) -> Force {
    let force = rot_mul_vec(shape, &link.rot, f.force);
    Force {
        moment: rot_mul_vec(shape, &link.rot, f.moment) + link.pos.cross(force),
        force,
    }
}

/// [`ParentLink::then`] for a child link of the given shape.
#[must_use]
#[inline(always)]
pub fn then(parent: &ParentLink, child: &ParentLink, shape: RotShape) -> ParentLink {
    ParentLink {
        rot: mul_rot(&parent.rot, shape, &child.rot),
        pos: parent.rot * child.pos + parent.pos,
    }
}

/// [`ParentLink::inertia_to_parent`] for a link of the given shape.
#[must_use]
pub fn inertia_to_parent(link: &ParentLink, shape: RotShape, i: &Inertia) -> Inertia {
    let r = &link.rot;
    let (a, b, c) = match shape {
        RotShape::Identity => (i.a, i.b, i.c),
        RotShape::About(0) => (
            sandwich::<0>(r, &i.a),
            sandwich::<0>(r, &i.b),
            sandwich::<0>(r, &i.c),
        ),
        RotShape::About(1) => (
            sandwich::<1>(r, &i.a),
            sandwich::<1>(r, &i.b),
            sandwich::<1>(r, &i.c),
        ),
        RotShape::About(2) => (
            sandwich::<2>(r, &i.a),
            sandwich::<2>(r, &i.b),
            sandwich::<2>(r, &i.c),
        ),
        RotShape::About(_) | RotShape::General => return link.inertia_to_parent(i),
    };
    let p = link.pos;
    let zero_xyz = u16::from(p.x == 0.0) | u16::from(p.y == 0.0) << 1 | u16::from(p.z == 0.0) << 2;
    match zero_xyz {
        0 => translate::<0>(p, a, b, c),
        1 => translate::<1>(p, a, b, c),
        2 => translate::<2>(p, a, b, c),
        3 => translate::<3>(p, a, b, c),
        4 => translate::<4>(p, a, b, c),
        5 => translate::<5>(p, a, b, c),
        6 => translate::<6>(p, a, b, c),
        // A joint at the parent's origin (a gimbal's inner axis): rotation only.
        _ => Inertia { a, b, c },
    }
}

/// The translation half of `Xᵀ I X` for a link at `p` whose components
/// marked in `Z` are zero (the dense formula of [`ParentLink::inertia_to_parent`]).
#[inline(always)]
fn translate<const Z: u16>(p: DVec3, a: DMat3, b: DMat3, c: DMat3) -> Inertia {
    let rx = crate::dynamics::spatial::skew(p);
    let zs = skew_mask(Z);
    let b_rx = mul(&b, 0, &rx, zs);
    let rx_c = mul(&rx, zs, &c, 0);
    let rx_c_rx = mul(&rx_c, zero_rows_of_product(zs), &rx, zs);
    Inertia {
        a: a - b_rx - b_rx.transpose() - rx_c_rx,
        b: b + rx_c,
        c,
    }
}
