//! The subshape as the solver wants it: chain ends within a sliver of a
//! vertex moved onto it, and chains that meet joined into one.

use crate::plane::medial::decompose::subshape::{BoundaryPos, ChainParts, Piece, Subshape};
use crate::shape::{JointKind, Shape2d};

/// The same boundary position, written at the end of one element or the
/// start of the next.
pub(super) fn same_position(shape: &Shape2d, a: BoundaryPos, b: BoundaryPos) -> bool {
    let n = shape.loops()[a.loop_index].len();
    a.loop_index == b.loop_index && (a == b || (a.t == 1.0 && b.t == 0.0 && b.element == (a.element + 1) % n))
}

/// `s` with every chain end that lies within `len` (model units, along the
/// boundary) past a vertex that is not a convex corner moved back to the
/// vertex. A cut a hair past a
/// reflex vertex leaves such a sliver of the next element; its disks are
/// the cut's own within the tolerance, and as separate events they send
/// the walk round in circles.
pub(super) fn drop_sliver_ends(shape: &Shape2d, s: &Subshape, len: f64) -> Subshape {
    let pieces = s
        .pieces
        .iter()
        .map(|p| match *p {
            Piece::Chain { mut from, mut to } if ChainParts::new(shape, from, to).len() > 1 => {
                // Never past a convex corner: the axis must reach it.
                let lp = &shape.loops()[to.loop_index];
                if to.t > 0.0
                    && to.t * lp.element(to.element).length() <= len
                    && shape.joint(to.loop_index, to.element) != JointKind::Convex
                {
                    to.t = 0.0;
                }
                let lp = &shape.loops()[from.loop_index];
                let next = (from.element + 1) % lp.len();
                if from.t < 1.0
                    && (1.0 - from.t) * lp.element(from.element).length() <= len
                    && shape.joint(from.loop_index, next) != JointKind::Convex
                {
                    from.t = 1.0;
                }
                Piece::Chain { from, to }
            }
            other => other,
        })
        .map(|p| match p {
            Piece::Chain { from, to } if !ChainParts::new(shape, from, to).is_empty() => Piece::Chain {
                from: short_of_reflex(shape, from, len, false),
                to: short_of_reflex(shape, to, len, true),
            },
            other => other,
        })
        .collect();
    Subshape { pieces }
}

/// A chain end within `len` (model units) short of a reflex vertex, moved
/// onto the vertex (`end`: the chain's end, else its start). A disk
/// touching the vertex from inside its fan gets a footpoint a few ulps
/// short of it on an arc (the closest point is clamped to the arc's end,
/// and its angle does not map back to exactly 1); the fan between the
/// element's normal and the disk is this subshape's boundary, which a
/// chain ending short of the vertex would leave out.
pub(super) fn short_of_reflex(shape: &Shape2d, p: BoundaryPos, len: f64, end: bool) -> BoundaryPos {
    let lp = &shape.loops()[p.loop_index];
    let e = lp.element(p.element);
    if end && p.t > 0.0 && p.t < 1.0 {
        let v = (p.element + 1) % lp.len();
        if (1.0 - p.t) * e.length() <= len && shape.joint(p.loop_index, v) == JointKind::Reflex {
            return BoundaryPos { t: 1.0, ..p };
        }
    }
    if !end
        && p.t > 0.0
        && p.t < 1.0
        && p.t * e.length() <= len
        && shape.joint(p.loop_index, p.element) == JointKind::Reflex
    {
        return BoundaryPos { t: 0.0, ..p };
    }
    p
}

/// Consecutive chains that meet (a cut exactly at a vertex leaves two) as
/// one chain, so that the joint between them is seen. Two chains that
/// make up a whole loop from a point inside an element back to it (a
/// loop with one augmenting disk, thesis 2.3.1) stay two: one chain from
/// a point to itself is that point; [`Builder::collect_sites`] sees the
/// joint between them.
pub(super) fn merge_touching_chains(shape: &Shape2d, pieces: Vec<Piece>) -> Vec<Piece> {
    let mut out: Vec<Piece> = Vec::with_capacity(pieces.len());
    for p in pieces {
        if let (Some(Piece::Chain { from, to }), Piece::Chain { from: f2, to: t2 }) = (out.last_mut(), p) {
            if same_position(shape, *to, f2) && *from != t2 {
                *to = t2;
                continue;
            }
        }
        out.push(p);
    }
    // The last chain may run on into the first.
    if out.len() > 1 {
        if let (Some(&Piece::Chain { from: f0, to: t0 }), Some(&Piece::Chain { from: fl, to: tl })) =
            (out.first(), out.last())
        {
            if same_position(shape, tl, f0) && fl != t0 {
                out[0] = Piece::Chain { from: fl, to: t0 };
                out.pop();
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::rectangle;
    use super::*;

    fn at(element: usize, t: f64) -> BoundaryPos {
        BoundaryPos { loop_index: 0, element, t }
    }

    #[test]
    fn an_elements_end_is_the_next_ones_start() {
        let shape = rectangle();
        assert!(same_position(&shape, at(1, 1.0), at(2, 0.0)));
        assert!(same_position(&shape, at(3, 1.0), at(0, 0.0)));
        assert!(!same_position(&shape, at(2, 0.0), at(1, 1.0)));
        assert!(!same_position(&shape, at(1, 0.5), at(2, 0.0)));
    }

    #[test]
    fn chains_that_meet_are_one() {
        let shape = rectangle();
        let pieces =
            vec![Piece::Chain { from: at(0, 0.5), to: at(1, 1.0) }, Piece::Chain { from: at(2, 0.0), to: at(3, 0.5) }];
        assert_eq!(merge_touching_chains(&shape, pieces), vec![Piece::Chain { from: at(0, 0.5), to: at(3, 0.5) }]);
    }

    #[test]
    fn two_halves_of_a_whole_loop_stay_two() {
        let shape = rectangle();
        let halves =
            vec![Piece::Chain { from: at(0, 0.5), to: at(2, 0.5) }, Piece::Chain { from: at(2, 0.5), to: at(0, 0.5) }];
        assert_eq!(merge_touching_chains(&shape, halves.clone()), halves);
    }

    #[test]
    fn a_chain_end_a_sliver_past_a_reflex_vertex_moves_onto_it() {
        // The vertex (2, 1) (index 3) of the L is reflex.
        let shape = super::super::fixtures::l_shape();
        let tol = shape.tolerance();
        let near = BoundaryPos { loop_index: 0, element: 2, t: 1.0 - tol / 4.0 };
        assert_eq!(short_of_reflex(&shape, near, 2.0 * tol, true).t, 1.0);
        // Not so at a convex corner (vertex 2 at (4, 1)).
        let near_convex = BoundaryPos { loop_index: 0, element: 1, t: 1.0 - tol / 4.0 };
        assert_eq!(short_of_reflex(&shape, near_convex, 2.0 * tol, true), near_convex);
    }
}
