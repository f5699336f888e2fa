//! The solved leaves gathered for gluing, in two flat lists.
//!
//! At 10^6 elements the leaves' axes are about as large as the finished
//! axis, and held as one small vector per leaf beside the glued copy they
//! set the peak memory (a random star of 10^6 vertices: 0.83 kB per
//! element, of which the leaves' axes were 0.33 kB). Here every leaf's
//! edges are written once, already in the glued axis's edge type, into one
//! list that gluing renumbers and filters in place and hands on as the
//! axis's edges: no second copy of them ever exists.

use crate::kernel::bisector::ConicKind;
use crate::plane::axis::AxisEdge;
use crate::plane::medial::base_case::{LocalAxis, LocalNode};

/// The axes of many subshapes: each one's nodes and edges contiguous, in
/// the order they were pushed.
#[derive(Debug, Clone, Default)]
pub struct LocalAxes {
    /// Every subshape's nodes.
    pub(crate) nodes: Vec<LocalNode>,
    /// Every subshape's edges; `from` and `to` index `nodes` (the whole
    /// list, not the subshape's part of it). `kind` is not set yet (it is
    /// [`ConicKind::Line`] until gluing names the conic).
    pub(crate) edges: Vec<AxisEdge>,
    /// Where each subshape's nodes and edges start, and one past the last.
    starts: Vec<(usize, usize)>,
}

/// One subshape's part of [`LocalAxes`].
#[derive(Debug, Clone, Copy)]
pub struct LocalView<'a> {
    /// Its nodes.
    pub nodes: &'a [LocalNode],
    /// Its edges, `from` and `to` relative to the whole list of nodes.
    pub edges: &'a [AxisEdge],
    /// Index of its first node in the whole list.
    pub first_node: usize,
}

impl LocalAxes {
    /// Appends one subshape's axis.
    pub fn push(&mut self, local: LocalAxis) {
        if self.starts.is_empty() {
            self.starts.push((0, 0));
        }
        let base = self.nodes.len();
        self.edges.extend(local.edges.iter().map(|e| AxisEdge {
            from: base + e.from,
            to: base + e.to,
            sites: e.sites,
            params: e.params,
            kind: ConicKind::Line,
            straight: e.straight,
        }));
        self.nodes.extend(local.nodes);
        self.starts.push((self.nodes.len(), self.edges.len()));
    }

    /// How many subshapes.
    pub fn count(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    /// Subshape `k`.
    pub fn get(&self, k: usize) -> LocalView<'_> {
        let ((n0, e0), (n1, e1)) = (self.starts[k], self.starts[k + 1]);
        LocalView { nodes: &self.nodes[n0..n1], edges: &self.edges[e0..e1], first_node: n0 }
    }

    /// Every subshape, in order.
    pub fn iter(&self) -> impl Iterator<Item = LocalView<'_>> + '_ {
        (0..self.count()).map(|k| self.get(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::plane::axis::Primitive;
    use crate::plane::medial::base_case::{EventKind, LocalEdge};
    use crate::shape::ElementRef;

    #[test]
    fn edges_index_the_whole_list_of_nodes() {
        let node = |x: f64| LocalNode { center: Point::new(x, 0.0), radius: 1.0, kind: EventKind::Joint };
        let site = Primitive::Element(ElementRef { loop_index: 0, element: 0 });
        let edge = LocalEdge { from: 1, to: 0, sites: [site, site], params: [(0.0, 1.0); 2], straight: false };
        let mut all = LocalAxes::default();
        assert_eq!(all.count(), 0);
        all.push(LocalAxis { nodes: vec![node(0.0), node(1.0)], edges: vec![edge] });
        all.push(LocalAxis { nodes: vec![node(2.0), node(3.0)], edges: vec![edge] });
        assert_eq!(all.count(), 2);
        let second = all.get(1);
        assert_eq!((second.first_node, second.nodes.len(), second.edges.len()), (2, 2, 1));
        assert_eq!((second.edges[0].from, second.edges[0].to), (3, 2));
        assert_eq!(all.nodes[second.edges[0].from].center.x, 3.0);
    }
}
