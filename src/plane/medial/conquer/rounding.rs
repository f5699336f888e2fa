//! Cycles of rounding in the glued axis: a branch point next to a joint
//! whose contacts snapped onto the joint's vertex is joined to the joint's
//! node on both sides, closing a cycle a few tolerances wide that can hold
//! no hole. The cluster of nodes is one node of the axis.

use crate::plane::axis::{AxisEdge, MedialAxis2d};
use crate::plane::medial::conquer::check::{first_of_each, root};
use crate::plane::medial::conquer::merge::compact;
use crate::util::fast_hash::FastMap;
use rayon::prelude::*;

/// Nodes a search for a cycle visits at most, so that it costs little.
const SEARCH: usize = 64;

/// Contracts each cycle of rounding into one node: an edge shorter than
/// `reach` (model units, `Tolerance::rounding_cycle`) that closes a cycle
/// over edges shorter than `reach`, every node of it within `reach` of
/// the edge's start and every disk larger than four times `reach`. A hole
/// inside such a cycle would lie within `reach` of its nodes and so inside
/// their disks: it holds none. The cluster's node is the member with the
/// most edges leaving the cluster (the joint, whose disk was a dividing
/// one); edges inside the cluster go, and the others end at that node
/// (their ends move by less than `reach`). Dropping one edge instead
/// would leave a stub of rounding length and a branch point that is not
/// in the shape.
pub(crate) fn contract_rounding_cycles(axis: &mut MedialAxis2d, reach: f64) {
    let nodes = &axis.nodes;
    let n = nodes.len();
    let big = |w: usize| nodes[w].radius > 4.0 * reach;
    let mut parent: Vec<usize> = (0..n).collect();
    let mut near: FastMap<usize, Vec<usize>> = FastMap::default();
    let mut contracted = false;
    // Few edges are that short: find them in parallel, then walk them in
    // order.
    let short: Vec<&AxisEdge> = axis
        .edges
        .par_iter()
        .filter(|e| e.from != e.to && nodes[e.from].point.dist(nodes[e.to].point) <= reach)
        .collect();
    for e in short {
        let (u, v) = (e.from, e.to);
        let p = nodes[u].point;
        // Is v already reached from u over short edges, near u?
        let mut seen = vec![u];
        let mut k = 0;
        let mut closes = false;
        while k < seen.len() && seen.len() < SEARCH && !closes {
            let w = seen[k];
            k += 1;
            for &x in near.get(&w).map_or(&[][..], Vec::as_slice) {
                if x == v {
                    closes = true;
                } else if !seen.contains(&x) && nodes[x].point.dist(p) <= reach {
                    seen.push(x);
                }
            }
        }
        if closes && big(v) && seen.iter().all(|&w| big(w)) {
            for &w in seen.iter().chain([&v]) {
                let (a, b) = (root(&mut parent, u), root(&mut parent, w));
                parent[a.max(b)] = a.min(b);
            }
            contracted = true;
        }
        near.entry(u).or_default().push(v);
        near.entry(v).or_default().push(u);
    }
    if !contracted {
        return;
    }
    let group: Vec<usize> = (0..n).map(|v| root(&mut parent, v)).collect();
    let mut leaving = vec![0usize; n];
    for e in axis.edges.iter().filter(|e| group[e.from] != group[e.to]) {
        leaving[e.from] += 1;
        leaving[e.to] += 1;
    }
    let mut chosen: Vec<Option<usize>> = vec![None; n];
    for v in 0..n {
        let g = group[v];
        if chosen[g].is_none_or(|c| leaving[v] > leaving[c]) {
            chosen[g] = Some(v);
        }
    }
    // In place: edges inside a cluster become loops at its node and go.
    for e in axis.edges.iter_mut() {
        let (a, b) = (group[e.from], group[e.to]);
        if a == b {
            e.to = e.from;
        } else {
            e.from = chosen[a].unwrap_or(e.from);
            e.to = chosen[b].unwrap_or(e.to);
        }
    }
    compact(axis, |v| (chosen[group[v]] == Some(v)).then_some(v), |_, e| e.from != e.to);
    let first = first_of_each(&axis.edges, axis.nodes.len());
    let mut k = 0;
    axis.edges.retain(|_| {
        k += 1;
        first[k - 1]
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::ConicKind;
    use crate::kernel::Point;
    use crate::plane::axis::{AxisNode, NodeKind, Primitive};
    use crate::shape::ElementRef;

    fn node(x: f64, y: f64, radius: f64) -> AxisNode {
        AxisNode { point: Point::new(x, y), radius, kind: NodeKind::Joint }
    }

    fn edge(from: usize, to: usize, site: usize) -> AxisEdge {
        let site = Primitive::Element(ElementRef { loop_index: 0, element: site });
        AxisEdge { from, to, sites: [site, site], params: [(0.0, 0.0); 2], kind: ConicKind::Line, straight: false }
    }

    #[test]
    fn a_small_cycle_of_large_disks_becomes_one_node() {
        // A joint (1) on a curve 0-1-3, a branch point (2) next to it
        // joined to it twice (by way of 4), and a branch leaving 2.
        let nodes = vec![
            node(-5.0, 0.0, 1.0),
            node(0.0, 0.0, 1.0),
            node(3e-7, 0.0, 1.0),
            node(5.0, 0.0, 1.0),
            node(0.0, 3e-7, 1.0),
            node(0.0, -5.0, 1.0),
        ];
        let edges = vec![edge(0, 1, 0), edge(1, 3, 1), edge(1, 2, 2), edge(2, 4, 3), edge(4, 1, 4), edge(2, 5, 5)];
        let mut axis = MedialAxis2d { nodes, edges };
        contract_rounding_cycles(&mut axis, 1e-6);
        assert_eq!(axis.nodes.len(), 4);
        // The joint stays, with three edges: no stub is left.
        let joint = axis.nodes.iter().position(|n| n.point == Point::new(0.0, 0.0)).unwrap();
        let degree = axis.edges.iter().filter(|e| e.from == joint || e.to == joint).count();
        assert_eq!((axis.edges.len(), degree), (3, 3));
    }

    #[test]
    fn a_cycle_that_could_hold_a_hole_is_kept() {
        let cycle = vec![edge(0, 1, 0), edge(1, 2, 1), edge(2, 0, 2)];
        // Disks no larger than the cycle's reach: a hole may lie inside.
        let small = vec![node(0.0, 0.0, 2e-6), node(3e-7, 0.0, 2e-6), node(0.0, 3e-7, 2e-6)];
        let mut axis = MedialAxis2d { nodes: small, edges: cycle.clone() };
        contract_rounding_cycles(&mut axis, 1e-6);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (3, 3));
        // A wide cycle of large disks.
        let wide = vec![node(0.0, 0.0, 1.0), node(3e-6, 0.0, 1.0), node(0.0, 3e-6, 1.0)];
        let mut axis = MedialAxis2d { nodes: wide, edges: cycle };
        contract_rounding_cycles(&mut axis, 1e-6);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (3, 3));
    }
}
