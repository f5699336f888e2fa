//! Graph surgery on the glued axis: a dividing disk that only passes an
//! edge through is no node (its two edges lie on one conic and become one),
//! branch points a few tolerances apart are one node of higher valency
//! (multi-branching), and branch points found by sliding are replaced by
//! the tritangent disk where the two agree.

use crate::kernel::tolerance::Tolerance;
use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Point};
use crate::plane::axis::{AxisEdge, MedialAxis2d, NodeKind, Primitive};
use crate::plane::medial::conquer::check::root;
use crate::shape::Shape2d;
use crate::util::fast_hash::FastMap;
use rayon::prelude::*;

/// Same unordered pair of primitives.
fn same_pair(a: [Primitive; 2], b: [Primitive; 2]) -> bool {
    a == b || a == [b[1], b[0]]
}

/// Removes dividing-disk nodes that only pass an edge through, merging the
/// two edges, and compacts the node list.
pub(crate) fn merge_pass_through(shape: &Shape2d, axis: &mut MedialAxis2d, is_port: &[bool], is_joint: &[bool]) {
    let n = axis.nodes.len();
    let mut at = Incidence::of(axis);
    let mut alive = vec![true; axis.edges.len()];
    let mut keep = vec![true; n];
    for v in 0..n {
        if !is_port[v] && !is_joint[v] {
            continue;
        }
        // Exactly two live edges, without a vector per node.
        let live = {
            let mut live_edges = at.of_node(v).filter(|&i| alive[i]);
            match (live_edges.next(), live_edges.next(), live_edges.next()) {
                (Some(a), Some(b), None) if a != b => [a, b],
                _ => continue,
            }
        };
        let (mut e1, mut e2) = (axis.edges[live[0]], axis.edges[live[1]]);
        // A straight edge across a hugged band stays apart from a conic.
        if !same_pair(e1.sites, e2.sites) || e1.straight != e2.straight {
            continue;
        }
        // A joint with the same pair on both sides: only where a point
        // site's fan was cut (base_case::POINT_SPLITS); other joints stay.
        let point_site = |p: &Primitive| matches!(*p, Primitive::Vertex { .. } if shape.kind(p.loop_index()) == crate::shape::LoopKind::Point);
        if !is_port[v] && !e1.sites.iter().any(point_site) {
            continue;
        }
        // Orient e1 into v and e2 out of v, with e2's sites in e1's order.
        if e1.to != v {
            e1 = reversed(e1);
        }
        if e2.from != v {
            e2 = reversed(e2);
        }
        if e1.sites != e2.sites {
            // Left and right swapped: the walk turned back (never on a
            // valid axis); leave the node in place.
            continue;
        }
        // Angles (a vertex's or an arc's parameter) go on from e1 to e2
        // without a jump of a whole turn: a point site's own augmenting
        // disk sits where its fan's angles wrap round.
        let on = |k: usize| {
            let (end, start, stop) = (e1.params[k].1, e2.params[k].0, e2.params[k].1);
            match e1.sites[k] {
                Primitive::Vertex { .. } => {
                    let turns = ((end - start) / std::f64::consts::TAU).round() * std::f64::consts::TAU;
                    stop + turns
                }
                Primitive::Element { .. } => stop,
            }
        };
        let merged = AxisEdge {
            from: e1.from,
            to: e2.to,
            sites: e1.sites,
            params: [(e1.params[0].0, on(0)), (e1.params[1].0, on(1))],
            kind: e1.kind,
            straight: e1.straight,
        };
        alive[live[1]] = false;
        axis.edges[live[0]] = merged;
        keep[v] = false;
        // The far end of e2 now sees the merged edge.
        for end in [merged.from, merged.to] {
            for slot in at.of_node_mut(end) {
                if *slot as usize == live[1] {
                    *slot = live[0] as u32;
                }
            }
        }
    }
    compact(axis, |v| keep[v].then_some(v), |i, _| alive[i]);
}

