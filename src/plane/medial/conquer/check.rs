//! The result checked before it is returned (a breakdown is reported,
//! never a wrong axis): connected with one independent cycle per hole, a
//! corner node at every convex vertex, every disk maximal and touching
//! the primitives of its edges.

use crate::kernel::element::Element;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Contact, Point};
use crate::plane::axis::Primitive;
use crate::plane::axis::{AxisEdge, MedialAxis2d, NodeKind};
use crate::plane::medial::conquer::error::AxisError;
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::{JointKind, Shape2d};
use crate::util::fast_hash::{FastMap, FastSet};
use rayon::prelude::*;

/// Where along each edge (fractions of its parameter range) [`check_disks`]
/// verifies that the disk touches both primitives: the middle, and close
/// to both ends, where a wrong footpoint range shows first.
const EDGE_CHECKS: [f64; 3] = [1.0 / 64.0, 0.5, 63.0 / 64.0];

/// Where along each edge [`check_disks`] also verifies that the disk is
/// empty. One emptiness query per edge besides those of its end nodes:
/// the queries are most of the check's cost (one per node and one per
/// edge; with three per edge they were a quarter of the whole computation
/// on smooth curves). Near an end, where a wrong footpoint range shows
/// first, the contacts are checked and the end node's disk is checked for
/// emptiness.
const EMPTY_CHECK: f64 = 0.5;

/// Every node's disk and the disk in the middle of every edge must hold
/// none of the boundary (emptiness queries on the shared index, independent
/// of how the axis was built), and the disks of the nodes and at three
/// interior points of every edge must touch both primitives of the edge
/// (distance to the primitive itself), which makes them touch the boundary;
/// a node without edges must have its nearest element on its circle. A wrong
/// pair of primitives on an edge, or a node placed off its edges, shows up
/// here and is reported, not returned.
pub(crate) fn check_disks<K: AxisKernel>(finder: &DiskFinder<K>, axis: &MedialAxis2d) -> Result<(), AxisError> {
    let shape = finder.shape();
    let slack = Tolerance::new(shape.tolerance()).final_check();
    let k = finder.kernel();
    let deg = axis.degrees();
    // Every node's emptiness is checked in the walk of one of its edges
    // (the first), beside that edge's middle disk: the three disks touch
    // the boundary at the same places, so one walk of the index serves
    // them (the walks are most of the check's cost).
    let mut owner = vec![usize::MAX; axis.nodes.len()];
    for (i, e) in axis.edges.iter().enumerate() {
        for v in [e.from, e.to] {
            if owner[v] == usize::MAX {
                owner[v] = i;
            }
        }
    }
    // A node without edges (a circle's centre): empty, and touching the
    // boundary at its nearest element.
    let lone = |v: usize| {
        let n = &axis.nodes[v];
        finder.intruder(n.point, n.radius, slack).is_some()
            || finder.nearest(n.point).is_none_or(|(near, _)| {
                let e = shape.loops()[near.loop_index].element(near.element);
                k.element_contact(Disk::new(n.point, n.radius), &e, slack) != Contact::Touching
            })
    };
    if let Some(n) = (0..axis.nodes.len()).into_par_iter().find_any(|&v| deg[v] == 0 && lone(v)).map(|v| &axis.nodes[v])
    {
        return Err(AxisError::Numerical(n.point, NODE_NOT_MAXIMAL));
    }
    // Every disk of an edge, its end nodes' included, touches both of the
    // edge's primitives (a node placed where only two of a branch's three
    // primitives are touched is a maximal disk, but not that branch).
    let apart = |e: &AxisEdge, c: Point, r: f64| {
        e.sites.iter().any(|p| {
            let disk = Disk::new(c, r);
            let l = &shape.loops()[p.loop_index()];
            let contact = match *p {
                Primitive::Vertex { .. } => k.point_contact(disk, l.vertices()[p.index()].p, slack),
                Primitive::Element { .. } => k.element_contact(disk, &l.element(p.index()), slack),
            };
            contact != Contact::Touching
        })
    };
    let astray = axis.edges.par_iter().find_map_any(|e| {
        [e.from, e.to].into_iter().map(|v| &axis.nodes[v]).find(|n| apart(e, n.point, n.radius)).map(|n| n.point)
    });
    if let Some(p) = astray {
        return Err(AxisError::Numerical(p, "a node's disk misses a primitive of its edge"));
    }
    let wrong = axis.edges.par_iter().enumerate().find_map_any(|(i, e)| {
        let mut middle = None;
        for s in EDGE_CHECKS {
            match e.eval(shape, &axis.nodes, s) {
                Some(d) if apart(e, d.center, d.radius) => return Some((d.center, EDGE_NOT_MAXIMAL)),
                Some(d) if s == EMPTY_CHECK => middle = Some(d),
                Some(_) => {}
                None => return Some((axis.nodes[e.from].point, EDGE_NOT_MAXIMAL)),
            }
        }
        let middle = middle?;
        let mut disks = [(middle.center, middle.radius); 3];
        let mut count = 1;
        for v in [e.from, e.to] {
            if owner[v] == i && (v == e.from || e.to != e.from) {
                disks[count] = (axis.nodes[v].point, axis.nodes[v].radius);
                count += 1;
            }
        }
        finder.any_intruder(&disks[..count], slack).map(|(d, _, _)| match d {
            0 => (middle.center, EDGE_NOT_MAXIMAL),
            _ => (disks[d].0, NODE_NOT_MAXIMAL),
        })
    });
    match wrong {
        Some((p, what)) => Err(AxisError::Numerical(p, what)),
        None => Ok(()),
    }
}

