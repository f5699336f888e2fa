//! The radius along an axis edge, split into monotonic pieces (thesis
//! 2.4.2, Figure 2.22), and the disk of a given radius on a piece.
//!
//! Along the bisector of two sites the radius has an inner extremum exactly
//! where the disk's two footpoints are opposite, i.e. where the centre
//! crosses the line L through the sites' foci (for a segment: the
//! perpendicular from the other focus). So the pieces are cut where a
//! site's footpoint parameter reaches the direction of L, without
//! computing the bisector.

use crate::kernel::apollonius::Site;
use crate::kernel::bisector::bisector_point;
use crate::kernel::construct::{circle_circle, line_circle};
use crate::kernel::direction::angle_of;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Point;
use crate::plane::axis::{AxisEdge, AxisNode};
use crate::plane::offset::prim::{Curve, OffsetPrim};

/// A disk on an edge where its pieces begin and end: centre, radius (model
/// units) and the footpoint parameter on each of the edge's two sites.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Break {
    pub point: Point,
    pub radius: f64,
    pub u: [f64; 2],
}

/// An edge with its two primitives and its breaks, from its `from` node to
/// its `to` node (at least two).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct EdgeProfile {
    pub prims: [OffsetPrim; 2],
    pub breaks: Vec<Break>,
    /// The radius is linear along the edge (two lines, or a segment and
    /// its own end vertex): crossings are interpolated.
    pub linear: bool,
    /// The side whose footpoint moves furthest (the better-conditioned
    /// parametrisation, as the axis samples it).
    pub driver: usize,
}

impl EdgeProfile {
    /// The profile of `edge` between `nodes`.
    /// `own_end` says the edge lies between an element and one of its own
    /// end vertices (along the element's normal there).
    /// `driver` is [`AxisEdge::driver`].
    pub fn new(
        edge: &AxisEdge,
        nodes: &[AxisNode],
        prims: [OffsetPrim; 2],
        own_end: bool,
        driver: usize,
    ) -> EdgeProfile {
        let (a, b) = (nodes[edge.from], nodes[edge.to]);
        let lines = matches!(prims[0].site, Site::Line { .. }) && matches!(prims[1].site, Site::Line { .. });
        let linear = own_end || lines;
        let first = Break { point: a.point, radius: a.radius, u: [edge.params[0].0, edge.params[1].0] };
        let last = Break { point: b.point, radius: b.radius, u: [edge.params[0].1, edge.params[1].1] };
        let mut breaks = vec![first];
        if !linear {
            breaks.extend(extrema(&prims, driver, edge));
        }
        breaks.push(last);
        EdgeProfile { prims, breaks, linear, driver }
    }

    /// The disk of radius `rho` between breaks `j` and `j + 1`, whose radii
    /// lie on either side of `rho`: (centre, parameters on both sides).
    pub fn crossing(&self, j: usize, rho: f64) -> (Point, [f64; 2]) {
        let (a, b) = (self.breaks[j], self.breaks[j + 1]);
        if a.radius == rho {
            return (a.point, a.u);
        }
        if b.radius == rho {
            return (b.point, b.u);
        }
        let t = (rho - a.radius) / (b.radius - a.radius);
        if self.linear {
            let u = [lerp(a.u[0], b.u[0], t), lerp(a.u[1], b.u[1], t)];
            return (a.point + (b.point - a.point) * t, u);
        }
        let k = self.driver;
        let (ua, ub) = (a.u[k], b.u[k]);
        let mut best: Option<(f64, Point)> = None;
        for c in intersections(self.prims[0].offset_curve(rho), self.prims[1].offset_curve(rho)) {
            let u = self.prims[k].param_of(c);
            let x = position(&self.prims[k], u, ua, ub);
            let out = if x < 0.0 {
                -x
            } else if x > 1.0 {
                x - 1.0
            } else {
                0.0
            };
            if best.is_none_or(|(o, _)| out < o) {
                best = Some((out, c));
            }
        }
        let c = match best {
            Some((out, c)) if out <= Tolerance::offset_piece_slack() => c,
            _ => self.bisect(j, rho),
        };
        let u = [self.param_within(0, c, a.u[0], b.u[0]), self.param_within(1, c, a.u[1], b.u[1])];
        (c, u)
    }

    /// The parameter of centre `c` on side `k`, clamped to the piece's
    /// range `u0..u1`: the footpoints move monotonically along a piece, so
    /// the true parameter lies in it, while the direction from an arc's
    /// centre to a disk's nearly concentric with it (a disk hugging a
    /// stretch of nearly concentric arcs) is rounding and may point to the
    /// far side of the circle.
    fn param_within(&self, k: usize, c: Point, u0: f64, u1: f64) -> f64 {
        let u = self.prims[k].unwrap(self.prims[k].param_of(c), 0.5 * (u0 + u1));
        u.clamp(u0.min(u1), u0.max(u1))
    }

