//! A boundary primitive seen by the offset: where its offset at distance ρ
//! lies for a footpoint parameter, which parameter a disk centre has, and
//! how far a piece of it turns (thesis 2.4.3: the offset of an arc is a
//! concentric arc, of a segment a parallel segment, of a reflex vertex an
//! arc of radius ρ around it).

use crate::kernel::apollonius::Site;
use crate::kernel::bisector::footpoint;
use crate::kernel::bisector::footpoint_param;
use crate::kernel::construct::unwrap_near;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Point;
use crate::plane::axis::Primitive;
use crate::shape::{turning_angle, Element, Shape2d};
use std::f64::consts::TAU;

/// One primitive with what the offset needs of it. Parameters are those of
/// [`footpoint`]: distance along a segment from its start, or the angle
/// (radians) of the direction from an arc's centre or a reflex vertex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct OffsetPrim {
    /// How a disk touches it.
    pub site: Site,
    /// Loop index.
    pub loop_index: u32,
    /// Position in the loop's boundary order: 2v for vertex v, 2e + 1 for
    /// element e.
    pub pos: u32,
    /// +1 when the footpoint angle grows along the boundary (a
    /// counter-clockwise arc), −1 when it shrinks (a clockwise arc, a
    /// reflex vertex, whose fan turns clockwise with the interior on the
    /// left); 0 for a segment.
    pub sigma: f64,
    /// The largest turn one piece of it can make, radians: the arc's sweep
    /// or the fan's width (below 2π, so a piece's turn is unambiguous).
    pub bound: f64,
}

impl OffsetPrim {
    /// The primitive `p` of `shape`.
    pub fn new(shape: &Shape2d, p: Primitive) -> OffsetPrim {
        let site = p.site(shape);
        let (loop_index, i) = (p.loop_index(), p.index());
        match p {
            Primitive::Element { .. } => {
                let (sigma, bound) = match shape.loops()[loop_index].element(i) {
                    Element::Segment(_) => (0.0, 0.0),
                    Element::Arc(a) => (if a.is_ccw() { 1.0 } else { -1.0 }, a.sweep().abs()),
                };
                OffsetPrim { site, loop_index: loop_index as u32, pos: 2 * i as u32 + 1, sigma, bound }
            }
            Primitive::Vertex { .. } => {
                // The fan turns clockwise from the incoming normal to the
                // outgoing one by the angle the boundary turns right.
                let width = turning_angle(&shape.loops()[loop_index], i).abs();
                OffsetPrim { site, loop_index: loop_index as u32, pos: 2 * i as u32, sigma: -1.0, bound: width }
            }
        }
    }

    /// Parameter `u` next to `near`: an angle shifted by whole turns to
    /// within π of it, a length as it is.
    pub fn unwrap(&self, u: f64, near: f64) -> f64 {
        if self.sigma == 0.0 {
            u
        } else {
            unwrap_near(u, near)
        }
    }

    /// The point of the offset at distance `rho` for footpoint parameter `u`.
    pub fn point_at(&self, u: f64, rho: f64) -> Point {
        let (f, n) = footpoint(&self.site, u);
        f + n * rho
    }

    /// The footpoint parameter of a disk centred at `c` tangent to the
    /// primitive (the angle is in (−π, π]).
    pub fn param_of(&self, c: Point) -> f64 {
        footpoint_param(&self.site, c, 0.0)
    }

    /// How far the offset runs from parameter `u0` to `u1` along the
    /// boundary: a length for a segment, a turn in radians (≥ 0) otherwise.
    pub fn advance(&self, u0: f64, u1: f64) -> f64 {
        if self.sigma == 0.0 {
            return u1 - u0;
        }
        let x = (self.sigma * (u1 - u0)).rem_euclid(TAU);
        // Between the bound and a whole turn the gap is split evenly:
        // beyond the middle, x is a rounding below 0, not a long way round.
        if x > 0.5 * (self.bound + TAU) {
            0.0
        } else {
            x
        }
    }

    /// The bulge of the offset piece that advances by `advance` (see
    /// [`OffsetPrim::advance`]).
    pub fn bulge(&self, advance: f64) -> f64 {
        if self.sigma == 0.0 {
            0.0
        } else {
            self.sigma * (advance.clamp(0.0, TAU - Tolerance::whole_turn_margin()) / 4.0).tan()
        }
    }

    /// The radius of the offset curve at distance `rho` (infinite for a
    /// segment): how long a piece of the given advance is.
    pub fn length(&self, advance: f64, rho: f64) -> f64 {
        match self.site {
            Site::Line { .. } => advance.max(0.0),
            Site::Point(_) => advance * rho,
            Site::Circle { r, outside: true, .. } => advance * (r + rho),
            Site::Circle { r, outside: false, .. } => advance * (r - rho).abs(),
        }
    }

    /// The offset at distance `rho` as a curve: a line (point, direction) or
    /// a circle (centre, radius).
    pub fn offset_curve(&self, rho: f64) -> Curve {
        match self.site {
            Site::Line { a, n } => Curve::Line(a + n * rho, -n.perp()),
            Site::Point(o) => Curve::Circle(o, rho),
            Site::Circle { o, r, outside: true } => Curve::Circle(o, r + rho),
            Site::Circle { o, r, outside: false } => Curve::Circle(o, r - rho),
        }
    }

    /// Whether `u` lies strictly inside the parameter range from `u0` to
    /// `u1` (angles taken the short way the range goes), away from the ends
    /// by more than `margin` of the range.
    pub fn strictly_between(&self, u: f64, u0: f64, u1: f64, margin: f64) -> bool {
        let d = u1 - u0;
        if d == 0.0 {
            return false;
        }
        let x = if self.sigma == 0.0 {
            (u - u0) / d
        } else if d > 0.0 {
            (u - u0).rem_euclid(TAU) / d
        } else {
            (u0 - u).rem_euclid(TAU) / -d
        };
        x > margin && x < 1.0 - margin
    }

    /// Whether `u` lies in the parameter range from `u0` to `u1` (angles
    /// taken next to the range) or outside it by at most `slack` of the
    /// the range (of 1 where the range is shorter than 1).
    pub fn within(&self, u: f64, u0: f64, u1: f64, slack: f64) -> bool {
        let u = self.unwrap(u, 0.5 * (u0 + u1));
        let (lo, hi) = (u0.min(u1), u0.max(u1));
        let margin = slack * (hi - lo).max(1.0);
        u >= lo - margin && u <= hi + margin
    }
}

/// An offset curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Curve {
    /// Point and direction.
    Line(Point, Point),
    /// Centre and radius (may be ≤ 0: no such offset).
    Circle(Point, f64),
}
