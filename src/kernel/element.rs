//! Boundary elements: line segments and circular arcs.
//!
//! An arc is stored by its endpoints and bulge (`tan(sweep/4)`, the DXF /
//! cavalier_contours convention) because the endpoints are what the user gave
//! exactly; centre and radius are derived once, at construction.

use super::construct;
use super::{BBox, Point};

/// A straight segment from `a` to `b`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// Start point.
    pub a: Point,
    /// End point.
    pub b: Point,
}

/// A circular arc from `a` to `b` with signed sweep `4·atan(bulge)`:
/// counter-clockwise for `bulge > 0`, clockwise for `bulge < 0`. The sweep
/// lies in (−2π, 2π) and is never zero (a zero bulge is a [`Segment`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arc {
    /// Start point.
    pub a: Point,
    /// End point.
    pub b: Point,
    /// `tan(sweep / 4)`; sign gives the direction.
    pub bulge: f64,
    /// Centre of the supporting circle (derived, rounded).
    pub center: Point,
    /// Radius of the supporting circle (derived, rounded), > 0.
    pub radius: f64,
}

/// One element of a boundary loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Element {
    /// A line segment.
    Segment(Segment),
    /// A circular arc.
    Arc(Arc),
}

impl Arc {
    /// The arc from `a` to `b` with the given non-zero bulge. Endpoints must
    /// differ; the caller checks both.
    pub fn from_bulge(a: Point, b: Point, bulge: f64) -> Arc {
        let d = b - a;
        // center = m + perp(d)·(1 − b²)/(4b): the signed distance of the centre
        // from the chord is (c/2)·cot(sweep/2), and cot(θ/2) = (1 − b²)/(2b)
        // for b = tan(θ/4). No trigonometry, so no error from atan/tan.
        // Written with 1/b so that huge bulges (nearly full circles) do not
        // overflow in b².
        let center = a.mid(b) + d.perp() * (0.25 * (1.0 / bulge - bulge));
        let radius = 0.25 * d.norm() * (bulge.abs() + 1.0 / bulge.abs());
        Arc { a, b, bulge, center, radius }
    }

    /// True when the arc runs counter-clockwise.
    pub fn is_ccw(&self) -> bool {
        self.bulge > 0.0
    }

    /// Signed sweep angle in radians, in (−2π, 2π).
    pub fn sweep(&self) -> f64 {
        4.0 * self.bulge.atan()
    }

    /// The point halfway along the arc.
    pub fn midpoint(&self) -> Point {
        // The sagitta is bulge·c/2 on the side opposite to perp(d) for ccw arcs.
        self.a.mid(self.b) - (self.b - self.a).perp() * (0.5 * self.bulge)
    }

    /// True when the direction from the centre towards `p` lies within the
    /// arc's angular span (endpoints included). `p` need not be on the circle.
    pub fn spans_direction(&self, p: Point) -> bool {
        let (s, e) = if self.is_ccw() { (self.a, self.b) } else { (self.b, self.a) };
        let (vs, ve, vp) = (s - self.center, e - self.center, p - self.center);
        if self.bulge.abs() <= 1.0 {
            // Sweep at most π: inside both half-planes.
            vs.cross(vp) >= 0.0 && vp.cross(ve) >= 0.0
        } else {
            // Sweep above π: inside unless strictly within the complement.
            !(ve.cross(vp) > 0.0 && vp.cross(vs) > 0.0)
        }
    }

