//! The axis of a subshape its dividing disks hug (see
//! [`Hugged`](crate::plane::medial::decompose::subshape::Hugged)): the
//! boundary stays within a few tolerances of the disks' circles, so the
//! order of footpoints along it is rounding, and the true axis runs inside
//! a sliver where every disk is one of the dividing disks within those
//! tolerances. No contact is decided there; the axis is the ports.

use super::{EventKind, LocalAxis, LocalEdge, LocalNode};
use crate::kernel::apollonius::Site;
use crate::kernel::bisector::footpoint_param;
use crate::kernel::construct::unwrap_near;
use crate::plane::axis::Primitive;
use crate::plane::medial::decompose::subshape::{chain_hugs, BoundaryPos, ChainParts, Cut, Hugged, Piece, Subshape};
use crate::shape::{ElementRef, Shape2d};

/// The node of dividing disk `disk` (an index into `cuts`) as a port.
fn port(cuts: &[Cut], disk: usize) -> LocalNode {
    LocalNode { center: cuts[disk].center, radius: cuts[disk].radius, kind: EventKind::Port(disk as u32) }
}

/// The axis of a lobe's tip hugged by its one dividing disk `disk`: that
/// port alone, a leaf of the axis.
pub(super) fn tip_axis(cuts: &[Cut], disk: usize) -> LocalAxis {
    LocalAxis { nodes: vec![port(cuts, disk)], edges: Vec::new(), aliases: Vec::new() }
}

/// The axis of `s`, a band hugged by both its dividing disks (`h`): the
/// straight edge between its two ports, whose disks (radius linear from
/// port to port) stay within the tolerance of both chains. `None` for a
/// tip, or when a band's chains cannot be named (never for a subshape
/// [`hugged`](crate::plane::medial::decompose::subshape::hugged) returned
/// it for).
pub(super) fn band_axis(shape: &Shape2d, s: &Subshape, cuts: &[Cut], h: Hugged) -> Option<LocalAxis> {
    match h {
        Hugged::Tip(_) | Hugged::Cluster => None,
        Hugged::Band([j0, j1]) => {
            let disk = |j: usize| match s.pieces[j] {
                Piece::Aux { disk } => Some(disk),
                Piece::Chain { .. } => None,
            };
            let chain = |j: usize| match s.pieces[j % s.pieces.len()] {
                Piece::Chain { from, to } if from != to => Some((from, to)),
                _ => None,
            };
            let (d0, d1) = (disk(j0)?, disk(j1)?);
            // Chain `a` runs from port 0 to port 1 with the inside on its
            // left, so walking the axis the same way it is on the right.
            let (a, b) = (chain(j0 + 1)?, chain(j1 + 1)?);
            Some(one_straight_edge(shape, cuts, [d0, d1], [middle_element(shape, b)?, middle_element(shape, a)?]))
        }
    }
}

/// The axis of a [`Hugged::Cluster`] subshape: its ports joined in order
/// of radius by straight edges (near the end of a branch the radius falls
/// towards the end, and every disk between two of these hugs every chain
/// as both do). Each edge names the middle elements of the chains (longer
/// than a point) before and after its first port's auxiliary arc as its
/// sides. `None` when a disk cuts the subshape twice (its two ports are
/// glued elsewhere, never joined here) or a chain cannot be named.
pub(super) fn cluster_axis(shape: &Shape2d, s: &Subshape, cuts: &[Cut]) -> Option<LocalAxis> {
    let (ports, sides) = radius_path(s, cuts)?;
    path_axis(shape, cuts, &ports, &sides)
}

