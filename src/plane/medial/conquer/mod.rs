//! The conquer step (thesis 2.2.3–2.2.4): the axes of all subshapes glued
//! at the centres of the dividing disks into one graph.
//!
//! Each subshape's axis ends at the centres of the disks whose circles
//! carry its auxiliary arcs; those become one node per disk. A dividing
//! disk that touches only two primitives, both in the inside of their
//! elements, is no node of the true axis: its two edges lie on one conic
//! and are merged back into one.

use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Contact, FilteredKernel, Point};
use crate::plane::axis::{edge_kind, AxisEdge, AxisNode, MedialAxis2d, NodeKind, Primitive};
use crate::plane::medial::base_case::{self, BaseCaseError, EventKind, LocalAxis};
use crate::plane::medial::decompose::augment::{augment, AugmentError};
use crate::plane::medial::decompose::divide::{decompose_in, divide_into, leaf_size, Decomposition};
use crate::plane::medial::decompose::subshape::{Cut, Subshape};
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::{JointKind, Shape2d};
use rayon::prelude::*;

/// Dividing disks whose centres and radii agree within this many
/// tolerances are one disk met twice.
const SAME_DISK: f64 = 64.0;

/// Options for [`medial_axis`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisOptions {
    /// Seed of the divide step's random choices; the axis is the same for
    /// every seed up to rounding, and bit-identical for one seed whatever
    /// the thread count.
    pub seed: u64,
    /// Subshapes with at most this many original element parts are solved
    /// directly (the thesis stops at 3; larger leaves mean fewer maximal
    /// disks to grow). At least 3.
    pub leaf_parts: usize,
}

impl Default for AxisOptions {
    fn default() -> Self {
        AxisOptions { seed: 0x006d_6564_6178, leaf_parts: 32 }
    }
}

/// Why an axis could not be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum AxisError {
    /// Hole `hole` (loop index) got no augmenting disk (thesis 2.3.1):
    /// every direction tried touched more than two places, or rounding on
    /// nearly touching loops broke the order of the disks.
    Augment {
        /// Loop index of the hole.
        hole: usize,
    },
    /// A subshape's axis broke down numerically near this point (what
    /// failed, for the error message).
    Numerical(Point, &'static str),
}

impl std::fmt::Display for AxisError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            AxisError::Augment { hole } => write!(f, "hole {hole} (loop {hole}) got no augmenting maximal disk"),
            AxisError::Numerical(p, what) => {
                write!(f, "medial axis computation broke down near ({}, {}): {what}", p.x, p.y)
            }
        }
    }
}

impl std::error::Error for AxisError {}

impl From<AugmentError> for AxisError {
    fn from(e: AugmentError) -> Self {
        match e {
            AugmentError::NoDisk { hole } | AugmentError::Cycle { hole } => AxisError::Augment { hole },
        }
    }
}

impl From<BaseCaseError> for AxisError {
    fn from(e: BaseCaseError) -> Self {
        match e {
            BaseCaseError::NoDisk(p) => AxisError::Numerical(p, "no maximal disk at a joint"),
            BaseCaseError::EmptyPocket(p) => AxisError::Numerical(p, "a pocket without events"),
            BaseCaseError::Inconsistent(p) => AxisError::Numerical(p, "footpoint order inconsistent"),
            BaseCaseError::NoBranch(p) => AxisError::Numerical(p, "no branch point in a pocket"),
            BaseCaseError::Budget => AxisError::Numerical(Point::default(), "step budget exhausted"),
        }
    }
}