    /// Cuts the arc where it passes the circle points `center ± radius·axis`
    /// (`axis` a unit vector): with `axis` = x the pieces are x-monotone,
    /// with `axis` = y they are y-monotone. Pieces come in travel order as
    /// (start, end, angle of the piece's middle from the centre). Cut points
    /// are placed exactly on the axis so neighbouring pieces share them.
    pub fn monotone_pieces(&self, axis: Point) -> impl Iterator<Item = (Point, Point, f64)> {
        let (c, r, sweep) = (self.center, self.radius, self.sweep());
        let v = self.a - c;
        let a0 = v.y.atan2(v.x);
        let phase = axis.y.atan2(axis.x);
        // Fractions t of the sweep at which the direction is phase + k·π; a
        // sweep below 2π passes at most two of them. Fixed arrays, because
        // this runs once per element in the sweep and per ray test.
        let mut cuts = [(1.0, self.b); 3];
        let mut n = 0;
        for k in -4i32..=4 {
            let t = (phase + k as f64 * std::f64::consts::PI - a0) / sweep;
            let sign = if k.rem_euclid(2) == 0 { 1.0 } else { -1.0 };
            if t > 1e-12 && t < 1.0 - 1e-12 && n < 2 {
                cuts[n] = (t, c + axis * (sign * r));
                n += 1;
            }
        }
        cuts[..n].sort_by(|x, y| x.0.total_cmp(&y.0));
        let mut pieces = [(self.a, self.b, 0.0); 3];
        let (mut start, mut t0) = (self.a, 0.0);
        for (piece, &(t1, end)) in pieces.iter_mut().zip(&cuts[..=n]) {
            *piece = (start, end, a0 + 0.5 * (t0 + t1) * sweep);
            start = end;
            t0 = t1;
        }
        pieces.into_iter().take(n + 1)
    }

    /// The arc's length.
    pub fn length(&self) -> f64 {
        self.radius * self.sweep().abs()
    }

    /// Tight bounding box: endpoints plus the circle's axis extremes the arc passes.
    pub fn bbox(&self) -> BBox {
        let mut bb = BBox::of_points(self.a, self.b);
        let (c, r) = (self.center, self.radius);
        for dir in [Point::new(1.0, 0.0), Point::new(0.0, 1.0), Point::new(-1.0, 0.0), Point::new(0.0, -1.0)] {
            let p = c + dir * r;
            if self.spans_direction(p) {
                bb.add_point(p);
            }
        }
        bb
    }

    /// Area between the chord and the arc, signed: positive when the arc
    /// bulges to the right of the chord direction (counter-clockwise arc).
    pub fn segment_area(&self) -> f64 {
        let t = self.sweep();
        // r²/2·(θ − sin θ) loses all digits for tiny θ; the series keeps them.
        let t_minus_sin = if t.abs() < 1e-3 {
            let t3 = t * t * t;
            t3 / 6.0 - t3 * t * t / 120.0
        } else {
            t - t.sin()
        };
        0.5 * self.radius * self.radius * t_minus_sin
    }
}

impl Element {
    /// The element from `a` to `b` with the given bulge: a segment when the
    /// bulge is 0, an arc otherwise.
    pub fn from_bulge(a: Point, b: Point, bulge: f64) -> Element {
        if bulge == 0.0 {
            Element::Segment(Segment { a, b })
        } else {
            Element::Arc(Arc::from_bulge(a, b, bulge))
        }
    }

    /// Start point.
    pub fn start(&self) -> Point {
        match self {
            Element::Segment(s) => s.a,
            Element::Arc(a) => a.a,
        }
    }

    /// End point.
    pub fn end(&self) -> Point {
        match self {
            Element::Segment(s) => s.b,
            Element::Arc(a) => a.b,
        }
    }

    /// Bulge (0 for segments).
    pub fn bulge(&self) -> f64 {
        match self {
            Element::Segment(_) => 0.0,
            Element::Arc(a) => a.bulge,
        }
    }

    /// Unit tangent at the start, in the direction of travel.
    pub fn start_tangent(&self) -> Point {
        self.tangent_rotated(-1.0)
    }

    /// Unit tangent at the end, in the direction of travel.
    pub fn end_tangent(&self) -> Point {
        self.tangent_rotated(1.0)
    }

    fn tangent_rotated(&self, sign: f64) -> Point {
        let d = self.end() - self.start();
        let b = self.bulge();
        // The tangent at either end is the chord turned by ∓sweep/2, and
        // cos(θ/2), sin(θ/2) are rational in b = tan(θ/4).
        let (c, s) = ((1.0 - b * b), sign * 2.0 * b);
        Point::new(c * d.x - s * d.y, s * d.x + c * d.y).unit()
    }

