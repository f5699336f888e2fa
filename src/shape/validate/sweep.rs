//! Intersection detection by a plane sweep (Shamos–Hoey), O(n log n) in the
//! worst case.
//!
//! Elements are cut into x-monotone pieces (arcs at their leftmost and
//! rightmost circle points). A vertical line sweeps left to right; the
//! pieces it crosses are kept ordered by height. Two elements that cross
//! are neighbours in that order at some moment before the sweep reaches
//! their leftmost crossing, so it suffices to test each pair that becomes
//! adjacent: O(n) tests and O(n log n) work, whatever the shape. The test
//! itself is [`approach_point`], which also reports near-touches between
//! neighbours. Pieces are compared at the later of their two left ends, a
//! relation that does not depend on the sweep position and is a consistent
//! order while no two pieces in the set cross — and the first crossing ends
//! the sweep.

use crate::kernel::element::Element;
use crate::kernel::Point;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::ElementRef;
use crate::shape::validate::intersect::element_pair_approach;
use crate::shape::validate::sweep_status::SweepStatus;
use rayon::prelude::*;
use std::cmp::Ordering;

#[derive(Debug, Clone, Copy)]
enum Shape {
    /// A non-vertical segment with its slope dy/dx.
    Line { slope: f64 },
    /// A vertical segment.
    Vertical,
    /// Upper (`true`) or lower half of the circle (`c`, `r`).
    Arc { c: Point, r: f64, upper: bool },
}

#[derive(Debug, Clone, Copy)]
struct Piece {
    /// Left end (smaller x, then smaller y).
    a: Point,
    /// Right end.
    b: Point,
    shape: Shape,
    /// Global element id.
    elem: u32,
    /// Unique piece id: the order tie-break.
    id: u32,
}

impl Piece {
    /// Height at `x` (clamped to the piece's x-range); a vertical piece
    /// answers with its lower end, which orders it where the sweep first meets it.
    fn y_at(&self, x: f64) -> f64 {
        match self.shape {
            Shape::Vertical => self.a.y.min(self.b.y),
            Shape::Line { slope } => {
                // End points exactly, so that shared ends compare equal.
                if x <= self.a.x {
                    self.a.y
                } else if x >= self.b.x {
                    self.b.y
                } else {
                    self.a.y + (x - self.a.x) * slope
                }
            }
            Shape::Arc { c, r, upper } => {
                if x <= self.a.x {
                    return self.a.y;
                }
                if x >= self.b.x {
                    return self.b.y;
                }
                let h = (r * r - (x - c.x) * (x - c.x)).max(0.0).sqrt();
                if upper {
                    c.y + h
                } else {
                    c.y - h
                }
            }
        }
    }

    /// Height order of two pieces that are both cut by the sweep line at some
    /// x ≥ `from`, decided at the later of their left ends (or `from`).
    fn order(&self, o: &Piece, from: f64) -> Ordering {
        if self.id == o.id {
            return Ordering::Equal;
        }
        let below = |x: f64| {
            let (y, yo) = (self.y_at(x), o.y_at(x));
            if y < yo {
                Some(Ordering::Less)
            } else if y > yo {
                Some(Ordering::Greater)
            } else {
                None
            }
        };
        let x = self.a.x.max(o.a.x).max(from);
        if let Some(ord) = below(x) {
            return ord;
        }
        // Same height at the later start (a shared end point): decide just
        // right of it, halfway to the nearer right end.
        let x2 = 0.5 * (x + self.b.x.min(o.b.x));
        if x2 > x {
            if let Some(ord) = below(x2) {
                return ord;
            }
        }
        self.id.cmp(&o.id)
    }
}

fn lex_less(p: Point, q: Point) -> bool {
    (p.x, p.y) < (q.x, q.y)
}

/// Cuts an element into x-monotone pieces.
fn pieces_of(e: &Element, elem: u32, out: &mut Vec<Piece>) {
    let mut push = |p: Point, q: Point, shape: Shape| {
        let (a, b) = if lex_less(p, q) { (p, q) } else { (q, p) };
        let id = out.len() as u32;
        out.push(Piece { a, b, shape, elem, id });
    };
    match e {
        Element::Segment(s) => {
            let (l, r) = if lex_less(s.a, s.b) { (s.a, s.b) } else { (s.b, s.a) };
            let shape = if r.x > l.x { Shape::Line { slope: (r.y - l.y) / (r.x - l.x) } } else { Shape::Vertical };
            push(s.a, s.b, shape)
        }
        Element::Arc(arc) => {
            let (c, r) = (arc.center, arc.radius);
            for (p0, p1, mid) in arc.monotone_pieces(Point::new(1.0, 0.0)) {
                push(p0, p1, Shape::Arc { c, r, upper: mid.sin() > 0.0 });
            }
        }
    }
}

/// Result of a sweep: the first pair found, or a sign that the order was
/// found inconsistent (floating-point trouble near an undetected crossing),
/// in which case the caller must fall back to an exhaustive method.
pub(crate) enum SweepOutcome {
    Clear,
    Found(ElementRef, ElementRef, Point),
    Inconsistent,
}

/// Sweeps all elements of `loops` (global ids by `offsets`) for a pair that
/// crosses or comes within `tol`, consecutive elements excepted at their
/// shared vertex.
/// Below this many pieces one sweep is cheaper than splitting into slabs.
const SLAB_MIN_PIECES: usize = 50_000;

