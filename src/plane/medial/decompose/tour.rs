//! The augmented domain's boundary cycle (thesis 2.3.1) kept whole while
//! the divide step cuts it.
//!
//! With h holes the cycle has about 4h pieces, and each cut copies the
//! pieces of the subshape it cuts: a plate of holes, whose tree of loops
//! is a comb of columns, would cost O(h^1.5) or worse. Subshapes of the
//! divide step ([`Ranged`]) hold [`Span::Range`]s of the cycle instead,
//! opened into real pieces only where a cut's footpoints land (and wholly
//! once a subshape is small), so a subshape stays a handful of pieces, as
//! on a shape without holes. Counts over ranges (original parts, reflex
//! points, chains) come from prefix sums.
//!
//! A range means nothing without its cycle, so none of this is public:
//! leaves and stuck subshapes leave the divide step as plain
//! [`Subshape`]s.

use crate::kernel::Point;
use crate::plane::medial::decompose::cut::split_slots;
use crate::plane::medial::decompose::subshape::{
    along, chain_holds, BoundaryPos, ChainParts, CutIds, Piece, Slot, Subshape,
};
use crate::shape::{JointKind, Shape2d};
use std::borrow::Cow;

/// A piece of a subshape in the divide step: a piece, or pieces
/// `from..=to` of the augmented cycle that no cut has touched yet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Span {
    /// A chain or an auxiliary arc.
    Piece(Piece),
    /// Pieces `from..=to` of the cycle.
    Range { from: usize, to: usize },
}

impl From<Piece> for Span {
    fn from(p: Piece) -> Span {
        Span::Piece(p)
    }
}

impl Slot for Span {
    fn piece(self) -> Option<Piece> {
        match self {
            Span::Piece(p) => Some(p),
            Span::Range { .. } => None,
        }
    }
}

/// A subshape in the divide step: a closed cyclic list of spans.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ranged {
    pub(crate) spans: Vec<Span>,
}

impl From<Subshape> for Ranged {
    fn from(s: Subshape) -> Ranged {
        Ranged { spans: s.pieces.into_iter().map(Span::Piece).collect() }
    }
}

impl Ranged {
    /// True when some span is a range of the cycle.
    pub(crate) fn has_ranges(&self) -> bool {
        self.spans.iter().any(|p| matches!(p, Span::Range { .. }))
    }

    /// The pieces that are not in ranges.
    pub(crate) fn pieces(&self) -> impl Iterator<Item = Piece> + '_ {
        self.spans.iter().filter_map(|p| p.piece())
    }

    /// The subshape itself when it holds no range.
    pub(crate) fn plain(&self) -> Option<Subshape> {
        self.spans.iter().map(|p| p.piece()).collect::<Option<Vec<Piece>>>().map(|pieces| Subshape { pieces })
    }
}

/// The boundary cycle with prefix counts and, per loop, its chains. The
/// default has no pieces: for subshapes that hold no range.
#[derive(Debug, Clone, Default)]
pub(crate) struct Tour {
    pieces: Vec<Piece>,
    /// Prefix sums over pieces: original parts, reflex single points,
    /// chains that are more than a point.
    parts: Vec<usize>,
    points: Vec<usize>,
    chains: Vec<usize>,
    /// For each loop, the indices of its chains in the cycle, and where
    /// each starts along the loop from the first one's start (a whole turn
    /// on for those starting back there after the walk went round).
    on_loop: Vec<Vec<usize>>,
    on_key: Vec<Vec<(usize, f64)>>,
}

/// Pieces opened on either side of one a footpoint lands on: the side
/// rules of [`Subshape::split`] look at a chain's neighbouring arcs.
const MARGIN: usize = 1;

