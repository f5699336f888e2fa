//! A piece of a carrier: the part of a point's fan, a line or a circle
//! between two footpoint parameters, as the base cases see a primitive.

use super::apollonius::Site;
use super::bisector::{footpoint, footpoint_param};
use super::construct::unwrap_near;
use super::Point;

/// The part of `site` between footpoint parameters `u0` and `u1` (either
/// order; see [`footpoint`] for what a parameter is).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SitePiece {
    /// The carrier.
    pub site: Site,
    /// Parameter at the piece's start.
    pub u0: f64,
    /// Parameter at the piece's end.
    pub u1: f64,
}

impl SitePiece {
    /// The footpoint parameter of the disk centred `c` of radius `r`
    /// tangent to the carrier, an angle unwrapped to within π of the
    /// piece's middle.
    #[inline]
    pub fn param(&self, c: Point, r: f64) -> f64 {
        let u = footpoint_param(&self.site, c, r);
        match self.site {
            Site::Line { .. } => u,
            Site::Point(_) | Site::Circle { .. } => unwrap_near(u, 0.5 * (self.u0 + self.u1)),
        }
    }

    /// The boundary point at parameter `u`.
    #[inline]
    pub fn point_at(&self, u: f64) -> Point {
        footpoint(&self.site, u).0
    }

    /// A disk (centre, radius; model units) holding the whole piece: the
    /// point of a fan, the circle on a segment's or a short arc's chord as
    /// diameter (an arc of at most half a turn sees its chord at an angle
    /// of at least a right angle), an arc's own circle beyond that. Exact
    /// up to the rounding of the piece's end points; callers allow a
    /// tolerance for it.
    pub fn bound(&self) -> (Point, f64) {
        match self.site {
            Site::Point(q) => (q, 0.0),
            Site::Circle { o, r, .. } if (self.u1 - self.u0).abs() > std::f64::consts::PI => (o, r),
            Site::Line { .. } | Site::Circle { .. } => {
                let (a, b) = (self.point_at(self.u0), self.point_at(self.u1));
                ((a + b) * 0.5, 0.5 * a.dist(b))
            }
        }
    }

    /// [`distance`](Self::distance) without trigonometry, given the
    /// piece's points at `u0` and `u1` (`ends`): the same value except
    /// where `c`'s direction from an arc's centre is within rounding of an
    /// end's, where the two differ by rounding.
    pub fn distance_near(&self, c: Point, ends: [Point; 2]) -> f64 {
        match self.site {
            Site::Point(q) => c.dist(q),
            Site::Line { .. } => self.distance(c).0,
            Site::Circle { o, r, .. } => {
                if self.in_sweep(c, ends) {
                    (c.dist(o) - r).abs()
                } else {
                    c.dist(ends[0]).min(c.dist(ends[1]))
                }
            }
        }
    }

    /// Whether the direction of `c` from a circle's centre lies within the
    /// piece's range of angles (`ends` its points at `u0`, `u1`), decided
    /// by signs instead of angles: the same answer as comparing
    /// [`param`](Self::param) with the range, except within rounding of an
    /// end. False for other carriers.
    pub fn in_sweep(&self, c: Point, ends: [Point; 2]) -> bool {
        let Site::Circle { o, .. } = self.site else { return false };
        let (va, vb, v) = (ends[0] - o, ends[1] - o, c - o);
        let s = if self.u1 >= self.u0 { 1.0 } else { -1.0 };
        if (self.u1 - self.u0).abs() <= std::f64::consts::PI {
            s * va.cross(v) >= 0.0 && s * v.cross(vb) >= 0.0
        } else {
            !(s * vb.cross(v) > 0.0 && s * v.cross(va) > 0.0)
        }
    }

    /// [`in_sweep`](Self::in_sweep) with an answer for outside too:
    /// `Some(true)` within the range of angles, `Some(false)` more than
    /// twice `slack` (radians) beyond both ends, `None` near an end (or for
    /// another carrier), where angles must decide.
    pub fn sweep_side(&self, c: Point, ends: [Point; 2], slack: f64) -> Option<bool> {
        let Site::Circle { o, .. } = self.site else { return None };
        if self.in_sweep(c, ends) {
            return Some(true);
        }
        let v = c - o;
        let beyond = |e: Point| {
            let e = e - o;
            v.dot(e) <= 0.0 || v.cross(e).abs() > 2.0 * slack * v.norm() * e.norm()
        };
        (beyond(ends[0]) && beyond(ends[1])).then_some(false)
    }