/// Compacts `axis` in place (fresh memory costs more than the work here on
/// 10^6 nodes): node `v` stays when `source(v)` is `Some(w)`, taking node
/// `w`'s disk (`w ≥ v`, not yet moved); the others go, and each edge `i`
/// with `keep_edge(i, edge)` stays, its ends renumbered (the ends of a
/// kept edge must stay).
pub(crate) fn compact(
    axis: &mut MedialAxis2d,
    mut source: impl FnMut(usize) -> Option<usize>,
    mut keep_edge: impl FnMut(usize, &AxisEdge) -> bool,
) {
    let n = axis.nodes.len();
    let mut new_id = vec![usize::MAX; n];
    let mut kept = 0;
    for (v, id) in new_id.iter_mut().enumerate() {
        if let Some(w) = source(v) {
            debug_assert!(w >= v);
            *id = kept;
            axis.nodes[kept] = axis.nodes[w];
            kept += 1;
        }
    }
    axis.nodes.truncate(kept);
    let mut i = 0;
    axis.edges.retain_mut(|e| {
        i += 1;
        keep_edge(i - 1, e) && {
            e.from = new_id[e.from];
            e.to = new_id[e.to];
            true
        }
    });
}

/// The edges at each node, in one array (compressed rows): a vector per
/// node cost more to allocate and free than the merge itself on 10^6
/// nodes.
pub(crate) struct Incidence {
    /// Node v's edges are `edges[start[v]..start[v + 1]]` (32-bit: half
    /// the memory traffic of these passes over 10^6 nodes; the axis's own
    /// ids are 32-bit too).
    start: Vec<u32>,
    edges: Vec<u32>,
}

