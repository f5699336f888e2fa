//! Short conic edges whose middle strays from their chord: between two
//! arcs that both hug the edge's end disks within the tolerance (a curve
//! within 10^-6 of a circle), the bisector is ill-conditioned, and the
//! disk at the middle footpoint parameter of an edge 30τ long was
//! measured to lie 80–210τ off its chord and to reach across the boundary.
//! Such an edge is the straight segment between its nodes, whose disks
//! (radius linear from node to node) stay within the tolerance of both
//! primitives, as a hugged band's is.

use crate::kernel::bisector::ConicKind;
use crate::kernel::AxisKernel;
use crate::plane::axis::MedialAxis2d;
use crate::plane::medial::disk::maximal::DiskFinder;
use rayon::prelude::*;

/// Makes straight every conic edge no longer than `short` (model units)
/// that has no middle disk, whose middle disk's centre lies farther than
/// `short` from the middle of its chord or whose radius differs by more
/// than `short` from the mean of its nodes', or whose middle disk strays
/// more than `slack / 4` and holds boundary deeper than `slack` while the
/// chord's middle disk (that centre, that mean radius) does not. The last
/// rule asks the index, so it runs only on the few edges that stray; a
/// short conic edge that bends that far for real (a parabola round a
/// vertex close to a side) keeps its shape, its middle disk being empty.
pub(crate) fn straighten_stray_conics<K: AxisKernel>(
    finder: &DiskFinder<K>,
    axis: &mut MedialAxis2d,
    short: f64,
    slack: f64,
) {
    let shape = finder.shape();
    let nodes = &axis.nodes;
    let full = |c, r| finder.intruder(c, r, slack).is_some();
    axis.edges.par_iter_mut().filter(|e| !e.straight && e.kind != ConicKind::Line).for_each(|e| {
        let (a, b) = (nodes[e.from].point, nodes[e.to].point);
        if a.dist(b) > short {
            return;
        }
        let (middle, radius) = ((a + b) * 0.5, 0.5 * (nodes[e.from].radius + nodes[e.to].radius));
        let stray = match e.eval(shape, nodes, 0.5) {
            None => true,
            Some(d) => {
                let off = d.center.dist(middle).max((d.radius - radius).abs());
                off > short || off > 0.25 * slack && full(d.center, d.radius) && !full(middle, radius)
            }
        };
        if stray {
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
    use crate::shape::{ElementRef, Shape2d, ShapeOptions};

    /// A 40 × 20 rectangle whose axis runs along y = 0, two nodes 10^-8
    /// apart at its left end (disks of radius 10 touching the left side
    /// too), and conic edges between the bottom and the top side from the
    /// first node to node `to` whose far footpoints are moved by `stray`
    /// in x.
    fn rectangle_edges(strays: &[(usize, f64)]) -> (Shape2d, MedialAxis2d) {
        let json = r#"{"loops": [[[-10, -10], [30, -10], [30, 10], [-10, 10]]]}"#;
        let shape = Shape2d::from_json_str(json, &ShapeOptions::default()).unwrap();
        let node = |x: f64| AxisNode { point: Point::new(x, 0.0), radius: 10.0, kind: NodeKind::Joint };
        let nodes = vec![node(0.0), node(1e-8), node(5.0)];
        let sides = [0, 2].map(|element| Primitive::of_element(ElementRef { loop_index: 0, element }));
        let edge = |(to, stray): (usize, f64)| {
            let param = |p: Primitive, v: usize| footpoint_param(&p.site(&shape), nodes[v].point, 10.0);
            // The top side runs in −x.
            let [bottom, top] = sides;
            let params = [(param(bottom, 0), param(bottom, to) + stray), (param(top, 0), param(top, to) - stray)];
            AxisEdge { from: 0, to, sites: sides, params, kind: ConicKind::Parabola, straight: false }
        };
        let edges = strays.iter().copied().map(edge).collect();
        (shape, MedialAxis2d { nodes, edges })
    }

    #[test]
    fn a_short_edge_whose_middle_strays_far_becomes_straight_and_no_other() {
        let (shape, mut axis) = rectangle_edges(&[(1, 0.0), (1, 5.0), (2, 5.0)]);
        straighten_stray_conics(&DiskFinder::new(&shape), &mut axis, 1e-6, 1e-7);
        assert_eq!(axis.edges.iter().map(|e| e.straight).collect::<Vec<_>>(), [false, true, false]);
    }

    #[test]
    fn a_short_edge_whose_middle_strays_a_little_becomes_straight_only_where_that_disk_is_not_empty() {
        // Moved 2·10^-7 one way or the other, the middle disk's centre
        // moves 10^-7: into the left side by more than the slack, or
        // away from it; both less than `short`.
        let (shape, mut axis) = rectangle_edges(&[(1, 2e-7), (1, -2e-7)]);
        let left: Vec<bool> =
            axis.edges.iter().map(|e| e.eval(&shape, &axis.nodes, 0.5).unwrap().center.x < 0.0).collect();
        assert_eq!(left.iter().filter(|&&l| l).count(), 1);
        straighten_stray_conics(&DiskFinder::new(&shape), &mut axis, 1e-6, 5e-8);
        assert_eq!(axis.edges.iter().map(|e| e.straight).collect::<Vec<_>>(), left);
    }
}
