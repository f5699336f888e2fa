//! Stubs of rounding, two kinds.
//!
//! An edge whose two sides are one primitive, out to a node of its own.
//! No disk touches one element at two points (it would have to be that
//! element's circle, the one disk there), so such an edge is no stretch of
//! axis; the base case walks one where every footpoint is rounding (a
//! curve within 10^-6 of a circle: 13 edges of 30–40τ from a leaf arc's
//! centre to a joint, whose offsets found no consistent order of sides at
//! the joint).
//!
//! A spike whose tip is the disk of the branch point it leaves (centres
//! and radii within [`Tolerance::same_disk`](crate::kernel::tolerance::Tolerance::same_disk)):
//! where the boundary hugs one circle over a hundred elements (the tip of
//! a smooth Fourier curve of 3·10^5 arcs, radius 0.28, hugged from
//! element 109078 to 109201), the base cases found the spine towards the
//! tip with two spikes of 4τ and 12τ off it, each naming as its sides
//! elements of the same hugged stretch as the spine beside it: the offsets
//! found the sides out of boundary order there and refused the shape. A
//! spike that short is no branch of the axis at the final check's
//! resolution.

use crate::plane::axis::{AxisEdge, AxisNode, MedialAxis2d};
use crate::plane::medial::conquer::merge::compact;
use rayon::prelude::*;

/// Drops each edge no longer than `reach` (model units) whose two sides
/// are the same primitive and one of whose ends has no other edge, with
/// that end. An edge that is the whole axis stays.
pub(crate) fn drop_self_stubs(axis: &mut MedialAxis2d, reach: f64) {
    // Rare: look for one before counting degrees (10^6 edges).
    if !axis.edges.par_iter().any(|e| e.sites[0] == e.sites[1]) {
        return;
    }
    let deg = axis.degrees();
    let nodes = &axis.nodes;
    let stub = |e: &AxisEdge| {
        e.sites[0] == e.sites[1]
            && (deg[e.from] == 1) != (deg[e.to] == 1)
            && nodes[e.from].point.dist(nodes[e.to].point) <= reach
    };
    let stubs: Vec<bool> = axis.edges.iter().map(stub).collect();
    if !stubs.contains(&true) {
        return;
    }
    let mut gone = vec![false; nodes.len()];
    for (e, _) in axis.edges.iter().zip(&stubs).filter(|(_, &s)| s) {
        gone[if deg[e.from] == 1 { e.from } else { e.to }] = true;
    }
    compact(axis, |v| (!gone[v]).then_some(v), |i, _| !stubs[i]);
}

