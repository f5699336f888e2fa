//! The largest ball `c + r·B` inside a solid at a given centre (thesis
//! 3.3.2.2: the polytope distance from `c` to the surface): the least
//! gauge `γ_B(q − c)` over the surface's points `q`, with the triangle and
//! point where the grown ball first touches.
//!
//! On one triangle T the gauge is convex and piecewise linear, so its
//! minimum is a linear program whose optimum sits at a vertex of the
//! feasible set: three active constraints among T's three sides and B's
//! facet planes. That leaves three kinds of candidates (the contact types
//! of 3.1.2): a corner of T (FV and its degenerate EV, VV), a point of a
//! side of T on the plane through `c` spanned by an edge of B (EE), and
//! the point where the ray from `c` through a vertex of B meets T (VF).
//! Every candidate is a point of T, so the gauge there bounds the minimum
//! from above whatever rounding did to its position, and the least one is
//! the minimum up to that rounding (f64: the exact decision of the contact
//! class is the next piece).
//!
//! Pruning: `γ_B(x) ≥ |x| / R` with `R` the ball's circumradius, so a box
//! farther than `best · R` from `c` cannot hold a closer point; the search
//! starts from the gauge at the Euclidean closest point.

use super::TriangleTree;
use crate::kernel::Point3;
use crate::shape::ball::Ball3;
use std::cell::Cell;

/// What kind of contact realises the distance (thesis 3.1.2), as found in
/// `f64`: which candidate gave the least gauge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactKind3 {
    /// A vertex of the ball on the triangle's interior (VF).
    VertexFace,
    /// An edge of the ball on an edge of the triangle (EE).
    EdgeEdge,
    /// A corner of the triangle on the ball's boundary (FV, or EV/VV when
    /// it meets an edge or a vertex of the ball).
    FaceVertex,
}

/// The largest ball at a centre and where it touches.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallContact {
    /// The radius: `c + radius·B` touches the surface and holds no point
    /// of it inside.
    pub radius: f64,
    /// The triangle touched (index in the tree's input).
    pub triangle: u32,
    /// The point of contact.
    pub point: Point3,
    /// The contact's kind.
    pub kind: ContactKind3,
}

/// The least gauge over triangle `t` seen from `c`, with its point and kind.
fn on_triangle(c: Point3, [a, b, d]: [Point3; 3], ball: &Ball3) -> (f64, Point3, ContactKind3) {
    let mut best = (f64::INFINITY, a, ContactKind3::FaceVertex);
    let mut offer = |q: Point3, kind: ContactKind3| {
        let g = ball.gauge(q - c);
        if g < best.0 {
            best = (g, q, kind);
        }
    };
    for p in [a, b, d] {
        offer(p, ContactKind3::FaceVertex);
    }
    let v = ball.vertices();
    for e in ball.edges() {
        let m = v[e.vertices[0]].cross(v[e.vertices[1]]);
        for (p, q) in [(a, b), (b, d), (d, a)] {
            let den = m.dot(q - p);
            if den != 0.0 {
                let u = m.dot(c - p) / den;
                if (0.0..=1.0).contains(&u) {
                    offer(p + (q - p) * u, ContactKind3::EdgeEdge);
                }
            }
        }
    }
    let n = (b - a).cross(d - a);
    for &w in v {
        let den = n.dot(w);
        if den == 0.0 {
            continue;
        }
        let t = n.dot(a - c) / den;
        if t > 0.0 {
            let q = c + w * t;
            if inside_triangle(q, [a, b, d], n) {
                offer(q, ContactKind3::VertexFace);
            }
        }
    }
    best
}

/// Whether `q` (near the plane of the triangle with normal `n`) lies in it:
/// the three sub-triangles turn the same way as `n`.
fn inside_triangle(q: Point3, [a, b, d]: [Point3; 3], n: Point3) -> bool {
    (b - a).cross(q - a).dot(n) >= 0.0 && (d - b).cross(q - b).dot(n) >= 0.0 && (a - d).cross(q - d).dot(n) >= 0.0
}

impl TriangleTree {
    /// The largest ball `c + r·B` whose interior holds no point of the
    /// surface, and where it touches (`None` for an empty tree). For `c`
    /// inside a solid this is the largest ball inside it at `c`.
    pub fn ball_radius(&self, c: Point3, ball: &Ball3) -> Option<BallContact> {
        let start = self.closest_point(c)?;
        let k0 = self.ids.iter().position(|&id| id == start.triangle)?;
        let (r0, p0, kind0) = on_triangle(c, self.corners(k0), ball);
        let best = Cell::new(BallContact { radius: r0, triangle: start.triangle, point: p0, kind: kind0 });
        let reach = ball.circumradius();
        let _ = self.visit(
            |b| super::box_distance2(b, c) <= (best.get().radius * reach).powi(2),
            |k| {
                let (r, p, kind) = on_triangle(c, self.corners(k), ball);
                if r < best.get().radius {
                    best.set(BallContact { radius: r, triangle: self.ids[k], point: p, kind });
                }
                std::ops::ControlFlow::Continue(())
            },
        );
        Some(best.get())
    }

    /// [`TriangleTree::ball_radius`] for many centres, in parallel.
    pub fn ball_radii(&self, centres: &[Point3], ball: &Ball3) -> Vec<Option<BallContact>> {
        use rayon::prelude::*;
        centres.par_iter().map(|&c| self.ball_radius(c, ball)).collect()
    }
}
