//! The desired body path on the ground plane, parameterised by arc length
//! (Girard & Maciejewski 1985, "Horizontal Control": a Catmull-Rom or
//! B-spline path, with positions found "using a numerical arclength
//! calculation").
//!
//! Control points are ground-plane `(x, z)` pairs in metres (world y is up).
//! Heading convention: heading 0 faces +z and a positive heading turns toward
//! +x, so the direction of heading `h` is `(sin h, cos h)` as `(x, z)`: a
//! positive yaw about +y, counter-clockwise seen from above (a left turn).
//!
//! Accuracy: at construction each spline segment is cut into 64 equal steps
//! of the curve parameter, each integrated with 5-point Gauss-Legendre
//! quadrature (lengths agree with a 400 000-chord polyline to 1e-10 m on a
//! 6 m path). [`BodyPath::sample`] inverts arc length by binary search in that
//! table plus safeguarded Newton steps, landing within about 1e-12 m of the
//! asked distance along the curve.
//!
//! Speeds along the path ("Horizontal Control": "given the desired body
//! speed along different parts of the curve, PODA may calculate the desired
//! positions and velocities along it"): a path may carry one desired speed
//! per control point. The lab's reading: each control point has a place on
//! the curve, the segment boundary it starts (`u = i / segments`) — the point
//! itself on a Catmull-Rom path, which passes through its points; on a
//! B-spline the boundary where the point weighs most (2/3, the curve point
//! `(pᵢ₋₁ + 4pᵢ + pᵢ₊₁)/6`), the curve point nearest the control point that
//! the spline's parameter singles out. Between two control points the desired
//! speed is linear in arc length from one place to the next, so that it is
//! a property of the ground the body covers, whatever the curve's
//! parameterisation ([`BodyPath::desired_speed_mps`]).

use gaitlab_core::portable::Portable;
use glam::{DVec2, DVec3};

use super::spline::{Basis, CurvePoint, eval_curve};

/// Control points a path may have (3..=64 when closed).
const POINT_COUNT: std::ops::RangeInclusive<usize> = 2..=64;
/// Smallest gap between consecutive control points, metres.
const MIN_GAP_M: f64 = 1e-3;
/// Shortest allowed path, metres.
const MIN_LENGTH_M: f64 = 0.01;
/// Largest allowed coordinate magnitude, metres.
const MAX_COORD_M: f64 = 1e6;
/// Arc-length table steps per spline segment.
const STEPS_PER_SEGMENT: usize = 64;
/// 5-point Gauss-Legendre abscissae and weights on `[-1, 1]`.
const GAUSS: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// Which cubic spline a body path uses (PODA allows either); the preset schema's enum.
pub use gaitlab_core::preset::PathKindSpec as PathKind;
/// The JSON form of a body path (`scenario.poda.path`); the preset schema's struct.
pub use gaitlab_core::preset::PathSpec;

/// Why a path could not be built: the field (`points[3]`, `points`,
/// `radius_m`) and the reason, shown as `path: reason`.
pub type PathError = crate::DriverError;

/// A [`PathError`] at `path` for `reason`.
fn error(path: impl Into<String>, reason: impl Into<String>) -> PathError {
    PathError::new(path, reason)
}

/// `value` must be finite and in `min..=max` (`unit` for the message).
fn check(value: f64, field: &str, min: f64, max: f64, unit: &str) -> Result<(), PathError> {
    if value.is_finite() && (min..=max).contains(&value) {
        return Ok(());
    }
    Err(error(
        field,
        format!("{value} {unit} is not within {min}..={max} {unit}"),
    ))
}

/// `p` must be finite and within ±1e6 m.
fn check_xz(p: DVec2, field: impl FnOnce() -> String) -> Result<(), PathError> {
    if p.is_finite() && p.abs().max_element() <= MAX_COORD_M {
        return Ok(());
    }
    Err(error(
        field(),
        format!("{p} m must be finite and within ±{MAX_COORD_M} m"),
    ))
}

/// The path at one arc length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathSample {
    /// Ground-plane position `(x, z)`, metres.
    pub position: DVec2,
    /// Unit direction of travel `(x, z)`.
    pub tangent: DVec2,
    /// Heading of `tangent`, radians in `[−π, π]` (see the module docs).
    pub heading_rad: f64,
    /// Signed curvature `d heading / d distance`, per metre; positive turns
    /// toward +x from +z (left, counter-clockwise seen from above).
    pub curvature_per_m: f64,
}

