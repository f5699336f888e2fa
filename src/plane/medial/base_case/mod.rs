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

use crate::kernel::apollonius::Site;
use crate::kernel::construct::unwrap_near;
use crate::kernel::growing_disk::GrowingDisk;
use crate::kernel::{AxisKernel, Contact, Point};
use crate::plane::axis::Primitive;
use crate::plane::medial::decompose::subshape::{
    hugged_disk, BoundaryPos, ChainParts, Cut, Piece, Subshape, HUGGED_TIP, SLIVER_END,
};
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::{Element, ElementRef, JointKind, Shape2d};
use std::f64::consts::TAU;

/// Pockets holding less boundary than this many tolerances are slivers
/// left by cuts within rounding of a vertex; the axis in them is shorter
/// than the same.
const SLIVER: f64 = 64.0;

/// Footpoint tolerance of constructed disks, as a fraction of the shape's
/// tolerance.
const TOUCH: f64 = 1e-3;

/// Fraction by which coinciding contacts of a branch point are pulled
/// into their own primitives.
const NUDGE: f64 = 1e-12;

/// How far (in tolerances, along the boundary) a branch point's contact
/// may fall outside the range it must lie in.
const CONTACT_SLACK: f64 = 16.0;

/// And at most this fraction of the site (short sites).
const CONTACT_SLACK_CAP: f64 = 0.5;

/// Disks whose centres and radii agree within this many tolerances are
/// one event.
const SAME_EVENT: f64 = 4.0;

/// Fans of normals narrower than this (radians) are rounding, not fans.
const FAN_MIN: f64 = 1e-7;

/// The directions (angles) where a point site's fan is cut into sites of
/// at most a quarter turn: fixed, so that every subshape holding part of
/// the fan cuts it at the same places.
const POINT_SPLITS: [f64; 4] = [-std::f64::consts::FRAC_PI_2, 0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI];

/// A primitive as one subshape sees it: a range of footpoint parameters
/// (see [`crate::kernel::bisector::footpoint`]) travelled from `u0` to `u1`.
#[derive(Debug, Clone, Copy)]
struct LocalSite {
    prim: Primitive,
    site: Site,
    u0: f64,
    u1: f64,
    /// The next primitive in the cycle follows without an auxiliary arc.
    joined_next: bool,
}

/// A position on the subshape's boundary cycle: primitive index and the
/// fraction `w` ∈ [0, 1] of its parameter range.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Key {
    site: usize,
    w: f64,
}

/// Where an event comes from (it decides the node kind).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// The dividing disk with this index (into the divide step's cuts).
    Port(usize),
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
}

/// The axis of one subshape.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LocalAxis {
    /// Nodes.
    pub nodes: Vec<LocalNode>,
    /// Edges.
    pub edges: Vec<LocalEdge>,
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

/// A branch point found in a pocket: its disk, its three contacts as
/// footpoints, and the same contacts before coinciding ones were pulled
/// apart.
struct Branch {
    center: Point,
    radius: f64,
    contacts: [Key; 3],
    snapped: [Key; 3],
}

/// A footpoint met walking into a pocket: offset, event, key.
type Met = (f64, usize, Key);

struct Event {
    center: Point,
    radius: f64,
    kind: EventKind,
    /// Footpoints in cycle order, distinct.
    feet: Vec<Key>,
    /// Primitives the disk touches along their whole range (an arc and its
    /// own circle): pockets made only of these are empty.
    whole: Vec<usize>,
}

fn angle(v: Point) -> f64 {
    v.y.atan2(v.x)
}

/// Global footpoint parameter of element fraction `t`.
fn element_param(e: &Element, t: f64) -> f64 {
    match e {
        Element::Segment(s) => t * s.a.dist(s.b),
        Element::Arc(a) => angle(a.a - a.center) + t * a.sweep(),
    }
}

/// The same boundary position, written at the end of one element or the
/// start of the next.
fn same_position(shape: &Shape2d, a: BoundaryPos, b: BoundaryPos) -> bool {
    let n = shape.loops()[a.loop_index].len();
    a.loop_index == b.loop_index && (a == b || (a.t == 1.0 && b.t == 0.0 && b.element == (a.element + 1) % n))
}

/// `s` with every chain end that lies within `len` (model units, along the
/// boundary) past a vertex that is not a convex corner moved back to the
/// vertex. A cut a hair past a
/// reflex vertex leaves such a sliver of the next element; its disks are
/// the cut's own within the tolerance, and as separate events they send
/// the walk round in circles.
fn drop_sliver_ends(shape: &Shape2d, s: &Subshape, len: f64) -> Subshape {
    let pieces = s
        .pieces
        .iter()
        .map(|p| match *p {
            Piece::Chain { mut from, mut to } if ChainParts::new(shape, from, to).len() > 1 => {
                // Never past a convex corner: the axis must reach it.
                let lp = &shape.loops()[to.loop_index];
                if to.t > 0.0
                    && to.t * lp.element(to.element).length() <= len
                    && shape.joint(to.loop_index, to.element) != JointKind::Convex
                {
                    to.t = 0.0;
                }
                let lp = &shape.loops()[from.loop_index];
                let next = (from.element + 1) % lp.len();
                if from.t < 1.0
                    && (1.0 - from.t) * lp.element(from.element).length() <= len
                    && shape.joint(from.loop_index, next) != JointKind::Convex
                {
                    from.t = 1.0;
                }
                Piece::Chain { from, to }
            }
            other => other,
        })
        .map(|p| match p {
            Piece::Chain { from, to } if !ChainParts::new(shape, from, to).is_empty() => Piece::Chain {
                from: short_of_reflex(shape, from, len, false),
                to: short_of_reflex(shape, to, len, true),
            },
            other => other,
        })
        .collect();
    Subshape { pieces }
}

