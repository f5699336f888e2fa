//! The contact domain of an EE class and its arrangement (thesis
//! 3.3.2.2.3, Propositions 1–3).
//!
//! For the class `(ẽ = [ṽ, ṽ*], e)` the contact plane holds the reflex
//! edge `e` and is parallel to `ẽ`; in its coordinates (see
//! [`DomainPlane::of_edge`]) the ball `p(a, b) + s·(B − ṽ)` anchored at
//! `p(a, b) = e₀ + a·(e₁ − e₀) + b·(ṽ* − ṽ)` reaches `e`'s line with its
//! edge at `s = −b`, at `x(a) = e₀ + a·(e₁ − e₀)`. Beyond that it slides
//! along `e` (the plane separates the ball from the exterior's wedge at
//! `e`, so `e`'s triangles only touch the wall of the balls' cone and
//! never stop the growth). So `p(a, b)` is in the domain iff `0 < a < 1`
//! (the slot, Proposition 2), `b < 0` (the half-plane, Proposition 1) and
//! the maximal* radius `ρ` there is at least `−b`.
//!
//! That last bound is a graph over the edge: with `σ(a)` the radius of the
//! maximal* ball anchored at `ṽ*` at `x(a)` (the VE balls of Proposition
//! 3), the domain is exactly `−σ(a) ≤ b < 0`. The ball at `p(a, −σ(a))`
//! with radius `σ(a)` is that VE ball; for `b' > b`, the ball at
//! `p(a, b')` with radius `−b'` lies inside the one at `p(a, b)` with
//! radius `−b` (`δ·ṽ* + (s − δ)·B ⊂ s·B` for a convex `B`), so the domain
//! holds every point between the edge and the graph; and a point beyond
//! the graph would give a ball at `x(a)` anchored at `ṽ*` larger than
//! `σ(a)`. So the one-dimensional arrangement along `e` (anchored at
//! `ṽ*`) gives the far side: a polygonal line, affine on each of its
//! pieces, with steps where it jumps. Each piece's trapezoid (between
//! the edge and the line) is a convex start region for
//! [`domain_arrangement`]; the vertical lines between them are the
//! thesis's convex dummy splits.

use super::along::{opposite_along_in, AlongError};
use super::arrangement::{domain_arrangement, inset, Cell};
use super::domain::DomainPlane;
use crate::shape::ball::Reach;
use crate::shape::Mesh3d;

/// How far inside the edge the walk along it starts and ends (a fraction
/// of its length): its ends are vertices, where other classes meet.
const EDGE_INSET: f64 = 1e-6;

/// The contact arrangement of one EE class.
#[derive(Debug, Clone, PartialEq)]
pub struct EdgeArrangement {
    /// The surface edge (its vertices, the lesser first).
    pub edge: [u32; 2],
    /// The ball edge.
    pub ball_edge: usize,
    /// The representative vertex `ṽ` (the ball edge's end asked for): the
    /// domain's balls are anchored at it.
    pub anchor: usize,
    /// The contact plane and its coordinates.
    pub plane: DomainPlane,
    /// The cells, in the plane's coordinates; together they cover the
    /// domain (less a rim of 10^-6 of each trapezoid's size).
    pub cells: Vec<Cell>,
}

/// The contact arrangement of the EE class (ball edge `ball_edge`,
/// surface edge `edge`), which must be a class (`contact_classes`), with
/// the ball edge's vertex `end` (0 or 1) as the representative vertex.
///
/// Which end matters (thesis 3.3.1.2, vertex-dependent projections): a
/// sheet whose other class holds a ball feature through the
/// representative vertex (a ball vertex of the edge on a face, the jump
/// sheets) collapses to a line in this domain, and is two-dimensional in
/// the domain of the other end.
///
/// # Errors
///
/// [`AlongError::NoClass`] for indices out of range; otherwise as
/// [`opposite_along_in`] and [`domain_arrangement`].
pub fn edge_arrangement(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    edge: [u32; 2],
    ball_edge: usize,
    end: usize,
) -> Result<EdgeArrangement, AlongError> {
    let ball = reach.ball();
    let ends = ball.edges().get(ball_edge).ok_or(AlongError::NoClass)?.vertices;
    if end > 1 {
        return Err(AlongError::NoClass);
    }
    let (anchor, far) = (ends[end], ends[1 - end]);
    let pos = |i: u32| mesh.positions().get(i as usize).copied().ok_or(AlongError::NoClass);
    let w = ball.vertices();
    let plane = DomainPlane::of_edge(pos(edge[0])?, pos(edge[1])?, w[anchor], w[far]);
    // The far side: the VE balls along the edge, anchored at ṽ*.
    let rim = opposite_along_in(mesh, reach, &plane, far, (EDGE_INSET, 0.0), (1.0 - EDGE_INSET, 0.0))?;
    let a_of = |t: f64| EDGE_INSET + t * (1.0 - 2.0 * EDGE_INSET);
    let mut cells = Vec::new();
    for piece in &rim.pieces {
        let (a0, a1) = (a_of(piece.from), a_of(piece.to));
        let depth = |a: f64| piece.radius.at(plane.point((a, 0.0)));
        let trapezoid = [(a0, 0.0), (a0, -depth(a0)), (a1, -depth(a1)), (a1, 0.0)];
        cells.extend(domain_arrangement(mesh, reach, &plane, anchor, &inset(&trapezoid))?);
    }
    Ok(EdgeArrangement { edge, ball_edge, anchor, plane, cells })
}
