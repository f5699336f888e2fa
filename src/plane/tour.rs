//! The augmented domain's boundary cycle (thesis 2.3.1) kept whole while
//! the divide step cuts it.
//!
//! With h holes the cycle has about 3h pieces, and each cut copies the
//! pieces of the subshape it cuts: a plate of holes, whose tree of loops
//! is a comb of columns, would cost O(h^1.5) or worse. Subshapes hold
//! [`Piece::Tour`] ranges of the cycle instead, opened into real pieces
//! only where a cut's footpoints land (and wholly once a subshape is small),
//! so a subshape stays a handful of pieces, as on a shape without holes.
//! Counts over ranges (original parts, reflex points, chains, auxiliary
//! arcs) come from prefix sums.

use super::subshape::{BoundaryPos, ChainParts, Piece, Subshape};
use crate::shape::{JointKind, Shape2d};
use std::borrow::Cow;

/// The boundary cycle with prefix counts and, per loop, its chains.
#[derive(Debug, Clone, Default)]
pub struct Tour {
    pieces: Vec<Piece>,
    /// Prefix sums over pieces: original parts, reflex single points,
    /// chains that are more than a point, auxiliary arcs.
    parts: Vec<usize>,
    points: Vec<usize>,
    chains: Vec<usize>,
    aux: Vec<usize>,
    /// For each loop, the indices of its chains in the cycle.
    on_loop: Vec<Vec<usize>>,
}

/// Pieces opened on either side of one a footpoint lands on: the side
/// rules of [`Subshape::split`] look at a chain's neighbouring arcs.
const MARGIN: usize = 1;