/// The medial axis of a shape, with any number of holes (thesis Algorithm
/// 2 on the augmented domain of 2.3.1).
///
/// Node positions and radii are in model units, accurate to a few
/// multiples of the shape's tolerance ([`Shape2d::tolerance`], by default
/// 1e-9 × the bounding-box diagonal). A numerical breakdown is an
/// [`AxisError::Numerical`], never a wrong axis: the result is checked to
/// be a tree.
///
/// ```
/// use medax::plane::{medial_axis, AxisOptions, NodeKind};
/// use medax::shape::{Shape2d, ShapeOptions};
///
/// let shape = Shape2d::from_json_str(r#"{"loops": [[[0, 0], [4, 0], [4, 2], [0, 2]]]}"#, &ShapeOptions::default())?;
/// let axis = medial_axis(&shape, &AxisOptions::default())?;
/// // A 4 x 2 rectangle: two branch points of radius 1 joined by a spine.
/// let branches: Vec<_> = axis.nodes.iter().filter(|n| n.kind == NodeKind::Branch).collect();
/// assert_eq!(branches.len(), 2);
/// assert!(branches.iter().all(|b| (b.radius - 1.0).abs() < 1e-9));
/// for edge in &axis.edges {
///     // Centres and radii along the edge, within 1e-6 of the true conic.
///     assert!(edge.sample(&shape, &axis.nodes, 1e-6).len() >= 2);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn medial_axis(shape: &Shape2d, opts: &AxisOptions) -> Result<MedialAxis2d, AxisError> {
    medial_axis_with(shape, opts, FilteredKernel)
}

/// [`medial_axis`] with every geometric question answered by `kernel`
/// (constructions, contact and emptiness decisions, orientations): the
/// algorithm is the same for every [`AxisKernel`].
pub fn medial_axis_with<K: AxisKernel>(
    shape: &Shape2d,
    opts: &AxisOptions,
    kernel: K,
) -> Result<MedialAxis2d, AxisError> {
    let finder = DiskFinder::with_kernel(shape, kernel);
    let aug = augment(&finder)?;
    // The divide step is randomized: a numerical breakdown in one
    // decomposition is retried with other random choices (derived from the
    // seed, so the result stays deterministic); the first error is
    // reported if every try fails.
    let mut first_error = None;
    for attempt in 0..RETRIES {
        let seed = opts.seed.wrapping_add(attempt.wrapping_mul(0x9e37_79b9_7f4a_7c15));
        let mut d = decompose_in(&finder, &aug, seed, opts.leaf_parts.max(3));
        let solved = solve_leaves(&finder, &mut d, seed);
        match solved
            .and_then(|locals| glue(&finder, &d.cuts, &locals))
            .and_then(|axis| check_corners(shape, &axis).and_then(|_| check_disks(&finder, &axis)).map(|_| axis))
        {
            Ok(axis) => return Ok(axis),
            Err(e) => {
                first_error.get_or_insert(e);
            }
        }
    }
    Err(first_error.unwrap_or(AxisError::Numerical(Point::default(), "no attempt")))
}

/// Decompositions tried before a numerical breakdown is reported.
const RETRIES: u64 = 3;

/// Where along each edge (fractions of its parameter range) [`check_disks`]
/// verifies the disk: the middle, and close to both ends, where a wrong
/// footpoint range shows first.
const EDGE_CHECKS: [f64; 3] = [1.0 / 64.0, 0.5, 63.0 / 64.0];

