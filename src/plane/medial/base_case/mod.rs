//! The medial axis of one subshape, computed directly (thesis 2.2.1 "Base
//! cases" and 2.2.3).
//!
//! The thesis enumerates thirteen base cases (Figures 2.3, 2.4) and writes
//! down each one's axis. Here one procedure covers all of them, and any
//! other small subshape: the boundary is a cycle of primitives (element
//! pieces, and reflex vertices as the zero-length arcs of the thesis, whose
//! positions are the directions of their fans of normals), separated by
//! joints or by auxiliary arcs.
//!
//! 1. Every place where the axis must have a node whose disk is known
//!    without search is an *event*: each auxiliary arc's dividing disk, each
//!    convex corner (radius 0), each smooth joint and each end of a reflex
//!    fan (the maximal disk grown there, where the pair defining the axis
//!    changes), and each arc whose own circle is maximal (Observation 5).
//! 2. Between two consecutive footpoints of one event disk lies a *pocket*
//!    of the boundary, and the axis leaves the disk once into it. Walking
//!    into the pocket from both ends, the first footpoints of other events
//!    met belong to one disk exactly when the axis runs straight to it: an
//!    edge between the primitives on the pocket's two sides. Otherwise a
//!    branch point lies between; it touches those two primitives and one
//!    in the middle of the pocket, so it is the one empty Apollonius disk
//!    of such a triple whose contacts lie in the right places. It becomes
//!    an event and the pocket is walked again.
//!
//! Maximal disks never cross each other's footpoint order, which is what
//! makes the walk correct; Observation 4 (auxiliary arcs hold no footpoints
//! of other maximal disks) is why only original primitives are searched.
//! The cost is O(k²) for k primitives, which the divide step keeps tiny.

use crate::kernel::tolerance::Tolerance;
use crate::kernel::{AxisKernel, Point};
use crate::plane::axis::Primitive;
use crate::plane::medial::decompose::subshape::{hugged, ChainParts, Cut, Hugged, Piece, Subshape};
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::JointKind;
use crate::shape::Shape2d;

mod branch;
mod cycle;
mod events;
mod foot_index;
mod hug_runs;
mod hugged;
mod port;
mod prepare;
mod sites;
mod walk;

use events::Event;
use hugged::{band_axis, banded_path_axis, cluster_axis, tip_axis, two_port_axis};
use port::Port;
use sites::{Key, LocalSite};

/// The directions (angles) where a point site's fan is cut into sites of
/// at most a quarter turn: fixed, so that every subshape holding part of
/// the fan cuts it at the same places.
const POINT_SPLITS: [f64; 4] = [-std::f64::consts::FRAC_PI_2, 0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI];

/// Where an event comes from (it decides the node kind).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// The dividing disk with this index (into the divide step's cuts;
    /// 32 bits: there is one of these per subshape node, 3·10^6 at 10^6
    /// elements, and fewer than 2^32 disks).
    Port(u32),
    /// A convex corner.
    Corner,
    /// A smooth joint or the end of a reflex fan.
    Joint,
    /// An arc's own maximal circle.
    Leaf,
    /// A disk found by the Apollonius construction.
    Branch,
}

/// A node of a subshape's axis.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalNode {
    /// Centre, model units.
    pub center: Point,
    /// Radius, model units.
    pub radius: f64,
    /// Origin.
    pub kind: EventKind,
}

/// An edge of a subshape's axis: node indices, the primitive on each side
/// (left first, walking `from` → `to`) and the footpoint parameters on
/// each at both ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LocalEdge {
    /// Start node.
    pub from: usize,
    /// End node.
    pub to: usize,
    /// Left and right primitive.
    pub sites: [Primitive; 2],
    /// (parameter at `from`, at `to`) per primitive.
    pub params: [(f64, f64); 2],
    /// The straight segment between the two nodes stands for the conic,
    /// the radius going linearly from node to node: across a band its
    /// disks hug, where the conic is ill-conditioned (nearly cocircular
    /// primitives) and strays from the segment by less than the tolerance.
    pub straight: bool,
}

/// The axis of one subshape.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LocalAxis {
    /// Nodes.
    pub nodes: Vec<LocalNode>,
    /// Edges.
    pub edges: Vec<LocalEdge>,
    /// The subshape's dividing disks that no node names, each with the
    /// disk of the port node that stands for it (`[omitted, named]`): a
    /// sliver between disks a few tolerances apart has one node for all
    /// of them, and gluing must join what the leaf joined, however far
    /// apart its own test of coinciding disks would put them.
    pub aliases: Vec<Alias>,
}

