//! The contact domain of an FV class and its arrangement (thesis
//! 3.3.2.2.4): a ball facet `f̃` resting on a vertex `v` where the
//! exterior lies beyond the facet's plane.
//!
//! The contact plane holds `v` and is parallel to `f̃`. With the
//! representative corner `ṽ` and two consecutive corners `x̃ₖ, x̃ₖ₊₁` of
//! `f̃` away from it, the sector coordinates of [`DomainPlane::of_corner`]
//! put the copy of `ṽ` at `p(a, b) = v + a·(ṽ − x̃ₖ) + b·(ṽ − x̃ₖ₊₁)`; the
//! ball `p + s·(B − ṽ)` then has `v` on its facet, in the triangle
//! `ṽ, x̃ₖ, x̃ₖ₊₁` scaled by `s`, from `s = a + b` on (on its far edge
//! `x̃ₖ x̃ₖ₊₁` at that radius), and keeps growing past it: the plane
//! separates the ball from the exterior near `v`, which only touches the
//! wall of the balls' cone. So `p(a, b)` (with `a, b > 0`) is in the
//! domain iff the maximal* radius there is at least `a + b`.
//!
//! For fixed `b`, the ball at `p(a, b)` with radius `a + b` has its copy
//! of `x̃ₖ` at `q(b) = v + b·(x̃ₖ − x̃ₖ₊₁)` whatever `a` is: these balls are
//! the balls anchored at `x̃ₖ` at `q(b)`, nested by radius. So the domain's
//! sector is exactly `0 < a ≤ σ(b) − b`, `σ(b)` the maximal* radius
//! anchored at `x̃ₖ` at `q(b)`, for `0 < b < R`, `R` the maximal* radius
//! anchored at `x̃ₖ₊₁` at `v` itself (the ball with `x̃ₖ₊₁` on `v`: a VV
//! ball; its homothetic copies about `v` show `σ(b) ≥ b` up to `R`, and a
//! larger `b` would give a larger one). Like an EE class's domain, one
//! walk along `q` (anchored at `x̃ₖ`) gives the far side, the EV balls of
//! `(x̃ₖ x̃ₖ₊₁, v)` (item 3 of 3.3.2.2.4), piece by piece; each piece's
//! trapezoid between `a = 0` and the far side is a convex start region
//! for [`domain_arrangement`]. A facet of more than three corners has a
//! sector per edge away from `ṽ`: the lines between them are dummy
//! splits, as are the trapezoids' sides.

use super::along::{opposite_along_in, AlongError};
use super::arrangement::{domain_arrangement, inset, Cell};
use super::domain::DomainPlane;
use crate::shape::ball::Reach;
use crate::shape::Mesh3d;

/// How far inside `(0, R)` the walk along `q` starts and ends (a
/// fraction of `R`): its ends are VV balls, where other classes meet.
const END_INSET: f64 = 1e-6;

/// One sector of an FV class's domain: its coordinates and its cells.
#[derive(Debug, Clone, PartialEq)]
pub struct CornerSector {
    /// The contact plane in the sector's coordinates.
    pub plane: DomainPlane,
    /// The cells, in those coordinates.
    pub cells: Vec<Cell>,
}

/// The contact arrangement of one FV class for one representative
/// corner.
#[derive(Debug, Clone, PartialEq)]
pub struct CornerArrangement {
    /// The surface vertex.
    pub vertex: u32,
    /// The ball facet.
    pub facet: usize,
    /// The representative corner `ṽ` (a ball vertex of the facet): the
    /// domain's balls are anchored at it.
    pub anchor: usize,
    /// The sectors (one per edge of the facet away from `ṽ`); together
    /// their cells cover the domain (less a rim of 10^-6 of each
    /// trapezoid's size).
    pub sectors: Vec<CornerSector>,
}

/// The contact arrangement of the FV class (ball facet `facet`, surface
/// vertex `vertex`), which must be a class (`contact_classes`), with the
/// facet's corner number `corner` as the representative vertex.
///
/// Which corner matters as for an EE class's ends (thesis 3.3.1.2): a
/// sheet whose other class holds a ball feature through the
/// representative vertex collapses to a line in this domain.
///
/// # Errors
///
/// [`AlongError::NoClass`] for indices out of range;
/// [`AlongError::NoBall`] when the ball on `v` has no positive finite
/// radius (not a class); otherwise as [`opposite_along_in`] and
/// [`domain_arrangement`].
pub fn corner_arrangement(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    vertex: u32,
    facet: usize,
    corner: usize,
) -> Result<CornerArrangement, AlongError> {
    let ball = reach.ball();
    let ring = &ball.facets().get(facet).ok_or(AlongError::NoClass)?.vertices;
    let n = ring.len();
    if corner >= n {
        return Err(AlongError::NoClass);
    }
    let v = *mesh.positions().get(vertex as usize).ok_or(AlongError::NoClass)?;
    let w = ball.vertices();
    let anchor = ring[corner];
    let mut sectors = Vec::with_capacity(n - 2);
    for step in 1..n - 1 {
        let (xk, xk1) = (ring[(corner + step) % n], ring[(corner + step + 1) % n]);
        let plane = DomainPlane::of_corner(v, w[anchor], w[xk], w[xk1]);
        let reach_end = mesh.tree().maximal_ball_exact(v, xk1, reach).map_or(0.0, |b| b.radius);
        if !(reach_end > 0.0 && reach_end.is_finite()) {
            return Err(AlongError::NoBall { at: 1.0 });
        }
        let (b0, b1) = (END_INSET * reach_end, (1.0 - END_INSET) * reach_end);
        let rim = opposite_along_in(mesh, reach, &plane, xk, (-b0, b0), (-b1, b1))?;
        let b_of = |t: f64| b0 + t * (b1 - b0);
        let mut cells = Vec::new();
        for piece in &rim.pieces {
            let (lo, hi) = (b_of(piece.from), b_of(piece.to));
            let width = |b: f64| (piece.radius.at(plane.point((-b, b))) - b).max(0.0);
            let mut region = vec![(0.0, lo), (width(lo), lo), (width(hi), hi), (0.0, hi)];
            region.dedup_by(|q, p| (q.0 - p.0).abs() + (q.1 - p.1).abs() <= 1e-15 * reach_end);
            if region.len() >= 3 {
                cells.extend(domain_arrangement(mesh, reach, &plane, anchor, &inset(&region))?);
            }
        }
        sectors.push(CornerSector { plane, cells });
    }
    Ok(CornerArrangement { vertex, facet, anchor, sectors })
}
