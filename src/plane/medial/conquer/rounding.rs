//! Cycles of rounding in the glued axis: a branch point next to a joint
//! whose contacts snapped onto the joint's vertex is joined to the joint's
//! node on both sides, closing a cycle a few tolerances wide that can hold
//! no hole. The cluster of nodes is one node of the axis.

use crate::plane::axis::MedialAxis2d;
use crate::plane::axis::{AxisEdge, AxisNode};
use crate::plane::medial::conquer::check::drop_repeats;
use crate::plane::medial::conquer::merge::compact;
use crate::util::fast_hash::{FastMap, FastSet};
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
/// in the shape. A cluster is contracted only where its node's disk
/// `fits` every edge that moves onto it (clusters chained over many short
/// cycles, as near the centre of a curve within 10^-6 of a circle, span
/// hundreds of tolerances: their cycles are left to `thin_cycles`).
pub(crate) fn contract_rounding_cycles(
    axis: &mut MedialAxis2d,
    reach: f64,
    fits: impl Fn(&AxisNode, &AxisEdge) -> bool,
) {
    let nodes = &axis.nodes;
    let n = nodes.len();
    let big = |w: usize| nodes[w].radius > 4.0 * reach;
    // Few edges are that short: find them in parallel, then walk them in
    // order. Everything below is sized by them, not by the axis (10^6
    // nodes: fresh memory per node cost more than the search).
    let short: Vec<(usize, usize)> = axis
        .edges
        .par_iter()
        .filter(|e| e.from != e.to && nodes[e.from].point.dist(nodes[e.to].point) <= reach)
        .map(|e| (e.from, e.to))
        .collect();
    if short.is_empty() {
        return;
    }
    // The short edges seen so far at each node, in the order seen: a list
    // per node threaded through `links` (first and last link per node).
    let mut ends = vec![(NONE, NONE); n];
    let mut links: Vec<(usize, u32)> = Vec::with_capacity(2 * short.len());
    let link = |ends: &mut Vec<(u32, u32)>, links: &mut Vec<(usize, u32)>, a: usize, b: usize| {
        let id = links.len() as u32;
        links.push((b, NONE));
        match ends[a] {
            (NONE, _) => ends[a] = (id, id),
            (first, last) => {
                links[last as usize].1 = id;
                ends[a] = (first, id);
            }
        }
    };
    // Union-find over the nodes of contracted clusters only; a root is its
    // set's smallest node.
    let mut parent: FastMap<usize, usize> = FastMap::default();
    let find = |parent: &FastMap<usize, usize>, mut x: usize| {
        while let Some(&p) = parent.get(&x) {
            x = p;
        }
        x
    };
    let mut members: Vec<usize> = Vec::new();
    for &(u, v) in &short {
        let p = nodes[u].point;
        // Is v already reached from u over short edges, near u?
        let mut seen = vec![u];
        let mut k = 0;
        let mut closes = false;
        while k < seen.len() && seen.len() < SEARCH && !closes {
            let w = seen[k];
            k += 1;
            let mut at = ends[w].0;
            while at != NONE {
                let (x, next) = links[at as usize];
                if x == v {
                    closes = true;
                } else if !seen.contains(&x) && nodes[x].point.dist(p) <= reach {
                    seen.push(x);
                }
                at = next;
            }
        }
        if closes && big(v) && seen.iter().all(|&w| big(w)) {
            for &w in seen.iter().chain([&v]) {
                let (a, b) = (find(&parent, u), find(&parent, w));
                if a != b {
                    parent.insert(a.max(b), a.min(b));
                }
                members.extend([u, w]);
            }
        }
        link(&mut ends, &mut links, u, v);
        link(&mut ends, &mut links, v, u);
    }
    if members.is_empty() {
        return;
    }
    drop(ends);
    members.sort_unstable();
    members.dedup();
    let mut in_cluster = vec![false; n];
    for &v in &members {
        in_cluster[v] = true;
    }
    let group = |v: usize| if in_cluster[v] { find(&parent, v) } else { v };
    let mut leaving: FastMap<usize, usize> = FastMap::default();
    for e in axis.edges.iter().filter(|e| in_cluster[e.from] || in_cluster[e.to]) {
        if group(e.from) != group(e.to) {
            for v in [e.from, e.to].into_iter().filter(|&v| in_cluster[v]) {
                *leaving.entry(v).or_default() += 1;
            }
        }
    }
    // The cluster's node: the member with most edges leaving (the first
    // of those in node order).
    let mut chosen: FastMap<usize, usize> = FastMap::default();
    let left = |v: usize| leaving.get(&v).copied().unwrap_or(0);
    for &v in &members {
        let g = group(v);
        if chosen.get(&g).is_none_or(|&c| left(v) > left(c)) {
            chosen.insert(g, v);
        }
    }
    // Clusters whose node does not fit an edge moving onto it stay apart.
    let misfits: FastSet<usize> = axis
        .edges
        .iter()
        .filter(|e| group(e.from) != group(e.to))
        .flat_map(|e| [(e.from, e), (e.to, e)])
        .filter(|&(v, e)| in_cluster[v] && chosen[&group(v)] != v && !fits(&axis.nodes[chosen[&group(v)]], e))
        .map(|(v, _)| group(v))
        .collect();
    if !misfits.is_empty() {
        for &v in &members {
            if misfits.contains(&find(&parent, v)) {
                in_cluster[v] = false;
            }
        }
    }
    let group = |v: usize| if in_cluster[v] { find(&parent, v) } else { v };
    let node_of = |v: usize| if in_cluster[v] { chosen[&group(v)] } else { v };
    // In place: edges inside a cluster become loops at its node and go.
    for e in axis.edges.iter_mut().filter(|e| in_cluster[e.from] || in_cluster[e.to]) {
        if group(e.from) == group(e.to) {
            e.to = e.from;
        } else {
            e.from = node_of(e.from);
            e.to = node_of(e.to);
        }
    }
    // Only an edge that now ends at a cluster's node can repeat another.
    let mut at_cluster = Vec::with_capacity(axis.edges.len());
    compact(
        axis,
        |v| (node_of(v) == v).then_some(v),
        |_, e| {
            let keep = e.from != e.to;
            if keep {
                at_cluster.push(in_cluster[e.from] || in_cluster[e.to]);
            }
            keep
        },
    );
    drop_repeats(&mut axis.edges, &at_cluster);
}