/// A dividing disk of a subshape that its axis names by another's node.
#[derive(Debug, Clone, PartialEq)]
pub struct Alias {
    /// `[omitted, named]`.
    pub disks: [usize; 2],
    /// Where the subshape lies between just those two disks: its axis as
    /// the straight edge between their ports, which gluing takes instead
    /// where making the two one node would stretch a node over more than
    /// [`Tolerance::same_disk`](crate::kernel::tolerance::Tolerance::same_disk)
    /// (leaves cut 2–4τ apart one after the other along a stretch of
    /// axis, near the centre of a curve within 10^-6 of a circle, named
    /// disks hundreds of tolerances apart as one).
    pub bridge: Option<LocalAxis>,
}

/// Why a subshape's axis could not be computed (a numerical breakdown;
/// never expected on a validated shape).
#[derive(Debug, Clone, PartialEq)]
pub enum BaseCaseError {
    /// No disk could be grown at a joint.
    NoDisk(Point),
    /// A pocket of the boundary held no event.
    EmptyPocket(Point),
    /// Two events are neighbours on the cycle but a primitive lies between
    /// them without a joint event.
    Inconsistent(Point),
    /// No valid branch point was found in a pocket.
    NoBranch(Point),
    /// The walk did not finish within its step budget.
    Budget,
}

/// Solves one subshape. `cuts` are the divide step's dividing disks (the
/// auxiliary arcs refer to them); `tol` is the contact tolerance.
/// `finder` is the whole shape's maximal-disk index: branch points are
/// also checked to be empty for the whole shape.
pub fn solve<K: AxisKernel>(
    shape: &Shape2d,
    s: &Subshape,
    cuts: &[Cut],
    tol: f64,
    finder: &DiskFinder<K>,
) -> Result<LocalAxis, BaseCaseError> {
    solve_unaliased(shape, s, cuts, tol, finder).map(|mut local| {
        local.aliases = aliases(s, cuts, &local);
        if let [alias] = local.aliases.as_mut_slice() {
            alias.bridge = two_port_axis(shape, s, cuts);
        }
        local
    })
}

/// The dividing disks of `s` that `local` has no port node for, each with
/// the port node whose centre is nearest its own.
fn aliases(s: &Subshape, cuts: &[Cut], local: &LocalAxis) -> Vec<Alias> {
    let named: Vec<usize> = local
        .nodes
        .iter()
        .filter_map(|n| match n.kind {
            EventKind::Port(d) => Some(d as usize),
            _ => None,
        })
        .collect();
    s.pieces
        .iter()
        .filter_map(|p| match *p {
            Piece::Aux { disk } if !named.contains(&disk) => named
                .iter()
                .min_by(|&&a, &&b| {
                    cuts[a].center.dist(cuts[disk].center).total_cmp(&cuts[b].center.dist(cuts[disk].center))
                })
                .map(|&to| Alias { disks: [disk, to], bridge: None }),
            _ => None,
        })
        .collect()
}

fn solve_unaliased<K: AxisKernel>(
    shape: &Shape2d,
    s: &Subshape,
    cuts: &[Cut],
    tol: f64,
    finder: &DiskFinder<K>,
) -> Result<LocalAxis, BaseCaseError> {
    let tol = Tolerance::new(tol);
    let hug = hugged(shape, s, cuts, tol.hugged_tip());
    if let Some(Hugged::Tip(disk)) = hug {
        // The tip of a lobe cut at nearly its osculating circle: its true
        // axis runs on inside a sliver a few tolerances thin, where the
        // order of footpoints is rounding rather than geometry, and every
        // disk there is this one within those tolerances. The disk is the
        // tip's whole axis, a leaf. A needle's tip cut a few tolerances
        // from its convex vertex is walked all the same: the vertex is a
        // corner node of the axis (a disk of 2.5·10^-7 from the tip of a
        // random star's spike hugged it, and its corner went missing).
        if !holds_convex_vertex(shape, s) {
            return Ok(tip_axis(cuts, disk));
        }
        return walk_leaf(shape, s, cuts, tol, finder).or_else(|_| Ok(tip_axis(cuts, disk)));
    }
    // A band between two disks that both hug it is solved like any leaf,
    // and where the footpoint order (rounding there) leaves no consistent
    // walk, its axis is the straight edge between the ports, within the
    // tolerance of the true one; so is a path of such bands.
    walk_leaf(shape, s, cuts, tol, finder).or_else(|e| match hug {
        Some(band @ Hugged::Band(_)) => band_axis(shape, s, cuts, band).ok_or(e),
        Some(Hugged::Cluster) => cluster_axis(shape, s, cuts).ok_or(e),
        Some(Hugged::Tip(_)) => Err(e),
        None => banded_path_axis(shape, s, cuts, tol.hugged_tip()).ok_or(e),
    })
}