    /// The least and greatest distance (model units) from `c` to a point
    /// of the piece, given its points at `u0` and `u1` (`ends`), without
    /// trigonometry: on a segment the far point is an end; on an arc the
    /// distance runs monotonically between the direction of `c` from the
    /// centre (nearest) and the opposite one (farthest), so each extreme
    /// is there when the arc spans that direction and at an end otherwise.
    /// Rounding as in [`in_sweep`](Self::in_sweep) near those directions.
    pub fn distance_range(&self, c: Point, ends: [Point; 2]) -> (f64, f64) {
        let (da, db) = (c.dist(ends[0]), c.dist(ends[1]));
        let (lo, hi) = (da.min(db), da.max(db));
        match self.site {
            Site::Point(q) => (c.dist(q), c.dist(q)),
            Site::Line { .. } => {
                let (ab, ac) = (ends[1] - ends[0], c - ends[0]);
                let len2 = ab.norm2();
                let s = if len2 > 0.0 { (ac.dot(ab) / len2).clamp(0.0, 1.0) } else { 0.0 };
                (c.dist(ends[0] + ab * s).min(lo), hi)
            }
            Site::Circle { o, r, .. } => {
                let d = c.dist(o);
                let near = if self.in_sweep(c, ends) { (d - r).abs() } else { lo };
                let far = if self.in_sweep(o * 2.0 - c, ends) { d + r } else { hi };
                (near.min(lo), far.max(hi))
            }
        }
    }

    /// Distance (model units) from `c` to the piece, and the parameter of
    /// the piece's point nearest to it (clamped to the piece).
    pub fn distance(&self, c: Point) -> (f64, f64) {
        let (lo, hi) = (self.u0.min(self.u1), self.u0.max(self.u1));
        match self.site {
            Site::Point(q) => (c.dist(q), self.param(c, 0.0).clamp(lo, hi)),
            Site::Line { a, n } => {
                let u = (c - a).dot(-n.perp()).clamp(lo, hi);
                (c.dist(self.point_at(u)), u)
            }
            Site::Circle { o, r, .. } => {
                let u = self.param(c, 0.0);
                if (lo..=hi).contains(&u) && c.dist(o) > 0.0 {
                    ((c.dist(o) - r).abs(), u)
                } else {
                    let (pa, pb) = (self.point_at(lo), self.point_at(hi));
                    if c.dist(pa) <= c.dist(pb) {
                        (c.dist(pa), lo)
                    } else {
                        (c.dist(pb), hi)
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_to_pieces_of_each_carrier() {
        // The segment from (0, 0) to (4, 0), normal up.
        let line =
            SitePiece { site: Site::Line { a: Point::new(0.0, 0.0), n: Point::new(0.0, 1.0) }, u0: 0.0, u1: 4.0 };
        assert_eq!(line.distance(Point::new(1.5, 0.75)), (0.75, 1.5));
        assert_eq!(line.distance(Point::new(7.0, 4.0)), (5.0, 4.0));
        // The upper half of the unit circle, seen from inside.
        let arc = SitePiece {
            site: Site::Circle { o: Point::new(0.0, 0.0), r: 1.0, outside: false },
            u0: 0.0,
            u1: std::f64::consts::PI,
        };
        let (d, u) = arc.distance(Point::new(0.0, 0.25));
        assert!((d - 0.75).abs() < 1e-15 && (u - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        // Below the arc its nearer end is nearest.
        let (d, u) = arc.distance(Point::new(0.9, -0.1));
        assert!((d - Point::new(0.1, 0.1).norm()).abs() < 1e-15 && u == 0.0);
        // A point's fan: the distance to the point, the parameter clamped.
        let fan = SitePiece { site: Site::Point(Point::new(0.0, 0.0)), u0: 0.0, u1: 1.0 };
        assert_eq!(fan.distance(Point::new(0.0, 2.0)), (2.0, 1.0));
    }

    #[test]
    fn distance_ranges_bracket_dense_samples() {
        // Oracle: the least and greatest distance over 4001 points of the
        // piece, against the closed form, on random segments and arcs of
        // either direction and up to almost a whole turn.
        let mut rng = crate::util::mix::Mix(5);
        let mut r = || 2.0 * rng.next() - 1.0;
        for case in 0..2000 {
            let site = if case % 2 == 0 {
                let a = r() * std::f64::consts::PI;
                Site::Line { a: Point::new(r(), r()), n: Point::new(a.cos(), a.sin()) }
            } else {
                Site::Circle { o: Point::new(r(), r()), r: 0.1 + r().abs(), outside: case % 4 == 1 }
            };
            let (u0, u1) = match site {
                Site::Line { .. } => (r(), r()),
                _ => {
                    let u0 = 3.0 * r();
                    (u0, u0 + 6.2 * r())
                }
            };
            let piece = SitePiece { site, u0, u1 };
            let c = Point::new(2.0 * r(), 2.0 * r());
            let ends = [piece.point_at(u0), piece.point_at(u1)];
            let (near, far) = piece.distance_range(c, ends);
            let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
            for k in 0..=4000 {
                let d = c.dist(piece.point_at(u0 + (u1 - u0) * k as f64 / 4000.0));
                (lo, hi) = (lo.min(d), hi.max(d));
            }
            // Samples never pass the extremes, and come within the spacing's
            // sagitta-sized gap of them.
            assert!(near <= lo + 1e-12 && hi <= far + 1e-12, "case {case}: {near} {far} vs {lo} {hi}");
            assert!(lo - near < 1e-5 && far - hi < 1e-5, "case {case}: {near} {far} vs {lo} {hi}");
        }
    }
}
