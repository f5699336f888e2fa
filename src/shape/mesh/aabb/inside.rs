//! Exact point-in-solid: the parity of the surface's crossings along a
//! segment from the point to a far point outside the surface's box.
//!
//! Every crossing is decided by exact predicates
//! ([`segment_crosses_triangle`]), so the count is right whenever no
//! crossing is degenerate (through an edge or a corner, or along a
//! triangle's plane); when one is, the segment is thrown away and another
//! direction tried, from a fixed pseudo-random sequence so that answers
//! repeat from run to run. The first segment leaves through the nearest
//! face of the surface's box (the shortest way out). A point exactly on the
//! surface has no answer: a segment from it is degenerate, and after the
//! first degenerate segment the triangles whose boxes hold the point are
//! searched for it, exactly.

use super::{enter_box, TriangleTree};
use crate::kernel::tri_tri::{segment_crosses_triangle, triangle_contains, Crossing};
use crate::kernel::{BBox3, Point3};
use rayon::prelude::*;
use std::ops::ControlFlow;

/// Directions tried before falling back to the winding number. Each
/// direction is degenerate only on a set of measure zero, so a second
/// try is already rare and this bound is never reached in practice.
const ATTEMPTS: u64 = 64;

/// The `k`-th direction of a fixed sequence, roughly uniform on the
/// sphere (SplitMix64 for the two angles).
fn direction(k: u64) -> Point3 {
    let mix = |mut z: u64| {
        z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    let unit = |z: u64| (z >> 11) as f64 / (1u64 << 53) as f64;
    let (u, v) = (unit(mix(2 * k + 1)), unit(mix(2 * k + 2)));
    let z = 2.0 * u - 1.0;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = std::f64::consts::TAU * v;
    Point3::new(r * phi.cos(), r * phi.sin(), z)
}

/// The first segment tried: out through the nearest face of the box, the
/// shortest way out and so the fewest boxes to open (on a flat part,
/// several times fewer than a random direction's). Tilted a little off the
/// axis, so that it does not run along the axis-parallel faces of CAD
/// parts, where it would be degenerate; it ends just past the face.
fn nearest_face_exit(p: Point3, b: &BBox3) -> Point3 {
    let (mut axis, mut up, mut gap) = (0, false, f64::INFINITY);
    for k in 0..3 {
        for (to_max, g) in [(false, p.coord(k) - b.min.coord(k)), (true, b.max.coord(k) - p.coord(k))] {
            if g < gap {
                (axis, up, gap) = (k, to_max, g);
            }
        }
    }
    let length = gap + 1e-3 * b.diagonal() + 1e-9 * p.coord(axis).abs() + f64::MIN_POSITIVE;
    let mut d = [0.0; 3];
    d[axis] = if up { 1.0 } else { -1.0 };
    d[(axis + 1) % 3] = 0.0137;
    d[(axis + 2) % 3] = -0.0291;
    p + Point3::from_array(d) * length
}

impl TriangleTree {
    /// Whether `p` lies inside the solid bounded by the surface, exactly:
    /// `Some(true)` inside, `Some(false)` outside, `None` when `p` lies on
    /// the surface. The surface must be closed (every edge shared by two
    /// triangles); nested components (cavities) count by parity. A point
    /// that is not finite is outside.
    pub fn inside(&self, p: Point3) -> Option<bool> {
        let bbox = self.bbox();
        if bbox.is_empty() || !p.is_finite() || !bbox.contains_box(&BBox3::of([p])) {
            return Some(false);
        }
        let reach = 2.0 * (bbox.diagonal() + (p - bbox.center()).norm());
        let scale = [bbox.min, bbox.max, p].iter().map(|c| c.x.abs().max(c.y.abs()).max(c.z.abs())).fold(0.0, f64::max);
        let slack = 1e-12 * (scale + reach);
        // Only a degenerate crossing can mean `p` is on the surface (a
        // segment from a point of a triangle meets it at an end), so the
        // exact on-surface search waits for one.
        let mut surface_checked = false;
        for k in 0..ATTEMPTS {
            let q = if k == 0 { nearest_face_exit(p, &bbox) } else { p + direction(k) * reach };
            if bbox.contains_box(&BBox3::of([q])) {
                continue;
            }
            if let Some(odd) = self.crossing_parity(p, q, slack) {
                return Some(odd);
            }
            if !surface_checked {
                if self.on_surface(p) {
                    return None;
                }
                surface_checked = true;
            }
        }
        if !surface_checked && self.on_surface(p) {
            return None;
        }
        Some(self.winding_number(p).abs() > 0.5)
    }

    /// [`TriangleTree::inside`] of many points, in parallel (and in an
    /// order of the points that keeps the tree in cache).
    pub fn inside_many(&self, points: &[Point3]) -> Vec<Option<bool>> {
        self.batch(points, |p| self.inside(p))
    }

    /// True when some triangle holds `p` exactly.
    fn on_surface(&self, p: Point3) -> bool {
        let at = BBox3::of([p]);
        let found = self.visit(
            |b| b.contains_box(&at),
            |k| {
                let corners = self.corners(k);
                if BBox3::of(corners).contains_box(&at) && triangle_contains(corners, p) {
                    ControlFlow::Break(())
                } else {
                    ControlFlow::Continue(())
                }
            },
        );
        found.is_break()
    }

    /// Odd number of crossings of segment `pq`, or `None` when one of
    /// them is degenerate.
    fn crossing_parity(&self, p: Point3, q: Point3, slack: f64) -> Option<bool> {
        let d = q - p;
        let mut odd = false;
        let flow = self.visit(
            |b| enter_box(p, d, 1.0, b, slack).is_some(),
            |k| {
                let corners = self.corners(k);
                if enter_box(p, d, 1.0, &BBox3::of(corners), slack).is_none() {
                    return ControlFlow::Continue(());
                }
                match segment_crosses_triangle(p, q, corners) {
                    Crossing::None => ControlFlow::Continue(()),
                    Crossing::Proper => {
                        odd = !odd;
                        ControlFlow::Continue(())
                    }
                    Crossing::Degenerate => ControlFlow::Break(()),
                }
            },
        );
        flow.is_continue().then_some(odd)
    }

    /// Generalized winding number of the surface about `p` (Jacobson et
    /// al. 2013; van Oosterom and Strackee's solid angle), in `f64`: the
    /// last resort when no exact ray could be found.
    fn winding_number(&self, p: Point3) -> f64 {
        let total: f64 = (0..self.len())
            .into_par_iter()
            .map(|k| {
                let [a, b, c] = self.corners(k).map(|v| v - p);
                let (la, lb, lc) = (a.norm(), b.norm(), c.norm());
                let num = a.dot(b.cross(c));
                let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
                2.0 * num.atan2(den)
            })
            .sum();
        total / (4.0 * std::f64::consts::PI)
    }
}
