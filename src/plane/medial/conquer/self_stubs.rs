//! Stubs of rounding: an edge whose two sides are one primitive, out to a
//! node of its own. No disk touches one element at two points (it would
//! have to be that element's circle, the one disk there), so such an edge
//! is no stretch of axis; the base case walks one where every footpoint
//! is rounding (a curve within 10^-6 of a circle: 13 edges of 30–40τ from
//! a leaf arc's centre to a joint, whose offsets found no consistent order
//! of sides at the joint).

use crate::plane::axis::{AxisEdge, MedialAxis2d};
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
}
