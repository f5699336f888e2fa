//! Subshapes of the divide step (thesis 2.2.1, Definitions 2.2.1–2.2.2,
//! Figure 2.1).
//!
//! A maximal disk D with footpoints f₁ … f_k (in boundary order) cuts a
//! (sub)shape into k subshapes. Subshape i runs along the boundary from f_i
//! to f_{i+1} and returns along D's circle, counter-clockwise around D's
//! centre, the far way round: it contains all of D, so its medial axis ends
//! at D's centre, where the k partial axes are glued (conquer step).
//!
//! A subshape is a cyclic list of pieces: chains of original boundary
//! (ranges of positions on one loop, never copies of elements) and
//! auxiliary arcs (a disk id; the arc's ends are the ends of the
//! neighbouring chains). A chain from a position to itself is a single
//! point: a footpoint shared by two disks, like a reflex vertex between two
//! auxiliary arcs (the thesis's zero-length arcs).
//!
//! Cutting a subshape by a disk's footpoints is in `cut.rs`.

use crate::kernel::Point;
use crate::shape::{Element, JointKind, Shape2d, Vertex};

/// A position on the original boundary: element `element` of loop
/// `loop_index` (as in [`Shape2d::loops`]) at arc-length fraction `t` ∈ [0, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundaryPos {
    /// Loop index.
    pub loop_index: usize,
    /// Element index within the loop.
    pub element: usize,
    /// Fraction along the element.
    pub t: f64,
}

impl BoundaryPos {
    /// The point at this position.
    pub fn point(&self, shape: &Shape2d) -> Point {
        shape.loops()[self.loop_index].element(self.element).point_at(self.t)
    }

    /// The vertex this position is at (the start of element `t` = 0 or the
    /// end of `t` = 1), if it is one.
    pub fn vertex(&self, shape: &Shape2d) -> Option<usize> {
        match self.t {
            0.0 => Some(self.element),
            1.0 => Some((self.element + 1) % shape.loops()[self.loop_index].len()),
            _ => None,
        }
    }

    /// The same vertex written the other way: the end of the element
    /// before (`t` = 1) for the start of an element (`t` = 0), and back.
    /// `None` inside an element.
    pub fn other_way(&self, shape: &Shape2d) -> Option<BoundaryPos> {
        let n = shape.loops()[self.loop_index].len();
        match self.t {
            0.0 => Some(BoundaryPos { element: (self.element + n - 1) % n, t: 1.0, ..*self }),
            1.0 => Some(BoundaryPos { element: (self.element + 1) % n, t: 0.0, ..*self }),
            _ => None,
        }
    }
}

/// Where the chain from `from` to `to` holds `p` (as [`along`] from
/// `from`), or `None` when it does not.
pub(crate) fn chain_holds(shape: &Shape2d, from: BoundaryPos, to: BoundaryPos, p: BoundaryPos) -> Option<(usize, f64)> {
    let (k, end) = (along(shape, from, p)?, along(shape, from, to)?);
    (k >= (0, from.t) && k <= end).then_some(k)
}

/// One piece of a subshape's boundary, in travel order (interior on the left).
///
/// A piece stands for itself. The divide step's ranges of an augmented
/// domain's cycle (thesis 2.3.1) index a cycle that a subshape does not
/// carry, so they stay inside the divide step: no variant here, no public
/// way to build one.
///
/// ```compile_fail,E0599
/// let _ = medax::plane::Piece::Tour { from: 0, to: 1 };
/// ```
///
/// ```compile_fail,E0603
/// use medax::plane::Tour;
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    /// Original boundary from `from` forwards along its loop to `to`
    /// (possibly passing the loop's element 0).
    Chain {
        /// Start.
        from: BoundaryPos,
        /// End (equal to `from`: a single point).
        to: BoundaryPos,
    },
    /// An arc of the circle of disk `disk` (an index into the caller's list
    /// of dividing disks), counter-clockwise from the end of the previous
    /// piece to the start of the next.
    Aux {
        /// Which dividing disk.
        disk: usize,
    },
}

/// An entry of a piece list that a cut splits: a [`Piece`], or, inside the
/// divide step, a stand-in for a run of pieces that no footpoint lands on
/// and that a cut copies whole (a range of an augmented domain's cycle).
/// Crate-private so that a public [`Subshape`] only ever holds pieces that
/// stand for themselves.
pub(crate) trait Slot: Copy + From<Piece> {
    /// The piece itself; `None` for a stand-in.
    fn piece(self) -> Option<Piece>;

    /// The chain's ends, when this is a chain.
    fn chain(self) -> Option<(BoundaryPos, BoundaryPos)> {
        match self.piece()? {
            Piece::Chain { from, to } => Some((from, to)),
            Piece::Aux { .. } => None,
        }
    }
}

impl Slot for Piece {
    fn piece(self) -> Option<Piece> {
        Some(self)
    }
}

/// A dividing disk as subshapes see it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cut {
    /// Centre, model units.
    pub center: Point,
    /// Radius, model units.
    pub radius: f64,
}