/// Whether a convex vertex lies inside one of `s`'s chains or where two
/// of its chains meet (at the loop's start, where the first chain of a
/// whole loop ends).
fn holds_convex_vertex(shape: &Shape2d, s: &Subshape) -> bool {
    let convex = |l: usize, v: usize| shape.joint(l, v) == JointKind::Convex;
    let m = s.pieces.len();
    (0..m).any(|j| match (s.pieces[j], s.pieces[(j + 1) % m]) {
        (Piece::Chain { from, to }, next) => {
            let (l, n) = (from.loop_index, shape.loops()[from.loop_index].len());
            let parts = ChainParts::new(shape, from, to);
            let inside = parts.iter().skip(1).any(|(e, _, _)| convex(l, e));
            let joined = matches!(next, Piece::Chain { from: f, .. } if to.t == 1.0 && f.t == 0.0 && f.element == (to.element + 1) % n);
            inside || (joined && convex(l, (to.element + 1) % n))
        }
        _ => false,
    })
}

/// The base case proper: sites, events and the walk.
fn walk_leaf<K: AxisKernel>(
    shape: &Shape2d,
    s: &Subshape,
    cuts: &[Cut],
    tol: Tolerance,
    finder: &DiskFinder<K>,
) -> Result<LocalAxis, BaseCaseError> {
    let touch = Builder::<K>::touch_tol(shape, tol);
    // Room for a typical leaf up front: its sites and events are pushed one
    // by one, and growing from empty cost a handful of reallocations per
    // list and leaf (a tenth of all allocations of the base cases).
    let (sites, events) = (Vec::with_capacity(LEAF_ROOM), Vec::with_capacity(LEAF_ROOM));
    let mut b = Builder { shape, tol, touch, sites, events, aux: Vec::new(), finder };
    b.collect_sites(s, cuts);
    if b.sites.is_empty() {
        // A subshape of auxiliary arcs and single points only: its axis is
        // its first port.
        let nodes = s
            .pieces
            .iter()
            .filter_map(|p| match *p {
                Piece::Aux { disk } => Some(LocalNode {
                    center: cuts[disk].center,
                    radius: cuts[disk].radius,
                    kind: EventKind::Port(disk as u32),
                }),
                _ => None,
            })
            .take(1)
            .collect();
        return Ok(LocalAxis { nodes, edges: Vec::new(), aliases: Vec::new() });
    }
    b.collect_events(cuts)?;
    b.walk()
}

/// Sites and events a leaf's lists are made ready for: a leaf of the
/// default 32 parts holds 30–60 of each.
const LEAF_ROOM: usize = 64;

struct Builder<'a, K: AxisKernel> {
    shape: &'a Shape2d,
    tol: Tolerance,
    /// Footpoint tolerance of constructed disks ([`Builder::touch_tol`]).
    touch: f64,
    sites: Vec<LocalSite>,
    events: Vec<Event>,
    /// The whole shape's index, for checking branch points.
    finder: &'a DiskFinder<'a, K>,
    /// Each auxiliary arc with its dividing disk.
    aux: Vec<Port>,
}

/// Shapes and a prepared builder for the unit tests of this folder.
#[cfg(test)]
pub(super) mod fixtures {
    use super::*;
    use crate::kernel::FilteredKernel;
    use crate::shape::{ShapeOptions, Vertex};

    /// A closed polygon (bulges 0) or bulge loop from `(x, y, bulge)`.
    pub(in crate::plane::medial::base_case) fn shape(points: &[(f64, f64, f64)]) -> Shape2d {
        let lp = points.iter().map(|&(x, y, bulge)| Vertex { p: Point::new(x, y), bulge }).collect();
        Shape2d::from_bulge_loops(vec![lp], &ShapeOptions::default()).unwrap()
    }

    /// The 4 × 2 rectangle with a corner at the origin.
    pub(in crate::plane::medial::base_case) fn rectangle() -> Shape2d {
        shape(&[(0.0, 0.0, 0.0), (4.0, 0.0, 0.0), (4.0, 2.0, 0.0), (0.0, 2.0, 0.0)])
    }

    /// An L of width 4 and height 3 whose vertex (2, 1), index 3, is reflex.
    pub(in crate::plane::medial::base_case) fn l_shape() -> Shape2d {
        shape(&[(0.0, 0.0, 0.0), (4.0, 0.0, 0.0), (4.0, 1.0, 0.0), (2.0, 1.0, 0.0), (2.0, 3.0, 0.0), (0.0, 3.0, 0.0)])
    }

