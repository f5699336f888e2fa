//! Maximal* balls decided exactly: the radius at which the ball
//! `p + s·(B − ṽ)` grown about a point from a ball vertex first touches
//! the surface elsewhere, its centre `p − s·ṽ`, and the contacts that
//! stop it, each with the least ball and surface features holding it.
//!
//! The `f64` construction (`maximal.rs`) gives `s₀`; every triangle near
//! the ball it found (least gauge from its centre within the band of
//! `contact_exact.rs`) is asked exactly how far the ball grows before
//! touching it: the same linear program as the largest ball's, with the
//! ball's origin moved to `ṽ` (its facets through `ṽ` become the walls
//! of the cone the balls fill). Only a triangle that meets the open cone
//! stops the growth: one through `p` that only touches it there, or one
//! that meets only the cone's walls (a ball edge lying along a face,
//! common with axis-aligned solids and cube balls: the balls slide along
//! it) never enters a ball. One through `p` that meets the open cone
//! stops it at radius 0.
//!
//! When the `f64` construction ends at radius 0 or without bound, its
//! slack may have hidden a stop (a plate thinner than 10^-13 of the
//! coordinates): the exact answer then comes from nested balls alone
//! (`maximal_nested`).

use super::contact_exact::BAND;
use super::{ExactContact, TriangleTree};
use crate::kernel::Point3;
use crate::shape::ball::{cone_crosses_plane, enters_cone, grow_exact_many, Centre, Reach};

/// A maximal* ball with its stopping contacts decided exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactMaximalBall {
    /// The radius: the exact value rounded, 0 when the vertex's cone
    /// enters the surface at `p`, infinity when nothing stops the ball
    /// (outside the solid); each decided exactly.
    pub radius: f64,
    /// The centre `p − radius·ṽ`: the exact value rounded (`p` itself for
    /// radius 0 or infinity).
    pub centre: Point3,
    /// The contacts that stop the growth (away from `p`), each once,
    /// ordered by surface then ball feature; empty for radius 0 or
    /// infinity.
    pub opposite: Vec<ExactContact>,
    /// True when the ball lies flat on a triangle it stops at.
    pub flat: bool,
}

impl TriangleTree {
    /// The maximal* ball with ball vertex `vertex` at `p` (see
    /// [`maximal_ball_with`](Self::maximal_ball_with)) with its radius,
    /// centre and stopping contacts decided exactly, for `p` exactly as
    /// given. `None` as for the `f64` construction. A point meant to lie
    /// on the surface but computed in `f64` (an interpolation) is seldom
    /// exactly on it: a point just inside the material is stopped at
    /// once by its own face. Use
    /// [`maximal_ball_exact_on`](Self::maximal_ball_exact_on) then.
    pub fn maximal_ball_exact(&self, p: Point3, vertex: usize, reach: &Reach<'_>) -> Option<ExactMaximalBall> {
        self.maximal_exact(Centre::At(p), vertex, reach)
    }

    /// [`maximal_ball_exact`](Self::maximal_ball_exact) at the point
    /// `t0 + a·(t1 − t0) + b·(t2 − t0)` of the triangle with corners
    /// `[t0, t1, t2]` (usually one of the surface's), taken exactly: on
    /// the triangle's plane, so a face through the point stops the ball
    /// only where the vertex's cone enters it.
    pub fn maximal_ball_exact_on(
        &self,
        corners: [Point3; 3],
        (a, b): (f64, f64),
        vertex: usize,
        reach: &Reach<'_>,
    ) -> Option<ExactMaximalBall> {
        self.maximal_exact(Centre::On(corners, a, b), vertex, reach)
    }

    /// [`maximal_ball_exact`](Self::maximal_ball_exact) at the point
    /// `base + a·(u₁ − u₀) + b·(w₁ − w₀)`, taken exactly: on the plane
    /// through `base` spanned by the two differences. The contact plane
    /// of a reflex edge and a ball edge is spanned by the edge and the
    /// ball edge's direction; a point of it computed in `f64` would lie a
    /// rounding off it, and a ball whose edge should slide along the
    /// reflex edge would be stopped by it.
    pub fn maximal_ball_exact_span(
        &self,
        base: Point3,
        u: [Point3; 2],
        w: [Point3; 2],
        (a, b): (f64, f64),
        vertex: usize,
        reach: &Reach<'_>,
    ) -> Option<ExactMaximalBall> {
        self.maximal_exact(Centre::Span(base, u, w, a, b), vertex, reach)
    }