/// The axis of a subshape whose ports, in order of radius, make a path of
/// bands: each edge's two side chains (as [`cluster_axis`] names them)
/// stay within `slack` (model units) of both its ports' circles, while
/// other chains may stray from the far disks. Near the centre of a curve
/// within 10^-3 of a circle, a disk reaching out to the curvature centre
/// of one short, tighter arc (radius 0.75 against 0.995) touches the
/// circles of the central disks from inside where that arc lies: the
/// spoke's disks slide along one normal, every one of them touching the
/// chains on both sides of the short arc within rounding, and the base
/// case's branch point, on two nearly tangent circles, is not found.
/// The axis is the straight path; `None` where an edge's sides stray,
/// where a chain is no edge's side, or for a single port.
pub(super) fn banded_path_axis(shape: &Shape2d, s: &Subshape, cuts: &[Cut], slack: f64) -> Option<LocalAxis> {
    let (ports, sides) = radius_path(s, cuts)?;
    let bands = ports.windows(2).zip(&sides).all(|(w, chains)| {
        chains.iter().all(|&chain| w.iter().all(|&(d, _)| chain_hugs(shape, chain, cuts[d], slack)))
    });
    // Every chain a side of some edge: a lobe's tip cut off by one disk
    // (no edge) holds axis of its own out to its curvature maximum.
    let covered = s.chains().all(|c| sides.iter().any(|pair| pair.contains(&c)));
    if bands && covered && !sides.is_empty() {
        path_axis(shape, cuts, &ports, &sides)
    } else {
        None
    }
}

/// The chains on either side of a path edge, before and after its first
/// port's auxiliary arc.
type Sides = [(BoundaryPos, BoundaryPos); 2];

/// Ports as (disk, piece index) in order of radius, and the sides of the
/// edges between consecutive ones.
type RadiusPath = (Vec<(usize, usize)>, Vec<Sides>);

/// The ports of `s` in order of radius, as (disk, piece index), and for
/// each consecutive pair the chains (longer than a point) before and after
/// the first one's auxiliary arc. `None` when a disk cuts `s` twice or a
/// chain is missing.
fn radius_path(s: &Subshape, cuts: &[Cut]) -> Option<RadiusPath> {
    let m = s.pieces.len();
    // The first chain longer than a point from piece `j` on, stepping by
    // `step` (1 forward, m − 1 back).
    let chain = |j: usize, step: usize| {
        (0..m).map(|k| (j + k * step) % m).find_map(|i| match s.pieces[i] {
            Piece::Chain { from, to } if from != to => Some((from, to)),
            _ => None,
        })
    };
    let mut ports: Vec<(usize, usize)> = (0..m)
        .filter_map(|j| match s.pieces[j] {
            Piece::Aux { disk } => Some((disk, j)),
            Piece::Chain { .. } => None,
        })
        .collect();
    ports.sort_by(|a, b| cuts[a.0].radius.total_cmp(&cuts[b.0].radius).then(a.0.cmp(&b.0)));
    // One disk's arcs share a radius, so they lie next to each other.
    if ports.windows(2).any(|w| w[0].0 == w[1].0) {
        return None;
    }
    let sides = ports[..ports.len().saturating_sub(1)]
        .iter()
        .map(|&(_, j0)| Some([chain(j0 + m - 1, m - 1)?, chain(j0 + 1, 1)?]))
        .collect::<Option<Vec<Sides>>>()?;
    Some((ports, sides))
}

/// The path through `ports` by straight edges with the middle elements of
/// `sides` as their left and right.
fn path_axis(shape: &Shape2d, cuts: &[Cut], ports: &[(usize, usize)], sides: &[Sides]) -> Option<LocalAxis> {
    let mut edges = Vec::with_capacity(sides.len());
    for (k, (w, &[before, after])) in ports.windows(2).zip(sides).enumerate() {
        let (left, right) = (middle_element(shape, before)?, middle_element(shape, after)?);
        edges.push(straight_edge(shape, cuts, (k, w[0].0), (k + 1, w[1].0), [left, right]));
    }
    Some(LocalAxis { nodes: ports.iter().map(|&(d, _)| port(cuts, d)).collect(), edges, aliases: Vec::new() })
}