    /// The disk of radius `rho` on the piece from break `j`, by bisection
    /// of the driver's parameter: the closed form missed (tangent offsets
    /// within rounding).
    fn bisect(&self, j: usize, rho: f64) -> Point {
        let (a, b) = (self.breaks[j], self.breaks[j + 1]);
        let k = self.driver;
        let (mut lo, mut hi) = (a.u[k], b.u[k]);
        let rising = b.radius > a.radius;
        let mut best = if (a.radius - rho).abs() < (b.radius - rho).abs() { a.point } else { b.point };
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            let Some((c, r)) = bisector_point(&self.prims[k].site, &self.prims[1 - k].site, mid) else { break };
            best = c;
            if (r > rho) == rising {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        best
    }
}

fn lerp(a: f64, b: f64, t: f64) -> f64 {
    a + (b - a) * t
}

/// Where `u` lies in the range `ua..ub` as a fraction (angles taken next to
/// the range).
fn position(p: &OffsetPrim, u: f64, ua: f64, ub: f64) -> f64 {
    let d = ub - ua;
    if d == 0.0 {
        return 0.5;
    }
    let u = p.unwrap(u, 0.5 * (ua + ub));
    (u - ua) / d
}

/// The inner extrema of the radius along `edge`, in order from its `from`
/// node.
fn extrema(prims: &[OffsetPrim; 2], k: usize, edge: &AxisEdge) -> Vec<Break> {
    let (p, q) = (&prims[k], &prims[1 - k]);
    let focus = |s: &Site| match *s {
        Site::Point(o) | Site::Circle { o, .. } => Some(o),
        Site::Line { .. } => None,
    };
    let angle = angle_of;
    // Footpoint parameters on the driver where the disk's centre lies on L.
    let candidates: Vec<f64> = match (p.site, q.site) {
        (Site::Line { .. }, Site::Line { .. }) => Vec::new(),
        (Site::Line { a, n }, s) => match focus(&s) {
            Some(o) => vec![(o - a).dot(-n.perp())],
            None => Vec::new(),
        },
        (s, Site::Line { n, .. }) => match focus(&s) {
            Some(_) => vec![angle(n), angle(-n)],
            None => Vec::new(),
        },
        (s, t) => match (focus(&s), focus(&t)) {
            (Some(o1), Some(o2)) if o1 != o2 => vec![angle(o2 - o1), angle(o1 - o2)],
            _ => Vec::new(),
        },
    };
    let (u0, u1) = edge.params[k];
    let mut found: Vec<(f64, Break)> = Vec::new();
    for u in candidates {
        if !p.strictly_between(u, u0, u1, Tolerance::extremum_at_node()) {
            continue;
        }
        let u = p.unwrap(u, 0.5 * (u0 + u1));
        let Some((c, r)) = bisector_point(&p.site, &q.site, u) else { continue };
        let (q0, q1) = edge.params[1 - k];
        let uq = q.unwrap(q.param_of(c), 0.5 * (q0 + q1));
        // The other footpoint must lie on this edge's range too: where both
        // sites are nearly concentric with the edge's disks, the driver's
        // candidate can fall in range while the bisector point it gives
        // touches the other site on the far side of its circle (a point of
        // the same conic, but not of this edge).
        if !q.within(uq, q0, q1, Tolerance::offset_piece_slack()) {
            continue;
        }
        let mut us = [0.0; 2];
        us[k] = u;
        us[1 - k] = uq;
        found.push(((u - u0) / (u1 - u0), Break { point: c, radius: r, u: us }));
    }
    found.sort_by(|x, y| x.0.total_cmp(&y.0));
    found.into_iter().map(|(_, b)| b).collect()
}

/// Intersection points of two offset curves.
fn intersections(a: Curve, b: Curve) -> Vec<Point> {
    match (a, b) {
        (Curve::Line(p, u), Curve::Circle(c, r)) | (Curve::Circle(c, r), Curve::Line(p, u)) => {
            if r <= 0.0 {
                return Vec::new();
            }
            line_circle(p, u, c, r).into_iter().map(|s| p + u * s).collect()
        }
        (Curve::Circle(c1, r1), Curve::Circle(c2, r2)) => {
            if r1 <= 0.0 || r2 <= 0.0 {
                return Vec::new();
            }
            circle_circle(c1, r1, c2, r2)
        }
        (Curve::Line(p, u), Curve::Line(q, v)) => {
            crate::kernel::construct::line_line(p, u, q, v).map(|(x, _, _)| x).into_iter().collect()
        }
    }
}