    /// Length along the element.
    pub fn length(&self) -> f64 {
        match self {
            Element::Segment(s) => s.a.dist(s.b),
            Element::Arc(a) => a.length(),
        }
    }

    /// Tight bounding box.
    pub fn bbox(&self) -> BBox {
        match self {
            Element::Segment(s) => BBox::of_points(s.a, s.b),
            Element::Arc(a) => a.bbox(),
        }
    }

    /// Unit normal to the left of the direction of travel (towards the
    /// shape's interior) at the element's point `q`; for an arc, `q` only
    /// gives the direction from the centre.
    pub fn left_normal_at(&self, q: Point) -> Point {
        match self {
            Element::Segment(s) => (s.b - s.a).perp().unit(),
            Element::Arc(a) => {
                let out = (q - a.center).unit();
                if a.is_ccw() {
                    -out
                } else {
                    out
                }
            }
        }
    }

    /// Euclidean distance from `p` to the closest point of the element, and that point.
    pub fn closest_point(&self, p: Point) -> (f64, Point) {
        match self {
            Element::Segment(s) => {
                let t = construct::project_param(s.a, s.b, p).clamp(0.0, 1.0);
                let q = s.a + (s.b - s.a) * t;
                (p.dist(q), q)
            }
            Element::Arc(a) => {
                let v = p - a.center;
                let n = v.norm();
                if n > 0.0 && a.spans_direction(p) {
                    let q = a.center + v * (a.radius / n);
                    ((n - a.radius).abs(), q)
                } else {
                    let (da, db) = (p.dist(a.a), p.dist(a.b));
                    if da <= db {
                        (da, a.a)
                    } else {
                        (db, a.b)
                    }
                }
            }
        }
    }

    /// The arc-length fraction in [0, 1] of the element's point nearest to
    /// `p` along its own parametrisation (the projection for a segment, the
    /// angle for an arc), clamped to the element.
    pub fn param_of(&self, p: Point) -> f64 {
        match self {
            Element::Segment(s) => crate::kernel::construct::project_param(s.a, s.b, p).clamp(0.0, 1.0),
            Element::Arc(a) => {
                let (u, v) = (a.a - a.center, p - a.center);
                let mut ang = u.cross(v).atan2(u.dot(v));
                let sweep = a.sweep();
                // Measure in the direction of travel, in [0, 2π).
                if sweep < 0.0 {
                    ang = -ang;
                }
                if ang < 0.0 {
                    ang += std::f64::consts::TAU;
                }
                let t = ang / sweep.abs();
                if t > 1.0 {
                    // Past the end: the nearer end by angle.
                    let past = ang - sweep.abs();
                    if past < std::f64::consts::TAU - ang {
                        1.0
                    } else {
                        0.0
                    }
                } else {
                    t
                }
            }
        }
    }

    /// The largest distance (model units) between the circle (`c`, `r`)
    /// and the part of the element between fractions `t0` and `t1`:
    /// distances to a circle are extreme at the part's ends, at the foot of
    /// `c` on a segment, and on an arc in the direction of `c` from the
    /// arc's centre and opposite to it.
    pub fn circle_deviation(&self, t0: f64, t1: f64, c: Point, r: f64) -> f64 {
        let off = |t: f64| (self.point_at(t).dist(c) - r).abs();
        let (lo, hi) = (t0.min(t1), t0.max(t1));
        let inner = match self {
            Element::Segment(_) => [Some(self.param_of(c)), None],
            Element::Arc(a) => [Some(self.param_of(c)), Some(self.param_of(a.center + (a.center - c)))],
        };
        inner.into_iter().flatten().filter(|t| (lo..=hi).contains(t)).map(off).fold(off(t0).max(off(t1)), f64::max)
    }