/// A body path over the ground plane with an arc-length table.
#[derive(Clone, Debug)]
pub struct BodyPath {
    /// Control points lifted to `(x, 0, z)` for the spline, metres.
    points: Vec<DVec3>,
    /// Spline kind.
    kind: PathKind,
    /// Whether the curve loops.
    closed: bool,
    /// Arc length, metres, at curve parameter `u = i / (table.len() − 1)`.
    table: Vec<f64>,
    /// Arc length, metres, of each control point's place on the curve (its
    /// segment boundary); a closed path ends with the length, where the
    /// first point comes round again.
    knots_m: Vec<f64>,
    /// Desired body speed at each control point, m/s (module docs); `None`:
    /// the gait's speed everywhere.
    speeds_mps: Option<Vec<f64>>,
}

impl TryFrom<&PathSpec> for BodyPath {
    type Error = PathError;

    /// Builds the path of a preset's `path` section, checked as in
    /// [`BodyPath::new`] and, with `speeds_mps`, [`BodyPath::with_speeds`].
    fn try_from(spec: &PathSpec) -> Result<Self, PathError> {
        let points: Vec<DVec2> = spec.points.iter().map(|&p| DVec2::from(p)).collect();
        let path = BodyPath::new(&points, spec.kind, spec.closed)?;
        match &spec.speeds_mps {
            Some(speeds) => path.with_speeds(speeds),
            None => Ok(path),
        }
    }
}

impl BodyPath {
    /// Builds a path through (Catmull-Rom) or around (B-spline) `points`,
    /// ground-plane `(x, z)` in metres; `closed` loops back to the first point.
    ///
    /// # Errors
    /// `points` if there are not 2..=64 points (3..=64 when closed) or the
    /// path is shorter than 0.01 m; `points[i]` if a point is not finite,
    /// lies beyond ±1e6 m, or is closer than 1 mm to the one before it
    /// (for a closed path, `points[0]` against the last one too).
    pub fn new(points: &[DVec2], kind: PathKind, closed: bool) -> Result<Self, PathError> {
        let n = points.len();
        let min = if closed { 3 } else { *POINT_COUNT.start() };
        if n < min || n > *POINT_COUNT.end() {
            let max = POINT_COUNT.end();
            return Err(error(
                "points",
                format!("need {min}..={max} points, got {n}"),
            ));
        }
        for (i, &p) in points.iter().enumerate() {
            check_xz(p, || format!("points[{i}]"))?;
        }
        for i in usize::from(!closed)..n {
            let prev = (i + n - 1) % n;
            let gap = points[i].distance(points[prev]);
            if gap < MIN_GAP_M {
                let reason = format!("{gap} m from points[{prev}]; need at least {MIN_GAP_M} m");
                return Err(error(format!("points[{i}]"), reason));
            }
        }
        let steps = STEPS_PER_SEGMENT * if closed { n } else { n - 1 };
        let mut path = Self {
            points: points.iter().map(|p| DVec3::new(p.x, 0.0, p.y)).collect(),
            kind,
            closed,
            table: Vec::with_capacity(steps + 1),
            knots_m: Vec::with_capacity(steps / STEPS_PER_SEGMENT + 1),
            speeds_mps: None,
        };
        let mut length = 0.0;
        path.table.push(length);
        for i in 0..steps {
            let (u0, u1) = (path.param(i), path.param(i + 1));
            length += path.integrate(u0, u1);
            path.table.push(length);
        }
        if length.is_nan() || length < MIN_LENGTH_M {
            let reason = format!("path length {length} m is under {MIN_LENGTH_M} m");
            return Err(error("points", reason));
        }
        path.knots_m
            .extend(path.table.iter().step_by(STEPS_PER_SEGMENT).copied());
        Ok(path)
    }

    /// This path with a desired body speed at each control point, m/s
    /// (module docs; [`BodyPath::desired_speed_mps`]).
    ///
    /// # Errors
    /// `speeds_mps` unless there is one speed per control point;
    /// `speeds_mps[i]` for the first speed outside `scenario.poda.speed_mps`'s
    /// range.
    pub fn with_speeds(mut self, speeds_mps: &[f64]) -> Result<Self, PathError> {
        gaitlab_core::preset::poda::check_path_speeds("speeds_mps", self.points.len(), speeds_mps)
            .map_err(|e| error(e.path, e.reason))?;
        self.speeds_mps = Some(speeds_mps.to_vec());
        Ok(self)
    }

