//! Uniform cubic splines for PODA foot transfer trajectories and body paths
//! (Girard & Maciejewski 1985, "Leg Support and Transfer Trajectories" and
//! "Horizontal Control").
//!
//! PODA moves each foot "precisely along the smooth Catmull-Rom spline from
//! foothold to foothold", with the animator's key foot positions as control
//! points, and lets the body path be either a Catmull-Rom or a B-spline. This
//! module evaluates both kinds through a list of control points:
//!
//! * Catmull-Rom (interpolating): the curve passes through every point.
//! * uniform cubic B-spline (approximating): the curve passes near the
//!   interior points and exactly through the end points of an open curve.
//!
//! The curve parameter `u` runs over `[0, 1]`, spread uniformly over the
//! segments; "tangent" means the derivative `d position / d u` (not unit
//! length). Positions keep the units of the control points (metres in
//! gaitlab). Open curves take end phantom points by reflection,
//! `p₋₁ = 2p₀ − p₁` and `pₙ = 2pₙ₋₁ − pₙ₋₂`; closed curves wrap indices. No
//! function here allocates or panics: an empty slice yields the origin, and a
//! non-finite `u` is treated as 0.

use glam::DVec3;

/// Which cubic basis a curve uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Basis {
    /// Uniform Catmull-Rom: interpolating, passes through every control point.
    #[default]
    CatmullRom,
    /// Uniform cubic B-spline: approximating, C² smooth.
    BSpline,
}

/// A curve's position and its first two derivatives with respect to `u`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CurvePoint {
    /// Position on the curve (units of the control points).
    pub position: DVec3,
    /// First derivative `d position / d u`.
    pub velocity: DVec3,
    /// Second derivative `d² position / d u²`.
    pub acceleration: DVec3,
}

/// Basis weights of the four points of one segment, for the position and
/// the first and second derivatives with respect to the local `s ∈ [0, 1]`.
fn weights(basis: Basis, s: f64) -> [[f64; 4]; 3] {
    let (s2, s3) = (s * s, s * s * s);
    match basis {
        Basis::CatmullRom => [
            [
                0.5 * (-s3 + 2.0 * s2 - s),
                0.5 * (3.0 * s3 - 5.0 * s2 + 2.0),
                0.5 * (-3.0 * s3 + 4.0 * s2 + s),
                0.5 * (s3 - s2),
            ],
            [
                0.5 * (-3.0 * s2 + 4.0 * s - 1.0),
                0.5 * (9.0 * s2 - 10.0 * s),
                0.5 * (-9.0 * s2 + 8.0 * s + 1.0),
                0.5 * (3.0 * s2 - 2.0 * s),
            ],
            [2.0 - 3.0 * s, 9.0 * s - 5.0, 4.0 - 9.0 * s, 3.0 * s - 1.0],
        ],
        Basis::BSpline => {
            let t = 1.0 - s;
            [
                [
                    t * t * t / 6.0,
                    (3.0 * s3 - 6.0 * s2 + 4.0) / 6.0,
                    (-3.0 * s3 + 3.0 * s2 + 3.0 * s + 1.0) / 6.0,
                    s3 / 6.0,
                ],
                [
                    -0.5 * t * t,
                    0.5 * (3.0 * s2 - 4.0 * s),
                    0.5 * (-3.0 * s2 + 2.0 * s + 1.0),
                    0.5 * s2,
                ],
                [t, 3.0 * s - 2.0, 1.0 - 3.0 * s, s],
            ]
        }
    }
}

/// Weighted sum of the four segment points.
fn combine(w: [f64; 4], p: [DVec3; 4]) -> DVec3 {
    p[0] * w[0] + p[1] * w[1] + p[2] * w[2] + p[3] * w[3]
}