impl Tour {
    /// The cycle `boundary` (pieces chains and auxiliary arcs only) of `shape`.
    pub fn new(shape: &Shape2d, boundary: &Subshape) -> Tour {
        let n = boundary.pieces.len();
        let mut t = Tour {
            pieces: boundary.pieces.clone(),
            parts: Vec::with_capacity(n + 1),
            points: Vec::with_capacity(n + 1),
            chains: Vec::with_capacity(n + 1),
            aux: Vec::with_capacity(n + 1),
            on_loop: vec![Vec::new(); shape.loops().len()],
        };
        let (mut parts, mut points, mut chains, mut aux) = (0, 0, 0, 0);
        for (i, p) in boundary.pieces.iter().enumerate() {
            t.parts.push(parts);
            t.points.push(points);
            t.chains.push(chains);
            t.aux.push(aux);
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
                Piece::Aux { .. } => aux += 1,
                Piece::Tour { .. } => unreachable!("a tour is made of chains and arcs"),
            }
        }
        t.parts.push(parts);
        t.points.push(points);
        t.chains.push(chains);
        t.aux.push(aux);
        t
    }

    /// The whole cycle as one range.
    pub fn root(&self) -> Subshape {
        Subshape { pieces: vec![Piece::Tour { from: 0, to: self.pieces.len() - 1 }] }
    }

    /// Original parts in range `from..=to`.
    pub fn parts(&self, from: usize, to: usize) -> usize {
        self.parts[to + 1] - self.parts[from]
    }

    /// Reflex single points in range `from..=to`.
    pub fn points(&self, from: usize, to: usize) -> usize {
        self.points[to + 1] - self.points[from]
    }

    /// Chains that are more than a point in range `from..=to`.
    pub fn chains(&self, from: usize, to: usize) -> usize {
        self.chains[to + 1] - self.chains[from]
    }

    /// Auxiliary arcs in range `from..=to`.
    pub fn aux(&self, from: usize, to: usize) -> usize {
        self.aux[to + 1] - self.aux[from]
    }

    /// The `k`-th chain (more than a point) in range `from..=to`.
    pub fn chain(&self, from: usize, k: usize) -> (BoundaryPos, BoundaryPos) {
        let want = self.chains[from] + k;
        // The first piece whose prefix passes `want` is the chain.
        let i = self.chains.partition_point(|&c| c <= want) - 1;
        match self.pieces[i] {
            Piece::Chain { from, to } => (from, to),
            _ => unreachable!("prefix counts step only at chains"),
        }
    }

    /// `s` with every range replaced by its pieces.
    pub fn expand(&self, s: &Subshape) -> Subshape {
        let mut pieces = Vec::with_capacity(s.pieces.len());
        for p in &s.pieces {
            match *p {
                Piece::Tour { from, to } => pieces.extend_from_slice(&self.pieces[from..=to]),
                other => pieces.push(other),
            }
        }
        Subshape { pieces }
    }

    /// Number of pieces `s` has once expanded.
    pub fn expanded_len(&self, s: &Subshape) -> usize {
        s.pieces.iter().map(|p| if let Piece::Tour { from, to } = *p { to + 1 - from } else { 1 }).sum()
    }

    /// `s` with the cycle's chains that hold any of `feet` (either way of
    /// writing a vertex), and [`MARGIN`] pieces on either side, taken out
    /// of their ranges as real pieces.
    pub fn open_at<'a>(&self, shape: &Shape2d, s: &'a Subshape, feet: &[BoundaryPos]) -> Cow<'a, Subshape> {
        if !s.pieces.iter().any(|p| matches!(p, Piece::Tour { .. })) {
            return Cow::Borrowed(s);
        }
        let mut hit: Vec<usize> = Vec::new();
        for &f in feet {
            let n = shape.loops()[f.loop_index].len();
            let other = match f.t {
                0.0 => Some(BoundaryPos { element: (f.element + n - 1) % n, t: 1.0, ..f }),
                1.0 => Some(BoundaryPos { element: (f.element + 1) % n, t: 0.0, ..f }),
                _ => None,
            };
            for &i in &self.on_loop[f.loop_index] {
                let Piece::Chain { from, to } = self.pieces[i] else { continue };
                let probe = Subshape { pieces: vec![Piece::Chain { from, to }] };
                if [Some(f), other].into_iter().flatten().any(|q| probe.holds(shape, q)) {
                    hit.push(i);
                }
            }
        }
        hit.sort_unstable();
        hit.dedup();
        let mut pieces = Vec::with_capacity(s.pieces.len() + 4 * hit.len());
        for p in &s.pieces {
            let Piece::Tour { from, to } = *p else {
                pieces.push(*p);
                continue;
            };
            let mut next = from;
            for &h in hit.iter().filter(|&&h| h + MARGIN >= from && h <= to + MARGIN) {
                let (a, b) = (h.saturating_sub(MARGIN).max(next), (h + MARGIN).min(to));
                if a > b {
                    continue;
                }
                if a > next {
                    pieces.push(Piece::Tour { from: next, to: a - 1 });
                }
                pieces.extend_from_slice(&self.pieces[a..=b]);
                next = b + 1;
            }
            if next <= to {
                pieces.push(Piece::Tour { from: next, to });
            }
        }
        Cow::Owned(Subshape { pieces })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plane::augment::augment;
    use crate::plane::divide::decompose_with;
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
        let mut rng = samples::Mix(5);
        for _ in 0..200 {
            let (a, b) = (rng.below(n), rng.below(n));
            let (from, to) = (a.min(b), a.max(b));
            let whole = Subshape { pieces: aug.boundary.pieces[from..=to].to_vec() };
            let ranged = Subshape { pieces: vec![Piece::Tour { from, to }] };
            assert_eq!(tour.expand(&ranged), whole);
            let parts: usize = whole.chains().map(|(f, t)| ChainParts::new(&shape, f, t).len()).sum();
            assert_eq!(tour.parts(from, to), parts);
            assert_eq!(tour.chains(from, to), whole.chains().count());
            let aux = whole.pieces.iter().filter(|p| matches!(p, Piece::Aux { .. })).count();
            assert_eq!(tour.aux(from, to), aux);
            for k in 0..tour.chains(from, to) {
                assert_eq!(tour.chain(from, k), whole.chains().nth(k).unwrap());
            }
            // Opening at a chain's points keeps the sequence.
            let first = whole.chains().next();
            if let Some((f, t)) = first {
                let opened = tour.open_at(&shape, &ranged, &[f, t]);
                assert_eq!(tour.expand(&opened), whole);
                assert!(opened.pieces.iter().any(|p| matches!(p, Piece::Chain { .. })));
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
            assert!(leaves.iter().all(|s| !s.pieces.iter().any(|p| matches!(p, Piece::Tour { .. }))));
            let covered: f64 = leaves.iter().map(|s| chain_length(&shape, s)).sum();
            let perimeter: f64 = shape.loops().iter().map(Loop::perimeter).sum();
            assert!((covered - perimeter).abs() <= 1e-9 * perimeter, "{k}: {covered} vs {perimeter}");
        }
    }
}