    /// The desired speed at each control point, m/s, when the path has them.
    #[must_use]
    pub fn speeds_mps(&self) -> Option<&[f64]> {
        self.speeds_mps.as_deref()
    }

    /// Arc length, metres, of each control point's place on the curve: the
    /// point itself (Catmull-Rom) or the segment boundary it weighs most
    /// (B-spline); a closed path adds its length, where the first point comes
    /// round again.
    #[must_use]
    pub fn knots_m(&self) -> &[f64] {
        &self.knots_m
    }

    /// The desired body speed at `distance_m` metres along the path, m/s:
    /// linear in arc length between the control points' places
    /// ([`BodyPath::knots_m`]); a closed path wraps (the last point's speed
    /// runs back to the first's), an open path holds its end speeds before
    /// 0 and past its length; a non-finite distance is treated as 0. `None`
    /// when the path has no speeds (the gait's speed applies).
    #[must_use]
    pub fn desired_speed_mps(&self, distance_m: f64) -> Option<f64> {
        let speeds = self.speeds_mps.as_deref()?;
        let d = if distance_m.is_finite() {
            distance_m
        } else {
            0.0
        };
        let d = if self.closed {
            d.rem_euclid(self.length_m())
        } else {
            d
        };
        let n = speeds.len();
        // The knot at or before `d`, so that segment `k` runs from knot `k`
        // to knot `k + 1` (speed `k` to speed `k + 1`, wrapping on a loop).
        let k = self
            .knots_m
            .partition_point(|&s| s <= d)
            .clamp(1, self.knots_m.len() - 1)
            - 1;
        let (v0, v1) = (speeds[k % n], speeds[(k + 1) % n]);
        let (s0, s1) = (self.knots_m[k], self.knots_m[k + 1]);
        let f = if s1 > s0 {
            ((d - s0) / (s1 - s0)).clamp(0.0, 1.0)
        } else {
            0.0
        };
        Some(v0 + (v1 - v0) * f)
    }

    /// A straight open path from `start` (metres) along `heading_rad`
    /// (0 faces +z, positive turns toward +x) for `length_m` metres.
    ///
    /// # Errors
    /// `start`, `heading_rad` (beyond ±1e6 rad) or `length_m` (outside
    /// 0.01..=1e6 m) when invalid or not finite.
    pub fn straight(start: DVec2, heading_rad: f64, length_m: f64) -> Result<Self, PathError> {
        check_xz(start, || "start".into())?;
        check(heading_rad, "heading_rad", -1e6, 1e6, "rad")?;
        check(length_m, "length_m", MIN_LENGTH_M, MAX_COORD_M, "m")?;
        let end = start + DVec2::new(heading_rad.psin(), heading_rad.pcos()) * length_m;
        Self::new(&[start, end], PathKind::CatmullRom, false)
    }

    /// A closed Catmull-Rom loop through 16 points on the circle of
    /// `radius_m` metres about `centre`, from angle `start_angle_rad` (measured
    /// like a heading: the first point is `centre + r (sin a, cos a)`), running
    /// counter-clockwise seen from above (heading increasing) or clockwise.
    /// The loop stays within 0.06% of the radius; its length is within 0.03%
    /// of 2πr.
    ///
    /// # Errors
    /// `centre`, `radius_m` (0.1..=1e5 m) or `start_angle_rad` (±1e6 rad)
    /// when invalid or not finite.
    pub fn circle(
        centre: DVec2,
        radius_m: f64,
        start_angle_rad: f64,
        counter_clockwise: bool,
    ) -> Result<Self, PathError> {
        check_xz(centre, || "centre".into())?;
        check(radius_m, "radius_m", 0.1, 1e5, "m")?;
        check(start_angle_rad, "start_angle_rad", -1e6, 1e6, "rad")?;
        let step = std::f64::consts::TAU / 16.0 * if counter_clockwise { 1.0 } else { -1.0 };
        let points: Vec<DVec2> = (0..16_u8)
            .map(|k| start_angle_rad + step * f64::from(k))
            .map(|a| centre + radius_m * DVec2::new(a.psin(), a.pcos()))
            .collect();
        Self::new(&points, PathKind::CatmullRom, true)
    }

    /// Arc length of the path, metres (one lap for a closed path).
    #[must_use]
    pub fn length_m(&self) -> f64 {
        self.table.last().copied().unwrap_or(0.0)
    }

    /// Spline kind.
    #[must_use]
    pub fn kind(&self) -> PathKind {
        self.kind
    }