/// Position and derivatives at `u` of the curve through (Catmull-Rom) or
/// around (B-spline) `points`.
///
/// Open curve (`closed == false`, or fewer than 3 points): `n − 1` segments,
/// segment `k` covering `u ∈ [k/(n−1), (k+1)/(n−1)]`, `u` clamped to `[0, 1]`,
/// end phantom points by reflection. Both bases then start at the first point
/// and end at the last (for the B-spline, reflection makes
/// `(p₋₁ + 4p₀ + p₁)/6 = p₀`, with zero curvature there). One point gives that
/// point with zero derivatives; two give the straight line between them.
///
/// Closed curve (`closed == true`, at least 3 points): `n` segments, the last
/// joining `pₙ₋₁` back to `p₀`; `u` wraps modulo 1.
#[must_use]
pub fn eval_curve(points: &[DVec3], u: f64, basis: Basis, closed: bool) -> CurvePoint {
    let n = points.len();
    let u = if u.is_finite() { u } else { 0.0 };
    let (first, last) = match (points.first(), points.last()) {
        (Some(&first), Some(&last)) if n >= 2 => (first, last),
        (Some(&only), _) => {
            return CurvePoint {
                position: only,
                ..CurvePoint::default()
            };
        }
        _ => return CurvePoint::default(),
    };
    let closed = closed && n >= 3;
    let (segments, u) = if closed {
        (n, u.rem_euclid(1.0))
    } else {
        (n - 1, u.clamp(0.0, 1.0))
    };
    #[expect(
        clippy::cast_precision_loss,
        reason = "at most a few thousand segments"
    )]
    let scale = segments as f64;
    let along = u * scale;
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "`along` is finite and in [0, segments]"
    )]
    let k = (along.floor() as usize).min(segments - 1);
    #[expect(clippy::cast_precision_loss, reason = "k < segments")]
    let local = (along - k as f64).clamp(0.0, 1.0);
    // Control point k + offset − 1, with reflection (open) or wrapping (closed).
    let point = |offset: usize| -> DVec3 {
        let i = k + offset;
        if closed {
            points[(i + n - 1) % n]
        } else if i == 0 {
            2.0 * first - points[1]
        } else if i > n {
            2.0 * last - points[n - 2]
        } else {
            points[i - 1]
        }
    };
    let quad = [point(0), point(1), point(2), point(3)];
    let [w, dw, ddw] = weights(basis, local);
    CurvePoint {
        position: combine(w, quad),
        velocity: combine(dw, quad) * scale,
        acceleration: combine(ddw, quad) * (scale * scale),
    }
}

/// Point at `u ∈ [0, 1]` on the open Catmull-Rom curve through all `points`
/// (see [`eval_curve`]).
#[must_use]
pub fn eval_open(points: &[DVec3], u: f64) -> DVec3 {
    eval_curve(points, u, Basis::CatmullRom, false).position
}

#[cfg(test)]
#[expect(clippy::cast_precision_loss, reason = "small test indices")]
mod tests {
    use super::*;

    // Shorthands over `eval_curve` and the segment weights.
    fn clamp_unit(s: f64) -> f64 {
        if s.is_finite() {
            s.clamp(0.0, 1.0)
        } else {
            0.0
        }
    }

    fn catmull_rom(p0: DVec3, p1: DVec3, p2: DVec3, p3: DVec3, s: f64) -> DVec3 {
        combine(
            weights(Basis::CatmullRom, clamp_unit(s))[0],
            [p0, p1, p2, p3],
        )
    }

    fn catmull_rom_tangent(p0: DVec3, p1: DVec3, p2: DVec3, p3: DVec3, s: f64) -> DVec3 {
        combine(
            weights(Basis::CatmullRom, clamp_unit(s))[1],
            [p0, p1, p2, p3],
        )
    }

    fn eval_open_tangent(points: &[DVec3], u: f64) -> DVec3 {
        eval_curve(points, u, Basis::CatmullRom, false).velocity
    }

    fn eval_closed(points: &[DVec3], u: f64) -> DVec3 {
        eval_curve(points, u, Basis::CatmullRom, true).position
    }

    fn eval_closed_tangent(points: &[DVec3], u: f64) -> DVec3 {
        eval_curve(points, u, Basis::CatmullRom, true).velocity
    }

    fn eval_uniform_bspline(points: &[DVec3], u: f64) -> DVec3 {
        eval_curve(points, u, Basis::BSpline, false).position
    }

    fn eval_uniform_bspline_tangent(points: &[DVec3], u: f64) -> DVec3 {
        eval_curve(points, u, Basis::BSpline, false).velocity
    }