/// Drops each leaf (a node of one edge, not a convex corner) whose disk
/// is its neighbour's within `same` (model units, centres and radii),
/// where that neighbour keeps two edges or more, with the leaf's edge.
pub(crate) fn drop_rounding_spikes(axis: &mut MedialAxis2d, same: f64) {
    let mut deg = axis.degrees();
    let nodes = &axis.nodes;
    let one = |a: &AxisNode, b: &AxisNode| a.point.dist(b.point) <= same && (a.radius - b.radius).abs() <= same;
    // Node kinds are settled only after this pass; a convex corner is the
    // node of radius 0.
    let tip = |v: usize, deg: &[usize]| deg[v] == 1 && nodes[v].radius > 0.0;
    let mut spikes = vec![false; axis.edges.len()];
    let mut gone = vec![false; nodes.len()];
    for (i, e) in axis.edges.iter().enumerate() {
        for (v, u) in [(e.from, e.to), (e.to, e.from)] {
            // Degrees are updated as spikes go, so that a branch point
            // with two spikes keeps one: its neighbour keeps two edges.
            if tip(v, &deg) && deg[u] >= 3 && one(&nodes[v], &nodes[u]) {
                (spikes[i], gone[v]) = (true, true);
                (deg[u], deg[v]) = (deg[u] - 1, 0);
                break;
            }
        }
    }
    if spikes.contains(&true) {
        compact(axis, |v| (!gone[v]).then_some(v), |i, _| !spikes[i]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::ConicKind;
    use crate::kernel::Point;
    use crate::plane::axis::{AxisNode, NodeKind, Primitive};
    use crate::shape::ElementRef;

    #[test]
    fn a_short_edge_between_one_primitive_and_itself_goes_with_its_lonely_end() {
        let node = |x: f64| AxisNode { point: Point::new(x, 0.0), radius: 1.0, kind: NodeKind::Joint };
        let p = |element: usize| Primitive::of_element(ElementRef { loop_index: 0, element });
        let edge = |from: usize, to: usize, sites: [Primitive; 2]| AxisEdge {
            from,
            to,
            sites,
            params: [(0.0, 0.0); 2],
            kind: ConicKind::Line,
            straight: false,
        };
        // 0 — 1 — 2 and stubs 1 — 3 (short), 2 — 4 (long), 0 — 1 again
        // between one primitive (both ends have other edges).
        let nodes = vec![node(0.0), node(1.0), node(2.0), node(1.0 + 1e-9), node(4.0)];
        let edges = vec![
            edge(0, 1, [p(0), p(1)]),
            edge(1, 2, [p(0), p(2)]),
            edge(3, 1, [p(5), p(5)]),
            edge(2, 4, [p(6), p(6)]),
            edge(0, 1, [p(7), p(7)]),
        ];
        let mut axis = MedialAxis2d { nodes, edges };
        drop_self_stubs(&mut axis, 1e-6);
        assert_eq!(axis.nodes.len(), 4);
        let ends: Vec<(usize, usize)> = axis.edges.iter().map(|e| (e.from, e.to)).collect();
        assert_eq!(ends, [(0, 1), (1, 2), (2, 3), (0, 1)]);
        assert_eq!(axis.nodes[3].point, Point::new(4.0, 0.0));
    }

    #[test]
    fn a_spike_whose_tip_is_its_branch_points_disk_goes() {
        let node = |x: f64, radius: f64, kind: NodeKind| AxisNode { point: Point::new(x, 0.0), radius, kind };
        let p = |element: usize| Primitive::of_element(ElementRef { loop_index: 0, element });
        let edge = |from: usize, to: usize| AxisEdge {
            from,
            to,
            sites: [p(from), p(to + 10)],
            params: [(0.0, 0.0); 2],
            kind: ConicKind::Line,
            straight: false,
        };
        let same = 1e-6;
        // Spine 0 — 1 — 2; node 1 has spikes to 3 (its own disk within
        // `same`: goes), 4 (a disk farther off) and 5 (a convex corner on
        // the same disk); node 2 ends the spine with two spikes on its
        // disk, 6 and 7: one goes, the other is the axis's tip.
        let nodes = vec![
            node(0.0, 1.0, NodeKind::Joint),
            node(1.0, 1.0, NodeKind::Branch),
            node(2.0, 1.0, NodeKind::Branch),
            node(1.0 + 0.5e-6, 1.0 - 0.5e-6, NodeKind::Leaf),
            node(1.0, 1.0 - 2e-6, NodeKind::Leaf),
            node(1.0, 0.0, NodeKind::Corner),
            node(2.0, 1.0 + 1e-7, NodeKind::Leaf),
            node(2.0 - 1e-7, 1.0, NodeKind::Leaf),
        ];
        let edges = vec![edge(0, 1), edge(1, 2), edge(3, 1), edge(1, 4), edge(1, 5), edge(6, 2), edge(2, 7)];
        let mut axis = MedialAxis2d { nodes, edges };
        drop_rounding_spikes(&mut axis, same);
        let radii: Vec<f64> = axis.nodes.iter().map(|n| n.radius).collect();
        assert_eq!(radii, [1.0, 1.0, 1.0, 1.0 - 2e-6, 0.0, 1.0]);
        assert_eq!(axis.nodes[5].point, Point::new(2.0 - 1e-7, 0.0));
        let ends: Vec<(usize, usize)> = axis.edges.iter().map(|e| (e.from, e.to)).collect();
        assert_eq!(ends, [(0, 1), (1, 2), (1, 3), (1, 4), (2, 5)]);
        assert_eq!(axis.edges[4].sites, [p(2), p(17)]);
    }
}