/// A chain end within `len` (model units) short of a reflex vertex, moved
/// onto the vertex (`end`: the chain's end, else its start). A disk
/// touching the vertex from inside its fan gets a footpoint a few ulps
/// short of it on an arc (the closest point is clamped to the arc's end,
/// and its angle does not map back to exactly 1); the fan between the
/// element's normal and the disk is this subshape's boundary, which a
/// chain ending short of the vertex would leave out.
fn short_of_reflex(shape: &Shape2d, p: BoundaryPos, len: f64, end: bool) -> BoundaryPos {
    let lp = &shape.loops()[p.loop_index];
    let e = lp.element(p.element);
    if end && p.t > 0.0 && p.t < 1.0 {
        let v = (p.element + 1) % lp.len();
        if (1.0 - p.t) * e.length() <= len && shape.joint(p.loop_index, v) == JointKind::Reflex {
            return BoundaryPos { t: 1.0, ..p };
        }
    }
    if !end
        && p.t > 0.0
        && p.t < 1.0
        && p.t * e.length() <= len
        && shape.joint(p.loop_index, p.element) == JointKind::Reflex
    {
        return BoundaryPos { t: 0.0, ..p };
    }
    p
}

/// Consecutive chains that meet (a cut exactly at a vertex leaves two) as
/// one chain, so that the joint between them is seen. Two chains that
/// make up a whole loop from a point inside an element back to it (a
/// loop with one augmenting disk, thesis 2.3.1) stay two: one chain from
/// a point to itself is that point; [`Builder::collect_sites`] sees the
/// joint between them.
fn merge_touching_chains(shape: &Shape2d, pieces: Vec<Piece>) -> Vec<Piece> {
    let mut out: Vec<Piece> = Vec::with_capacity(pieces.len());
    for p in pieces {
        if let (Some(Piece::Chain { from, to }), Piece::Chain { from: f2, to: t2 }) = (out.last_mut(), p) {
            if same_position(shape, *to, f2) && *from != t2 {
                *to = t2;
                continue;
            }
        }
        out.push(p);
    }
    // The last chain may run on into the first.
    if out.len() > 1 {
        if let (Some(&Piece::Chain { from: f0, to: t0 }), Some(&Piece::Chain { from: fl, to: tl })) =
            (out.first(), out.last())
        {
            if same_position(shape, tl, f0) && fl != t0 {
                out[0] = Piece::Chain { from: fl, to: t0 };
                out.pop();
            }
        }
    }
    out
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
    if let Some(disk) = hugged_disk(shape, s, cuts, HUGGED_TIP * tol) {
        // The tip of a lobe cut at nearly its osculating circle: its true
        // axis runs on inside a sliver a few tolerances thin, where the
        // order of footpoints is rounding rather than geometry, and every
        // disk there is this one within those tolerances. The disk is the
        // tip's whole axis, a leaf.
        let c = cuts[disk];
        return Ok(LocalAxis {
            nodes: vec![LocalNode { center: c.center, radius: c.radius, kind: EventKind::Port(disk) }],
            edges: Vec::new(),
        });
    }
    let touch = Builder::<K>::touch_tol(shape, tol);
    let mut b = Builder { shape, tol, touch, sites: Vec::new(), events: Vec::new(), aux: Vec::new(), finder };
    b.collect_sites(s, cuts);
    if b.sites.is_empty() {
        // A subshape of auxiliary arcs and single points only: its axis is
        // its one port.
        let nodes = s
            .pieces
            .iter()
            .filter_map(|p| match *p {
                Piece::Aux { disk } => Some(LocalNode {
                    center: cuts[disk].center,
                    radius: cuts[disk].radius,
                    kind: EventKind::Port(disk),
                }),
                _ => None,
            })
            .take(1)
            .collect();
        return Ok(LocalAxis { nodes, edges: Vec::new() });
    }
    b.collect_events(cuts)?;
    b.walk()
}

/// An auxiliary arc: counter-clockwise around `c` from `a` to `b`.
#[derive(Debug, Clone, Copy)]
struct AuxArc {
    c: Point,
    r: f64,
    a: Point,
    b: Point,
}

impl AuxArc {
    /// True when the circle (`o`, `rho`) passes through the arc's inside
    /// (by more than `tol`): such a disk leaves the subshape.
    fn crossed_by(&self, o: Point, rho: f64, tol: f64) -> bool {
        let d = o.dist(self.c);
        if d + self.r <= rho + tol {
            // The arc's whole disk inside the circle: the circle reaches
            // past the arc, unless it is the arc's own circle.
            return rho > self.r + tol;
        }
        if d >= rho + self.r - tol || d + rho <= self.r + tol {
            return false;
        }
        // The two intersection points of the circles.
        let x = (d * d + self.r * self.r - rho * rho) / (2.0 * d);
        let h = (self.r * self.r - x * x).max(0.0).sqrt();
        let u = (o - self.c) * (1.0 / d);
        let base = self.c + u * x;
        let (va, vb) = (self.a - self.c, self.b - self.c);
        let sweep = (va.cross(vb).atan2(va.dot(vb))).rem_euclid(TAU);
        [base + u.perp() * h, base - u.perp() * h].into_iter().any(|q| {
            let vq = q - self.c;
            let at = (va.cross(vq).atan2(va.dot(vq))).rem_euclid(TAU);
            // Strictly inside the arc, away from its ends by the tolerance.
            at * self.r > tol && (sweep - at) * self.r > tol
        })
    }
}

struct Builder<'a, K: AxisKernel> {
    shape: &'a Shape2d,
    tol: f64,
    /// Footpoint tolerance of constructed disks ([`Builder::touch_tol`]).
    touch: f64,
    sites: Vec<LocalSite>,
    events: Vec<Event>,
    /// The whole shape's index, for checking branch points.
    finder: &'a DiskFinder<'a, K>,
    /// Each auxiliary arc: its disk, the index of the site after it, and
    /// the arc itself (centre, radius, start and end point, counter-clockwise).
    aux: Vec<(usize, usize, AuxArc)>,
}