/// Every node's disk and the disks at interior points of every edge must hold
/// none of the boundary (emptiness queries on the shared index, independent
/// of how the axis was built) and touch both primitives of the edge
/// (distance to the primitive itself), which makes them touch the boundary;
/// a node without edges must have its nearest element on its circle. A wrong
/// pair of primitives on an edge, or a node placed off its edges, shows up
/// here and is reported, not returned.
fn check_disks<K: AxisKernel>(finder: &DiskFinder<K>, axis: &MedialAxis2d) -> Result<(), AxisError> {
    let shape = finder.shape();
    let slack = 64.0 * shape.tolerance();
    let k = finder.kernel();
    // Empty; that the disk touches the boundary follows from touching
    // the primitives of its edges (checked below), and for a node without
    // edges (a circle's centre) from its nearest element.
    let bad = |c: Point, r: f64| finder.intruder(c, r, slack).is_some();
    let deg = axis.degrees();
    let untouched = |v: usize| {
        let n = &axis.nodes[v];
        deg[v] == 0 && finder.nearest(n.point).is_none_or(|(_, d)| k.contact(d, n.radius, slack) != Contact::Touching)
    };
    if let Some(n) = (0..axis.nodes.len())
        .into_par_iter()
        .find_any(|&v| bad(axis.nodes[v].point, axis.nodes[v].radius) || untouched(v))
        .map(|v| &axis.nodes[v])
    {
        return Err(AxisError::Numerical(n.point, "a node's disk is not maximal"));
    }
    // Every disk of an edge, its end nodes' included, touches both of the
    // edge's primitives (a node placed where only two of a branch's three
    // primitives are touched is a maximal disk, but not that branch).
    let apart = |e: &AxisEdge, c: Point, r: f64| {
        e.sites.iter().any(|p| k.contact(p.distance(shape, c), r, slack) != Contact::Touching)
    };
    let astray = axis.edges.par_iter().find_map_any(|e| {
        [e.from, e.to].into_iter().map(|v| &axis.nodes[v]).find(|n| apart(e, n.point, n.radius)).map(|n| n.point)
    });
    if let Some(p) = astray {
        return Err(AxisError::Numerical(p, "a node's disk misses a primitive of its edge"));
    }
    let wrong = axis.edges.par_iter().find_map_any(|e| {
        EDGE_CHECKS.iter().find_map(|&s| match e.eval(shape, &axis.nodes, s) {
            Some((c, r)) if !bad(c, r) && !apart(e, c, r) => None,
            Some((c, _)) => Some(c),
            None => Some(axis.nodes[e.from].point),
        })
    });
    match wrong {
        Some(p) => Err(AxisError::Numerical(p, "an edge's disks are not maximal")),
        None => Ok(()),
    }
}

/// Rounds of [`solve_leaves`] that divide a failed leaf further.
const REFINES: usize = 3;

/// Solves every leaf and stuck subshape of `d` (in parallel); `finder`
/// indexes the shape `d` was made of. A leaf whose base case breaks down
/// numerically (rare: near-degenerate configurations such as many disks
/// alike to within a few tolerances) is divided again into leaves of half
/// its size, with random choices of its own, and those are solved; after
/// `REFINES` rounds the first breakdown is reported. New cuts are
/// appended to `d.cuts`. The order of the result depends only on `d` and
/// `seed`.
pub fn solve_leaves<K: AxisKernel>(
    finder: &DiskFinder<K>,
    d: &mut Decomposition,
    seed: u64,
) -> Result<Vec<LocalAxis>, AxisError> {
    let shape = finder.shape();
    let tol = shape.tolerance();
    let mut pending: Vec<Subshape> = std::mem::take(&mut d.leaves);
    pending.append(&mut d.stuck);
    let mut locals = Vec::with_capacity(pending.len());
    for round in 0..=REFINES {
        let results: Vec<Result<LocalAxis, BaseCaseError>> =
            pending.par_iter().map(|s| base_case::solve(shape, s, &d.cuts, tol, finder)).collect();
        let mut failed = Vec::new();
        for (s, r) in pending.into_iter().zip(results) {
            match r {
                Ok(local) => locals.push(local),
                Err(e) if round == REFINES => return Err(e.into()),
                Err(_) => failed.push(s),
            }
        }
        if failed.is_empty() {
            break;
        }
        let mut more = Decomposition { cuts: std::mem::take(&mut d.cuts), ..Decomposition::default() };
        for (i, s) in failed.into_iter().enumerate() {
            let size = leaf_size(shape, &s);
            let again = seed ^ ((round as u64) << 32 | i as u64).wrapping_mul(0x2545_f491_4f6c_dd1d);
            // Forced to cut at least once: a failed leaf of three parts is
            // retried as three-part leaves from other random disks.
            divide_into(finder, &mut more, vec![s], again, (size / 2).max(3).min(size.saturating_sub(1)));
        }
        d.cuts = more.cuts;
        pending = more.leaves;
        pending.append(&mut more.stuck);
    }
    Ok(locals)
}

