//! The boundary's order of the axis edge sides: the side cycle round the axis
//! that the offset walks (thesis 2.4.2, Figure 2.21 (b), (c)).
//!
//! Half-edge `2e + k` is side `k` of edge `e`, walked the way its
//! footpoints move along the boundary: side 1 (on the right going from
//! `from` to `to`) from `from` to `to`, side 0 the other way. At a node, the
//! half-edge arriving on a primitive continues with the half-edge leaving
//! the node on the same primitive (one footpoint per primitive), or, where
//! the footpoint passes a joint, a convex corner or a leaf arc, on the
//! nearest primitive after it in the loop. The order comes from the
//! combinatorics alone: no angles at the nodes are compared.

use crate::kernel::tolerance::Tolerance;
use crate::plane::axis::{MedialAxis2d, Primitive};
use crate::shape::{Element, Shape2d};

/// The successor of every half-edge and the leaf arcs passed on the way.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SideCycle {
    /// Successor of each half-edge.
    pub next: Vec<u32>,
    /// For half-edge h, `gaps[gap_start[h]..gap_start[h + 1]]` are the
    /// elements (loop, element) between h and its successor, all leaf arcs
    /// (thesis Observation 5) whose whole arc the node's disk touches, or
    /// elements that stay within the final check's slack (64τ) of the
    /// node's circle.
    gap_start: Vec<u32>,
    gaps: Vec<(u32, u32)>,
}

/// The node a half-edge starts at.
pub(crate) fn half_start(axis: &MedialAxis2d, h: usize) -> usize {
    let e = &axis.edges[h / 2];
    if h % 2 == 1 {
        e.from
    } else {
        e.to
    }
}

/// The node a half-edge ends at.
pub(crate) fn half_end(axis: &MedialAxis2d, h: usize) -> usize {
    let e = &axis.edges[h / 2];
    if h % 2 == 1 {
        e.to
    } else {
        e.from
    }
}

/// Loop and boundary position (2v for vertex v, 2e + 1 for element e).
fn place(p: Primitive) -> (usize, usize) {
    match p {
        Primitive::Element { .. } => (p.loop_index(), 2 * p.index() + 1),
        Primitive::Vertex { .. } => (p.loop_index(), 2 * p.index()),
    }
}

impl SideCycle {
    /// The tour of `axis`, the medial axis of `shape`.
    pub fn new(shape: &Shape2d, axis: &MedialAxis2d) -> Result<SideCycle, &'static str> {
        let halves = 2 * axis.edges.len();
        let mut leaving: Vec<Vec<u32>> = vec![Vec::new(); axis.nodes.len()];
        for h in 0..halves {
            leaving[half_start(axis, h)].push(h as u32);
        }
        let prim = |h: usize| place(axis.edges[h / 2].sites[h % 2]);
        let mut next = vec![u32::MAX; halves];
        let mut gap_start = Vec::with_capacity(halves + 1);
        let mut gaps = Vec::new();
        let mut has_pred = vec![false; halves];
        let hug = Tolerance::new(shape.tolerance()).final_check();
        for h in 0..halves {
            gap_start.push(gaps.len() as u32);
            let (l, pos) = prim(h);
            let period = 2 * shape.loops()[l].len();
            let mut best: Option<(usize, u32)> = None;
            for &c in &leaving[half_end(axis, h)] {
                let (lc, pc) = prim(c as usize);
                if lc != l {
                    continue;
                }
                let d = (pc + period - pos) % period;
                if best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, c));
                }
            }
            let Some((d, c)) = best else { return Err("an axis edge side has no successor at its node") };
            if std::mem::replace(&mut has_pred[c as usize], true) {
                return Err("two axis edge sides lead to the same successor");
            }
            next[h] = c;
            let node = &axis.nodes[half_end(axis, h)];
            for step in 1..d {
                let q = (pos + step) % period;
                if q % 2 == 1 {
                    let e = q / 2;
                    match shape.loops()[l].element(e) {
                        Element::Arc(a) if a.is_ccw() => gaps.push((l as u32, e as u32)),
                        // A stretch the node's disk hugs (a band's straight
                        // edge names the middle element of each chain).
                        el if el.circle_deviation(0.0, 1.0, node.point, node.radius) <= hug => {
                            gaps.push((l as u32, e as u32))
                        }
                        _ => return Err("a whole element is skipped that is no leaf arc"),
                    }
                }
            }
        }
        gap_start.push(gaps.len() as u32);
        Ok(SideCycle { next, gap_start, gaps })
    }

    /// The leaf arcs between half-edge `h` and its successor.
    pub fn gaps(&self, h: usize) -> &[(u32, u32)] {
        &self.gaps[self.gap_start[h] as usize..self.gap_start[h + 1] as usize]
    }
}