// The middle disk checked for contacts is the one checked for emptiness
// (and the edge's nodes with it).
const _: () = assert!(EDGE_CHECKS[1] == EMPTY_CHECK);

const NODE_NOT_MAXIMAL: &str = "a node's disk is not maximal";
const EDGE_NOT_MAXIMAL: &str = "an edge's disks are not maximal";

/// Every boundary element is accounted for: a primitive of some edge, or,
/// where no edge has it (a band hugged by a disk within rounding, a leaf
/// arc, a footpoint smeared over several elements), within the final
/// check's slack of the circle of a node next to it: a node of an edge
/// whose primitive is the nearest element with edges on either side, or
/// one of the element's own two vertices. Without this, an axis
/// missing a whole branch (the disks of a small spike never computed)
/// would pass, as every disk it has is right. Measured: such elements lie
/// within 13–18τ of those circles on smooth and nearly circular curves of
/// 10^5–10^6 arcs (1–99 % of their elements).
pub(crate) fn check_coverage(shape: &Shape2d, axis: &MedialAxis2d) -> Result<(), AxisError> {
    let slack = Tolerance::new(shape.tolerance()).final_check();
    let loops = shape.loops();
    let mut marked: Vec<Vec<bool>> = loops.iter().map(|l| vec![false; l.len()]).collect();
    for e in &axis.edges {
        for p in e.sites {
            if let Some(r) = p.element() {
                marked[r.loop_index][r.element] = true;
            }
        }
    }
    // Runs of unmarked elements: (loop, first, count).
    let mut runs: Vec<(usize, usize, usize)> = Vec::new();
    for (l, m) in marked.iter().enumerate() {
        let n = m.len();
        let Some(start) = (0..n).find(|&i| m[i]) else {
            if n > 0 {
                runs.push((l, 0, n));
            }
            continue;
        };
        let mut i = 0;
        while i < n {
            let first = (start + i) % n;
            if m[first] {
                i += 1;
                continue;
            }
            let count = (i..n).take_while(|&k| !m[(start + k) % n]).count();
            runs.push((l, first, count));
            i += count;
        }
    }
    if runs.is_empty() {
        return Ok(());
    }
    // The primitives next to each run, and the nodes of their edges.
    type Key = (usize, usize, bool);
    let mut wanted: FastSet<Key> = FastSet::default();
    for &(l, first, count) in &runs {
        wanted.extend(wanted_keys(l, first, count, loops[l].len()));
    }
    let mut nodes_of: FastMap<Key, Vec<usize>> = FastMap::default();
    for e in &axis.edges {
        for p in e.sites {
            let key = (p.loop_index(), p.index(), matches!(p, Primitive::Vertex { .. }));
            if wanted.contains(&key) {
                nodes_of.entry(key).or_default().extend([e.from, e.to]);
            }
        }
    }
    // Lone nodes (circle centres) only where a whole loop has no edges.
    let lone: Vec<usize> = if runs.iter().any(|&(l, _, count)| count == loops[l].len()) {
        let deg = axis.degrees();
        (0..axis.nodes.len()).filter(|&v| deg[v] == 0).collect()
    } else {
        Vec::new()
    };
    let nodes_at = |k: Key| nodes_of.get(&k).into_iter().flatten().copied();
    let uncovered = runs.par_iter().find_map_any(|&(l, first, count)| {
        let n = loops[l].len();
        // The run's ends (or, for a loop no edge touches, a circle whose
        // centre is a lone node), and for each element its own two
        // vertices: the work stays linear in the run.
        let mut ends: Vec<usize> = if count < n {
            nodes_at((l, (first + n - 1) % n, false)).chain(nodes_at((l, (first + count) % n, false))).collect()
        } else {
            lone.clone()
        };
        ends.sort_unstable();
        ends.dedup();
        let on =
            |e: &Element, v: usize| e.circle_deviation(0.0, 1.0, axis.nodes[v].point, axis.nodes[v].radius) <= slack;
        (0..count).map(|k| (first + k) % n).find_map(|i| {
            let e = loops[l].element(i);
            let own = nodes_at((l, i, true)).chain(nodes_at((l, (i + 1) % n, true)));
            let covered = ends.iter().any(|&v| on(&e, v)) || own.into_iter().any(|v| on(&e, v));
            (!covered).then(|| e.point_at(0.5))
        })
    });
    match uncovered {
        Some(p) => Err(AxisError::Numerical(p, "a boundary element is on no disk of the axis")),
        None => Ok(()),
    }
}