impl<K: AxisKernel> Builder<'_, K> {
    fn n(&self) -> usize {
        self.sites.len()
    }

    fn k(&self) -> &K {
        self.finder.kernel()
    }

    /// True when the disk (`c`, `r`) is event `e`'s own (centres and radii
    /// within [`SAME_EVENT`] tolerances): one event, not two.
    fn same_disk(&self, e: &Event, c: Point, r: f64) -> bool {
        let near = SAME_EVENT * self.tol;
        e.center.dist(c) <= near && (e.radius - r).abs() <= near
    }

    /// How the circle (`c`, `r`) meets site `i`'s piece, within `tol`.
    fn contact(&self, i: usize, c: Point, r: f64, tol: f64) -> Contact {
        self.k().contact(self.distance(i, c).0, r, tol)
    }

    fn push_site(&mut self, prim: Primitive, site: Site, u0: f64, u1: f64) {
        self.sites.push(LocalSite { prim, site, u0, u1, joined_next: true });
    }

    /// A reflex vertex's fan between directions `from` and `to` (clockwise),
    /// measured from the fan's start (the previous element's end normal)
    /// so that the parameter agrees in every subshape; skipped when it is
    /// no wider than the tolerance.
    fn push_fan(&mut self, l: usize, v: usize, from: Point, to: Point, r: f64) {
        let lp = &self.shape.loops()[l];
        if lp.kind() == crate::shape::LoopKind::Point {
            self.push_point_fan(l, from, to, r);
            return;
        }
        let n = lp.len();
        let n_prev = lp.element((v + n - 1) % n).end_tangent().perp();
        let n_next = lp.element(v).start_tangent().perp();
        let base = angle(n_prev);
        let raw = |d: Point| (base - angle(d)).rem_euclid(TAU);
        let width = raw(n_next);
        // A dividing disk may meet the vertex from a direction just outside
        // its fan: it touches the element beside the vertex within the
        // tolerance there. Angles are cut in the middle of the gap between
        // the fan's ends, so that such a direction stays on its own side
        // of the end (a fan of this subshape a hair wider, or one of the
        // neighbouring subshape a hair narrower), ordered as the disks are.
        let cw = |d: Point| {
            let x = raw(d);
            if x > width && TAU - x < x - width {
                x - TAU
            } else {
                x
            }
        };
        let (d0, d1) = (cw(from), cw(to));
        // Dividing disks found by sliding (maxdisk*) meet a vertex in a
        // direction accurate to about 1e-8 rad; narrower fans are that.
        if d1 - d0 <= FAN_MIN || (d1 - d0) * r <= 4.0 * self.tol {
            return;
        }
        let q = lp.vertices()[v].p;
        self.push_site(Primitive::Vertex { loop_index: l, vertex: v }, Site::Point(q), base - d0, base - d1);
    }

    /// A point site's fan from direction `from` clockwise to `to` (a whole
    /// turn when they are one direction: the point between the two arcs of
    /// one disk), cut at the fixed directions of [`POINT_SPLITS`] into
    /// pieces narrower than a quarter turn, each a site of its own joined to
    /// the next: the joint between two pieces is an event (the maximal disk
    /// through the point in that direction), so that no site's range comes
    /// near a whole turn, where angles are ambiguous.
    fn push_point_fan(&mut self, l: usize, from: Point, to: Point, r: f64) {
        use crate::kernel::fan::cw_angle;
        let q = self.shape.loops()[l].vertices()[0].p;
        let mut width = cw_angle(from, to);
        if width <= FAN_MIN {
            width = TAU;
        }
        if width * r <= 4.0 * self.tol {
            return;
        }
        let mut cuts: Vec<f64> = POINT_SPLITS
            .iter()
            .map(|&a| cw_angle(from, Point::new(a.cos(), a.sin())))
            .filter(|&o| o > FAN_MIN && o < width - FAN_MIN)
            .collect();
        cuts.sort_by(f64::total_cmp);
        cuts.push(width);
        let base = angle(from);
        let prim = Primitive::Vertex { loop_index: l, vertex: 0 };
        let mut d0 = 0.0;
        for d1 in cuts {
            self.push_site(prim, Site::Point(q), base - d0, base - d1);
            d0 = d1;
        }
    }

    fn element_site(&mut self, l: usize, k: usize, lo: f64, hi: f64) {
        let e = self.shape.loops()[l].element(k);
        let prim = Primitive::Element(ElementRef { loop_index: l, element: k });
        self.push_site(prim, prim.site(self.shape), element_param(&e, lo), element_param(&e, hi));
    }

    fn collect_sites(&mut self, s: &Subshape, cuts: &[Cut]) {
        let shape = self.shape;
        let s = &drop_sliver_ends(shape, s, SLIVER_END * self.tol);
        // A chain with no parts next to another chain is the other chain's
        // end point (a cut at an element's very end leaves one): drop it.
        let is_point =
            |p: &Piece| matches!(*p, Piece::Chain { from, to } if ChainParts::new(shape, from, to).is_empty());
        let k = s.pieces.len();
        let pieces: Vec<Piece> = (0..k)
            .filter(|&j| {
                let neighbour_chain = |i: usize| matches!(s.pieces[i], Piece::Chain { .. }) && !is_point(&s.pieces[i]);
                let (next, prev) = ((j + 1) % k, (j + k - 1) % k);
                // Of two points in a row (the two ends of a vertex), keep one.
                let twin = is_point(&s.pieces[next]) && next != j;
                !(k > 1 && is_point(&s.pieces[j]) && (neighbour_chain(next) || neighbour_chain(prev) || twin))
            })
            .map(|j| s.pieces[j])
            .collect();
        let s = &Subshape { pieces: merge_touching_chains(shape, pieces) };
        let m = s.pieces.len();
        let aux_center = |j: usize| match s.pieces[j % m] {
            Piece::Aux { disk } => Some((cuts[disk].center, cuts[disk].radius)),
            Piece::Chain { .. } => None,
        };
        // A single chain of a whole loop closes on itself.
        let closed = m == 1;
        for (j, piece) in s.pieces.iter().enumerate() {
            let Piece::Chain { from, to } = *piece else {
                if let Some(last) = self.sites.last_mut() {
                    last.joined_next = false;
                }
                if let Piece::Aux { disk } = *piece {
                    let end_of = |p: &Piece, start: bool| match *p {
                        Piece::Chain { from, to } => Some(if start { from } else { to }.point(shape)),
                        Piece::Aux { .. } => None,
                    };
                    let c = cuts[disk];
                    let a = end_of(&s.pieces[(j + m - 1) % m], false).unwrap_or(c.center);
                    let b = end_of(&s.pieces[(j + 1) % m], true).unwrap_or(c.center);
                    self.aux.push((disk, self.sites.len(), AuxArc { c: c.center, r: c.radius, a, b }));
                }
                continue;
            };
            let l = from.loop_index;
            let lp = &shape.loops()[l];
            let n = lp.len();
            let before = aux_center(j + m - 1);
            let after = aux_center(j + 1);
            let parts = ChainParts::new(shape, from, to);
            if parts.is_empty() {
                // A single point between two auxiliary arcs: a reflex
                // vertex's fan between the two disks' directions.
                if let (Some(v), Some((c0, r0)), Some((c1, r1))) = (from.vertex(shape), before, after) {
                    if shape.joint(l, v) == JointKind::Reflex {
                        let q = lp.vertices()[v].p;
                        self.push_fan(l, v, c0 - q, c1 - q, r0.min(r1));
                    }
                }
                continue;
            }
            let (e0, lo0, _) = parts.get(0);
            let start_vertex = (lo0 == 0.0).then_some(e0);
            if let (Some(v), Some((c, r))) = (start_vertex, before) {
                if shape.joint(l, v) == JointKind::Reflex {
                    let q = lp.vertices()[v].p;
                    let n_next = lp.element(v).start_tangent().perp();
                    self.push_fan(l, v, c - q, n_next, r);
                }
            }
            // The chain carries on from the one before (the two halves of
            // a whole loop): the joint where they meet is inside the boundary.
            let carries_on =
                matches!(s.pieces[(j + m - 1) % m], Piece::Chain { to, .. } if m > 1 && same_position(shape, to, from));
            for i in 0..parts.len() {
                let (e, lo, hi) = parts.get(i);
                if i > 0 || (closed && e == 0 && lo == 0.0) || (i == 0 && lo == 0.0 && carries_on) {
                    // The joint at this element's start, inside the chain.
                    if shape.joint(l, e) == JointKind::Reflex {
                        let prev = lp.element((e + n - 1) % n);
                        let np = prev.end_tangent().perp();
                        self.push_fan(l, e, np, lp.element(e).start_tangent().perp(), f64::INFINITY);
                    }
                }
                // A chain that is one sliver (a cut within the tolerance of
                // a vertex) is that vertex; slivers at the ends of longer
                // chains went in `drop_sliver_ends`, except next to a
                // convex corner, whose corner event needs the sliver's site.
                let sliver = parts.len() == 1 && (hi - lo) * lp.element(e).length() <= self.tol;
                if !sliver {
                    self.element_site(l, e, lo, hi);
                }
            }
            let (el, _, hil) = parts.get(parts.len() - 1);
            if let (true, Some((c, r))) = (hil == 1.0, after) {
                let v = (el + 1) % n;
                if shape.joint(l, v) == JointKind::Reflex {
                    let q = lp.vertices()[v].p;
                    let n_prev = lp.element(el).end_tangent().perp();
                    self.push_fan(l, v, n_prev, c - q, r);
                }
            }
        }
        if !closed {
            if let Some(last) = self.sites.last_mut() {
                // The cycle wraps from the last piece to the first: joined
                // only when no auxiliary arc lies between, which happens
                // when the pieces start with a chain and end with one.
                let ends_aux = matches!(s.pieces.last(), Some(Piece::Aux { .. }));
                let starts_aux = matches!(s.pieces.first(), Some(Piece::Aux { .. }));
                last.joined_next = !(ends_aux || starts_aux);
            }
        }
    }

    /// True when the disk (`c`, `r`) crosses one of the auxiliary arcs.
    fn leaves_subshape(&self, c: Point, r: f64) -> bool {
        self.aux.iter().any(|(_, _, arc)| arc.crossed_by(c, r, self.tol))
    }

    /// Parameter of the disk (`c`, `r`) on site `i`, unwrapped into its range.
    fn param(&self, i: usize, c: Point, r: f64) -> f64 {
        let s = &self.sites[i];
        let mid = 0.5 * (s.u0 + s.u1);
        match s.site {
            Site::Line { a, n } => (c - n * r - a).dot(-n.perp()),
            Site::Point(q) => unwrap_near(angle(c - q), mid),
            Site::Circle { o, .. } => unwrap_near(angle(c - o), mid),
        }
    }

    fn fraction(&self, i: usize, u: f64) -> f64 {
        let s = &self.sites[i];
        (u - s.u0) / (s.u1 - s.u0)
    }

    /// The boundary point at parameter `u` of site `i`.
    fn point_of(&self, i: usize, u: f64) -> Point {
        crate::kernel::bisector::footpoint(&self.sites[i].site, u).0
    }

    /// Distance from `c` to site `i`'s piece and the parameter of the
    /// closest point (clamped to the range).
    fn distance(&self, i: usize, c: Point) -> (f64, f64) {
        let s = &self.sites[i];
        let (lo, hi) = (s.u0.min(s.u1), s.u0.max(s.u1));
        match s.site {
            Site::Point(q) => (c.dist(q), self.param(i, c, 0.0).clamp(lo, hi)),
            Site::Line { a, n } => {
                let u = (c - a).dot(-n.perp()).clamp(lo, hi);
                (c.dist(self.point_of(i, u)), u)
            }
            Site::Circle { o, r, .. } => {
                let u = self.param(i, c, 0.0);
                if (lo..=hi).contains(&u) && c.dist(o) > 0.0 {
                    ((c.dist(o) - r).abs(), u)
                } else {
                    let (pa, pb) = (self.point_of(i, lo), self.point_of(i, hi));
                    if c.dist(pa) <= c.dist(pb) {
                        (c.dist(pa), lo)
                    } else {
                        (c.dist(pb), hi)
                    }
                }
            }
        }
    }

    /// The cycle key of parameter `u` on site `i`: ends snapped when within
    /// the tolerance (in length, for a disk of radius `r`), and the end of
    /// a primitive joined to the next stored as the next one's start.
    fn key(&self, i: usize, u: f64, r: f64) -> Key {
        let s = &self.sites[i];
        let scale = match s.site {
            Site::Line { .. } => 1.0,
            Site::Circle { r: rc, .. } => rc,
            Site::Point(_) => r,
        };
        let mut w = self.fraction(i, u).clamp(0.0, 1.0);
        if (u - s.u0).abs() * scale <= self.tol {
            w = 0.0;
        }
        if (u - s.u1).abs() * scale <= self.tol {
            w = 1.0;
        }
        if w == 1.0 && s.joined_next {
            return Key { site: (i + 1) % self.n(), w: 0.0 };
        }
        // Where a site meets an auxiliary arc only the dividing disk itself
        // touches (a maximal disk tangent there lies on the same normal,
        // so it is that disk or not maximal): any other disk's contact
        // there is rounding of one just inside the site.
        let n = self.n();
        if w == 0.0 && !self.sites[(i + n - 1) % n].joined_next {
            w = NUDGE;
        } else if w == 1.0 && !s.joined_next {
            w = 1.0 - NUDGE;
        }
        Key { site: i, w }
    }

    /// Every site the circle (`c`, `r`) touches within the tolerance.
    fn touching(&self, c: Point, r: f64) -> (Vec<Key>, Vec<usize>) {
        let mut feet = Vec::new();
        let mut whole = Vec::new();
        for i in 0..self.n() {
            if let Site::Circle { o, r: rc, outside: false } = self.sites[i].site {
                if c.dist(o) <= self.tol && (rc - r).abs() <= self.tol {
                    feet.push((i, self.key(i, self.sites[i].u0, r)));
                    feet.push((i, self.key(i, self.sites[i].u1, r)));
                    whole.push(i);
                    continue;
                }
            }
            let (d, u) = self.distance(i, c);
            if self.k().contact(d, r, self.touch) == Contact::Touching && self.faces_inside(i, c, u) {
                if let Site::Point(q) = self.sites[i].site {
                    // A disk through a reflex vertex from outside its fan
                    // (in this subshape) touches the element beside it.
                    let w = self.fraction(i, self.param(i, c, 0.0));
                    let slack = 4.0 * self.tol / self.length(i, 0.0, 1.0, c.dist(q)).max(f64::MIN_POSITIVE);
                    if w < -slack || w > 1.0 + slack {
                        continue;
                    }
                }
                let k = self.key(i, u, r);
                // A touch at a reflex vertex belongs to the vertex's fan,
                // at the disk's direction, not to the element's end.
                if self.fan_owns(i, k) {
                    continue;
                }
                feet.push((i, k));
            }
        }
        // A contact at an element's clamped end, where the joined
        // neighbour has a contact of its own, is that neighbour's contact
        // seen within the tolerance (nearly concentric arcs smear one
        // contact over a range): one footpoint, not two.
        let n = self.n();
        let has = |j: usize, feet: &[(usize, Key)]| feet.iter().any(|&(s, k)| s == j && k.w > 0.0 && k.w < 1.0);
        let keep: Vec<bool> = feet
            .iter()
            .map(|&(i, k)| {
                let at_start = k.site == i && k.w == 0.0;
                let at_end = k.site != i || k.w == 1.0;
                let prev = (i + n - 1) % n;
                let next = (i + 1) % n;
                let start_taken = at_start && self.sites[prev].joined_next && has(prev, &feet) && !has(i, &feet);
                let end_taken = at_end && self.sites[i].joined_next && has(next, &feet) && !has(i, &feet);
                !(start_taken || end_taken)
            })
            .collect();
        let feet = feet.into_iter().zip(keep).filter(|(_, k)| *k).map(|((_, k), _)| k).collect();
        (feet, whole)
    }

    /// False when a disk centred `c` touches site `i` at parameter `u`
    /// strictly inside the site's piece from the site's outer side: the
    /// two sides of a curve site lie on each other, and a disk touching
    /// one touches the other there from behind.
    fn faces_inside(&self, i: usize, c: Point, u: f64) -> bool {
        let s = &self.sites[i];
        let w = self.fraction(i, u);
        if !(w > 0.0 && w < 1.0) {
            return true;
        }
        let signed = match s.site {
            Site::Point(_) => return true,
            Site::Line { a, n } => (c - a).dot(n),
            Site::Circle { o, r, outside: true } => c.dist(o) - r,
            Site::Circle { o, r, outside: false } => r - c.dist(o),
        };
        signed >= 0.0
    }

    /// Contacts of a constructed disk count as footpoints within this
    /// distance: the disks here come from closed-form constructions
    /// (residuals of a few ulps), while the shape's tolerance would let a
    /// disk inside a nearly circular stretch of arcs (a rounded tip) touch
    /// all of them at once.
    /// Far from the origin, rounding of the coordinates themselves sets the
    /// floor.
    fn touch_tol(shape: &Shape2d, tol: f64) -> f64 {
        let bb = shape.bbox();
        let magnitude = bb.min.x.abs().max(bb.min.y.abs()).max(bb.max.x.abs()).max(bb.max.y.abs()) + bb.diagonal();
        (TOUCH * tol).max(256.0 * f64::EPSILON * magnitude).min(tol)
    }

    /// True when key `k`, found on element site `i`, is an end of `i`
    /// where a reflex vertex's fan joins it.
    fn fan_owns(&self, i: usize, k: Key) -> bool {
        let n = self.n();
        let is_fan = |j: usize| matches!(self.sites[j].prim, Primitive::Vertex { .. });
        if is_fan(i) {
            return false;
        }
        let prev = (i + n - 1) % n;
        // `k` may already be the next site's start (a joined end).
        let at_start = k.site == i && k.w == 0.0 && self.sites[prev].joined_next && is_fan(prev);
        let at_end = k.site == (i + 1) % n && k.w == 0.0 && k.site != i && is_fan(k.site);
        at_start || at_end
    }

    fn pos(&self, k: Key) -> f64 {
        2.0 * k.site as f64 + k.w
    }

    fn add_event(
        &mut self,
        center: Point,
        radius: f64,
        kind: EventKind,
        mut feet: Vec<Key>,
        whole: Vec<usize>,
    ) -> usize {
        // The same disk found twice (a joint disk that is also a branch
        // point or a leaf circle) is one event with all its footpoints.
        // The two auxiliary arcs of one augmenting disk (thesis 2.3.1) are
        // the two sides of a cycle cut open: two ends of this axis, glued
        // into one node only with the other subshapes.
        let twin = |e: &Event| matches!((e.kind, kind), (EventKind::Port(a), EventKind::Port(b)) if a == b);
        let same = self.events.iter().position(|e| self.same_disk(e, center, radius) && !twin(e));
        let id = match same {
            Some(i) => {
                let e = &mut self.events[i];
                feet.append(&mut e.feet);
                e.whole.extend(whole);
                if matches!(kind, EventKind::Port(_)) {
                    e.kind = kind;
                }
                i
            }
            None => {
                self.events.push(Event { center, radius, kind, feet: Vec::new(), whole });
                self.events.len() - 1
            }
        };
        feet.sort_by(|a, b| self.pos(*a).total_cmp(&self.pos(*b)));
        feet.dedup_by(|a, b| a.site == b.site && (a.w - b.w).abs() <= 1e-12);
        let e = &mut self.events[id];
        e.feet = feet;
        e.whole.sort_unstable();
        e.whole.dedup();
        id
    }

    /// The maximal disk grown at the start of site `j` (a joint with the
    /// previous site), tangent with normal `nrm`; `own` are the sites whose
    /// supporting curve is tangent there (skipped, but an arc among them
    /// curving inwards caps the radius at its own).
    fn grow(&self, p: Point, nrm: Point, own: &[usize]) -> Option<(Point, f64)> {
        let g = GrowingDisk { p, n: nrm };
        let t_min = 0.25 * self.tol;
        let mut best = f64::INFINITY;
        for i in 0..self.n() {
            let s = &self.sites[i];
            if own.contains(&i) {
                if let Site::Circle { o, r, outside: false } = s.site {
                    if nrm.dot(o - p) > 0.0 {
                        best = best.min(r);
                    }
                }
                continue;
            }
            let (lo, hi) = (s.u0.min(s.u1), s.u0.max(s.u1));
            // The piece's ends are boundary points: always safe contacts.
            for q in [self.point_of(i, s.u0), self.point_of(i, s.u1)] {
                if q.dist(p) > self.tol {
                    if let Some(t) = self.k().through_point(&g, q).filter(|&t| t > t_min) {
                        best = best.min(t);
                    }
                }
            }
            if let Site::Point(_) = s.site {
                continue;
            }
            if let Some(t) = self.k().touch_site(&g, &s.site).filter(|&t| t > t_min) {
                let c = g.center(t);
                let u = self.param(i, c, t);
                let slack = match s.site {
                    Site::Circle { r, .. } => self.tol / r,
                    _ => self.tol,
                };
                if u >= lo - slack && u <= hi + slack && s.site.contact(c, t).dist(p) > self.tol {
                    best = best.min(t);
                }
            }
        }
        // A dividing disk tangent at `p` is the maximal disk there (its
        // other contacts may lie outside this subshape).
        for (_, _, arc) in &self.aux {
            let v = arc.c - p;
            if (v.norm() - arc.r).abs() <= self.tol && v.cross(nrm).abs() <= self.tol && v.dot(nrm) > 0.0 {
                best = best.min(arc.r);
            }
        }
        best.is_finite().then(|| (g.center(best), best))
    }

    fn collect_events(&mut self, cuts: &[Cut]) -> Result<(), BaseCaseError> {
        let n = self.n();
        // Ports: the auxiliary arcs, between the site before and after.
        for (disk, next, _) in self.aux.clone() {
            let c = cuts[disk];
            let next = next % n;
            let feet = vec![Key { site: (next + n - 1) % n, w: 1.0 }, Key { site: next, w: 0.0 }];
            self.add_event(c.center, c.radius, EventKind::Port(disk), feet, Vec::new());
        }
        // Joints between consecutive sites.
        for i in 0..n {
            if !self.sites[i].joined_next {
                continue;
            }
            let j = (i + 1) % n;
            let (a, b) = (self.sites[i], self.sites[j]);
            let key = Key { site: j, w: 0.0 };
            let p = self.point_of(j, b.u0);
            // The element whose normal the joint's disk grows along: the
            // one after the joint, or before it at the start of a fan.
            let grow_from = match (a.prim, b.prim) {
                (Primitive::Element(_), Primitive::Element(eb)) => {
                    if self.shape.joint(eb.loop_index, eb.element) == JointKind::Convex {
                        self.add_event(p, 0.0, EventKind::Corner, vec![key], Vec::new());
                        continue;
                    }
                    (eb, false)
                }
                (Primitive::Element(ea), Primitive::Vertex { .. }) => (ea, true),
                (Primitive::Vertex { .. }, Primitive::Element(eb)) => (eb, false),
                (Primitive::Vertex { .. }, Primitive::Vertex { .. }) => {
                    // Two pieces of one point site's fan: the maximal disk
                    // through the point in the direction where they meet.
                    if a.prim != b.prim {
                        continue;
                    }
                    let Site::Point(q) = b.site else { continue };
                    let nrm = Point::new(b.u0.cos(), b.u0.sin());
                    let (c, r) = self.grow(q, nrm, &[i, j]).ok_or(BaseCaseError::NoDisk(q))?;
                    let (mut feet, whole) = self.touching(c, r);
                    feet.push(key);
                    self.add_event(c, r, EventKind::Joint, feet, whole);
                    continue;
                }
            };
            let (er, at_end) = grow_from;
            let elements = &self.shape.loops()[er.loop_index];
            let e = elements.element(er.element);
            let mut nrm = if at_end { e.end_tangent() } else { e.start_tangent() }.perp();
            if let (Primitive::Element(ea), Primitive::Element(_)) = (a.prim, b.prim) {
                // A smooth joint's two normals agree only within the angular
                // tolerance: grow along their mean, so that a mirror image
                // grows the mirrored disk and one disk met from two joints
                // is found twice alike.
                nrm = (elements.element(ea.element).end_tangent().perp() + nrm).unit();
            }
            let (c, r) = self.grow(p, nrm, &[i, j]).ok_or(BaseCaseError::NoDisk(p))?;
            let (mut feet, whole) = self.touching(c, r);
            feet.push(key);
            self.add_event(c, r, EventKind::Joint, feet, whole);
        }
        // Arcs whose own circle is the maximal disk at their middle.
        for i in 0..n {
            let Site::Circle { o, r, outside: false } = self.sites[i].site else { continue };
            let um = 0.5 * (self.sites[i].u0 + self.sites[i].u1);
            let (p, nrm) = crate::kernel::bisector::footpoint(&self.sites[i].site, um);
            if let Some((_, t)) = self.grow(p, nrm, &[i]) {
                if (t - r).abs() <= self.tol && !self.leaves_subshape(o, r) {
                    let (feet, whole) = self.touching(o, r);
                    self.add_event(o, r, EventKind::Leaf, feet, whole);
                }
            }
        }
        Ok(())
    }

    /// Offset of `k` after `a` along the cycle, in [0, 2n).
    fn offset(&self, a: Key, k: Key) -> f64 {
        // Both positions lie in [0, 2n): one wrap, exactly what
        // `rem_euclid` gives, without its division (this runs for every
        // footpoint of every event at every pocket walked).
        let d = self.pos(k) - self.pos(a);
        if d < 0.0 {
            d + 2.0 * self.n() as f64
        } else {
            d
        }
    }

    /// Length (model units) of the part of site `i` between fractions
    /// `w0` and `w1`, for a disk of radius `r` at a vertex.
    fn length(&self, i: usize, w0: f64, w1: f64, r: f64) -> f64 {
        let s = &self.sites[i];
        let du = (s.u1 - s.u0).abs() * (w1 - w0).abs();
        match s.site {
            Site::Line { .. } => du,
            Site::Circle { r: rc, .. } => du * rc,
            Site::Point(_) => du * r,
        }
    }

    /// True when site `i` between fractions `w0` and `w1` stays within the
    /// tolerance of the circle (`c`, `r`): a footpoint smeared by rounding
    /// into two (a disk through a vertex just beside its tangency point).
    fn hugs(&self, i: usize, w0: f64, w1: f64, c: Point, r: f64) -> bool {
        if let Site::Point(_) = self.sites[i].site {
            // A disk through the vertex touches it in one direction only;
            // the rest of the fan is real boundary for the axis.
            return false;
        }
        (0..=8).all(|k| {
            let w = w0 + (w1 - w0) * k as f64 / 8.0;
            self.k().contact(c.dist(self.point_of(i, self.u_at(i, w))), r, 4.0 * self.tol) == Contact::Touching
        })
    }

    /// True when the pocket of event `d` from `a` to `b` holds no more
    /// boundary than a sliver of [`SLIVER`] tolerances, besides the sites the
    /// disk touches along their whole range or hugs.
    fn pocket_is_empty(&self, d: usize, a: Key, b: Key) -> bool {
        let ev = &self.events[d];
        let n = self.n();
        let len = if a == b { 2.0 * n as f64 } else { self.offset(a, b) };
        let eps = 1e-12;
        let mut content = 0.0;
        // Site i occupies [2i, 2i + 1] on the cycle.
        let mut x = self.pos(a);
        let end = x + len;
        while x < end - eps {
            let block = (x / 2.0).floor();
            let i = block as usize % n;
            let (lo, hi) = (x - 2.0 * block, (end - 2.0 * block).min(1.0));
            if hi > lo && !ev.whole.contains(&i) && !self.hugs(i, lo, hi, ev.center, ev.radius) {
                content += self.length(i, lo, hi, ev.radius);
            }
            x = 2.0 * block + 2.0;
        }
        content <= SLIVER * self.tol
    }

    /// The site just after `k` and its fraction there.
    fn site_after(&self, k: Key) -> (usize, f64) {
        if k.w < 1.0 {
            (k.site, k.w)
        } else {
            ((k.site + 1) % self.n(), 0.0)
        }
    }

    /// The site just before `k` and its fraction there.
    fn site_before(&self, k: Key) -> (usize, f64) {
        if k.w > 0.0 {
            (k.site, k.w)
        } else {
            ((k.site + self.n() - 1) % self.n(), 1.0)
        }
    }

    /// Footpoint parameters on site `i` of the disks of events `d` and `e`,
    /// from the disks themselves: cycle keys are clamped to the site's
    /// range, and a clamped end would send the edge's curve past its node.
    /// A corner (radius 0) or a disk concentric with an arc has no
    /// direction: its key (fractions `w`) stands in.
    fn params_between(&self, i: usize, d: usize, e: usize, w: (f64, f64)) -> (f64, f64) {
        let at = |ev: usize, w: f64| {
            let (c, r) = (self.events[ev].center, self.events[ev].radius);
            let degenerate = match self.sites[i].site {
                Site::Point(q) => c.dist(q) <= self.tol,
                Site::Circle { o, .. } => c.dist(o) <= self.tol,
                Site::Line { .. } => false,
            };
            if degenerate || r == 0.0 {
                self.u_at(i, w)
            } else {
                self.param(i, c, r)
            }
        };
        (at(d, w.0), at(e, w.1))
    }

    fn u_at(&self, i: usize, w: f64) -> f64 {
        let s = &self.sites[i];
        s.u0 + (s.u1 - s.u0) * w
    }

    fn walk(mut self) -> Result<LocalAxis, BaseCaseError> {
        let mut edges: Vec<LocalEdge> = Vec::new();
        let mut linked: Vec<(usize, usize)> = Vec::new();
        let mut work: Vec<(usize, usize)> = Vec::new();
        for (d, e) in self.events.iter().enumerate() {
            work.extend((0..e.feet.len()).map(|j| (d, j)));
        }
        // Every pocket is walked a few times (once more per branch point
        // found in it); far more steps means the walk is going round.
        let budget = 64 * (self.n() + self.events.len()) + 64;
        let mut steps = 0;
        while let Some((d, j)) = work.pop() {
            steps += 1;
            if steps > budget {
                return Err(BaseCaseError::Budget);
            }
            let feet = &self.events[d].feet;
            let (a, b) = (feet[j], feet[(j + 1) % feet.len()]);
            let span = if a == b { 2.0 * self.n() as f64 } else { self.offset(a, b) };
            // The first footpoints of other events met from either end.
            let (mut first, mut last): (Option<Met>, Option<Met>) = (None, None);
            for (id, e) in self.events.iter().enumerate() {
                if id == d {
                    continue;
                }
                for &k in &e.feet {
                    let o = self.offset(a, k);
                    if o <= 0.0 || o >= span {
                        continue;
                    }
                    if first.is_none_or(|f| o < f.0) {
                        first = Some((o, id, k));
                    }
                    if last.is_none_or(|f| o > f.0) {
                        last = Some((o, id, k));
                    }
                }
            }
            // A pocket with no other event in it must hold no boundary (but
            // slivers); one with events is walked even if it is thin.
            let (Some(first), Some(last)) = (first, last) else {
                if self.pocket_is_empty(d, a, b) {
                    continue;
                }
                return Err(BaseCaseError::EmptyPocket(self.events[d].center));
            };
            let (s1, w1a) = self.site_after(a);
            let (s2, w2b) = self.site_before(b);
            if first.1 == last.1 {
                let e = first.1;
                let pair = (d.min(e), d.max(e));
                if !linked.contains(&pair) {
                    linked.push(pair);
                    let (t1, w1e) = self.site_before(first.2);
                    let (t2, w2e) = self.site_after(last.2);
                    if t1 != s1 || t2 != s2 {
                        return Err(BaseCaseError::Inconsistent(self.events[d].center));
                    }
                    // Walking from d into the pocket, s1 (after a) is on the right.
                    edges.push(LocalEdge {
                        from: d,
                        to: e,
                        sites: [self.sites[s2].prim, self.sites[s1].prim],
                        params: [self.params_between(s2, d, e, (w2b, w2e)), self.params_between(s1, d, e, (w1a, w1e))],
                    });
                }
                continue;
            }
            let Some(found) = self.branch(d, a, span, s1, s2, first.0, last.0) else {
                return Err(BaseCaseError::NoBranch(self.events[d].center));
            };
            let (c, r) = (found.center, found.radius);
            // The three contacts the construction placed are footpoints
            // even where rounding puts them a hair beyond the tolerance:
            // without them the pocket would be walked to the same branch
            // point again. Where two of them were pulled apart, the
            // snapped position they shared is not a footpoint.
            let (mut feet, whole) = self.touching(c, r);
            feet.retain(|k| found.snapped.iter().zip(&found.contacts).all(|(sn, ct)| k != sn || sn == ct));
            feet.extend(found.contacts);
            let id = self.add_event(c, r, EventKind::Branch, feet, whole);
            work.push((d, j));
            work.extend((0..self.events[id].feet.len()).map(|k| (id, k)));
        }
        let nodes =
            self.events.iter().map(|e| LocalNode { center: e.center, radius: e.radius, kind: e.kind }).collect();
        // A subshape's axis is a tree: a pocket walked to the wrong event
        // shows up as a missing or a doubled edge.
        if edges.len() + 1 != self.events.len() {
            return Err(BaseCaseError::Inconsistent(self.events.first().map_or(Point::default(), |e| e.center)));
        }
        Ok(LocalAxis { nodes, edges })
    }

    /// The branch point in the pocket of event `d` starting at `a` (length
    /// `span`): an empty disk other than `d`'s own, touching `s1` before
    /// offset `x1`, `s2` after offset `y2` and a third site in between. The
    /// one touching `s1` first wins.
    #[allow(clippy::too_many_arguments)]
    fn branch(&self, d: usize, a: Key, span: f64, s1: usize, s2: usize, x1: f64, y2: f64) -> Option<Branch> {
        // The pocket's own disk touches its two sites at the pocket's ends
        // (and a third site there, at a vertex): it would merge back into
        // event `d` and the pocket be walked again, for ever.
        let is_own = |c: Point, r: f64| self.same_disk(&self.events[d], c, r);
        // Candidates that touch the three sites within their ranges, in
        // the pocket, by where they touch `s1`; the first empty one wins.
        // (Emptiness costs O(n) each, so it is tested last and in order.)
        let mut candidates: Vec<(f64, usize, Point, f64)> = Vec::new();
        for t in 0..self.n() {
            if t == s1 || t == s2 {
                continue;
            }
            // The third contact lies between offsets x1 and y2, give or
            // take the slack: skip sites wholly outside. A contact at a
            // site's end may be keyed as the next site's start, one further
            // on; a site that holds `a` or whose end wraps round stays.
            let (o_start, o_end) = (self.offset(a, Key { site: t, w: 0.0 }), self.offset(a, Key { site: t, w: 1.0 }));
            let whole = o_start <= o_end && o_end + 1.0 < 2.0 * self.n() as f64;
            if whole && (o_end + 1.0 < x1 - CONTACT_SLACK_CAP || o_start > y2 + CONTACT_SLACK_CAP) {
                continue;
            }
            for (c, r) in self.k().tritangent_disks([self.sites[s1].site, self.sites[s2].site, self.sites[t].site]) {
                if r <= self.tol || !c.is_finite() || is_own(c, r) {
                    continue;
                }
                // Near-degenerate triples (many disks nearly alike, as at
                // the centre of a symmetric shape) place contacts a few
                // tolerances off: allow that much, in length, per site.
                let slack = |i: usize| {
                    (CONTACT_SLACK * self.tol / self.length(i, 0.0, 1.0, r).max(f64::MIN_POSITIVE))
                        .min(CONTACT_SLACK_CAP)
                };
                let at = |i: usize| {
                    let u = self.param(i, c, r);
                    let w = self.fraction(i, u);
                    let sl = slack(i);
                    ((-sl..=1.0 + sl).contains(&w)).then(|| self.offset(a, self.key(i, u, r)))
                };
                let (Some(o1), Some(o2), Some(ot)) = (at(s1), at(s2), at(t)) else { continue };
                let o2 = if o2 == 0.0 { span } else { o2 };
                let (sl1, sl2, slt) = (slack(s1), slack(s2), slack(t));
                if o1 > x1 + sl1 || o2 < y2 - sl2 || ot < x1 - slt || ot > y2 + slt || o1 >= o2 {
                    continue;
                }
                // Touching all three: the construction is ill-conditioned
                // for nearly parallel lines, where a root can miss a site.
                if [s1, s2, t].iter().any(|&i| self.contact(i, c, r, CONTACT_SLACK * self.tol) != Contact::Touching) {
                    continue;
                }
                candidates.push((o1, t, c, r));
            }
        }
        // Stable: among equal offsets the first found wins, as it did.
        candidates.sort_by(|x, y| x.0.total_cmp(&y.0));
        let (_, t, c, r) = candidates.into_iter().find(|&(_, _, c, r)| {
            // Empty: no site closer than the radius, inside the subshape,
            // and for the whole shape (a subshape's own primitives do not
            // see past its auxiliary arcs).
            !(0..self.n()).any(|i| self.contact(i, c, r, self.tol) == Contact::Overlapping)
                && self.finder.intruder(c, r, 4.0 * self.tol).is_none()
        })?;
        let key = |i: usize| self.key(i, self.param(i, c, r), r);
        let raw = [key(s1), key(s2), key(t)];
        let mut keys = raw;
        let sites = [s1, s2, t];
        // Two contacts within the tolerance of one vertex (a disk in the
        // wedge of a nearly flat convex corner) are still two contacts,
        // each on its own side of the vertex: keep them apart so the
        // corner's own event lies between them.
        for x in 0..3 {
            for y in 0..3 {
                if x != y && raw[x] == raw[y] {
                    let w = self.fraction(sites[x], self.param(sites[x], c, r));
                    keys[x] = Key { site: sites[x], w: if w > 0.5 { 1.0 - NUDGE } else { NUDGE } };
                }
            }
        }
        Some(Branch { center: c, radius: r, contacts: keys, snapped: raw })
    }
}