/// Glues the axes of the subshapes (`locals`) at the centres of the
/// dividing disks `cuts`; `finder` indexes the shape they were made of.
pub fn glue<K: AxisKernel>(
    finder: &DiskFinder<K>,
    cuts: &[Cut],
    locals: &[LocalAxis],
) -> Result<MedialAxis2d, AxisError> {
    let shape = finder.shape();
    let tol = shape.tolerance();
    let mut nodes: Vec<AxisNode> = Vec::new();
    let mut port_node: Vec<Option<usize>> = vec![None; cuts.len()];
    // Dividing disks found by sliding (maxdisk*) agree to about 1e-8 of
    // the diagonal; disks closer than this are one node.
    let same_as = coinciding_cuts(cuts, SAME_DISK * tol);
    let mut edges: Vec<AxisEdge> = Vec::new();
    let mut is_port: Vec<bool> = Vec::new();
    let mut is_joint: Vec<bool> = Vec::new();
    for local in locals {
        let ids: Vec<usize> = local
            .nodes
            .iter()
            .map(|n| {
                let make = |nodes: &mut Vec<AxisNode>, is_port: &mut Vec<bool>, port: bool| {
                    // Kinds are settled from the degrees once all is glued.
                    nodes.push(AxisNode { point: n.center, radius: n.radius, kind: NodeKind::Joint });
                    is_port.push(port);
                    nodes.len() - 1
                };
                match n.kind {
                    EventKind::Port(c) => {
                        *port_node[same_as[c]].get_or_insert_with(|| make(&mut nodes, &mut is_port, true))
                    }
                    _ => {
                        let id = make(&mut nodes, &mut is_port, false);
                        is_joint.resize(id + 1, false);
                        is_joint[id] = n.kind == EventKind::Joint;
                        id
                    }
                }
            })
            .collect();
        for e in &local.edges {
            edges.push(AxisEdge {
                from: ids[e.from],
                to: ids[e.to],
                sites: e.sites,
                params: e.params,
                kind: edge_kind(shape, e.sites[0], e.sites[1]),
            });
        }
    }
    // Two subshapes that both hold the same stretch of axis (between two
    // disks met twice) give the same edge twice: keep one.
    let mut seen: std::collections::HashSet<(usize, usize, [Primitive; 2])> = std::collections::HashSet::new();
    edges.retain(|e| {
        let (a, b, s) = if e.from <= e.to { (e.from, e.to, e.sites) } else { (e.to, e.from, [e.sites[1], e.sites[0]]) };
        e.from != e.to && seen.insert((a, b, s))
    });
    let mut axis = MedialAxis2d { nodes, edges };
    is_joint.resize(axis.nodes.len(), false);
    merge_pass_through(shape, &mut axis, &is_port, &is_joint);
    classify(&mut axis, tol);
    merge_coinciding_branches(shape, &mut axis, SAME_DISK * tol);
    classify(&mut axis, tol);
    polish_branches(finder.kernel(), shape, &mut axis);
    check_graph(&axis, shape.loops().len() - 1)?;
    Ok(axis)
}

