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

use super::contact_exact::BAND;
use super::{ExactContact, TriangleTree};
use crate::kernel::Point3;
use crate::shape::ball::{enters_cone, grow_exact_many, Centre, Reach};

/// A maximal* ball with its stopping contacts decided exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactMaximalBall {
    /// The radius: the exact value rounded, 0 when the vertex's cone
    /// enters the surface at `p`; infinity (nothing stops the ball:
    /// outside the solid) as the `f64` construction decides it, and so a
    /// radius 0 that construction already found (by its rounding slack).
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

    fn maximal_exact(&self, centre: Centre, vertex: usize, reach: &Reach<'_>) -> Option<ExactMaximalBall> {
        let p = centre.approx();
        let found = self.maximal_ball_with(p, vertex, reach)?;
        let (r, c) = (found.radius, found.centre);
        if !(r > 0.0 && r.is_finite()) {
            return Some(ExactMaximalBall { radius: r, centre: c, opposite: Vec::new(), flat: false });
        }
        let ball = reach.ball();
        let b = self.bbox();
        let size = [p, c, b.min, b.max].iter().flat_map(|q| q.to_array()).fold(0.0f64, |m, v| m.max(v.abs()));
        // The band, and should rounding have put every stopping triangle
        // outside it, every triangle the ball of twice the radius meets.
        for limit in [r + BAND * (r + size / ball.inradius()), 2.0 * r] {
            // Only triangles that meet the open cone can stop the growth:
            // one that meets only its walls (or only `p`, the apex) never
            // enters a ball. One through `p` that meets the open cone
            // stops it at once (radius 0: the cone straddles the surface).
            let near: Vec<usize> = self
                .near_triangles(c, limit, reach)
                .into_iter()
                .map(|(k, _)| k)
                .filter(|&k| enters_cone(ball, vertex, centre, self.corners(k)))
                .collect();
            let corners: Vec<[Point3; 3]> = near.iter().map(|&k| self.corners(k)).collect();
            if let Some(solved) = grow_exact_many(ball, vertex, centre, &corners) {
                let (opposite, flat) = self.contacts_of(&near, solved.points);
                return Some(ExactMaximalBall { radius: solved.radius, centre: solved.centre, opposite, flat });
            }
        }
        None
    }
}