pub(crate) fn sweep_intersections(loops: &[Loop], offsets: &[usize], tol: f64) -> SweepOutcome {
    let total = offsets.last().copied().unwrap_or(0);
    let slabs = if total < SLAB_MIN_PIECES { 1 } else { rayon::current_num_threads().clamp(1, 16) };
    sweep_in_slabs(loops, offsets, tol, slabs)
}

/// [`sweep_intersections`] with a given number of slabs.
pub(crate) fn sweep_in_slabs(loops: &[Loop], offsets: &[usize], tol: f64, slabs: usize) -> SweepOutcome {
    let locate = |id: u32| {
        let l = offsets.partition_point(|&o| o <= id as usize) - 1;
        ElementRef { loop_index: l, element: id as usize - offsets[l] }
    };
    let mut pieces = Vec::with_capacity(offsets.last().copied().unwrap_or(0) * 5 / 4);
    for (li, l) in loops.iter().enumerate() {
        for (i, e) in l.elements().enumerate() {
            pieces_of(&e, (offsets[li] + i) as u32, &mut pieces);
        }
    }
    let check = |p: &Piece, q: &Piece| -> Option<(ElementRef, ElementRef, Point)> {
        if p.elem == q.elem {
            return None;
        }
        let (ra, rb) = (locate(p.elem), locate(q.elem));
        let (f, s) = if ra <= rb { (ra, rb) } else { (rb, ra) };
        element_pair_approach(loops, f, s, tol).map(|pt| (f, s, pt))
    };
    // Vertical slabs with equal numbers of left ends, swept independently
    // and in parallel: every crossing lies in some slab, where both pieces
    // are present, and the leftmost crossing of a slab is found by its sweep.
    let slabs = slabs.clamp(1, pieces.len().max(1));
    let mut starts: Vec<f64> = pieces.iter().map(|p| p.a.x).collect();
    starts.sort_unstable_by(f64::total_cmp);
    let mut bounds = vec![f64::NEG_INFINITY];
    bounds.extend((1..slabs).map(|k| starts[k * starts.len() / slabs]));
    bounds.push(f64::INFINITY);
    bounds.dedup();
    let outcomes: Vec<SweepOutcome> =
        bounds.par_windows(2).map(|w| sweep_slab(&pieces, w[0], w[1], tol, &check)).collect();
    let mut result = SweepOutcome::Clear;
    for o in outcomes {
        match o {
            SweepOutcome::Found(..) => return o,
            SweepOutcome::Inconsistent => result = SweepOutcome::Inconsistent,
            SweepOutcome::Clear => {}
        }
    }
    result
}

type Check<'a> = dyn Fn(&Piece, &Piece) -> Option<(ElementRef, ElementRef, Point)> + Sync + 'a;

/// Shamos–Hoey over the slab `lo ≤ x ≤ hi`. Pieces that start left of the
/// slab enter at `lo`, ordered by their height there; pieces that end right
/// of it never leave.
fn sweep_slab(pieces: &[Piece], lo: f64, hi: f64, tol: f64, check: &Check<'_>) -> SweepOutcome {
    // Event keys: coordinates' bits mapped to integers in float order, so
    // the sort compares integers; at one point removals come first, so the
    // set never holds a piece whose right end lies behind the sweep.
    // Carried pieces get the smallest key and enter before anything else.
    let ordered = |v: f64| {
        let b = v.to_bits();
        if b >> 63 == 1 {
            !b
        } else {
            b | (1 << 63)
        }
    };
    let mut keyed: Vec<(u64, u64, u64)> = Vec::new();
    for p in pieces {
        // Each piece is live over its x-range widened by `tol` on both
        // sides, so pieces that only meet (or nearly meet) where one ends
        // and another starts are in the set together and get compared.
        let (enter_x, leave_x) = (p.a.x - tol, p.b.x + tol);
        if leave_x < lo || enter_x > hi {
            continue;
        }
        let enter = if enter_x < lo { (0, 0) } else { (ordered(enter_x), ordered(p.a.y)) };
        keyed.push((enter.0, enter.1, 1 << 32 | p.id as u64));
        if leave_x <= hi {
            keyed.push((ordered(leave_x), ordered(p.b.y), p.id as u64));
        }
    }
    keyed.sort_unstable();
    let order = |a: u32, b: u32| pieces[a as usize].order(&pieces[b as usize], lo);
    let mut status = SweepStatus::new(pieces.len());
    for (_, _, k) in keyed {
        let (removal, id) = (k >> 32 == 0, k as u32);
        if removal {
            let Some((below, above)) = status.remove(id, &order) else {
                return SweepOutcome::Inconsistent;
            };
            if let (Some(p), Some(q)) = (below, above) {
                if let Some((f, s, pt)) = check(&pieces[p as usize], &pieces[q as usize]) {
                    return SweepOutcome::Found(f, s, pt);
                }
            }
        } else {
            let (below, above) = status.insert(id, &order);
            for n in [below, above].into_iter().flatten() {
                if let Some((f, s, pt)) = check(&pieces[id as usize], &pieces[n as usize]) {
                    return SweepOutcome::Found(f, s, pt);
                }
            }
        }
    }
    SweepOutcome::Clear
}