    fn maximal_exact(&self, centre: Centre, vertex: usize, reach: &Reach<'_>) -> Option<ExactMaximalBall> {
        let p = centre.approx();
        let Some(found) = self.maximal_ball_with(p, vertex, reach) else {
            // The `f64` shrinking did not settle (a ball edge grazing a
            // face can make it step back and forth within its slack): the
            // nested balls alone, from a ball of about its rounding up.
            reach.ball().vertices().get(vertex)?;
            let start = 256.0 * f64::EPSILON * size_of(p, &self.bbox()) / reach.ball().inradius();
            return self.maximal_nested(centre, vertex, reach, start);
        };
        let (r, c) = (found.radius, found.centre);
        if r == 0.0 {
            // A point strictly inside its own triangle lies on no other
            // (a valid surface does not cross itself): radius 0 exactly
            // when the open cone crosses that triangle's plane. A few
            // signs, where the nested balls below would solve the whole
            // linear program on integers (a zero is beyond any filter).
            if let Centre::On(own, a, b) = centre {
                let inside = a > 0.0 && b > 0.0 && a + b < 1.0 - 4.0 * f64::EPSILON;
                if inside && cone_crosses_plane(reach.ball(), vertex, own) {
                    return Some(ExactMaximalBall { radius: 0.0, centre: p, opposite: Vec::new(), flat: false });
                }
                // Otherwise the slack hid a stop or an unbounded ball, or
                // the point is on a side.
            }
            // Within the `f64` construction's slack of 0: from a ball of
            // about that size up.
            let start = 256.0 * f64::EPSILON * size_of(p, &self.bbox()) / reach.ball().inradius();
            return self.maximal_nested(centre, vertex, reach, start);
        }
        if r.is_infinite() {
            return self.maximal_nested(centre, vertex, reach, f64::INFINITY);
        }
        let ball = reach.ball();
        let b = self.bbox();
        let size = size_of(p, &b).max(size_of(c, &b));
        // The band, and should rounding have put every stopping triangle
        // outside it, every triangle the ball of twice the radius meets.
        for limit in [r + BAND * (r + size / ball.inradius()), 2.0 * r] {
            if let Some(found) = self.stop_among(c, limit, centre, vertex, reach, f64::INFINITY) {
                return Some(found);
            }
        }
        // Nothing near the `f64` ball stops it exactly: the triangle that
        // stopped the `f64` growth only grazes the cone's wall (a ball
        // edge along a face), and the true stop lies farther. The balls
        // are nested: from twice that radius up.
        self.maximal_nested(centre, vertex, reach, 2.0 * r)
    }

    /// The exact maximal* ball among the triangles whose least gauge from
    /// `c` is at most `limit`, when its radius is at most `up_to`. Only
    /// triangles that meet the open cone can stop the growth: one that
    /// meets only its walls (or only `p`, the apex) never enters a ball.
    /// One through `p` that meets the open cone stops it at once (radius
    /// 0: the cone straddles the surface; no contacts reported).
    fn stop_among(
        &self,
        c: Point3,
        limit: f64,
        centre: Centre,
        vertex: usize,
        reach: &Reach<'_>,
        up_to: f64,
    ) -> Option<ExactMaximalBall> {
        let ball = reach.ball();
        let near: Vec<usize> = self
            .near_triangles(c, limit, reach)
            .into_iter()
            .map(|(k, _)| k)
            .filter(|&k| {
                let t = self.corners(k);
                // The point's own triangle, holding it inside: the open
                // cone meets it iff it crosses its plane (a few signs; the
                // general test's linear program is degenerate there, its
                // best value exactly 0, and runs on integers).
                match centre {
                    Centre::On(own, a, b) if t == own && a > 0.0 && b > 0.0 && a + b < 1.0 => {
                        cone_crosses_plane(ball, vertex, own)
                    }
                    _ => enters_cone(ball, vertex, centre, t),
                }
            })
            .collect();
        let corners: Vec<[Point3; 3]> = near.iter().map(|&k| self.corners(k)).collect();
        let solved = grow_exact_many(ball, vertex, centre, &corners).filter(|x| x.radius <= up_to)?;
        if solved.radius == 0.0 {
            return Some(ExactMaximalBall { radius: 0.0, centre: centre.approx(), opposite: Vec::new(), flat: false });
        }
        let (opposite, flat) = self.contacts_of(&near, solved.points);
        Some(ExactMaximalBall { radius: solved.radius, centre: solved.centre, opposite, flat })
    }

    /// The exact maximal* ball without an `f64` radius to start from (that
    /// construction found radius 0 within its slack, or no end): the balls
    /// are nested, so every triangle that stops the growth at a radius up
    /// to `s` meets the ball of radius `s`, and the least stopping radius
    /// over the triangles that ball meets (within the band) is the answer
    /// when it is at most `s`. Asked at `start`, then at radii 16 times
    /// larger, up to the radius beyond which the balls gain no point of
    /// the box: nothing by then, and the ball grows without bound.
    fn maximal_nested(&self, centre: Centre, vertex: usize, reach: &Reach<'_>, start: f64) -> Option<ExactMaximalBall> {
        let p = centre.approx();
        let ball = reach.ball();
        let v = *ball.vertices().get(vertex)?;
        let b = self.bbox();
        let unbounded = self.unbounded_radius(p, v, ball)?;
        let mut s = start.min(unbounded);
        loop {
            let c = p - v * s;
            let limit = s + BAND * (s + size_of(p, &b).max(size_of(c, &b)) / ball.inradius());
            if let Some(found) = self.stop_among(c, limit, centre, vertex, reach, s) {
                return Some(found);
            }
            if s >= unbounded {
                return Some(ExactMaximalBall { radius: f64::INFINITY, centre: p, opposite: Vec::new(), flat: false });
            }
            s = (s * 16.0).min(unbounded);
        }
    }
}

/// The largest coordinate magnitude of `q` and the box.
fn size_of(q: Point3, b: &crate::kernel::BBox3) -> f64 {
    [q, b.min, b.max].iter().flat_map(|x| x.to_array()).fold(0.0f64, |m, v| m.max(v.abs()))
}