/// The representative of `x` in a union-find forest (with path halving).
fn root(parent: &mut [usize], mut x: usize) -> usize {
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
fn check_graph(axis: &MedialAxis2d, holes: usize) -> Result<(), AxisError> {
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
fn check_corners(shape: &Shape2d, axis: &MedialAxis2d) -> Result<(), AxisError> {
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

/// For each dividing disk, the first one that is the same disk (centre and
/// radius within `tol`): the divide step can meet one disk twice, from two
/// sides, and both must be one node.
fn coinciding_cuts(cuts: &[Cut], tol: f64) -> Vec<usize> {
    use std::collections::HashMap;
    let cell = |x: f64| (x / (4.0 * tol)).floor() as i64;
    let mut grid: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    let mut out = Vec::with_capacity(cuts.len());
    for (i, c) in cuts.iter().enumerate() {
        let (gx, gy) = (cell(c.center.x), cell(c.center.y));
        let found = (-1..=1)
            .flat_map(|dx| (-1..=1).map(move |dy| (gx + dx, gy + dy)))
            .filter_map(|k| grid.get(&k))
            .flatten()
            .copied()
            .find(|&j| cuts[j].center.dist(c.center) <= tol && (cuts[j].radius - c.radius).abs() <= tol);
        match found {
            Some(j) => out.push(j),
            None => {
                grid.entry((gx, gy)).or_default().push(i);
                out.push(i);
            }
        }
    }
    out
}

/// Same unordered pair of primitives.
fn same_pair(a: [Primitive; 2], b: [Primitive; 2]) -> bool {
    a == b || a == [b[1], b[0]]
}

/// Removes dividing-disk nodes that only pass an edge through, merging the
/// two edges, and compacts the node list.
fn merge_pass_through(shape: &Shape2d, axis: &mut MedialAxis2d, is_port: &[bool], is_joint: &[bool]) {
    let n = axis.nodes.len();
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, e) in axis.edges.iter().enumerate() {
        at[e.from].push(i);
        at[e.to].push(i);
    }
    let mut alive = vec![true; axis.edges.len()];
    let mut keep = vec![true; n];
    for v in 0..n {
        if !is_port[v] && !is_joint[v] {
            continue;
        }
        let live: Vec<usize> = at[v].iter().copied().filter(|&i| alive[i]).collect();
        if live.len() != 2 || live[0] == live[1] {
            continue;
        }
        let (mut e1, mut e2) = (axis.edges[live[0]], axis.edges[live[1]]);
        if !same_pair(e1.sites, e2.sites) {
            continue;
        }
        // A joint with the same pair on both sides: only where a point
        // site's fan was cut (base_case::POINT_SPLITS); other joints stay.
        let point_site = |p: &Primitive| matches!(*p, Primitive::Vertex { loop_index, .. } if shape.kind(loop_index) == crate::shape::LoopKind::Point);
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
                Primitive::Element(_) => stop,
            }
        };
        let merged = AxisEdge {
            from: e1.from,
            to: e2.to,
            sites: e1.sites,
            params: [(e1.params[0].0, on(0)), (e1.params[1].0, on(1))],
            kind: e1.kind,
        };
        alive[live[1]] = false;
        axis.edges[live[0]] = merged;
        keep[v] = false;
        // The far end of e2 now sees the merged edge.
        for end in [merged.from, merged.to] {
            for slot in at[end].iter_mut() {
                if *slot == live[1] {
                    *slot = live[0];
                }
            }
        }
    }
    let mut new_id = vec![usize::MAX; n];
    let mut nodes = Vec::new();
    for v in 0..n {
        if keep[v] {
            new_id[v] = nodes.len();
            nodes.push(axis.nodes[v]);
        }
    }
    let edges = axis
        .edges
        .iter()
        .zip(&alive)
        .filter(|(_, &a)| a)
        .map(|(e, _)| AxisEdge { from: new_id[e.from], to: new_id[e.to], ..*e })
        .collect();
    axis.nodes = nodes;
    axis.edges = edges;
}

/// Multi-branching (thesis 2.2.2.2): a disk touching m ≥ 4 primitives is
/// one node of valency m. Where the m contacts are cocircular only within
/// rounding (the centre of a shape with m-fold symmetry), the base cases
/// find several branch points a few tolerances apart, joined by edges of
/// that length: branch nodes joined by an edge whose disks agree within
/// `tol` (centre and radius) are one node, the one of them (a disk that
/// was constructed, not an average that would touch nothing) that best
/// touches all the primitives of their other edges.
fn merge_coinciding_branches(shape: &Shape2d, axis: &mut MedialAxis2d, tol: f64) {
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
    let prims = primitives_at(axis, |k| !inner[k], |v| root(&mut parent, v));
    let misfit = |v: usize, ps: &[Primitive]| {
        let node = &axis.nodes[v];
        ps.iter().map(|p| (p.distance(shape, node.point) - node.radius).abs()).fold(0.0, f64::max)
    };
    let mut best: Vec<Option<(f64, usize)>> = vec![None; n];
    for v in 0..n {
        let g = root(&mut parent, v);
        let m = misfit(v, &prims[g]);
        if best[g].is_none_or(|(bm, _)| m < bm) {
            best[g] = Some((m, v));
        }
    }
    let fits = |g: usize| best[g].is_some_and(|(m, _)| m <= 0.5 * tol);
    let mut new_id = vec![usize::MAX; n];
    let mut kept = Vec::new();
    for (v, id) in new_id.iter_mut().enumerate() {
        let g = root(&mut parent, v);
        let alone = !fits(g);
        if alone || g == v {
            *id = kept.len();
            kept.push(axis.nodes[if alone { v } else { best[g].map_or(v, |b| b.1) }]);
        }
    }
    let mut edges = Vec::with_capacity(axis.edges.len());
    for (e, &i) in axis.edges.iter().zip(&inner) {
        let (ga, gb) = (root(&mut parent, e.from), root(&mut parent, e.to));
        if i && fits(ga) {
            continue;
        }
        let id = |v: usize, g: usize| if fits(g) { new_id[g] } else { new_id[v] };
        edges.push(AxisEdge { from: id(e.from, ga), to: id(e.to, gb), ..*e });
    }
    axis.edges = edges;
    axis.nodes = kept;
}