impl Tour {
    /// The cycle `boundary` (pieces chains and auxiliary arcs only) of `shape`.
    pub(crate) fn new(shape: &Shape2d, boundary: &Subshape) -> Tour {
        let n = boundary.pieces.len();
        let mut t = Tour {
            pieces: boundary.pieces.clone(),
            parts: Vec::with_capacity(n + 1),
            points: Vec::with_capacity(n + 1),
            chains: Vec::with_capacity(n + 1),
            on_loop: vec![Vec::new(); shape.loops().len()],
            on_key: vec![Vec::new(); shape.loops().len()],
        };
        let (mut parts, mut points, mut chains) = (0, 0, 0);
        for (i, p) in boundary.pieces.iter().enumerate() {
            t.parts.push(parts);
            t.points.push(points);
            t.chains.push(chains);
            match *p {
                Piece::Chain { from, to } => {
                    let k = ChainParts::new(shape, from, to).len();
                    parts += k;
                    chains += usize::from(from != to);
                    let reflex =
                        from.vertex(shape).is_some_and(|v| shape.joint(from.loop_index, v) == JointKind::Reflex);
                    points += usize::from(k == 0 && reflex);
                    t.on_loop[from.loop_index].push(i);
                }
                Piece::Aux { .. } => {}
            }
        }
        t.parts.push(parts);
        t.points.push(points);
        t.chains.push(chains);
        for (l, list) in t.on_loop.iter().enumerate() {
            let from_of = |i: usize| match t.pieces[i] {
                Piece::Chain { from, .. } => from,
                _ => BoundaryPos { loop_index: l, element: 0, t: 0.0 },
            };
            let Some(&first) = list.first() else { continue };
            let origin = from_of(first);
            let n = shape.loops()[l].len();
            let mut went_on = false;
            for &i in list {
                let f = from_of(i);
                let k = if f == origin && went_on {
                    (n, origin.t)
                } else {
                    along(shape, origin, f).unwrap_or((n, origin.t))
                };
                went_on |= f != origin;
                t.on_key[l].push(k);
            }
        }
        t
    }

    /// The whole cycle as one range.
    pub(crate) fn root(&self) -> Ranged {
        Ranged { spans: vec![Span::Range { from: 0, to: self.pieces.len() - 1 }] }
    }

    /// Original parts in range `from..=to`.
    pub(crate) fn parts(&self, from: usize, to: usize) -> usize {
        self.parts[to + 1] - self.parts[from]
    }

    /// Reflex single points in range `from..=to`.
    pub(crate) fn points(&self, from: usize, to: usize) -> usize {
        self.points[to + 1] - self.points[from]
    }

    /// Chains that are more than a point in range `from..=to`.
    pub(crate) fn chains(&self, from: usize, to: usize) -> usize {
        self.chains[to + 1] - self.chains[from]
    }

    /// The `k`-th chain (more than a point) of the range starting at
    /// `from`; `None` past the cycle's end.
    pub(crate) fn chain(&self, from: usize, k: usize) -> Option<(BoundaryPos, BoundaryPos)> {
        let want = self.chains.get(from)? + k;
        // The piece after which the prefix passes `want` is the chain.
        let i = self.chains.partition_point(|&c| c <= want).checked_sub(1)?;
        match self.pieces.get(i)? {
            &Piece::Chain { from, to } => Some((from, to)),
            _ => None,
        }
    }

    /// The piece index of the `k`-th reflex single point of the range
    /// starting at `from`; `None` past the cycle's end.
    pub(crate) fn point(&self, from: usize, k: usize) -> Option<usize> {
        let want = self.points.get(from)? + k;
        self.points.partition_point(|&c| c <= want).checked_sub(1).filter(|&i| i < self.pieces.len())
    }

    /// Piece `i` of the cycle.
    pub(crate) fn piece(&self, i: usize) -> Option<Piece> {
        self.pieces.get(i).copied()
    }

    /// `s` with every range replaced by its pieces.
    pub(crate) fn expand(&self, s: &Ranged) -> Subshape {
        let mut pieces = Vec::with_capacity(s.spans.len());
        for p in &s.spans {
            match *p {
                Span::Range { from, to } => pieces.extend_from_slice(&self.pieces[from..=to]),
                Span::Piece(p) => pieces.push(p),
            }
        }
        Subshape { pieces }
    }

    /// Number of pieces `s` has once expanded.
    pub(crate) fn expanded_len(&self, s: &Ranged) -> usize {
        s.spans.iter().map(|p| if let Span::Range { from, to } = *p { to + 1 - from } else { 1 }).sum()
    }

    /// Pushes the cycle's chains on `q`'s loop that hold `q`. A loop's
    /// chains follow its travel order from the first one's start, so a
    /// binary search finds the last chain starting at or before `q`; the
    /// chains starting at that same place (single points between disks
    /// at one vertex) and the one before them are the only others that
    /// can hold it.
    fn chains_holding(&self, shape: &Shape2d, q: BoundaryPos, out: &mut Vec<usize>) {
        let list = &self.on_loop[q.loop_index];
        let from_of = |i: usize| match self.pieces[i] {
            Piece::Chain { from, to } => Some((from, to)),
            _ => None,
        };
        let Some((origin, _)) = list.first().and_then(|&i| from_of(i)) else { return };
        let keys = &self.on_key[q.loop_index];
        let holds = |i: usize| from_of(i).is_some_and(|(from, to)| chain_holds(shape, from, to, q).is_some());
        let kq = along(shape, origin, q).unwrap_or((usize::MAX, 0.0));
        let mut starts = vec![keys.partition_point(|&k| k <= kq)];
        if q == origin {
            starts.push(list.len());
        }
        for idx in starts {
            // Back from the last chain starting at or before `q`: the run
            // of chains starting where it does, and one more.
            let mut j = idx;
            let mut group: Option<(usize, f64)> = None;
            while j > 0 {
                j -= 1;
                if holds(list[j]) {
                    out.push(list[j]);
                }
                let kf = keys[j];
                match group {
                    None => group = Some(kf),
                    Some(g) if g != kf => break,
                    Some(_) => {}
                }
            }
        }
        // Past everything (q before the first start on its element): the
        // last chain runs round to it.
        if let Some(&last) = list.last() {
            if holds(last) {
                out.push(last);
            }
        }
    }