    /// Whether the path loops back to its start.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.closed
    }

    /// The serialisable form of this path (control points `[x, z]`, metres).
    #[must_use]
    pub fn to_spec(&self) -> PathSpec {
        let points = self.points.iter().map(|p| [p.x, p.z]).collect();
        PathSpec {
            kind: self.kind,
            points,
            closed: self.closed,
            speeds_mps: self.speeds_mps.clone(),
        }
    }

    /// Curve parameter of table entry `i` (the table has 64 steps a segment).
    fn param(&self, i: usize) -> f64 {
        let n = self.points.len();
        let segments = if self.closed { n } else { n.saturating_sub(1) };
        #[expect(clippy::cast_precision_loss, reason = "at most 4096 steps")]
        let u = i as f64 / (STEPS_PER_SEGMENT * segments.max(1)) as f64;
        u
    }

    /// Position and derivatives at curve parameter `u`.
    fn curve(&self, u: f64) -> CurvePoint {
        let basis = match self.kind {
            PathKind::CatmullRom => Basis::CatmullRom,
            PathKind::BSpline => Basis::BSpline,
        };
        eval_curve(&self.points, u, basis, self.closed)
    }

    /// Ground-plane speed `|d position / d u|`, metres per unit `u`.
    fn speed(&self, u: f64) -> f64 {
        let v = self.curve(u).velocity;
        DVec2::new(v.x, v.z).length()
    }

    /// Signed arc length from `u0` to `u1`, metres (5-point Gauss-Legendre).
    fn integrate(&self, u0: f64, u1: f64) -> f64 {
        let (mid, half) = (0.5 * (u0 + u1), 0.5 * (u1 - u0));
        half * GAUSS
            .iter()
            .map(|&(x, w)| w * self.speed(mid + half * x))
            .sum::<f64>()
    }

    /// Curve parameter at arc length `s ∈ [0, length]`: binary search in the
    /// table, then Newton steps on the integral, bisecting whenever Newton
    /// would leave the bracketing step.
    fn param_at(&self, s: f64) -> f64 {
        let i = self
            .table
            .partition_point(|&t| t <= s)
            .clamp(1, self.table.len() - 1)
            - 1;
        let (s0, span) = (self.table[i], self.table[i + 1] - self.table[i]);
        let (u0, u1) = (self.param(i), self.param(i + 1));
        if span.is_nan() || span <= 0.0 {
            return u0;
        }
        let (mut below, mut above) = (u0, u1);
        let mut u = u0 + (u1 - u0) * ((s - s0) / span).clamp(0.0, 1.0);
        for _ in 0..16 {
            let err = s0 + self.integrate(u0, u) - s;
            if err.abs() <= 1e-12 * s.max(1.0) {
                break;
            }
            if err > 0.0 {
                above = u;
            } else {
                below = u;
            }
            let newton = u - err / self.speed(u);
            u = if newton > below && newton < above {
                newton
            } else {
                0.5 * (below + above)
            };
        }
        u
    }

    /// The path at `distance_m` metres from its start, without allocating.
    /// A closed path wraps modulo its length; an open path continues in a
    /// straight line along its end tangents before 0 and past the length. A
    /// non-finite distance is treated as 0.
    #[must_use]
    pub fn sample(&self, distance_m: f64) -> PathSample {
        let d = if distance_m.is_finite() {
            distance_m
        } else {
            0.0
        };
        let length = self.length_m();
        if self.closed {
            self.sample_at(self.param_at(d.rem_euclid(length)), 0.0)
        } else if d < 0.0 {
            self.sample_at(0.0, d)
        } else if d > length {
            self.sample_at(1.0, d - length)
        } else {
            self.sample_at(self.param_at(d), 0.0)
        }
    }

    /// The curve at parameter `u`, moved `beyond_m` metres along the tangent
    /// (then with zero curvature) when nonzero.
    fn sample_at(&self, u: f64, beyond_m: f64) -> PathSample {
        let c = self.curve(u);
        let vel = DVec2::new(c.velocity.x, c.velocity.z);
        let acc = DVec2::new(c.acceleration.x, c.acceleration.z);
        // At a zero-speed cusp the direction of travel is that of the acceleration.
        let tangent = vel
            .try_normalize()
            .or_else(|| acc.try_normalize())
            .unwrap_or(DVec2::Y);
        let speed = vel.length();
        let curvature = if speed > 1e-9 && beyond_m == 0.0 {
            (vel.y * acc.x - vel.x * acc.y) / speed.powi(3)
        } else {
            0.0
        };
        PathSample {
            position: DVec2::new(c.position.x, c.position.z) + tangent * beyond_m,
            tangent,
            heading_rad: tangent.x.patan2(tangent.y),
            curvature_per_m: curvature,
        }
    }

    /// Arc length, metres, of the path point closest to `point` (`(x, z)`,
    /// metres): the nearest table entry, then a golden-section search over
    /// the steps either side. On an open path a point beyond an end gives a
    /// distance below 0 or above the length, matching [`Self::sample`].
    #[must_use]
    pub fn closest_distance(&self, point: DVec2) -> f64 {
        let gap2 = |u: f64| {
            let p = self.curve(u).position;
            DVec2::new(p.x, p.z).distance_squared(point)
        };
        let nearest = (0..self.table.len())
            .map(|i| (i, gap2(self.param(i))))
            .fold((0, f64::INFINITY), |best, next| {
                if next.1 < best.1 { next } else { best }
            });
        let (centre, step) = (self.param(nearest.0), self.param(1));
        // A closed curve wraps u, so the search may straddle the seam.
        let (mut left, mut right) = if self.closed {
            (centre - step, centre + step)
        } else {
            ((centre - step).max(0.0), (centre + step).min(1.0))
        };
        let golden = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let (inner_left, inner_right) = (
                right - golden * (right - left),
                left + golden * (right - left),
            );
            if gap2(inner_left) < gap2(inner_right) {
                right = inner_right;
            } else {
                left = inner_left;
            }
        }
        let s = self.table[nearest.0] + self.integrate(centre, 0.5 * (left + right));
        let length = self.length_m();
        if self.closed {
            return s.rem_euclid(length);
        }
        // Past an end, measure along the straight extrapolation instead.
        let (start, end) = (self.sample(0.0), self.sample(length));
        let before = (point - start.position).dot(start.tangent);
        let after = (point - end.position).dot(end.tangent);
        if s < 1e-9 && before < 0.0 {
            before
        } else if s > length - 1e-9 && after > 0.0 {
            length + after
        } else {
            s
        }
    }
}