/// The dividing disks that `Piece::Aux` ids refer to, by id: the flat list
/// of a finished decomposition, or the view of one path of the divide
/// step (the disks cut before it forked and the ancestors of the
/// subshape at hand; see `divide::PathCuts`).
pub trait CutIds: std::ops::Index<usize, Output = Cut> {
    /// The next id: one more than the largest id in view.
    fn count(&self) -> usize;
}

impl CutIds for [Cut] {
    fn count(&self) -> usize {
        self.len()
    }
}

impl CutIds for Vec<Cut> {
    fn count(&self) -> usize {
        self.len()
    }
}

/// A subshape: a closed cyclic list of pieces.
#[derive(Debug, Clone, PartialEq)]
pub struct Subshape {
    /// The pieces in travel order.
    pub pieces: Vec<Piece>,
}

/// Where a position lies along a chain starting at `from`: (elements
/// after `from.element`, fraction), comparable lexicographically. `None`
/// on another loop.
pub(crate) fn along(shape: &Shape2d, from: BoundaryPos, p: BoundaryPos) -> Option<(usize, f64)> {
    if p.loop_index != from.loop_index {
        return None;
    }
    let n = shape.loops()[p.loop_index].len();
    let mut d = (p.element + n - from.element) % n;
    if d == 0 && p.t < from.t {
        d = n;
    }
    Some((d, p.t))
}

/// The element parts a chain runs over, in travel order: each element it
/// uses with the fraction range it uses. An element the chain touches only
/// at its very start or end is not one of its parts; a single-point chain
/// has none. Constant time to build and to index, so that a chain of a
/// whole loop costs nothing until its parts are visited.
#[derive(Debug, Clone, Copy)]
pub struct ChainParts {
    from: BoundaryPos,
    to: BoundaryPos,
    /// Elements in the loop.
    n: usize,
    /// Elements after `from.element` where the chain ends.
    steps: usize,
    /// Offsets (from `from.element`) of the first and one past the last part.
    first: usize,
    end: usize,
}

impl ChainParts {
    /// The parts of the chain from `from` to `to`.
    pub fn new(shape: &Shape2d, from: BoundaryPos, to: BoundaryPos) -> ChainParts {
        let n = shape.loops()[from.loop_index].len();
        let steps = along(shape, from, to).map_or(0, |a| a.0);
        let (first, end) = if from == to {
            (0, 0)
        } else {
            (usize::from(from.t == 1.0), steps + 1 - usize::from(to.t == 0.0 && steps > 0))
        };
        ChainParts { from, to, n, steps, first, end: end.max(first) }
    }

    /// Number of parts.
    pub fn len(&self) -> usize {
        self.end - self.first
    }

    /// True when the chain has no part.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Part `i` (< `len()`): element index and the fraction range used.
    pub fn get(&self, i: usize) -> (usize, f64, f64) {
        let k = self.first + i;
        let lo = if k == 0 { self.from.t } else { 0.0 };
        let hi = if k == self.steps { self.to.t } else { 1.0 };
        ((self.from.element + k) % self.n, lo, hi)
    }

    /// All parts in travel order.
    pub fn iter(&self) -> impl Iterator<Item = (usize, f64, f64)> + '_ {
        (0..self.len()).map(|i| self.get(i))
    }
}

/// A subshape whose whole boundary lies within a few tolerances of its
/// dividing disks' circles, so that the order of footpoints along it is
/// rounding rather than geometry: every disk there is each of these disks
/// within the tolerance, and the subshape's axis is its ports.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hugged {
    /// The tip of a smooth lobe cut off by one disk (an index into `cuts`)
    /// at nearly its osculating circle: the disk is the tip's whole axis.
    Tip(usize),
    /// A band between two disks (auxiliary pieces `[j0, j1]`, with one
    /// chain between them on either side) that both hug both chains: near
    /// the end of a branch at a curvature extremum, where the disks'
    /// centres move by far more than the boundary strays from them. Its
    /// axis is the straight edge between the two disks' centres.
    Band([usize; 2]),
    /// Three or more disks, or two that do not make a band, all pairwise
    /// as close as a band's and all hugging every chain: where the
    /// boundary follows one circle within rounding over a stretch that
    /// several dividing disks cut (the end of a branch at the curvature
    /// maximum of a nearly circular curve). Its axis is the path through
    /// the disks' centres in order of radius.
    Cluster,
}

