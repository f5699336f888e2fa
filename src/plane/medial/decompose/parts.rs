//! What a subshape holds, counted (original element parts, reflex single
//! points), and where a footpoint lies on the boundary: the measures the
//! divide step and the cuts at reflex points both decide by.

use crate::kernel::tolerance::Tolerance;
use crate::plane::medial::decompose::subshape::{BoundaryPos, ChainParts, Piece, Subshape};
use crate::plane::medial::decompose::tour::{Ranged, Span, Tour};
use crate::plane::medial::disk::maximal::Footpoint;
use crate::shape::{JointKind, Shape2d};

/// Number of original element parts in a subshape (a single-point chain
/// counts as none).
pub fn original_parts(shape: &Shape2d, s: &Subshape) -> usize {
    s.chains().map(|(from, to)| ChainParts::new(shape, from, to).len()).sum()
}

/// [`original_parts`] of `s`, its ranges of the augmented cycle `tour` included.
pub(crate) fn parts_in(shape: &Shape2d, s: &Ranged, tour: &Tour) -> usize {
    s.spans
        .iter()
        .map(|p| match *p {
            Span::Piece(Piece::Chain { from, to }) => ChainParts::new(shape, from, to).len(),
            Span::Piece(Piece::Aux { .. }) => 0,
            Span::Range { from, to } => tour.parts(from, to),
        })
        .sum()
}

/// Reflex single points of `s` (see [`leaf_size`]), ranges of `tour` included.
pub(crate) fn points_in(shape: &Shape2d, s: &Ranged, tour: &Tour) -> usize {
    s.pieces().filter(|&p| reflex_point(shape, p).is_some()).count()
        + s.spans
            .iter()
            .map(|p| if let Span::Range { from, to } = *p { tour.points(from, to) } else { 0 })
            .sum::<usize>()
}

/// The boundary position of a footpoint: exactly at the vertex for a
/// touch within the tolerance of a reflex vertex (on an arc the clamped
/// closest point maps back to a fraction a few ulps short of it). Such a
/// touch is the vertex's, and only at the vertex itself can
/// [`Subshape::split`] tell which side of an augmenting disk it is on.
pub(crate) fn position(shape: &Shape2d, f: &Footpoint) -> BoundaryPos {
    let (l, k) = (f.element.loop_index, f.element.element);
    let lp = &shape.loops()[l];
    let e = lp.element(k);
    let tol = shape.tolerance();
    let t = if f.point.dist(e.start()) <= tol && shape.joint(l, k) == JointKind::Reflex {
        0.0
    } else if f.point.dist(e.end()) <= tol && shape.joint(l, (k + 1) % lp.len()) == JointKind::Reflex {
        1.0
    } else {
        e.param_of(f.point)
    };
    BoundaryPos { loop_index: l, element: k, t }
}

/// True when a footpoint of a disk of radius `r` lies within
/// [`Tolerance::sliver_end`] of a convex corner. Only a disk of radius 0
/// touches a convex corner; a larger one comes that close at a nearly flat
/// corner, where its contacts on the two elements merge into one footpoint
/// at the vertex (or leave a sliver of a few tolerances past it), and a
/// cut there would leave the corner's branch of the axis in neither
/// subshape, or a branch point and the cut's centre within rounding of
/// each other.
pub(crate) fn foot_at_convex_corner(shape: &Shape2d, feet: &[BoundaryPos], r: f64) -> bool {
    let tol = shape.tolerance();
    let near = Tolerance::new(tol).sliver_end();
    r > tol
        && feet.iter().any(|f| {
            let lp = &shape.loops()[f.loop_index];
            let p = f.point(shape);
            [f.element, (f.element + 1) % lp.len()]
                .into_iter()
                .any(|v| shape.joint(f.loop_index, v) == JointKind::Convex && lp.vertices()[v].p.dist(p) <= near)
        })
}

/// The position of `p` when it is a single-point chain at a reflex vertex.
pub(crate) fn reflex_point(shape: &Shape2d, p: Piece) -> Option<BoundaryPos> {
    let Piece::Chain { from, to } = p else { return None };
    let reflex = from.vertex(shape).is_some_and(|v| shape.joint(from.loop_index, v) == JointKind::Reflex);
    (reflex && ChainParts::new(shape, from, to).is_empty()).then_some(from)
}
