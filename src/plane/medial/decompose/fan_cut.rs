//! Cuts grown from reflex single points (thesis 2.2.2.2: zero-length arcs
//! between auxiliary arcs, and point sites, 2.3). A subshape made mostly of
//! such points has few original parts to grow disks from, and the
//! three-point search of `divide::cluster_cut` costs O(k²) per cut. Here a
//! random point and a random direction in the part of its fan that the
//! subshape holds give a maximal disk by one growing-disk query, as a
//! random boundary point does for original parts (Algorithm 1), so that a
//! cloud of k points divides in O(k log k).

use crate::kernel::fan::Fan;
use crate::kernel::AxisKernel;
use crate::plane::medial::decompose::parts::{foot_at_convex_corner, parts_in, points_in, position, reflex_point};
use crate::plane::medial::decompose::subshape::{BoundaryPos, Cut, CutIds, Piece};
use crate::plane::medial::decompose::tour::{Ranged, Span, Tour};
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::{ElementRef, Shape2d};
use crate::util::mix::Mix;

/// A random reflex single point of `s` with its neighbouring auxiliary
/// arcs' disks (before, after), or `None` (no such point, or one at the
/// edge of a range, whose neighbours are not looked up).
fn pick(shape: &Shape2d, s: &Ranged, tour: &Tour, rng: &mut Mix) -> Option<(BoundaryPos, usize, usize)> {
    let count = |p: &Span| match *p {
        Span::Piece(piece) => usize::from(reflex_point(shape, piece).is_some()),
        Span::Range { from, to } => tour.points(from, to),
    };
    let total: usize = s.spans.iter().map(count).sum();
    if total == 0 {
        return None;
    }
    let mut k = rng.below(total);
    let n = s.spans.len();
    let aux = |p: Option<Piece>| match p {
        Some(Piece::Aux { disk }) => Some(disk),
        _ => None,
    };
    let edge_piece = |j: usize, last: bool| match s.spans[j % n] {
        Span::Piece(p) => Some(p),
        Span::Range { from, to } => tour.piece(if last { to } else { from }),
    };
    for (j, span) in s.spans.iter().enumerate() {
        let c = count(span);
        if k >= c {
            k -= c;
            continue;
        }
        return match *span {
            Span::Piece(piece) => {
                let at = reflex_point(shape, piece)?;
                Some((at, aux(edge_piece(j + n - 1, true))?, aux(edge_piece(j + 1, false))?))
            }
            Span::Range { from, to } => {
                let i = tour.point(from, k)?;
                if i <= from || i >= to {
                    return None;
                }
                let at = reflex_point(shape, tour.piece(i)?)?;
                Some((at, aux(tour.piece(i - 1))?, aux(tour.piece(i + 1))?))
            }
        };
    }
    None
}

/// A cut of `s` (of leaf size `size`: original parts plus reflex single
/// points) by the maximal disk grown from a random reflex single point in
/// a random direction of the part of its fan that `s` holds (clockwise
/// from the disk of the auxiliary arc before it to the one after it; a
/// whole turn between the two arcs of one disk). `None` when the pick or
/// the disk does not divide `s` into smaller pieces.
pub(super) fn fan_cut<K: AxisKernel, C: CutIds + ?Sized>(
    finder: &DiskFinder<K>,
    s: &Ranged,
    size: usize,
    (cuts, tour): (&C, &Tour),
    rng: &mut Mix,
) -> Option<(Cut, Vec<Ranged>)> {
    let shape = finder.shape();
    let (at, before, after) = pick(shape, s, tour, rng)?;
    let q = at.point(shape);
    let a = (cuts[before].center - q).unit();
    let fan = if before == after { Fan::whole_turn(a) } else { Fan::clockwise(a, (cuts[after].center - q).unit()) };
    // Clear of the fan part's ends, where the disk would be the
    // neighbouring cut again.
    let m = fan.direction_at(0.1 + 0.8 * rng.next());
    let d = finder.max_disk_toward(ElementRef { loop_index: at.loop_index, element: at.element }, at.t, m);
    if d.radius <= finder.contact_tolerance() || d.footpoints.len() < 2 {
        return None;
    }
    let feet: Vec<BoundaryPos> =
        d.footpoints.iter().enumerate().map(|(i, f)| if i == 0 { at } else { position(shape, f) }).collect();
    if foot_at_convex_corner(shape, &feet, d.radius) {
        return None;
    }
    let children = tour.cut(shape, s, cuts.count(), &feet, d.center, cuts)?;
    let smaller = children.iter().all(|c| parts_in(shape, c, tour) + points_in(shape, c, tour) < size);
    (children.len() >= 2 && smaller).then_some((Cut { center: d.center, radius: d.radius }, children))
}