    /// Point at arc-length fraction `t` in [0, 1] along the element; exactly
    /// the start and end points at 0 and 1, so that positions at vertices
    /// are the vertices.
    pub fn point_at(&self, t: f64) -> Point {
        if t == 0.0 {
            return self.start();
        }
        if t == 1.0 {
            return self.end();
        }
        match self {
            Element::Segment(s) => s.a + (s.b - s.a) * t,
            Element::Arc(a) => {
                let ang = a.sweep() * t;
                let (sn, cs) = ang.sin_cos();
                let v = a.a - a.center;
                a.center + Point::new(cs * v.x - sn * v.y, sn * v.x + cs * v.y)
            }
        }
    }

    /// Signed area contribution of the element's bulge beyond its chord
    /// (0 for segments); see [`Arc::segment_area`].
    pub fn bulge_area(&self) -> f64 {
        match self {
            Element::Segment(_) => 0.0,
            Element::Arc(a) => a.segment_area(),
        }
    }

    /// Sagitta: the largest distance between the element and its chord.
    pub fn sagitta(&self) -> f64 {
        match self {
            Element::Segment(_) => 0.0,
            Element::Arc(a) => {
                let half_chord = 0.5 * a.a.dist(a.b);
                if a.bulge.abs() <= 1.0 {
                    a.bulge.abs() * half_chord
                } else {
                    a.radius + (a.radius * a.radius - half_chord * half_chord).max(0.0).sqrt()
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn half_circle_from_unit_bulge() {
        let e = Element::from_bulge(Point::new(-1.0, 0.0), Point::new(1.0, 0.0), 1.0);
        let Element::Arc(a) = e else { panic!("not an arc") };
        assert!(close(a.radius, 1.0) && close(a.center.x, 0.0) && close(a.center.y, 0.0));
        assert!(close(a.sweep(), PI));
        // Counter-clockwise from (−1,0) to (1,0) passes below: through (0,−1).
        assert!(close(a.midpoint().y, -1.0));
        let bb = e.bbox();
        assert!(close(bb.min.y, -1.0) && close(bb.max.y, 0.0));
        assert!(close(e.length(), PI));
        assert!(close(a.segment_area(), PI / 2.0));
    }

    #[test]
    fn tangents_follow_travel_direction() {
        let e = Element::from_bulge(Point::new(-1.0, 0.0), Point::new(1.0, 0.0), 1.0);
        let t0 = e.start_tangent();
        let t1 = e.end_tangent();
        assert!(close(t0.x, 0.0) && close(t0.y, -1.0), "{t0:?}");
        assert!(close(t1.x, 0.0) && close(t1.y, 1.0), "{t1:?}");
    }

    #[test]
    fn large_bulge_covers_more_than_half_circle() {
        // bulge 3 → sweep 4·atan(3) ≈ 286°.
        let e = Element::from_bulge(Point::new(1.0, 0.0), Point::new(0.0, 1.0), -(PI * 3.0 / 8.0).tan());
        let Element::Arc(a) = e else { panic!() };
        assert!(close(a.radius, 1.0) && close(a.center.x, 0.0) && close(a.center.y, 0.0), "{a:?}");
        // Clockwise 270° from (1,0) to (0,1) passes (0,−1) and (−1,0).
        assert!(a.spans_direction(Point::new(0.0, -5.0)));
        assert!(a.spans_direction(Point::new(-5.0, 0.0)));
        assert!(!a.spans_direction(Point::new(1.0, 1.0)));
        assert!(close(e.point_at(1.0).x, 0.0) && close(e.point_at(1.0).y, 1.0));
        assert!(close(e.point_at(1.0 / 3.0).y, -1.0));
    }

    #[test]
    fn monotone_pieces_cut_at_the_axis_points() {
        // Clockwise 270° from (1,0) to (0,1) around the origin: passes the
        // bottom (0,−1) and the leftmost point (−1,0).
        let Element::Arc(a) = Element::from_bulge(Point::new(1.0, 0.0), Point::new(0.0, 1.0), -(PI * 3.0 / 8.0).tan())
        else {
            panic!()
        };
        let xs: Vec<_> = a.monotone_pieces(Point::new(1.0, 0.0)).collect();
        assert_eq!(xs.len(), 2);
        assert!(xs[0].1.dist(Point::new(-1.0, 0.0)) < 1e-12);
        let ys: Vec<_> = a.monotone_pieces(Point::new(0.0, 1.0)).collect();
        assert_eq!(ys.len(), 2);
        assert!(ys[0].1.dist(Point::new(0.0, -1.0)) < 1e-12);
        for (s, e, mid) in ys {
            // Each y-monotone piece lies in one half: left or right of the centre.
            let m = Point::new(mid.cos(), mid.sin());
            assert!(s.x * m.x >= -1e-12 && e.x * m.x >= -1e-12, "{s:?} {e:?} {m:?}");
        }
    }

    #[test]
    fn param_of_inverts_point_at() {
        for bulge in [0.0, 0.3, -0.7, 2.5, -4.0] {
            let e = Element::from_bulge(Point::new(1.0, 2.0), Point::new(-3.0, 0.5), bulge);
            for k in 0..=20 {
                let t = k as f64 / 20.0;
                assert!((e.param_of(e.point_at(t)) - t).abs() < 1e-12, "bulge {bulge}, t {t}");
            }
        }
    }

    #[test]
    fn closest_point_on_arc_and_segment() {
        let e = Element::from_bulge(Point::new(1.0, 0.0), Point::new(-1.0, 0.0), 1.0);
        let (d, q) = e.closest_point(Point::new(0.0, 3.0));
        assert!(close(d, 2.0) && close(q.y, 1.0));
        let (d, _) = e.closest_point(Point::new(0.0, -3.0));
        assert!(close(d, 10f64.sqrt()));
        let s = Element::from_bulge(Point::new(0.0, 0.0), Point::new(2.0, 0.0), 0.0);
        assert!(close(s.closest_point(Point::new(1.0, 1.0)).0, 1.0));
    }

    #[test]
    fn tiny_bulge_area_keeps_its_digits() {
        let e = Element::from_bulge(Point::new(0.0, 0.0), Point::new(1.0, 0.0), 1e-6);
        // Parabolic approximation: area ≈ 2/3 · chord · sagitta.
        let expect = 2.0 / 3.0 * 1.0 * 0.5e-6;
        assert!((e.bulge_area() - expect).abs() < 1e-15, "{}", e.bulge_area());
    }

    #[test]
    fn circle_deviation_finds_the_extremes_inside_a_part() {
        let o = Point::new(0.0, 0.0);
        // A half circle of radius 1 (ccw from (1, 0) to (-1, 0)) against
        // the circle of radius 1 centred (0, 0.1): farthest from it at the
        // top (0, 1), 0.1 inside; the ends lie √1.01 − 1 outside.
        let half = Element::from_bulge(Point::new(1.0, 0.0), Point::new(-1.0, 0.0), 1.0);
        let c = Point::new(0.0, 0.1);
        assert!(close(half.circle_deviation(0.0, 1.0, c, 1.0), 0.1), "{}", half.circle_deviation(0.0, 1.0, c, 1.0));
        // The part near the start only: the top is outside it.
        let part = half.circle_deviation(0.0, 0.25, c, 1.0);
        let p = half.point_at(0.25);
        assert!(close(part, (p.dist(c) - 1.0).abs().max((1.01f64.sqrt() - 1.0).abs())), "{part}");
        // A segment through the circle's centre line: extreme at its foot.
        let seg = Element::from_bulge(Point::new(-1.0, 2.0), Point::new(1.0, 2.0), 0.0);
        assert!(close(seg.circle_deviation(0.0, 1.0, o, 2.0), 5f64.sqrt() - 2.0));
        assert!(close(seg.circle_deviation(0.25, 0.75, o, 2.0), 4.25f64.sqrt() - 2.0));
    }
}
