//! Short conic edges whose middle strays far from their chord: between two
//! arcs that both hug the edge's end disks within the tolerance (a curve
//! within 10^-6 of a circle), the bisector is ill-conditioned, and the
//! disk at the middle footpoint parameter of an edge 30τ long was
//! measured to reach 150τ across the boundary. Such an edge is the straight segment
//! between its nodes, whose disks (radius linear from node to node) stay
//! within the tolerance of both primitives, as a hugged band's is.

use crate::kernel::bisector::ConicKind;
use crate::plane::axis::MedialAxis2d;
use crate::shape::Shape2d;
use rayon::prelude::*;

/// Makes straight every conic edge no longer than `short` (model units)
/// whose middle disk's centre lies farther than `short` from the middle
/// of its chord, or whose radius differs by more than `short` from the
/// mean of its nodes' (or that has no middle disk).
pub(crate) fn straighten_stray_conics(shape: &Shape2d, axis: &mut MedialAxis2d, short: f64) {
    let nodes = &axis.nodes;
    axis.edges.par_iter_mut().filter(|e| !e.straight && e.kind != ConicKind::Line).for_each(|e| {
        let (a, b) = (nodes[e.from].point, nodes[e.to].point);
        if a.dist(b) > short {
            return;
        }
        let (middle, radius) = ((a + b) * 0.5, 0.5 * (nodes[e.from].radius + nodes[e.to].radius));
        if e.eval(shape, nodes, 0.5).is_none_or(|d| d.center.dist(middle) > short || (d.radius - radius).abs() > short)
        {
            e.straight = true;
            e.kind = ConicKind::Line;
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::footpoint_param;
    use crate::kernel::Point;
    use crate::plane::axis::{AxisEdge, AxisNode, NodeKind, Primitive};
    use crate::shape::{ElementRef, ShapeOptions};

    #[test]
    fn a_short_edge_whose_middle_strays_becomes_straight_and_no_other() {
        let json = r#"{"loops": [[[-10, -10], [10, -10], [10, 10], [-10, 10]]]}"#;
        let shape = Shape2d::from_json_str(json, &ShapeOptions::default()).unwrap();
        let node = |x: f64| AxisNode { point: Point::new(x, 0.0), radius: 10.0, kind: NodeKind::Joint };
        let nodes = vec![node(0.0), node(1e-8), node(5.0)];
        // Between the bottom and the top side; `stray` moves the middle
        // footpoints 2.5 away.
        let sides = [0, 2].map(|element| Primitive::Element(ElementRef { loop_index: 0, element }));
        let edge = |to: usize, stray: f64| {
            let param = |p: Primitive, v: usize| footpoint_param(&p.site(&shape), nodes[v].point, 10.0);
            let params = sides.map(|p| (param(p, 0), param(p, to) + stray));
            AxisEdge { from: 0, to, sites: sides, params, kind: ConicKind::Parabola, straight: false }
        };
        let mut axis = MedialAxis2d { nodes: nodes.clone(), edges: vec![edge(1, 0.0), edge(1, 5.0), edge(2, 5.0)] };
        straighten_stray_conics(&shape, &mut axis, 1e-6);
        assert_eq!(axis.edges.iter().map(|e| e.straight).collect::<Vec<_>>(), [false, true, false]);
    }
}