/// The primitives of the edges `keep(edge index)` at each of their ends,
/// gathered at `group(node)` (each primitive once, in edge order).
fn primitives_at(
    axis: &MedialAxis2d,
    keep: impl Fn(usize) -> bool,
    mut group: impl FnMut(usize) -> usize,
) -> Vec<Vec<Primitive>> {
    let mut prims: Vec<Vec<Primitive>> = vec![Vec::new(); axis.nodes.len()];
    for (_, e) in axis.edges.iter().enumerate().filter(|(k, _)| keep(*k)) {
        for v in [e.from, e.to] {
            let g = group(v);
            for p in e.sites {
                if !prims[g].contains(&p) {
                    prims[g].push(p);
                }
            }
        }
    }
    prims
}

/// The edge walked the other way.
fn reversed(e: AxisEdge) -> AxisEdge {
    AxisEdge {
        from: e.to,
        to: e.from,
        sites: [e.sites[1], e.sites[0]],
        params: [(e.params[1].1, e.params[1].0), (e.params[0].1, e.params[0].0)],
        kind: e.kind,
    }
}

/// Branch points that are dividing disks come from `maxdisk*`'s slide,
/// accurate to about 1e-8 of the diagonal; the disk tangent to three of
/// the node's primitives (Apollonius) is accurate to rounding. Replaced
/// when the two agree to within 1e-6 of the disk's radius and the new disk
/// fits every primitive of the node (otherwise the triples are
/// ill-conditioned and the slide's disk stays).
fn polish_branches(kernel: &impl AxisKernel, shape: &Shape2d, axis: &mut MedialAxis2d) {
    let prims = primitives_at(axis, |_| true, |v| v);
    for (node, ps) in axis.nodes.iter_mut().zip(&prims) {
        if node.kind != NodeKind::Branch || ps.len() < 3 {
            continue;
        }
        // Of the disks tangent to three of the node's primitives (every
        // triple of the first eight), the one nearest to fitting them all.
        let sites: Vec<_> = ps.iter().take(8).map(|p| p.site(shape)).collect();
        let misfit = |c: Point, r: f64| ps.iter().map(|p| p.site(shape).defect(c, r).abs()).fold(0.0, f64::max);
        let near = |c: Point, r: f64| {
            c.dist(node.point) <= 1e-6 * node.radius && (r - node.radius).abs() <= 1e-6 * node.radius
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
    }
}

/// Node kinds from the final degrees. An end whose disk is within the
/// tolerance `tol` of radius 0 is a convex corner (a dividing disk that
/// small, in a needle's tip, is that corner's node).
fn classify(axis: &mut MedialAxis2d, tol: f64) {
    let deg = axis.degrees();
    for (v, node) in axis.nodes.iter_mut().enumerate() {
        node.kind = if node.radius == 0.0 || (deg[v] <= 1 && node.radius <= tol) {
            NodeKind::Corner
        } else if deg[v] >= 3 {
            NodeKind::Branch
        } else if deg[v] <= 1 {
            NodeKind::Leaf
        } else {
            NodeKind::Joint
        };
    }
}