    /// `s` with the cycle's chains that hold any of `feet` (either way of
    /// writing a vertex), and [`MARGIN`] pieces on either side, taken out
    /// of their ranges as real pieces.
    fn open_at<'a>(&self, shape: &Shape2d, s: &'a Ranged, feet: &[BoundaryPos]) -> Cow<'a, Ranged> {
        if !s.has_ranges() {
            return Cow::Borrowed(s);
        }
        let mut hit: Vec<usize> = Vec::new();
        for &f in feet {
            for q in [Some(f), f.other_way(shape)].into_iter().flatten() {
                self.chains_holding(shape, q, &mut hit);
            }
        }
        // The hit pieces and their neighbours, round the end of the cycle
        // too (its last chain and its first arc meet at the outer loop's
        // first contact).
        let n = self.pieces.len();
        let mut open: Vec<usize> =
            hit.iter().flat_map(|&h| (0..=2 * MARGIN).map(move |d| (h + n + d - MARGIN) % n)).collect();
        open.sort_unstable();
        open.dedup();
        let mut spans = Vec::with_capacity(s.spans.len() + 4 * hit.len());
        for p in &s.spans {
            let Span::Range { from, to } = *p else {
                spans.push(*p);
                continue;
            };
            let mut next = from;
            let first = open.partition_point(|&h| h < from);
            for &h in open[first..].iter().take_while(|&&h| h <= to) {
                if h > next {
                    spans.push(Span::Range { from: next, to: h - 1 });
                }
                spans.push(Span::Piece(self.pieces[h]));
                next = h + 1;
            }
            if next <= to {
                spans.push(Span::Range { from: next, to });
            }
        }
        Cow::Owned(Ranged { spans })
    }

    /// [`Subshape::split`] for a subshape of the divide step: the ranges
    /// where `feet` land are opened first, those between them go to the
    /// subshapes whole.
    pub(crate) fn cut<C: CutIds + ?Sized>(
        &self,
        shape: &Shape2d,
        s: &Ranged,
        disk: usize,
        feet: &[BoundaryPos],
        center: Point,
        cuts: &C,
    ) -> Option<Vec<Ranged>> {
        let opened = self.open_at(shape, s, feet);
        let out = split_slots(&opened.spans, shape, disk, feet, center, cuts)?;
        Some(out.into_iter().map(|spans| Ranged { spans }).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plane::medial::decompose::augment::augment;
    use crate::plane::medial::decompose::divide::decompose_with;
    use crate::plane::DiskFinder;
    use crate::shape::{samples, Element, Loop, ShapeOptions};

    fn shape_of(k: usize, seed: u64) -> Shape2d {
        Shape2d::from_bulge_loops(samples::random_holes(k, seed), &ShapeOptions::default()).unwrap()
    }

    #[test]
    fn ranges_expand_to_the_cycle_and_count_like_it() {
        let shape = shape_of(6, 3);
        let finder = DiskFinder::new(&shape);
        let aug = augment(&finder).unwrap();
        let tour = Tour::new(&shape, &aug.boundary);
        assert_eq!(tour.expand(&tour.root()), aug.boundary);
        let n = aug.boundary.pieces.len();
        let mut rng = crate::util::mix::Mix(5);
        for _ in 0..200 {
            let (a, b) = (rng.below(n), rng.below(n));
            let (from, to) = (a.min(b), a.max(b));
            let whole = Subshape { pieces: aug.boundary.pieces[from..=to].to_vec() };
            let ranged = Ranged { spans: vec![Span::Range { from, to }] };
            assert_eq!(tour.expand(&ranged), whole);
            let parts: usize = whole.chains().map(|(f, t)| ChainParts::new(&shape, f, t).len()).sum();
            assert_eq!(tour.parts(from, to), parts);
            assert_eq!(tour.chains(from, to), whole.chains().count());
            for k in 0..tour.chains(from, to) {
                assert_eq!(tour.chain(from, k), whole.chains().nth(k));
            }
            // Opening at a chain's points keeps the sequence.
            let first = whole.chains().next();
            if let Some((f, t)) = first {
                let opened = tour.open_at(&shape, &ranged, &[f, t]);
                assert_eq!(tour.expand(&opened), whole);
                assert!(opened.pieces().any(|p| matches!(p, Piece::Chain { .. })));
            }
        }
    }

    /// Length of the original boundary a subshape's chains run along.
    fn chain_length(shape: &Shape2d, s: &Subshape) -> f64 {
        s.chains()
            .map(|(f, t)| {
                let lp = &shape.loops()[f.loop_index];
                ChainParts::new(shape, f, t)
                    .iter()
                    .map(|(e, lo, hi)| {
                        let el: Element = lp.element(e);
                        el.length() * (hi - lo)
                    })
                    .sum::<f64>()
            })
            .sum()
    }

    #[test]
    fn leaves_cover_every_loop_once() {
        for (k, seed) in [(3, 1), (8, 2), (20, 3)] {
            let shape = shape_of(k, seed);
            let d = decompose_with(&shape, 7, 32).unwrap();
            let leaves: Vec<&Subshape> = d.leaves.iter().chain(d.stuck.iter()).collect();
            let covered: f64 = leaves.iter().map(|s| chain_length(&shape, s)).sum();
            let perimeter: f64 = shape.loops().iter().map(Loop::perimeter).sum();
            assert!((covered - perimeter).abs() <= 1e-9 * perimeter, "{k}: {covered} vs {perimeter}");
        }
    }
}

#[cfg(test)]
mod apex_tests {
    use super::*;
    use crate::plane::medial::decompose::augment::augment;
    use crate::plane::medial::decompose::subshape::Cut;
    use crate::plane::DiskFinder;
    use crate::shape::{samples, ElementRef, ShapeOptions};

    fn apex_shape(twin: bool, many: bool) -> Shape2d {
        Shape2d::from_bulge_loops(samples::spike_holes(twin, many), &ShapeOptions::default()).unwrap()
    }

    /// Splits `root` (ranges of `tour`) by the maximal disk grown at the
    /// apex from `element` at fraction `t`, the apex written as `apex`;
    /// the children's sizes once expanded.
    fn split_sizes(
        s: &Shape2d,
        tour: &Tour,
        root: &Ranged,
        cuts: &[Cut],
        element: usize,
        t: f64,
        apex: BoundaryPos,
    ) -> Option<Vec<usize>> {
        let finder = DiskFinder::new(s);
        let d = finder.max_disk(ElementRef { loop_index: 0, element }, t);
        let feet: Vec<BoundaryPos> = std::iter::once(apex)
            .chain(d.footpoints[1..].iter().map(|f| {
                let e = s.loops()[f.element.loop_index].element(f.element.element);
                BoundaryPos { loop_index: f.element.loop_index, element: f.element.element, t: e.param_of(f.point) }
            }))
            .collect();
        let mut cuts = cuts.to_vec();
        cuts.push(Cut { center: d.center, radius: d.radius });
        let children = tour.cut(s, root, cuts.len() - 1, &feet, d.center, &cuts)?;
        let mut sizes: Vec<usize> = children.iter().map(|c| tour.expanded_len(c)).collect();
        sizes.sort_unstable();
        Some(sizes)
    }

    #[test]
    fn a_cut_at_the_apex_splits_alike_however_the_apex_is_written() {
        for (twin, many) in [(false, true), (true, false), (true, true)] {
            let s = apex_shape(twin, many);
            let finder = DiskFinder::new(&s);
            let aug = augment(&finder).unwrap();
            let tour = Tour::new(&s, &aug.boundary);
            let n = s.loops()[0].len();
            let start = BoundaryPos { loop_index: 0, element: 0, t: 0.0 };
            let end = BoundaryPos { loop_index: 0, element: n - 1, t: 1.0 };
            for root in [Ranged::from(aug.boundary.clone()), tour.root()] {
                for (element, t) in [(0, 0.0), (n - 1, 1.0)] {
                    let a = split_sizes(&s, &tour, &root, &aug.cuts, element, t, start);
                    let b = split_sizes(&s, &tour, &root, &aug.cuts, element, t, end);
                    assert!(a.is_some(), "twin {twin} many {many}: the cut at the apex from {element} was lost");
                    assert_eq!(a, b, "twin {twin} many {many} from element {element}");
                }
            }
        }
    }
}