    /// Runs `f` on the builder of the whole of `shape`'s outer loop, with
    /// its sites and events collected (not yet walked).
    pub(in crate::plane::medial::base_case) fn with_events<T>(
        shape: &Shape2d,
        f: impl FnOnce(Builder<'_, FilteredKernel>) -> T,
    ) -> T {
        let finder = DiskFinder::new(shape);
        let tol = Tolerance::new(shape.tolerance());
        let touch = Builder::<FilteredKernel>::touch_tol(shape, tol);
        let mut b =
            Builder { shape, tol, touch, sites: Vec::new(), events: Vec::new(), aux: Vec::new(), finder: &finder };
        b.collect_sites(&Subshape::whole_loop(shape, 0), &[]);
        b.collect_events(&[]).unwrap();
        f(b)
    }
}

#[cfg(test)]
mod tests {
    use super::fixtures::{rectangle, shape};
    use super::*;

    fn solve_whole(shape: &Shape2d) -> LocalAxis {
        solve(shape, &Subshape::whole_loop(shape, 0), &[], shape.tolerance(), &DiskFinder::new(shape)).unwrap()
    }

    #[test]
    fn convex_vertices_inside_chains_and_where_two_chains_meet() {
        let r = rectangle();
        let at = |element: usize, t: f64| crate::plane::BoundaryPos { loop_index: 0, element, t };
        let aux = Piece::Aux { disk: 0 };
        let holds = |pieces: Vec<Piece>| holds_convex_vertex(&r, &Subshape { pieces });
        assert!(holds(Subshape::whole_loop(&r, 0).pieces));
        // Inside one side: no vertex.
        assert!(!holds(vec![Piece::Chain { from: at(0, 0.2), to: at(0, 0.8) }, aux]));
        // Over the corner (4, 0).
        assert!(holds(vec![Piece::Chain { from: at(0, 0.5), to: at(1, 0.5) }, aux]));
        // The loop's start (0, 0) between the last chain and the first.
        let split = vec![
            Piece::Chain { from: at(3, 0.5), to: at(3, 1.0) },
            Piece::Chain { from: at(0, 0.0), to: at(0, 0.5) },
            aux,
        ];
        assert!(holds(split));
        // A chain ending at a vertex and an arc after it: the vertex is a
        // footpoint, not inside.
        assert!(!holds(vec![Piece::Chain { from: at(0, 0.5), to: at(0, 1.0) }, aux]));
    }

    #[test]
    fn a_dividing_disk_without_a_node_is_named_by_the_nearest_port() {
        let cut = |x: f64| Cut { center: Point::new(x, 0.0), radius: 1.0 };
        let cuts = [cut(0.0), cut(3e-9), cut(5.0)];
        let s = Subshape { pieces: (0..3).map(|disk| Piece::Aux { disk }).collect() };
        let port =
            |disk: usize| LocalNode { center: cuts[disk].center, radius: 1.0, kind: EventKind::Port(disk as u32) };
        let local = LocalAxis { nodes: vec![port(0), port(2)], edges: Vec::new(), aliases: Vec::new() };
        assert_eq!(aliases(&s, &cuts, &local), [Alias { disks: [1, 0], bridge: None }]);
        let whole = LocalAxis { nodes: (0..3).map(port).collect(), edges: Vec::new(), aliases: Vec::new() };
        assert!(aliases(&s, &cuts, &whole).is_empty());
    }

    #[test]
    fn a_rectangle_has_four_corners_two_branch_points_and_five_edges() {
        let axis = solve_whole(&rectangle());
        let corners = axis.nodes.iter().filter(|n| n.kind == EventKind::Corner).count();
        assert_eq!(corners, 4);
        let mut branches: Vec<(f64, f64, f64)> = axis
            .nodes
            .iter()
            .filter(|n| n.kind == EventKind::Branch)
            .map(|n| (n.center.x, n.center.y, n.radius))
            .collect();
        branches.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert_eq!(branches.len(), 2);
        for (got, want) in branches.iter().zip([(1.0, 1.0, 1.0), (3.0, 1.0, 1.0)]) {
            assert!((got.0 - want.0).abs() < 1e-12 && (got.1 - want.1).abs() < 1e-12 && (got.2 - want.2).abs() < 1e-12);
        }
        assert_eq!(axis.edges.len(), 5);
    }

    #[test]
    fn a_disk_is_one_node_at_its_centre() {
        // Two half circles of radius 1 round the origin: the disks at both
        // joints and both arcs' own circles are one disk.
        let axis = solve_whole(&shape(&[(1.0, 0.0, 1.0), (-1.0, 0.0, 1.0)]));
        assert_eq!((axis.nodes.len(), axis.edges.len()), (1, 0));
        assert!(axis.nodes[0].center.norm() < 1e-12 && (axis.nodes[0].radius - 1.0).abs() < 1e-12);
    }
}
