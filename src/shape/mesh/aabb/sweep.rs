//! Whether a family of balls between two is free of the surface: the
//! thesis's `sweep` (Algorithm 4, 3.3.2.3.2). The balls
//! `c(t) + r(t)·B` with centre and radius affine in `t ∈ [0, 1]` fill the
//! convex hull of the two end balls (a convex combination of a point of
//! each is a point of the ball in between), so when the maximal* balls at
//! both ends of a segment of a contact domain have the same opposite
//! class, the segment is crossing-free (no projection line crosses it)
//! iff no triangle enters that hull.
//!
//! Per triangle, `g(t) = least gauge from c(t) over T − r(t)` is convex
//! (the gauge is convex, the centre affine, and a least over a convex
//! set keeps convexity), so a golden-section search finds its least value;
//! the triangle enters the hull where that is below 0 by more than the
//! rounding of a gauge. Triangles touching the family without entering
//! (the domain's own face, the opposite contact's triangles) stay at 0.

use super::TriangleTree;
use crate::kernel::{BBox3, Point3};
use crate::shape::ball::{Reach, ReachHint};

/// Golden-section steps: the bracket shrinks by 0.618 per step, to 10^-13
/// of `[0, 1]` after 64.
const STEPS: usize = 64;

impl TriangleTree {
    /// A triangle (its index) entering the hull of the balls `c0 + r0·B`
    /// and `c1 + r1·B` (`r0, r1 ≥ 0`) by more than `tol` in radius, if
    /// any: the first found (the walk stops there, and so does each
    /// triangle's search once it is below `−tol`).
    pub fn enters_hull(
        &self,
        (c0, r0): (Point3, f64),
        (c1, r1): (Point3, f64),
        reach: &Reach<'_>,
        tol: f64,
    ) -> Option<u32> {
        let ball = reach.ball();
        let bb = BBox3::of(ball.vertices().iter().copied());
        let placed = |c: Point3, r: f64| BBox3 { min: c + bb.min * r, max: c + bb.max * r };
        let hull = placed(c0, r0).union(placed(c1, r1));
        // A box beyond one facet plane of both end balls is beyond it for
        // every ball between (the plane's offset is affine in t): outside
        // the hull. Few-facet balls only: a round ball's many planes cost
        // more than the boxes they spare.
        let planes: Vec<(Point3, f64)> = if ball.facets().len() <= 8 {
            ball.facets()
                .iter()
                .map(|f| {
                    let reach_of = |c: Point3, r: f64| f.normal.dot(c) + f.offset * r;
                    (f.normal, reach_of(c0, r0).max(reach_of(c1, r1)))
                })
                .collect()
        } else {
            Vec::new()
        };
        let slack = tol.max(1e-12 * (hull.max - hull.min).norm());
        let beyond = |b: &BBox3| {
            planes.iter().any(|&(n, far)| {
                let least = |v: f64, lo: f64, hi: f64| if v >= 0.0 { v * lo } else { v * hi };
                least(n.x, b.min.x, b.max.x) + least(n.y, b.min.y, b.max.y) + least(n.z, b.min.z, b.max.z) > far + slack
            })
        };
        let mut hint = ReachHint::default();
        let mut found = None;
        let _ = self.visit(
            |b| b.overlaps(&hull) && !beyond(b),
            |k| {
                let t = self.corners(k);
                let mut g = |s: f64| reach.triangle(c0 + (c1 - c0) * s, t, &mut hint).radius - (r0 + (r1 - r0) * s);
                if least_convex(&mut g, -tol) < -tol {
                    found = Some(self.ids[k]);
                    std::ops::ControlFlow::Break(())
                } else {
                    std::ops::ControlFlow::Continue(())
                }
            },
        );
        found
    }
}

/// The least value of a convex function on `[0, 1]`, by golden section
/// (the ends included), or the first value found below `enough`.
fn least_convex(g: &mut impl FnMut(f64) -> f64, enough: f64) -> f64 {
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let mut best = g(0.0).min(g(1.0));
    let (mut x1, mut x2) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
    let (mut g1, mut g2) = (g(x1), g(x2));
    for _ in 0..STEPS {
        best = best.min(g1).min(g2);
        if best < enough {
            return best;
        }
        if g1 <= g2 {
            hi = x2;
            (x2, g2) = (x1, g1);
            x1 = hi - phi * (hi - lo);
            g1 = g(x1);
        } else {
            lo = x1;
            (x1, g1) = (x2, g2);
            x2 = lo + phi * (hi - lo);
            g2 = g(x2);
        }
    }
    best.min(g1).min(g2)
}
