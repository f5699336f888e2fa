//! Cycles of the glued axis that can hold no hole: where dividing disks a
//! few tolerances apart hug long stretches of boundary (a curve within
//! 10^-6 of a circle), the maximal disks along such a stretch touch it
//! everywhere within the tolerance, so two subshapes can both hold one
//! stretch of axis, and leaves that named two such disks by one node
//! (`LocalAxis::aliases`) close the two copies into a cycle. A cycle
//! whose every node and edge middle lies within half the radius of one
//! of its nodes, `a`, lies inside `a`'s disk, which holds no boundary: no
//! hole lies inside, and one of the two copies goes.

use crate::plane::axis::MedialAxis2d;
use crate::plane::medial::conquer::check::root;
use crate::plane::medial::conquer::merge::{compact, Incidence};
use crate::shape::Shape2d;

/// Nodes a search for the other way round a cycle visits at most.
const SEARCH: usize = 256;

/// Removes the copies of axis stretches that close cycles inside one
/// disk (see the module text). Each edge that closes a cycle (in edge
/// order) lies on a route of nodes of degree 2 between two nodes of other
/// degree: where those differ and the cycle through the rest of the axis
/// is thin, the route goes with its inner nodes; where the route comes
/// back to the node it left (a loop hanging off one node, a tip reached
/// twice), only the closing edge goes. Cycles round holes are never thin
/// (their disks cannot reach across the hole) and stay. Nothing is done
/// where the axis has no more independent cycles than `holes` (an axis
/// that passes the graph check is left as it is).
pub(crate) fn drop_thin_cycles(shape: &Shape2d, axis: &mut MedialAxis2d, holes: usize) {
    let n = axis.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    let mut closing = Vec::new();
    for (i, e) in axis.edges.iter().enumerate() {
        let (a, b) = (root(&mut parent, e.from), root(&mut parent, e.to));
        if a == b {
            closing.push(i);
        }
        parent[a] = b;
    }
    if closing.len() <= holes {
        return;
    }
    drop(parent);
    let incidence = Incidence::of(axis);
    let edges = &axis.edges;
    let mut gone = vec![false; edges.len()];
    let mut inner_gone = vec![false; n];
    // Marks of the closing edge at hand: on its route (odd stamps) or
    // reached by the search for the other way (even stamps).
    let mut node_mark = vec![0u32; n];
    let mut edge_mark = vec![0u32; edges.len()];
    let live = |v: usize, gone: &[bool]| -> Vec<usize> { incidence.of_node(v).filter(|&i| !gone[i]).collect() };
    let other = |i: usize, v: usize| if edges[i].from == v { edges[i].to } else { edges[i].from };
    for (k, &c) in closing.iter().enumerate() {
        if gone[c] {
            continue;
        }
        let (on_route, searched) = (2 * k as u32 + 1, 2 * k as u32 + 2);
        let u = edges[c].from;
        let (centre, reach) = (axis.nodes[u].point, 0.5 * axis.nodes[u].radius);
        let near = |v: usize| axis.nodes[v].point.dist(centre) <= reach;
        let middle_near =
            |i: usize| edges[i].eval(shape, &axis.nodes, 0.5).is_some_and(|d| d.center.dist(centre) <= reach);
        // The route through `c`, out to a node of degree other than 2 on
        // each side; given up where it strays from `u`'s disk.
        let mut route = vec![c];
        edge_mark[c] = on_route;
        let mut inner = Vec::new();
        let mut ends = [edges[c].from, edges[c].to];
        let mut thin = middle_near(c) && near(ends[1]);
        for end in ends.iter_mut() {
            let mut via = c;
            while thin {
                let at = live(*end, &gone);
                if at.len() != 2 || node_mark[*end] == on_route {
                    break;
                }
                let next = if at[0] == via { at[1] } else { at[0] };
                if edge_mark[next] == on_route {
                    break;
                }
                node_mark[*end] = on_route;
                inner.push(*end);
                route.push(next);
                edge_mark[next] = on_route;
                *end = other(next, *end);
                via = next;
                thin = middle_near(next) && near(*end);
            }
        }
        if !thin {
            continue;
        }
        let [a, b] = ends;
        if a == b {
            // A loop off one node: the closing edge alone goes.
            gone[c] = true;
            continue;
        }
        // The other way from `a` to `b` within `u`'s disk, off the route.
        let mut seen = vec![a];
        node_mark[a] = searched;
        let mut at = 0;
        let mut found = false;
        while at < seen.len() && seen.len() < SEARCH && !found {
            let w = seen[at];
            for i in live(w, &gone).into_iter().filter(|&i| edge_mark[i] != on_route && middle_near(i)) {
                let x = other(i, w);
                if node_mark[x] == searched || !near(x) {
                    continue;
                }
                node_mark[x] = searched;
                seen.push(x);
                if x == b {
                    found = true;
                    break;
                }
            }
            at += 1;
        }
        if found {
            for &i in &route {
                gone[i] = true;
            }
            for &v in &inner {
                inner_gone[v] = true;
            }
        }
    }
    compact(axis, |v| (!inner_gone[v]).then_some(v), |i, _| !gone[i]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::ConicKind;
    use crate::kernel::Point;
    use crate::plane::axis::{AxisEdge, AxisNode, NodeKind, Primitive};
    use crate::shape::{ElementRef, ShapeOptions};

    fn shape() -> Shape2d {
        let json = r#"{"loops": [[[-10, -10], [10, -10], [10, 10], [-10, 10]]]}"#;
        Shape2d::from_json_str(json, &ShapeOptions::default()).unwrap()
    }

    fn node(x: f64, y: f64, radius: f64) -> AxisNode {
        AxisNode { point: Point::new(x, y), radius, kind: NodeKind::Joint }
    }

    fn edge(from: usize, to: usize) -> AxisEdge {
        let site = Primitive::of_element(ElementRef { loop_index: 0, element: 0 });
        AxisEdge { from, to, sites: [site, site], params: [(0.0, 0.0); 2], kind: ConicKind::Line, straight: true }
    }

    #[test]
    fn a_second_route_between_two_nodes_inside_one_disk_goes() {
        // A (0) and B (1) joined directly and by way of X (4), each with a
        // branch of its own (to 2 and 3): X's route closes the cycle.
        let nodes = vec![
            node(0.0, 0.0, 1.0),
            node(0.1, 0.0, 1.0),
            node(-5.0, 0.0, 1.0),
            node(5.0, 0.0, 1.0),
            node(0.05, 0.01, 1.0),
        ];
        let edges = vec![edge(0, 2), edge(1, 3), edge(0, 1), edge(0, 4), edge(4, 1)];
        let mut axis = MedialAxis2d { nodes, edges };
        drop_thin_cycles(&shape(), &mut axis, 0);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (4, 3));
        assert!(axis.edges.iter().any(|e| (e.from, e.to) == (0, 1)));
    }

    #[test]
    fn a_tip_reached_twice_keeps_one_edge_and_stays_a_tip() {
        let nodes = vec![node(0.0, 0.0, 1.0), node(-5.0, 0.0, 1.0), node(0.1, 0.0, 1.0)];
        let edges = vec![edge(0, 1), edge(0, 2), edge(2, 0)];
        let mut axis = MedialAxis2d { nodes, edges };
        drop_thin_cycles(&shape(), &mut axis, 0);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (3, 2));
    }

    #[test]
    fn a_cycle_round_a_hole_stays() {
        // Four nodes on a circle of radius 2 whose disks (radius 1) cannot
        // reach across it: the axis round a hole.
        let nodes = vec![node(2.0, 0.0, 1.0), node(0.0, 2.0, 1.0), node(-2.0, 0.0, 1.0), node(0.0, -2.0, 1.0)];
        let edges = vec![edge(0, 1), edge(1, 2), edge(2, 3), edge(3, 0)];
        let mut axis = MedialAxis2d { nodes, edges };
        drop_thin_cycles(&shape(), &mut axis, 0);
        assert_eq!((axis.nodes.len(), axis.edges.len()), (4, 4));
        // Two nodes joined twice round a hole: their disks are too small.
        let nodes = vec![node(2.0, 0.0, 1.0), node(-2.0, 0.0, 1.0)];
        let mut axis = MedialAxis2d { nodes, edges: vec![edge(0, 1), edge(1, 0)] };
        drop_thin_cycles(&shape(), &mut axis, 0);
        assert_eq!(axis.edges.len(), 2);
    }
}
