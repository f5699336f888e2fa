//! Distances under a ball, and which feature of a ball touches a line or
//! lies towards a point: the contact classes of thesis 3.1.2 (a ball
//! vertex on a shape edge VE, a ball edge on a shape vertex EV, vertex on
//! vertex VV) are a [`Feature`] of the ball against an edge or a vertex of
//! the shape. Distances are `f64` constructions; features are decided
//! with exact predicates.

use super::ball2::Ball2;
use crate::kernel::{FilteredKernel, Kernel, Orientation, Point};

/// A feature of a ball's boundary.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Feature {
    /// Vertex `i` (counter-clockwise order of [`Ball2::vertices`]).
    Vertex(usize),
    /// The edge from vertex `i` to vertex `i + 1` (cyclically).
    Edge(usize),
}

impl Ball2 {
    /// The gauge (Minkowski functional) of `x`: the least r ≥ 0 with
    /// x ∈ r·B; positively homogeneous, convex, 0 only at the origin.
    /// Relative error a few ulps of the largest term.
    pub fn gauge(&self, x: Point) -> f64 {
        (0..self.len()).map(|i| self.facet(i).dot(x)).fold(0.0, f64::max)
    }

    /// δ_B(from, to): the least r with `to` in `from + r·B` (model
    /// units). Not symmetric unless the ball is.
    pub fn distance(&self, from: Point, to: Point) -> f64 {
        self.gauge(to - from)
    }

    /// The least δ_B(c, p) over the points p of the segment `a`–`b`: the
    /// radius of the largest ball `c + r·B` that does not cross the
    /// segment. The distance along the segment is convex and piecewise
    /// linear, with kinks where the segment crosses the rays from `c`
    /// through the ball's vertices: its minimum is at an end or at one of
    /// those crossings (O(k) for a ball of k vertices).
    pub fn distance_to_segment(&self, c: Point, a: Point, b: Point) -> f64 {
        self.nearest_on_segment(c, a, b).0
    }

    /// [`distance_to_segment`](Self::distance_to_segment) with the point of
    /// the segment where it is attained (one of them, where the least
    /// distance is attained along a piece of the segment).
    pub fn nearest_on_segment(&self, c: Point, a: Point, b: Point) -> (f64, Point) {
        let (ac, d) = (a - c, b - a);
        let mut best = (self.gauge(ac), 0.0);
        let mut offer = |t: f64| {
            let g = self.gauge(ac + d * t);
            if g < best.0 {
                best = (g, t);
            }
        };
        for &v in self.vertices() {
            let denominator = v.cross(d);
            if denominator != 0.0 {
                let t = -v.cross(ac) / denominator;
                if t > 0.0 && t < 1.0 {
                    offer(t);
                }
            }
        }
        offer(1.0);
        let foot = if best.1 == 1.0 { b } else { a + d * best.1 };
        (best.0, foot)
    }

    /// The feature of the ball furthest in direction `n` (non-zero): the
    /// feature that touches a line with outward normal `n` when the ball
    /// lies behind it. An edge only when `n` is exactly its outward normal.
    pub fn support(&self, n: Point) -> Feature {
        let along = Point::new(-n.y, n.x);
        let origin = Point::new(0.0, 0.0);
        // (q − p)·n as a cross product with n turned a quarter: exact.
        self.extreme(|p, q| FilteredKernel.cross_sign(p, q, origin, along))
    }

    /// The feature of a ball inside a shape that touches the shape's edge
    /// `a → b` (the shape's interior on its left, as on outer loops
    /// counter-clockwise and holes clockwise): a vertex (contact class VE)
    /// or, when the edge is parallel to a ball edge, that edge (EE, a
    /// degenerate contact outside general position). Exact.
    pub fn touching_edge(&self, a: Point, b: Point) -> Feature {
        // Along the edge's right normal: (q − p) × (b − a).
        self.extreme(|p, q| FilteredKernel.cross_sign(p, q, a, b))
    }

    /// The feature of a ball centred at `c` through which the ray from `c`
    /// towards `p` (≠ `c`) leaves it: where the ball touches a shape vertex
    /// at `p`, a vertex means the contact class VV (a pseudo-branching
    /// point), an edge EV. Exact.
    pub fn towards(&self, c: Point, p: Point) -> Feature {
        let k = FilteredKernel;
        let origin = Point::new(0.0, 0.0);
        let n = self.len();
        let side = |i: usize| k.cross_sign(origin, self.vertices()[i % n], c, p);
        for i in 0..n {
            let v = self.vertices()[i];
            // On the ray through vertex i, not the opposite one: (p − c)·v > 0,
            // as the cross product of p − c with v turned a quarter.
            let ahead = k.cross_sign(c, p, origin, Point::new(-v.y, v.x)) == Orientation::Left;
            if side(i) == Orientation::Collinear && ahead {
                return Feature::Vertex(i);
            }
            // Strictly between the rays through vertices i and i + 1.
            if side(i) == Orientation::Left && side(i + 1) == Orientation::Right {
                return Feature::Edge(i);
            }
        }
        // Unreachable for p ≠ c: the rays through the vertices split the
        // plane into the edges' cones, decided exactly.
        Feature::Vertex(0)
    }

    /// The vertex or edge extreme under `further(p, q)` (`Left` when `q`
    /// is further than `p`, `Collinear` when level).
    fn extreme(&self, further: impl Fn(Point, Point) -> Orientation) -> Feature {
        let v = self.vertices();
        let n = v.len();
        let mut best = 0;
        for j in 1..n {
            if further(v[best], v[j]) == Orientation::Left {
                best = j;
            }
        }
        if further(v[best], v[(best + 1) % n]) == Orientation::Collinear {
            Feature::Edge(best)
        } else if further(v[(best + n - 1) % n], v[best]) == Orientation::Collinear {
            Feature::Edge((best + n - 1) % n)
        } else {
            Feature::Vertex(best)
        }
    }
}