/// The axis of a subshape of two chains between two auxiliary arcs of
/// two dividing disks, where the base case found one node (the disks
/// within [`Tolerance::same_event`](crate::kernel::tolerance::Tolerance::same_event)
/// of each other, or chains within the tolerance of their ends, no site):
/// the straight edge between their ports, with the chains' middle
/// elements as its sides. `None` for any other subshape. Named as one
/// node instead, such leaves chained along a stretch of axis (disks cut
/// 2–4τ apart one after the other, near the centre of a curve within
/// 10^-6 of a circle) made one node of disks hundreds of tolerances apart.
pub(super) fn two_port_axis(shape: &Shape2d, s: &Subshape, cuts: &[Cut]) -> Option<LocalAxis> {
    let m = s.pieces.len();
    let aux: Vec<(usize, usize)> = (0..m)
        .filter_map(|j| match s.pieces[j] {
            Piece::Aux { disk } => Some((disk, j)),
            Piece::Chain { .. } => None,
        })
        .collect();
    let &[(d0, j0), (d1, j1)] = aux.as_slice() else { return None };
    if d0 == d1 || j1 != j0 + 2 || m != 4 {
        return None;
    }
    let middle = |j: usize| match s.pieces[j % m] {
        Piece::Chain { from, to } => middle_element(shape, (from, to)),
        Piece::Aux { .. } => None,
    };
    Some(one_straight_edge(shape, cuts, [d0, d1], [middle(j0 + 3)?, middle(j0 + 1)?]))
}

/// The axis of the two ports of dividing disks `disks` joined by one
/// straight edge with primitives `sides` on its left and right.
fn one_straight_edge(shape: &Shape2d, cuts: &[Cut], [d0, d1]: [usize; 2], sides: [Primitive; 2]) -> LocalAxis {
    LocalAxis {
        nodes: vec![port(cuts, d0), port(cuts, d1)],
        edges: vec![straight_edge(shape, cuts, (0, d0), (1, d1), sides)],
        aliases: Vec::new(),
    }
}

/// The straight edge from node `from.0` (dividing disk `from.1`) to node
/// `to.0` (disk `to.1`) with primitives `sites` on its left and right,
/// their footpoint parameters taken from the two disks.
fn straight_edge(
    shape: &Shape2d,
    cuts: &[Cut],
    from: (usize, usize),
    to: (usize, usize),
    sites: [Primitive; 2],
) -> LocalEdge {
    let (c0, c1) = (cuts[from.1], cuts[to.1]);
    // The disks hug every element of the chain, so the direction from an
    // arc's centre to theirs can be rounding (a leaf's disk is concentric
    // with one of them) and point to the far side of the circle; the
    // segment between the nodes is the geometry, the parameters only say
    // which part of the element the sides touch, so they are kept on it.
    let params = |p: Primitive| {
        let site = p.site(shape);
        let u0 = footpoint_param(&site, c0.center, c0.radius);
        let u1 = near(&site, footpoint_param(&site, c1.center, c1.radius), u0);
        (p.clamp_param(shape, u0), p.clamp_param(shape, u1))
    };
    LocalEdge { from: from.0, to: to.0, sites, params: sites.map(params), straight: true }
}

/// The element in the middle of the chain `from` → `to`: every element of
/// a hugged chain touches every disk of the band, and the middle one lies
/// wholly inside the chain wherever the chain holds three or more. A chain
/// that is only the joint between two elements (from the end of one to
/// the start of the next: no part) names the element after the joint.
fn middle_element(shape: &Shape2d, (from, to): (BoundaryPos, BoundaryPos)) -> Option<Primitive> {
    let parts = ChainParts::new(shape, from, to);
    let e = parts.iter().nth(parts.len() / 2).map_or(to.element, |(e, _, _)| e);
    Some(Primitive::of_element(ElementRef { loop_index: from.loop_index, element: e }))
}

/// An angular footpoint parameter `u` moved by whole turns next to `at`;
/// a line's parameter unchanged.
fn near(site: &Site, u: f64, at: f64) -> f64 {
    match site {
        Site::Line { .. } => u,
        Site::Point(_) | Site::Circle { .. } => unwrap_near(u, at),
    }
}