/// No link (the end of a node's list of short edges).
const NONE: u32 = u32::MAX;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::ConicKind;
    use crate::kernel::Point;
    use crate::plane::axis::{NodeKind, Primitive};
    use crate::shape::ElementRef;

    fn node(x: f64, y: f64, radius: f64) -> AxisNode {
        AxisNode { point: Point::new(x, y), radius, kind: NodeKind::Joint }
    }

    fn edge(from: usize, to: usize, site: usize) -> AxisEdge {
        let site = Primitive::of_element(ElementRef { loop_index: 0, element: site });
        AxisEdge { from, to, sites: [site, site], params: [(0.0, 0.0); 2], kind: ConicKind::Line, straight: false }
    }

    /// A joint (1) on a curve 0-1-3, a branch point (2) next to it
    /// joined to it twice (by way of 4), and a branch leaving 2.
    fn joint_with_a_branch_point_beside_it() -> MedialAxis2d {
        let nodes = vec![
            node(-5.0, 0.0, 1.0),
            node(0.0, 0.0, 1.0),
            node(3e-7, 0.0, 1.0),
            node(5.0, 0.0, 1.0),
            node(0.0, 3e-7, 1.0),
            node(0.0, -5.0, 1.0),
        ];
        let edges = vec![edge(0, 1, 0), edge(1, 3, 1), edge(1, 2, 2), edge(2, 4, 3), edge(4, 1, 4), edge(2, 5, 5)];
        MedialAxis2d { nodes, edges }
    }

    #[test]
    fn a_small_cycle_of_large_disks_becomes_one_node() {
        let mut axis = joint_with_a_branch_point_beside_it();
        contract_rounding_cycles(&mut axis, 1e-6, |_, _| true);
        assert_eq!(axis.nodes.len(), 4);
        // The joint stays, with three edges: no stub is left.
        let joint = axis.nodes.iter().position(|n| n.point == Point::new(0.0, 0.0)).unwrap();
        let degree = axis.edges.iter().filter(|e| e.from == joint || e.to == joint).count();
        assert_eq!((axis.edges.len(), degree), (3, 3));
    }

    #[test]
    fn a_cluster_whose_node_misses_an_edge_moving_onto_it_stays() {
        let mut axis = joint_with_a_branch_point_beside_it();
        // Only edge 5 (site 5, leaving node 2) misses the joint's disk.
        let site5 = Primitive::of_element(ElementRef { loop_index: 0, element: 5 });
        contract_rounding_cycles(&mut axis, 1e-6, |_, e| e.sites[0] != site5);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (6, 6));
    }

    #[test]
    fn a_cycle_that_could_hold_a_hole_is_kept() {
        let cycle = vec![edge(0, 1, 0), edge(1, 2, 1), edge(2, 0, 2)];
        // Disks no larger than the cycle's reach: a hole may lie inside.
        let small = vec![node(0.0, 0.0, 2e-6), node(3e-7, 0.0, 2e-6), node(0.0, 3e-7, 2e-6)];
        let mut axis = MedialAxis2d { nodes: small, edges: cycle.clone() };
        contract_rounding_cycles(&mut axis, 1e-6, |_, _| true);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (3, 3));
        // A wide cycle of large disks.
        let wide = vec![node(0.0, 0.0, 1.0), node(3e-6, 0.0, 1.0), node(0.0, 3e-6, 1.0)];
        let mut axis = MedialAxis2d { nodes: wide, edges: cycle };
        contract_rounding_cycles(&mut axis, 1e-6, |_, _| true);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (3, 3));
    }
}