impl Incidence {
    /// Each edge of `axis` listed at both ends, in edge order (a loop
    /// twice at its node).
    pub(crate) fn of(axis: &MedialAxis2d) -> Incidence {
        let n = axis.nodes.len();
        let mut start = vec![0u32; n + 1];
        for e in &axis.edges {
            start[e.from + 1] += 1;
            start[e.to + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut edges = vec![0u32; start[n] as usize];
        for (i, e) in axis.edges.iter().enumerate() {
            for v in [e.from, e.to] {
                edges[fill[v] as usize] = i as u32;
                fill[v] += 1;
            }
        }
        Incidence { start, edges }
    }

    /// The edges at node `v`.
    pub(crate) fn of_node(&self, v: usize) -> impl Iterator<Item = usize> + '_ {
        self.edges[self.start[v] as usize..self.start[v + 1] as usize].iter().map(|&i| i as usize)
    }

    fn of_node_mut(&mut self, v: usize) -> &mut [u32] {
        &mut self.edges[self.start[v] as usize..self.start[v + 1] as usize]
    }
}

/// Multi-branching (thesis 2.2.2.2): a disk touching m ≥ 4 primitives is
/// one node of valency m. Where the m contacts are cocircular only within
/// rounding (the centre of a shape with m-fold symmetry), the base cases
/// find several branch points a few tolerances apart, joined by edges of
/// that length: branch nodes joined by an edge whose disks agree within
/// `tol` (centre and radius) are one node, the one of them (a disk that
/// was constructed, not an average that would touch nothing) that best
/// touches all the primitives of their other edges.
pub(crate) fn merge_coinciding_branches(shape: &Shape2d, axis: &mut MedialAxis2d, t: Tolerance) {
    let tol = t.same_disk();
    let n = axis.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    let nodes = &axis.nodes;
    let close = |a: usize, b: usize| {
        let (p, q) = (&nodes[a], &nodes[b]);
        p.kind == NodeKind::Branch
            && q.kind == NodeKind::Branch
            && p.point.dist(q.point) <= tol
            && (p.radius - q.radius).abs() <= tol
    };
    let inner: Vec<bool> = axis.edges.iter().map(|e| close(e.from, e.to)).collect();
    if !inner.contains(&true) {
        return;
    }
    for (e, _) in axis.edges.iter().zip(&inner).filter(|(_, &i)| i) {
        let (a, b) = (root(&mut parent, e.from), root(&mut parent, e.to));
        parent[a.max(b)] = a.min(b);
    }
    // The group's node is the member whose disk fits every primitive of
    // the group's outer edges best; a group that no member fits within
    // half the final check's slack stays apart.
    // Only groups of two or more nodes (ends of inner edges) are looked at.
    let group: Vec<usize> = (0..n).map(|v| root(&mut parent, v)).collect();
    let mut grouped = vec![false; n];
    for (e, _) in axis.edges.iter().zip(&inner).filter(|(_, &i)| i) {
        grouped[e.from] = true;
        grouped[e.to] = true;
    }
    let mut prims: FastMap<usize, Vec<Primitive>> = FastMap::default();
    for (e, _) in axis.edges.iter().zip(&inner).filter(|(_, &i)| !i) {
        for v in [e.from, e.to].into_iter().filter(|&v| grouped[v]) {
            let ps = prims.entry(group[v]).or_default();
            for p in e.sites {
                if !ps.contains(&p) {
                    ps.push(p);
                }
            }
        }
    }
    let misfit = |v: usize, ps: &[Primitive]| {
        let node = &axis.nodes[v];
        ps.iter().map(|p| (p.distance(shape, node.point) - node.radius).abs()).fold(0.0, f64::max)
    };
    let mut best: FastMap<usize, (f64, usize)> = FastMap::default();
    for v in (0..n).filter(|&v| grouped[v]) {
        let g = group[v];
        let m = misfit(v, prims.get(&g).map_or(&[][..], Vec::as_slice));
        if best.get(&g).is_none_or(|&(bm, _)| m < bm) {
            best.insert(g, (m, v));
        }
    }
    let fits = |g: usize| best.get(&g).is_some_and(|&(m, _)| m <= t.branch_group_fit());
    // A fitting group's edges end at its root (its smallest member), which
    // takes the disk of its best member (a later one or itself).
    let home = |v: usize| if fits(group[v]) { group[v] } else { v };
    for (e, &i) in axis.edges.iter_mut().zip(&inner) {
        if !(i && fits(group[e.from])) {
            e.from = home(e.from);
            e.to = home(e.to);
        }
    }
    compact(
        axis,
        |v| {
            let g = group[v];
            if !fits(g) {
                Some(v)
            } else {
                (g == v).then(|| best.get(&g).map_or(v, |b| b.1))
            }
        },
        // An edge inside a fitting group goes (its ends were left as they
        // were, and a kept edge's remapped ends are their own group's).
        |i, e| !(inner[i] && fits(group[e.from])),
    );
}

/// The edge walked the other way.
fn reversed(e: AxisEdge) -> AxisEdge {
    AxisEdge {
        from: e.to,
        to: e.from,
        sites: [e.sites[1], e.sites[0]],
        params: [(e.params[1].1, e.params[1].0), (e.params[0].1, e.params[0].0)],
        kind: e.kind,
        straight: e.straight,
    }
}

/// Branch points that are dividing disks come from `maxdisk*`'s slide,
/// accurate to about 1e-8 of the diagonal; the disk tangent to three of
/// the node's primitives (Apollonius) is accurate to rounding. Replaced
/// when the two agree to within 1e-6 of the disk's radius and the new disk
/// fits every primitive of the node (otherwise the triples are
/// ill-conditioned and the slide's disk stays).
pub(crate) fn polish_branches(kernel: &impl AxisKernel, shape: &Shape2d, axis: &mut MedialAxis2d) {
    let at = Incidence::of(axis);
    let edges = &axis.edges;
    axis.nodes.par_iter_mut().enumerate().for_each(|(v, node)| {
        if node.kind != NodeKind::Branch {
            return;
        }
        // The node's primitives, each once, in edge order.
        let mut ps: Vec<Primitive> = Vec::new();
        for p in at.of_node(v).flat_map(|i| edges[i].sites) {
            if !ps.contains(&p) {
                ps.push(p);
            }
        }
        if ps.len() < 3 {
            return;
        }
        // Of the disks tangent to three of the node's primitives (every
        // triple of the first eight), the one nearest to fitting them all.
        let sites: Vec<_> = ps.iter().take(8).map(|p| p.site(shape)).collect();
        let misfit = |c: Point, r: f64| ps.iter().map(|p| p.site(shape).defect(c, r).abs()).fold(0.0, f64::max);
        let near = |c: Point, r: f64| {
            let reach = Tolerance::polish_reach() * node.radius;
            c.dist(node.point) <= reach && (r - node.radius).abs() <= reach
        };
        let mut best: Option<(f64, Point, f64)> = None;
        for i in 0..sites.len() {
            for j in i + 1..sites.len() {
                for k in j + 1..sites.len() {
                    for Disk { center: c, radius: r } in kernel.tritangent_disks([sites[i], sites[j], sites[k]]) {
                        let m = misfit(c, r);
                        if near(c, r) && best.is_none_or(|b| m < b.0) {
                            best = Some((m, c, r));
                        }
                    }
                }
            }
        }
        // All of the node's primitives must fit the new disk (a node of
        // four or more primitives cocircular only within the tolerance
        // keeps its own).
        if let Some((m, c, r)) = best {
            if m <= shape.tolerance() {
                node.point = c;
                node.radius = r;
            }
        }
    });
}