/// The primitives next to a run of `count` elements from `first` on loop
/// `l` of `n` elements, as `check_coverage` keys them: the elements before
/// and after (unless the run is the whole loop) and every vertex of the run.
fn wanted_keys(l: usize, first: usize, count: usize, n: usize) -> impl Iterator<Item = (usize, usize, bool)> {
    let ends = (count < n).then(|| [(l, (first + n - 1) % n, false), (l, (first + count) % n, false)]);
    ends.into_iter().flatten().chain((0..=count.min(n - 1)).map(move |k| (l, (first + k) % n, true)))
}

/// The representative of `x` in a union-find forest (with path halving).
pub(crate) fn root(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// The axis of a shape with h holes is connected with exactly h
/// independent cycles (a tree when h = 0); anything else means the
/// subshapes were glued from inconsistent pieces, which is reported rather
/// than returned.
pub(crate) fn check_graph(axis: &MedialAxis2d, holes: usize) -> Result<(), AxisError> {
    let n = axis.nodes.len();
    let mut parent: Vec<usize> = (0..n).collect();
    let mut cycles = 0;
    for e in &axis.edges {
        let (a, b) = (root(&mut parent, e.from), root(&mut parent, e.to));
        if a == b {
            cycles += 1;
            if cycles > holes {
                return Err(AxisError::Numerical(axis.nodes[e.from].point, "the axis closed a cycle too many"));
            }
        }
        parent[a] = b;
    }
    if n > 0 && axis.edges.len() + 1 != n + holes {
        let lonely = (0..n).find(|&v| root(&mut parent, v) != root(&mut parent, 0)).unwrap_or(0);
        return Err(AxisError::Numerical(axis.nodes[lonely].point, "the axis fell apart into pieces"));
    }
    Ok(())
}

/// Every subtree of the axis ends in leaves, and on a polygon every leaf
/// is a convex corner: one corner node per convex vertex, each at its
/// vertex, is what shows that no piece of the axis went missing between
/// subshapes (the graph check cannot: the rest of a tree is a tree).
pub(crate) fn check_corners(shape: &Shape2d, axis: &MedialAxis2d) -> Result<(), AxisError> {
    let mut at: Vec<Point> = axis.nodes.iter().filter(|n| n.kind == NodeKind::Corner).map(|n| n.point).collect();
    if at.len() == shape.joint_counts()[JointKind::Convex as usize] {
        return Ok(());
    }
    // Report a convex vertex without its corner node (corners sorted by x).
    let tol = shape.tolerance();
    at.sort_by(|a, b| a.x.total_cmp(&b.x));
    let has_corner = |p: Point| {
        let first = at.partition_point(|q| q.x < p.x - tol);
        at[first..].iter().take_while(|q| q.x <= p.x + tol).any(|q| q.dist(p) <= tol)
    };
    let missing = shape.loops().iter().enumerate().find_map(|(l, lp)| {
        (0..lp.len())
            .map(|v| lp.vertices()[v].p)
            .enumerate()
            .find_map(|(v, p)| (shape.joint(l, v) == JointKind::Convex && !has_corner(p)).then_some(p))
    });
    Err(AxisError::Numerical(missing.unwrap_or_default(), "a convex corner has no axis"))
}

/// An edge's ends and sites in an order that does not depend on its
/// direction: two edges with the same key are the same stretch of axis.
pub(crate) fn undirected(e: &AxisEdge) -> (usize, usize, [Primitive; 2]) {
    if e.from <= e.to {
        (e.from, e.to, e.sites)
    } else {
        (e.to, e.from, [e.sites[1], e.sites[0]])
    }
}

/// Keeps the first edge of each [`undirected`] key among the edges marked
/// in `maybe` (in edge order; the others stay whatever their keys): the
/// caller marks every edge that can repeat another, a few of 10^6, so
/// the set stays small (a set of all keys spent most of its time in page
/// faults as it grew).
pub(crate) fn drop_repeats(edges: &mut Vec<AxisEdge>, maybe: &[bool]) {
    let mut seen = FastSet::default();
    let mut i = 0;
    edges.retain(|e| {
        i += 1;
        !maybe[i - 1] || seen.insert(undirected(e))
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plane::medial::conquer::{medial_axis, AxisOptions};
    use crate::shape::{samples, ElementRef, ShapeOptions};

    /// The check refuses an axis that is wrong in any of the ways a
    /// numerical breakdown makes it wrong, on nodes chosen all along it.
    #[test]
    fn the_check_refuses_moved_nodes_grown_disks_and_wrong_sites() {
        for loops in [samples::flower_arcs(400), samples::star_polygon(300, 3)] {
            let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
            let finder = DiskFinder::new(&shape);
            let axis = medial_axis(&shape, &AxisOptions::default()).unwrap();
            assert_eq!(check_disks(&finder, &axis), Ok(()));
            let step = shape.bbox().diagonal() * 1e-3;
            let deg = axis.degrees();
            let mut tried = 0;
            for v in (0..axis.nodes.len()).step_by(37).filter(|&v| axis.nodes[v].radius > 10.0 * step && deg[v] > 0) {
                // A node moved off the axis, along either coordinate.
                for d in [Point::new(step, 0.0), Point::new(0.0, -step)] {
                    let mut moved = axis.clone();
                    moved.nodes[v].point = moved.nodes[v].point + d;
                    assert!(check_disks(&finder, &moved).is_err(), "node {v} moved by {d:?}");
                }
                // A node's disk grown past the boundary.
                let mut grown = axis.clone();
                grown.nodes[v].radius += step;
                assert!(check_disks(&finder, &grown).is_err(), "node {v} grown");
                tried += 1;
            }
            assert!(tried >= 5, "{tried} nodes tried");
            // An edge given a primitive from across the shape.
            for i in (0..axis.edges.len()).step_by(41) {
                let mut wrong = axis.clone();
                let Some(er) = wrong.edges[i].sites[0].element() else { continue };
                let n = shape.loops()[er.loop_index].len();
                wrong.edges[i].sites[0] = Primitive::of_element(ElementRef { element: (er.element + n / 2) % n, ..er });
                assert!(check_disks(&finder, &wrong).is_err(), "edge {i} with a far site");
            }
        }
    }

    /// An axis missing the edges of some elements (the branch of a spike
    /// never computed) is refused, though every disk it keeps is right:
    /// one element's edges on a flower of long arcs and on a star, twenty
    /// elements' on a smooth curve of short arcs (a single short arc's
    /// edges are below the check's resolution there: the circles of the
    /// disks at its ends stay within the slack of it).
    #[test]
    fn the_check_refuses_an_axis_missing_the_edges_of_elements() {
        let cases = [
            (samples::flower_arcs(400), 1),
            (samples::star_polygon(300, 3), 1),
            (samples::fourier_biarcs(2000, 4), 20),
        ];
        for (loops, run) in cases {
            let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
            let axis = medial_axis(&shape, &AxisOptions::default()).unwrap();
            assert_eq!(check_coverage(&shape, &axis), Ok(()));
            let n = shape.loops()[0].len();
            let mut tried = 0;
            for k in (0..n).step_by(n / 7) {
                let mut cut = axis.clone();
                let gone = |p: &Primitive| matches!(p.element(), Some(r) if (r.element + n - k) % n < run);
                cut.edges.retain(|e| !e.sites.iter().any(gone));
                if cut.edges.len() < axis.edges.len() {
                    assert!(check_coverage(&shape, &cut).is_err(), "edges of elements {k}.. removed");
                    tried += 1;
                }
            }
            assert!(tried >= 5, "{tried}");
        }
    }
}
