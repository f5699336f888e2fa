//! Contact classes (thesis 3.1.2): which feature of the ball touches which
//! feature of the shape. Each class makes the radius of the ball centred at
//! `c` an affine function `f(c) = (K − n·c)/h` (`h > 0`), valid where the
//! contact really lies on both features: a convex region bounded by at most
//! three lines `G(c) ≥ 0`.
//!
//! * VE: ball vertex `v` on the interior of shape edge `a → b` (outward
//!   normal `n`): `h = n·v`, `K = n·a`; valid while `c + f·v` lies on
//!   `[a, b]` and `f ≥ 0`. Every edge has exactly one (Section 3.2.2.1).
//! * EE: a ball edge parallel to the shape edge lies along it (outside
//!   general position, as in every rectilinear drawing under the square):
//!   the same function, valid while the contact segment overlaps `[a, b]`.
//! * EV: ball edge `v_i → v_(i+1)` (outward normal `m`) through a reflex
//!   vertex `p`: `h = m·v_i`, `K = m·p`; valid while `p − c` lies in the
//!   cone of `v_i` and `v_(i+1)`. Only ball edges whose normal lies strictly
//!   inside the vertex's fan of outward normals: the others would cross the
//!   boundary, and the fan's own ends are the EE classes of its edges.
//!
//! VV contacts are where two of these meet (a ball vertex on a shape
//! vertex); they are the validity boundaries, not classes of their own.

use crate::kernel::exact_line::{ILine, IVec};
use crate::kernel::BigInt;
use crate::kernel::Point;

/// A feature of the shape, by global index: edge `i` runs from vertex `i`
/// to the next vertex of its loop.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ShapeFeature {
    /// A shape edge (global element index).
    Edge(u32),
    /// A shape vertex (global vertex index).
    Vertex(u32),
}

/// A feature of the ball's boundary: vertex `i`, or edge `i` from vertex `i`
/// to vertex `i + 1` (counter-clockwise, [`crate::shape::Ball2::vertices`]).
pub use crate::shape::Feature as BallFeature;

/// The kind of a contact class.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ClassKind {
    /// Ball vertex on a shape edge (regular).
    VE,
    /// Ball edge on a shape vertex (regular; only at reflex vertices).
    EV,
    /// Ball edge along a shape edge (degenerate: parallel edges).
    EE,
}

/// One contact class: its kind and the two features in contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ContactClass {
    /// VE, EV or EE.
    pub kind: ClassKind,
    /// The shape's feature: an edge for VE and EE, a vertex for EV.
    pub shape: ShapeFeature,
    /// The ball's feature: a vertex for VE, an edge for EV and EE.
    pub ball: BallFeature,
}

impl ContactClass {
    /// True when the two classes' ball features are the same or incident
    /// on ∂B (a vertex and an edge ending there, or two edges sharing a
    /// vertex): the classes neighbour on the ball (Observation 10).
    pub fn ball_neighbours(&self, o: &ContactClass, k: usize) -> bool {
        use BallFeature::{Edge, Vertex};
        match (self.ball, o.ball) {
            (Vertex(a), Vertex(b)) => a == b,
            (Vertex(v), Edge(e)) | (Edge(e), Vertex(v)) => v == e || v == (e + 1) % k,
            (Edge(a), Edge(b)) => a == b || (a + 1) % k == b || (b + 1) % k == a,
        }
    }
}

/// A class's function and validity, exact: in shape units for points and
/// ball units for ball coordinates ([`crate::kernel::exact_line::Units`]).
#[derive(Debug, Clone)]
pub(crate) struct ExactClass {
    pub n: IVec,
    pub k: BigInt,
    pub h: BigInt,
    /// Validity: `value ≥ 0` on every line.
    pub valid: Vec<ILine>,
}

/// The same in `f64` model units, each validity line scaled to unit normal
/// (so its value is a signed distance), for filters.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ApproxClass {
    pub n: Point,
    pub k: f64,
    pub h: f64,
    pub valid: [(Point, f64); 3],
    pub n_valid: usize,
}

impl ApproxClass {
    /// The radius this class gives the ball centred at `c`.
    pub(crate) fn radius(&self, c: Point) -> f64 {
        (self.k - self.n.dot(c)) / self.h
    }

    /// How much the radius grows per unit step along `d`.
    pub(crate) fn slope(&self, d: Point) -> f64 {
        -self.n.dot(d) / self.h
    }

    /// The least signed distance of `c` inside the validity region
    /// (negative: outside by that much).
    pub(crate) fn validity(&self, c: Point) -> f64 {
        self.valid[..self.n_valid].iter().map(|(g, g0)| g.dot(c) + g0).fold(f64::INFINITY, f64::min)
    }
}
