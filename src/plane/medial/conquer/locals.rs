//! The solved leaves gathered for gluing, in two flat lists.
//!
//! At 10^6 elements the leaves' axes are about as large as the finished
//! axis, and held as one small vector per leaf beside the glued copy they
//! set the peak memory (a random star of 10^6 vertices: 0.83 kB per
//! element, of which the leaves' axes were 0.33 kB). Here every leaf's
//! nodes and edges are written once, already in the glued axis's types,
//! into lists that gluing compacts, renumbers and filters in place and
//! hands on as the axis's nodes and edges: no second copy of them ever
//! exists.

use crate::kernel::bisector::ConicKind;
use crate::plane::axis::{AxisEdge, AxisNode, NodeKind};
use crate::plane::medial::base_case::{Alias, EventKind, LocalAxis};

/// The axes of many subshapes: each one's nodes and edges contiguous, in
/// the order they were pushed.
#[derive(Debug, Clone, Default)]
pub struct LocalAxes {
    /// Every subshape's nodes (`kind` is [`NodeKind::Joint`] until gluing
    /// settles it from the degrees).
    pub(crate) nodes: Vec<AxisNode>,
    /// Where each node comes from, beside `nodes`.
    pub(crate) events: Vec<EventKind>,
    /// Every subshape's edges; `from` and `to` index `nodes` (the whole
    /// list, not the subshape's part of it). `kind` is not set yet (it is
    /// [`ConicKind::Line`] until gluing names the conic).
    pub(crate) edges: Vec<AxisEdge>,
    /// Every subshape's [`LocalAxis::aliases`].
    pub(crate) aliases: Vec<Alias>,
    /// Where each subshape's nodes and edges start, and one past the last.
    starts: Vec<(usize, usize)>,
}

/// One subshape's part of [`LocalAxes`].
#[derive(Debug, Clone, Copy)]
pub struct LocalView<'a> {
    /// Its nodes (the debugging examples look at them; gluing needs only
    /// the events).
    #[cfg_attr(not(any(test, feature = "internals")), allow(dead_code))]
    pub nodes: &'a [AxisNode],
    /// Where each of its nodes comes from.
    pub events: &'a [EventKind],
    /// Its edges, `from` and `to` relative to the whole list of nodes.
    pub edges: &'a [AxisEdge],
}

impl LocalAxes {
    /// Appends one subshape's axis.
    pub fn push(&mut self, local: LocalAxis) {
        if self.starts.is_empty() {
            self.starts.push((0, 0));
        }
        let base = self.nodes.len();
        grow(&mut self.nodes, local.nodes.len());
        grow(&mut self.events, local.nodes.len());
        grow(&mut self.edges, local.edges.len());
        self.edges.extend(local.edges.iter().map(|e| AxisEdge {
            from: base + e.from,
            to: base + e.to,
            sites: e.sites,
            params: e.params,
            kind: ConicKind::Line,
            straight: e.straight,
        }));
        self.nodes.extend(local.nodes.iter().map(|n| AxisNode {
            point: n.center,
            radius: n.radius,
            kind: NodeKind::Joint,
        }));
        self.events.extend(local.nodes.iter().map(|n| n.kind));
        self.aliases.extend(local.aliases);
        self.starts.push((self.nodes.len(), self.edges.len()));
    }

    /// Gives back the room the lists grew beyond what they hold.
    pub(crate) fn shrink_to_fit(&mut self) {
        self.nodes.shrink_to_fit();
        self.events.shrink_to_fit();
        self.edges.shrink_to_fit();
    }

    /// How many subshapes.
    pub fn count(&self) -> usize {
        self.starts.len().saturating_sub(1)
    }

    /// Subshape `k`.
    pub fn get(&self, k: usize) -> LocalView<'_> {
        let ((n0, e0), (n1, e1)) = (self.starts[k], self.starts[k + 1]);
        LocalView { nodes: &self.nodes[n0..n1], events: &self.events[n0..n1], edges: &self.edges[e0..e1] }
    }

    /// The lists, each node's origin `None` where its subshape is left out
    /// (`skip[k]` for subshape `k`).
    pub(crate) fn into_parts(self, skip: &[bool]) -> (Vec<AxisNode>, Vec<Option<EventKind>>, Vec<AxisEdge>) {
        let mut events: Vec<Option<EventKind>> = self.events.into_iter().map(Some).collect();
        for (w, _) in self.starts.windows(2).zip(skip).filter(|(_, &left_out)| left_out) {
            events[w[0].0..w[1].0].fill(None);
        }
        (self.nodes, events, self.edges)
    }

    /// Every subshape, in order.
    pub fn iter(&self) -> impl Iterator<Item = LocalView<'_>> + '_ {
        (0..self.count()).map(|k| self.get(k))
    }
}

/// Makes room in `v` for `more` items: doubling while small, by a quarter
/// of what it holds once it is large. The lists reach hundreds of
/// megabytes at 10^6 elements, and doubling left up to half of that
/// allocated and unused through gluing (a plate of random holes: 4.3·10^6
/// nodes allocated for 3.0·10^6); large blocks are moved by remapping
/// pages, small ones by copying, which a quarter at a time would repeat.
fn grow<T>(v: &mut Vec<T>, more: usize) {
    if v.capacity() - v.len() < more {
        let small = v.len() * std::mem::size_of::<T>() < QUARTER_FROM_BYTES;
        v.reserve_exact(more.max(if small { v.len() } else { v.len() / 4 }));
    }
}

/// The size from which [`grow`] adds a quarter: glibc maps blocks this
/// large (its threshold grows to at most 32 MiB) and moves them by
/// remapping.
const QUARTER_FROM_BYTES: usize = 32 << 20;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::plane::axis::Primitive;
    use crate::plane::medial::base_case::{LocalEdge, LocalNode};
    use crate::shape::ElementRef;

    #[test]
    fn edges_index_the_whole_list_of_nodes() {
        let node = |x: f64| LocalNode { center: Point::new(x, 0.0), radius: 1.0, kind: EventKind::Joint };
        let site = Primitive::of_element(ElementRef { loop_index: 0, element: 0 });
        let edge = LocalEdge { from: 1, to: 0, sites: [site, site], params: [(0.0, 1.0); 2], straight: false };
        let mut all = LocalAxes::default();
        assert_eq!(all.count(), 0);
        all.push(LocalAxis { nodes: vec![node(0.0), node(1.0)], edges: vec![edge], aliases: Vec::new() });
        all.push(LocalAxis { nodes: vec![node(2.0), node(3.0)], edges: vec![edge], aliases: Vec::new() });
        assert_eq!(all.count(), 2);
        let second = all.get(1);
        assert_eq!((second.nodes.len(), second.edges.len()), (2, 1));
        assert_eq!((second.edges[0].from, second.edges[0].to), (3, 2));
        assert_eq!(all.nodes[second.edges[0].from].point.x, 3.0);
        assert_eq!(second.events, [EventKind::Joint; 2]);
    }
}