/// How `s` is [`Hugged`] by its dividing disks, its chains staying within
/// `slack` (model units) of each disk's circle with no convex corner;
/// `None` for any other subshape. Stops at the first part that strays, so
/// it costs little on ordinary subshapes.
pub fn hugged<C: CutIds + ?Sized>(shape: &Shape2d, s: &Subshape, cuts: &C, slack: f64) -> Option<Hugged> {
    let aux: Vec<usize> = (0..s.pieces.len()).filter(|&j| matches!(s.pieces[j], Piece::Aux { .. })).collect();
    let disk = |j: usize| match s.pieces[j] {
        Piece::Aux { disk } => cuts[disk],
        Piece::Chain { .. } => unreachable!("aux holds auxiliary pieces only"),
    };
    let found = match *aux.as_slice() {
        [j] => match s.pieces[j] {
            Piece::Aux { disk } => Hugged::Tip(disk),
            Piece::Chain { .. } => return None,
        },
        // Exactly aux, chain, aux, chain: one side each way, between
        // disks close enough that the straight edge between their centres
        // (radius linear) strays from the boundary by at most `slack`: a
        // boundary point at distance r(t) from the moving centre c(t)
        // deviates from linear by at most |c1 − c0|² / (8 r) (the
        // distance is convex along the segment). Farther apart, the disks
        // hug short chains where the axis runs towards a curvature
        // extremum, and the base case decides the contacts.
        [j0, j1]
            if s.pieces.len() == 4
                && j1 == j0 + 2
                && s.chains().count() == 2
                && (disk(j0).center - disk(j1).center).norm2()
                    <= 8.0 * disk(j0).radius.min(disk(j1).radius) * slack =>
        {
            Hugged::Band([j0, j1])
        }
        [_, _, ..]
            if aux.iter().enumerate().all(|(x, &i)| {
                aux[x + 1..].iter().all(|&j| {
                    (disk(i).center - disk(j).center).norm2() <= 8.0 * disk(i).radius.min(disk(j).radius) * slack
                })
            }) =>
        {
            Hugged::Cluster
        }
        _ => return None,
    };
    // A convex corner is a feature however close to the circle: the axis
    // reaches it. A reflex vertex that close is touched by the disk within
    // the tolerance (with a fan of rounding width, or the disk would have
    // cut there).
    let hugs = aux.iter().all(|&j| s.chains().all(|chain| chain_hugs(shape, chain, disk(j), slack)));
    hugs.then_some(found)
}

/// Whether the chain `from` → `to` stays within `slack` (model units) of
/// the circle of `disk` with no convex corner inside it.
pub fn chain_hugs(shape: &Shape2d, (from, to): (BoundaryPos, BoundaryPos), disk: Cut, slack: f64) -> bool {
    let lp = &shape.loops()[from.loop_index];
    ChainParts::new(shape, from, to).iter().enumerate().all(|(k, (e, lo, hi))| {
        (k == 0 || shape.joint(from.loop_index, e) != JointKind::Convex)
            && lp.element(e).circle_deviation(lo, hi, disk.center, disk.radius) <= slack
    })
}

impl Subshape {
    /// The whole of loop `loop_index` as one chain (a simply connected shape
    /// before any cut).
    pub fn whole_loop(shape: &Shape2d, loop_index: usize) -> Subshape {
        let n = shape.loops()[loop_index].len();
        let from = BoundaryPos { loop_index, element: 0, t: 0.0 };
        let to = BoundaryPos { loop_index, element: n - 1, t: 1.0 };
        Subshape { pieces: vec![Piece::Chain { from, to }] }
    }

    /// The chains that are more than a point, as (from, to).
    pub fn chains(&self) -> impl Iterator<Item = (BoundaryPos, BoundaryPos)> + '_ {
        self.pieces.iter().filter_map(|p| match *p {
            Piece::Chain { from, to } if from != to => Some((from, to)),
            _ => None,
        })
    }

    /// The boundary as a closed bulge loop (vertices in travel order), for
    /// drawing and for checks: chains contribute their (partial) elements,
    /// auxiliary arcs the counter-clockwise arc of their disk.
    pub fn to_vertices(&self, shape: &Shape2d, cuts: &[Cut]) -> Vec<Vertex> {
        let m = self.pieces.len();
        let start = |j: usize| match self.pieces[j % m] {
            Piece::Chain { from, .. } => Some(from.point(shape)),
            Piece::Aux { .. } => None,
        };
        let end = |j: usize| match self.pieces[j % m] {
            Piece::Chain { to, .. } => Some(to.point(shape)),
            Piece::Aux { .. } => None,
        };
        let mut out = Vec::new();
        for (j, piece) in self.pieces.iter().enumerate() {
            match *piece {
                Piece::Chain { from, to } => {
                    let lp = &shape.loops()[from.loop_index];
                    for (e, ta, tb) in ChainParts::new(shape, from, to).iter().filter(|p| p.2 > p.1) {
                        let bulge = match lp.element(e) {
                            Element::Segment(_) => 0.0,
                            Element::Arc(a) => (a.sweep() * (tb - ta) / 4.0).tan(),
                        };
                        out.push(Vertex { p: lp.element(e).point_at(ta), bulge });
                    }
                }
                Piece::Aux { disk } => {
                    let c = cuts[disk];
                    let (Some(a), Some(b)) = (end(j + m - 1), start(j + 1)) else { continue };
                    let (u, v) = (a - c.center, b - c.center);
                    let mut sweep = crate::kernel::direction::signed_angle(u, v);
                    if sweep <= 0.0 {
                        sweep += std::f64::consts::TAU;
                    }
                    out.push(Vertex { p: a, bulge: (sweep / 4.0).tan() });
                }
            }
        }
        out
    }
}