#[cfg(test)]
#[expect(
    clippy::cast_precision_loss,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "small test counts"
)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI, TAU};

    use super::*;

    fn wavy(kind: PathKind) -> BodyPath {
        let pts = [
            (0.0, 0.0),
            (0.5, 1.0),
            (-0.3, 2.0),
            (0.4, 3.2),
            (1.5, 3.6),
            (2.2, 2.9),
        ];
        let pts: Vec<DVec2> = pts.iter().map(|&(x, z)| DVec2::new(x, z)).collect();
        BodyPath::new(&pts, kind, false).expect("valid wavy path")
    }

    /// Independent reference: a dense polyline through the curve, with its
    /// cumulative chord lengths.
    fn polyline(path: &BodyPath, n: usize) -> (Vec<DVec2>, Vec<f64>) {
        let pts: Vec<DVec2> = (0..=n)
            .map(|i| {
                let p = path.curve(i as f64 / n as f64).position;
                DVec2::new(p.x, p.z)
            })
            .collect();
        let mut cum = vec![0.0];
        for w in pts.windows(2) {
            cum.push(cum[cum.len() - 1] + w[0].distance(w[1]));
        }
        (pts, cum)
    }

    #[test]
    fn circle_length_radius_heading_and_curvature() {
        let (centre, r) = (DVec2::new(1.0, -3.0), 2.0);
        let ccw = BodyPath::circle(centre, r, 0.3, true).expect("circle");
        let rel = (ccw.length_m() - TAU * r).abs() / (TAU * r);
        // Measured: 12.562722 m against 4π = 12.566371 m, 2.9e-4 short.
        assert!(rel < 5e-4, "length off by {rel}");
        // Catmull-Rom is only C¹, so curvature jumps at the knots; but the
        // total turning ∫κ ds over one lap must be 2π.
        let (mut worst, mut turning, mut kmin, mut kmax) = (0.0_f64, 0.0, f64::MAX, 0.0_f64);
        let n = 4000;
        for i in 0..n {
            let s = ccw.sample(ccw.length_m() * (f64::from(i) + 0.5) / f64::from(n));
            worst = worst.max(((s.position - centre).length() - r).abs() / r);
            turning += s.curvature_per_m * ccw.length_m() / f64::from(n);
            (kmin, kmax) = (kmin.min(s.curvature_per_m), kmax.max(s.curvature_per_m));
        }
        // Measured: radial deviation ≤ 5.5e-4 r, κ r in [0.944, 1.117],
        // ∫κ ds = 2π − 6.4e-6.
        assert!(worst < 1e-3 && (turning - TAU).abs() < 1e-4);
        assert!(kmin * r > 0.9 && kmax * r < 1.15);
        let start = ccw.sample(0.0);
        assert!(
            (start.position - centre - r * DVec2::new(0.3f64.psin(), 0.3f64.pcos())).length()
                < 1e-12
        );
        assert!((start.heading_rad - (0.3 + FRAC_PI_2)).abs() < 1e-9);
        let cw = BodyPath::circle(centre, r, 0.3, false).expect("circle");
        assert!((cw.sample(1.0).curvature_per_m * r + 1.0).abs() < 0.2);
        assert!((cw.sample(0.0).heading_rad - (0.3 - FRAC_PI_2)).abs() < 1e-9);
    }

    #[test]
    fn straight_path_and_extrapolation() {
        let (start, h) = (DVec2::new(1.0, 2.0), 0.7_f64);
        let dir = DVec2::new(h.psin(), h.pcos());
        let path = BodyPath::straight(start, h, 3.0).expect("straight");
        assert!((path.length_m() - 3.0).abs() < 1e-12);
        for d in [-0.5, 0.0, 1.2, 3.0, 3.5] {
            let s = path.sample(d);
            assert!((s.position - (start + dir * d)).length() < 1e-12, "d {d}");
            assert!((s.heading_rad - h).abs() < 1e-12 && s.curvature_per_m.abs() < 1e-12);
        }
        assert_eq!(path.sample(f64::NAN).position, start);
        assert!(path.closest_distance(DVec2::NAN).is_finite());
        assert!((path.closest_distance(start + dir * -0.4 + dir.perp()) + 0.4).abs() < 1e-9);
        assert!((path.closest_distance(start + dir * 4.0) - 4.0).abs() < 1e-9);
    }

    #[test]
    fn equal_arc_steps_match_a_dense_polyline() {
        for kind in [PathKind::CatmullRom, PathKind::BSpline] {
            let path = wavy(kind);
            let (pts, cum) = polyline(&path, 400_000);
            let total = cum[cum.len() - 1];
            // Measured: differences 6e-11 m (Catmull-Rom), 2e-11 m (B-spline).
            assert!((path.length_m() - total).abs() < 1e-9);
            let (mut worst_pos, mut worst_gap) = (0.0_f64, 0.0_f64);
            let step = 0.01;
            let mut prev = path.sample(0.0).position;
            for k in 1..(path.length_m() / step) as usize {
                let d = k as f64 * step;
                let here = path.sample(d).position;
                let j = cum.partition_point(|&c| c <= d).min(cum.len() - 1);
                let t = (d - cum[j - 1]) / (cum[j] - cum[j - 1]);
                worst_pos = worst_pos.max(here.distance(pts[j - 1].lerp(pts[j], t)));
                worst_gap = worst_gap.max((here.distance(prev) - step).abs());
                prev = here;
            }
            // Measured: positions within 9e-11 m of the polyline's; 1 cm steps
            // equal to 6.4e-7 m (chords fall short of arcs by ≈ Δ³κ²/24).
            assert!(worst_pos < 1e-6 && worst_gap < 1e-4);
        }
    }

    #[test]
    fn tangent_and_curvature_match_finite_differences() {
        let step = 1e-4;
        for kind in [PathKind::CatmullRom, PathKind::BSpline] {
            let path = wavy(kind);
            for i in 1..60 {
                let d = path.length_m() * f64::from(i) / 60.0 + 0.0123;
                let here = path.sample(d);
                let (back, ahead) = (path.sample(d - step), path.sample(d + step));
                let dp = (ahead.position - back.position) / (2.0 * step);
                assert!(
                    (here.tangent - dp).length() < 1e-6,
                    "{kind:?} tangent at {d}"
                );
                assert!((here.tangent.length() - 1.0).abs() < 1e-12);
                let turn = (ahead.heading_rad - back.heading_rad + PI).rem_euclid(TAU) - PI;
                assert!(
                    (here.curvature_per_m - turn / (2.0 * step)).abs() < 1e-5,
                    "{kind:?} κ at {d}"
                );
            }
        }
    }

    #[test]
    fn closed_paths_wrap_and_closest_distance_inverts_sample() {
        let path = BodyPath::circle(DVec2::ZERO, 1.5, 0.0, true).expect("circle");
        let l = path.length_m();
        for d in [0.0, 0.7, 5.1] {
            for lap in [-3.0, 1.0, 2.0] {
                assert!(
                    (path.sample(d + lap * l).position - path.sample(d).position).length() < 1e-9
                );
            }
            let s = path.sample(d);
            let off = s.position + DVec2::new(s.tangent.y, -s.tangent.x) * 0.05;
            let back = (path.closest_distance(off) - d + l / 2.0).rem_euclid(l) - l / 2.0;
            assert!(back.abs() < 1e-6, "closest to {d}");
        }
        for p in path.to_spec().points.into_iter().map(DVec2::from) {
            let d = path.closest_distance(p);
            assert!(
                path.sample(d).position.distance(p) < 1e-9,
                "passes through {p}"
            );
        }
        let open = wavy(PathKind::CatmullRom);
        let end = open.sample(open.length_m());
        let beyond = end.position + end.tangent * 0.3;
        assert!((open.closest_distance(beyond) - open.length_m() - 0.3).abs() < 1e-9);
        assert!((open.sample(open.length_m() + 0.3).position - beyond).length() < 1e-12);
    }

    #[test]
    fn invalid_inputs_name_the_field() {
        let err = |r: Result<BodyPath, PathError>| r.map(|_| ()).expect_err("should fail");
        let xz = |pts: &[[f64; 2]]| pts.iter().map(|&p| DVec2::from(p)).collect::<Vec<_>>();
        let cases: [(&[[f64; 2]], bool, &str); 7] = [
            (&[[0.0, 0.0]], false, "points"),
            (&[[0.0, 0.0], [1.0, 0.0]], true, "points"),
            (&[[0.0, 0.0]; 65], false, "points"),
            (
                &[[0.0, 0.0], [1.0, 0.0], [f64::NAN, 1.0]],
                false,
                "points[2]",
            ),
            (&[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0005]], false, "points[2]"),
            (
                &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 2e-4]],
                true,
                "points[0]",
            ),
            (&[[0.0, 0.0], [0.005, 0.0]], false, "points"),
        ];
        for (pts, closed, field) in cases {
            for kind in [PathKind::CatmullRom, PathKind::BSpline] {
                assert_eq!(err(BodyPath::new(&xz(pts), kind, closed)).path, field);
            }
        }
        assert_eq!(
            err(BodyPath::circle(DVec2::ZERO, 0.05, 0.0, true)).path,
            "radius_m"
        );
        assert_eq!(
            err(BodyPath::straight(DVec2::ZERO, f64::NAN, 1.0)).path,
            "heading_rad"
        );
        assert_eq!(
            err(BodyPath::straight(DVec2::ZERO, 0.0, -1.0)).path,
            "length_m"
        );
        let e = err(BodyPath::straight(DVec2::new(f64::NAN, 0.0), 0.0, 1.0));
        assert!(e.to_string().starts_with("start: "), "{e}");
    }

    #[test]
    fn speeds_are_linear_in_arc_length_between_the_control_points() {
        let pts = [
            [0.0, 0.0],
            [0.5, 1.0],
            [-0.3, 2.0],
            [0.4, 3.2],
            [1.5, 3.6],
            [2.2, 2.9],
        ];
        let speeds = [0.3, 0.6, 0.4, 0.8, 0.5, 0.2];
        for kind in [PathKind::CatmullRom, PathKind::BSpline] {
            let spec = PathSpec {
                kind,
                points: pts.to_vec(),
                closed: false,
                speeds_mps: Some(speeds.to_vec()),
            };
            let path = BodyPath::try_from(&spec).expect("path with speeds");
            assert_eq!(path.to_spec(), spec);
            let knots = path.knots_m();
            assert_eq!(knots.len(), pts.len());
            assert!(knots[0] == 0.0 && (knots[5] - path.length_m()).abs() < 1e-12);
            for i in 0..pts.len() {
                // Each point's place: the point itself (Catmull-Rom), or the
                // B-spline's curve point (p₋ + 4p + p₊)/6 (p at the ends).
                let p = DVec2::from(pts[i]);
                let place = match kind {
                    PathKind::CatmullRom => p,
                    PathKind::BSpline if i == 0 || i == pts.len() - 1 => p,
                    PathKind::BSpline => {
                        (DVec2::from(pts[i - 1]) + 4.0 * p + DVec2::from(pts[i + 1])) / 6.0
                    }
                };
                let at = path.sample(knots[i]).position;
                assert!(at.distance(place) < 1e-9, "{kind:?} point {i}: {at}");
                let v = path.desired_speed_mps(knots[i]).expect("speeds");
                assert!((v - speeds[i]).abs() < 1e-12, "{kind:?} speed {i}: {v}");
            }
            for i in 0..pts.len() - 1 {
                let (s0, s1) = (knots[i], knots[i + 1]);
                let quarter = path.desired_speed_mps(s0 + 0.25 * (s1 - s0)).expect("v");
                let wanted = 0.75 * speeds[i] + 0.25 * speeds[i + 1];
                assert!((quarter - wanted).abs() < 1e-12, "{kind:?} segment {i}");
            }
            assert_eq!(path.desired_speed_mps(-1.0), Some(0.3));
            assert_eq!(path.desired_speed_mps(path.length_m() + 1.0), Some(0.2));
            assert_eq!(path.desired_speed_mps(f64::NAN), Some(0.3));
        }
        // A loop: the last point's speed runs back to the first's.
        let speeds: Vec<f64> = (0..16).map(|k| 0.2 + 0.05 * f64::from(k)).collect();
        let loop_ = BodyPath::circle(DVec2::ZERO, 2.0, 0.0, true)
            .expect("circle")
            .with_speeds(&speeds)
            .expect("speeds");
        let (l, last) = (loop_.length_m(), loop_.knots_m()[15]);
        assert_eq!(loop_.knots_m().len(), 17);
        let halfway = loop_.desired_speed_mps(0.5 * (last + l)).expect("v");
        assert!((halfway - 0.5 * (0.95 + 0.2)).abs() < 1e-12, "{halfway}");
        let lap = loop_.desired_speed_mps(l + 0.1).expect("v");
        assert!((lap - loop_.desired_speed_mps(0.1).expect("v")).abs() < 1e-12);
        // Without speeds the gait's speed applies.
        assert_eq!(wavy(PathKind::CatmullRom).desired_speed_mps(1.0), None);
        assert_eq!(wavy(PathKind::CatmullRom).to_spec().speeds_mps, None);
    }

    #[test]
    fn bad_speeds_name_the_field() {
        let err = |speeds: &[f64]| {
            wavy(PathKind::CatmullRom)
                .with_speeds(speeds)
                .map(|_| ())
                .expect_err("should fail")
        };
        let short = err(&[0.5; 5]);
        assert_eq!(short.path, "speeds_mps");
        assert_eq!(
            short.reason,
            "needs one speed per point (6 points, 5 speeds)"
        );
        for bad in [0.0, -0.4, 25.0, f64::NAN, f64::INFINITY] {
            let mut speeds = [0.5; 6];
            speeds[3] = bad;
            assert_eq!(err(&speeds).path, "speeds_mps[3]", "{bad}");
        }
        let spec: PathSpec = serde_json::from_str(
            r#"{"points": [[0, 0], [1, 0], [2, 0]], "speeds_mps": [0.3, 0.6]}"#,
        )
        .expect("json");
        let e = BodyPath::try_from(&spec).map(|_| ()).expect_err("2 speeds");
        assert_eq!(
            e.to_string(),
            "speeds_mps: needs one speed per point (3 points, 2 speeds)"
        );
    }

    #[test]
    fn spec_round_trips_through_json() {
        let spec: PathSpec =
            serde_json::from_str(r#"{"kind": "b_spline", "points": [[0, 0], [1, 0.5], [2, 0]]}"#)
                .expect("json");
        assert!(!spec.closed);
        let path = BodyPath::try_from(&spec).expect("build");
        assert_eq!(path.kind(), PathKind::BSpline);
        assert_eq!(path.to_spec(), spec);
        let text = serde_json::to_string(
            &BodyPath::circle(DVec2::ZERO, 1.0, 0.0, true)
                .expect("c")
                .to_spec(),
        )
        .expect("ser");
        assert!(text.contains(r#""kind":"catmull_rom""#) && text.contains(r#""closed":true"#));
        let bad = r#"{"kind": "catmull_rom", "points": [[0, 0], [1, 0]], "speed": 1}"#;
        assert!(serde_json::from_str::<PathSpec>(bad).is_err());
        let spec = PathSpec {
            kind: PathKind::CatmullRom,
            points: vec![[0.0, 0.0], [f64::NAN, 1.0]],
            closed: false,
            speeds_mps: None,
        };
        assert_eq!(
            BodyPath::try_from(&spec).map(|_| ()).expect_err("nan").path,
            "points[1]"
        );
    }
}