    fn zigzag() -> Vec<DVec3> {
        vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(0.3, 0.2, 0.1),
            DVec3::new(0.5, 0.25, 0.4),
            DVec3::new(1.1, 0.05, 0.3),
            DVec3::new(1.4, 0.0, 0.9),
        ]
    }

    fn close(a: DVec3, b: DVec3, tol: f64) -> bool {
        (a - b).length() <= tol
    }

    #[test]
    fn segment_hits_ends_with_textbook_tangents() {
        let [p0, p1, p2, p3] = [0, 1, 2, 3].map(|i| zigzag()[i]);
        assert!(close(catmull_rom(p0, p1, p2, p3, 0.0), p1, 1e-12));
        assert!(close(catmull_rom(p0, p1, p2, p3, 1.0), p2, 1e-12));
        assert!(close(catmull_rom(p0, p1, p2, p3, 7.0), p2, 1e-12));
        assert!(close(catmull_rom(p0, p1, p2, p3, f64::NAN), p1, 1e-12));
        assert!(close(
            catmull_rom_tangent(p0, p1, p2, p3, 0.0),
            (p2 - p0) / 2.0,
            1e-12
        ));
        assert!(close(
            catmull_rom_tangent(p0, p1, p2, p3, 1.0),
            (p3 - p1) / 2.0,
            1e-12
        ));
        // Midpoint from the matrix form: (−p0 + 9p1 + 9p2 − p3) / 16.
        let mid = (-p0 + 9.0 * p1 + 9.0 * p2 - p3) / 16.0;
        assert!(close(catmull_rom(p0, p1, p2, p3, 0.5), mid, 1e-12));
    }

    #[test]
    fn open_and_closed_pass_through_every_point() {
        let pts = zigzag();
        for (k, &p) in pts.iter().enumerate() {
            let u = k as f64 / 4.0;
            assert!(close(eval_open(&pts, u), p, 1e-12), "open point {k}");
            let u = k as f64 / 5.0;
            assert!(close(eval_closed(&pts, u), p, 1e-12), "closed point {k}");
            assert!(
                close(eval_closed(&pts, u - 3.0), p, 1e-12),
                "closed wrap {k}"
            );
        }
        assert!(close(eval_closed(&pts, 1.0), pts[0], 1e-12));
        assert!(close(eval_open(&pts, -2.0), pts[0], 1e-12));
        assert!(close(eval_open(&pts, 9.0), pts[4], 1e-12));
        assert!(close(eval_open(&pts, f64::INFINITY), pts[0], 1e-12));
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        assert_eq!(eval_open(&[], 0.5), DVec3::ZERO);
        let one = [DVec3::new(1.0, 2.0, 3.0)];
        assert_eq!(eval_closed(&one, 0.7), one[0]);
        assert_eq!(eval_uniform_bspline_tangent(&one, 0.7), DVec3::ZERO);
        // Two points: the straight line, at constant speed, for every variant.
        let two = [DVec3::new(1.0, 0.0, 0.0), DVec3::new(3.0, 1.0, -2.0)];
        for u in [0.0, 0.3, 0.5, 0.9, 1.0] {
            let line = two[0].lerp(two[1], u);
            assert!(close(eval_open(&two, u), line, 1e-12));
            assert!(close(eval_closed(&two, u), line, 1e-12));
            assert!(close(eval_uniform_bspline(&two, u), line, 1e-12));
            assert!(close(eval_open_tangent(&two, u), two[1] - two[0], 1e-12));
        }
    }

    #[test]
    fn bspline_clamps_ends_and_averages_interior_knots() {
        let pts = zigzag();
        assert!(close(eval_uniform_bspline(&pts, 0.0), pts[0], 1e-12));
        assert!(close(eval_uniform_bspline(&pts, 1.0), pts[4], 1e-12));
        assert!(close(
            eval_uniform_bspline_tangent(&pts, 0.0),
            (pts[1] - pts[0]) * 4.0,
            1e-12
        ));
        for k in 1..4 {
            let knot = (pts[k - 1] + 4.0 * pts[k] + pts[k + 1]) / 6.0;
            assert!(close(
                eval_uniform_bspline(&pts, k as f64 / 4.0),
                knot,
                1e-12
            ));
        }
        // Zero curvature at a reflected end.
        let end = eval_curve(&pts, 0.0, Basis::BSpline, false);
        assert!(end.acceleration.length() < 1e-12);
    }

    #[test]
    fn derivatives_match_central_differences() {
        let pts = zigzag();
        let h = 1e-5;
        for basis in [Basis::CatmullRom, Basis::BSpline] {
            for closed in [false, true] {
                for i in 1..40 {
                    let u = f64::from(i) / 40.0 + 0.0031;
                    let at = |u| eval_curve(&pts, u, basis, closed);
                    let c = at(u);
                    let dv = (at(u + h).position - at(u - h).position) / (2.0 * h);
                    let da = (at(u + h).velocity - at(u - h).velocity) / (2.0 * h);
                    assert!(close(c.velocity, dv, 1e-6), "{basis:?} {closed} u={u}");
                    assert!(close(c.acceleration, da, 1e-5), "{basis:?} {closed} u={u}");
                }
            }
        }
    }

    #[test]
    fn smooth_across_knots_and_the_closing_seam() {
        let pts = zigzag();
        let e = 1e-9;
        for k in 1..4 {
            let u = f64::from(k) / 4.0;
            let (a, b) = (
                eval_open_tangent(&pts, u - e),
                eval_open_tangent(&pts, u + e),
            );
            assert!(close(a, b, 1e-6), "C1 at knot {k}");
        }
        let (a, b) = (eval_closed_tangent(&pts, -e), eval_closed_tangent(&pts, e));
        assert!(close(a, b, 1e-6));
        assert!(close(a, (pts[1] - pts[4]) / 2.0 * 5.0, 1e-6));
        // Collinear, evenly spaced points reproduce the line exactly.
        let line: Vec<DVec3> = (0..5).map(|i| DVec3::X * f64::from(i)).collect();
        for basis in [Basis::CatmullRom, Basis::BSpline] {
            let c = eval_curve(&line, 0.37, basis, false);
            assert!(close(c.position, DVec3::X * 1.48, 1e-12));
            assert!(close(c.velocity, DVec3::X * 4.0, 1e-12));
        }
    }
}
