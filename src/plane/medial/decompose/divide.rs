//! The divide step (thesis 2.2.1, Algorithm 2 lines 2–14): cut a shape with
//! random maximal disks until every subshape is small.
//!
//! Each subshape picks a random original element part and a point on it (a
//! reflex end when the part has one, as the thesis prescribes), grows the
//! maximal disk there and cuts at its footpoints. A cut is kept when every
//! resulting subshape has fewer original parts than the one cut (a dividing
//! disk, Definition 2.2.1); otherwise another point is tried. Subshapes
//! with at most three original parts are leaves. Every random choice is
//! derived from the seed and the subshape itself, so the result depends on
//! nothing else (subshapes are cut one after another for now; they are
//! independent, which is what parallel cutting will use).
//!
//! A redundant cut (two footpoints, one subshape as large as before) is
//! replaced by `maxdisk*` ([`crate::plane::medial::disk::slide`]); a leaf arc's own
//! circle (Observation 5) cuts the arc off as a leaf. Not yet here:
//! multi-branching and reflex clusters (2.2.2.2), the reflex and convex
//! termination rules and the base-case axes (2.2.2–2.2.3). Subshapes that
//! could not be divided are returned as such, never dropped (today about 1
//! in 140 leaves on smooth biarc shapes and 1 in 80 on random star
//! polygons).

use crate::kernel::tolerance::Tolerance;
use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Contact, Point};
use crate::plane::medial::decompose::augment::Augmentation;
#[cfg(any(test, feature = "internals"))]
use crate::plane::medial::decompose::augment::{augment, AugmentError};
use crate::plane::medial::decompose::fan_cut::fan_cut;
use crate::plane::medial::decompose::parts::{
    foot_at_convex_corner, original_parts, parts_in, points_in, position, reflex_point,
};
use crate::plane::medial::decompose::subshape::{hugged, BoundaryPos, ChainParts, Cut, Hugged, Piece, Subshape};
use crate::plane::medial::decompose::tour::{Ranged, Span, Tour};
use crate::plane::medial::disk::maximal::{DiskFinder, MaxDisk};
use crate::plane::medial::disk::slide::slide_to_third;
use crate::shape::{ElementRef, JointKind, Shape2d};
use crate::util::mix::Mix;

/// Attempts with different random points before a subshape counts as stuck.
const ATTEMPTS: u32 = 12;

/// A subshape is a leaf once it has at most this many original parts.
#[cfg(any(test, feature = "internals"))]
const LEAF_PARTS: usize = 3;

/// What the divide step produced.
#[derive(Debug, Clone, Default)]
pub struct Decomposition {
    /// The dividing disks; `Piece::Aux` indices refer to this list.
    pub cuts: Vec<Cut>,
    /// Subshapes with at most three original parts.
    pub leaves: Vec<Subshape>,
    /// Subshapes no attempted disk divided (they need the rules not built
    /// yet: multi-branching, reflex clusters).
    pub stuck: Vec<Subshape>,
}

/// Subshapes of at most this many pieces once expanded hold no ranges of
/// the augmented cycle: every rule of the divide step sees them whole.
const EXPAND_BELOW: usize = 64;

/// A seed for a subshape: its first piece and the caller's seed, so that
/// the choice does not depend on the order in which subshapes are cut.
fn seed_of(seed: u64, s: &Ranged) -> u64 {
    let mut h = seed ^ 0x5851_f42d_4c95_7f2d;
    for p in s.spans.iter().take(2) {
        let (a, b) = match *p {
            Span::Piece(Piece::Chain { from, to }) => ((from.element as u64) << 32 ^ from.t.to_bits(), to.t.to_bits()),
            Span::Piece(Piece::Aux { disk }) => (disk as u64, 0),
            Span::Range { from, to } => ((from as u64) << 32 ^ 0x746f_7572, to as u64),
        };
        h = (h ^ a).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ b;
    }
    h
}

/// A random point on a random original part of `s`: the position and the
/// part's fraction range, at a reflex end of the part when it has one.
fn pick_point(shape: &Shape2d, s: &Ranged, tour: &Tour, rng: &mut Mix) -> Option<(BoundaryPos, (f64, f64))> {
    // The chains in piece order, those inside ranges of the augmented
    // cycle counted in place.
    let count = |p: &Span| match *p {
        Span::Piece(Piece::Chain { from, to }) => usize::from(from != to),
        Span::Range { from, to } => tour.chains(from, to),
        Span::Piece(Piece::Aux { .. }) => 0,
    };
    let total: usize = s.spans.iter().map(count).sum();
    if total == 0 {
        return None;
    }
    let mut k = rng.below(total);
    let (from, to) = s.spans.iter().find_map(|p| {
        let c = count(p);
        if k >= c {
            k -= c;
            return None;
        }
        match *p {
            Span::Piece(Piece::Chain { from, to }) => Some((from, to)),
            Span::Range { from, .. } => tour.chain(from, k),
            Span::Piece(Piece::Aux { .. }) => None,
        }
    })?;
    let parts = ChainParts::new(shape, from, to);
    if parts.is_empty() {
        return None;
    }
    let (element, lo, hi) = parts.get(rng.below(parts.len()));
    if hi <= lo {
        return None;
    }
    let l = from.loop_index;
    let n = shape.loops()[l].len();
    let reflex_start = lo == 0.0 && shape.joint(l, element) == JointKind::Reflex;
    let reflex_end = hi == 1.0 && shape.joint(l, (element + 1) % n) == JointKind::Reflex;
    let t = if reflex_start && (!reflex_end || rng.below(2) == 0) {
        0.0
    } else if reflex_end {
        1.0
    } else {
        lo + (hi - lo) * (0.1 + 0.8 * rng.next())
    };
    Some((BoundaryPos { loop_index: l, element, t }, (lo, hi)))
}

/// The subshapes of `s` cut at `feet` by a disk that will get id `disk`,
/// if every one of them has fewer original parts than `s` (`parts`).
fn dividing(
    shape: &Shape2d,
    s: &Ranged,
    parts: usize,
    (disk, center, cuts, tour): (usize, Point, &[Cut], &Tour),
    feet: &[BoundaryPos],
) -> Option<Vec<Ranged>> {
    let children = tour.cut(shape, s, disk, feet, center, cuts)?;
    children.iter().all(|c| parts_in(shape, c, tour) < parts).then_some(children)
}

/// Cuts `s` with the maximal disk `d` grown at `pos` (fraction range
/// `lo..hi` of its part), or with what replaces it: the leaf arc's circle,
/// or `maxdisk*` after a redundant cut. `None` when the disk does not divide.
fn cut_with<K: AxisKernel>(
    finder: &DiskFinder<K>,
    s: &Ranged,
    parts: usize,
    (cuts, tour): (&[Cut], &Tour),
    d: &MaxDisk,
    pos: BoundaryPos,
    (lo, hi): (f64, f64),
) -> Option<(Cut, Vec<Ranged>)> {
    let shape = finder.shape();
    let tol = finder.contact_tolerance();
    let disk = cuts.len();
    if d.leaf_arc {
        // The disk is the arc's own circle (Observation 5): cut the whole
        // arc off as a leaf, with every other part the circle touches. A
        // partial arc means its circle has cut here already.
        if lo > 0.0 || hi < 1.0 {
            return None;
        }
        let ends = [BoundaryPos { t: 0.0, ..pos }, BoundaryPos { t: 1.0, ..pos }];
        let (pa, pb) = (ends[0].point(shape), ends[1].point(shape));
        let own = d.footpoints[0].element;
        let others = finder
            .touching(d.center, d.radius)
            .into_iter()
            .filter(|f| f.element != own && f.point.dist(pa) > tol && f.point.dist(pb) > tol);
        let feet: Vec<BoundaryPos> = ends.into_iter().chain(others.map(|f| position(shape, &f))).collect();
        let children = dividing(shape, s, parts, (disk, d.center, cuts, tour), &feet)?;
        return Some((Cut { center: d.center, radius: d.radius }, children));
    }
    if d.radius == 0.0 || d.footpoints.len() < 2 {
        return None;
    }
    let feet: Vec<BoundaryPos> =
        d.footpoints.iter().enumerate().map(|(i, f)| if i == 0 { pos } else { position(shape, f) }).collect();
    if foot_at_convex_corner(shape, &feet, d.radius) {
        return None;
    }
    let children = tour.cut(shape, s, disk, &feet, d.center, cuts)?;
    let counts: Vec<usize> = children.iter().map(|c| parts_in(shape, c, tour)).collect();
    if counts.iter().all(|&c| c < parts) {
        return Some((Cut { center: d.center, radius: d.radius }, children));
    }
    if d.footpoints.len() != 2 {
        return None;
    }
    // A redundant cut: slide the disk away from where the two parts meet
    // (on the side of the smaller subshape) to a disk touching a third part
    // or where a contact reaches its element's end (maxdisk*).
    let small = (0..children.len()).min_by_key(|&i| counts[i]).unwrap_or(0);
    let ends: Vec<Point> =
        tour.expand(&children[small]).chains().flat_map(|(a, b)| [a.point(shape), b.point(shape)]).collect();
    let junction = ends.iter().fold(Point::default(), |acc, &p| acc + p) * (1.0 / ends.len().max(1) as f64);
    let Disk { center: c, radius: r } =
        slide_to_third(finder, &d.footpoints[0], &d.footpoints[1], Disk::new(d.center, d.radius), junction)?;
    // Only an empty disk that touches the boundary can cut.
    let touch = finder.touching(c, r);
    let empty = finder.nearest(c).is_some_and(|(near, _)| {
        let e = shape.loops()[near.loop_index].element(near.element);
        finder.kernel().element_contact(Disk::new(c, r), &e, tol) == Contact::Touching
    });
    if touch.len() < 2 || r <= tol || !empty {
        return None;
    }
    let feet: Vec<BoundaryPos> = touch.iter().map(|f| position(shape, f)).collect();
    if foot_at_convex_corner(shape, &feet, r) {
        return None;
    }
    let children = dividing(shape, s, parts, (disk, c, cuts, tour), &feet)?;
    Some((Cut { center: c, radius: r }, children))
}

/// Cuts the shape (its augmented domain when it has holes, thesis 2.3.1)
/// down to leaves; `seed` fixes every random choice.
#[cfg(any(test, feature = "internals"))]
pub fn decompose(shape: &Shape2d, seed: u64) -> Result<Decomposition, AugmentError> {
    decompose_with(shape, seed, LEAF_PARTS)
}

/// The subshape's single-point chains that are reflex vertices (the
/// thesis's zero-length arcs between auxiliary arcs), in piece order.
fn reflex_points(shape: &Shape2d, s: &Subshape) -> Vec<BoundaryPos> {
    s.pieces.iter().filter_map(|&p| reflex_point(shape, p)).collect()
}

/// A cluster of reflex vertices separated by auxiliary arcs only (thesis
/// 2.2.2.2): fix two neighbouring zero-length arcs and find a third so
/// that the circle through the three holds no other point of the cluster
/// and no boundary at all. That disk touches three (or more) parts and
/// cuts the cluster into smaller pieces. `None` when no such circle is
/// found (the subshape then stays whole for the base-case solver).
fn cluster_cut<K: AxisKernel>(
    finder: &DiskFinder<K>,
    s: &Subshape,
    points: &[BoundaryPos],
    cuts: &[Cut],
) -> Option<(Cut, Vec<Subshape>)> {
    let disk = cuts.len();
    let shape = finder.shape();
    if points.len() < 3 {
        return None;
    }
    let tol = finder.contact_tolerance();
    let kernel = finder.kernel();
    let pts: Vec<Point> = points.iter().map(|p| p.point(shape)).collect();
    for i in 0..pts.len() {
        let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
        for (k, &r) in pts.iter().enumerate() {
            if k == i || k == (i + 1) % pts.len() {
                continue;
            }
            let Some(Disk { center: c, radius: rad }) = kernel.circumcircle(p, q, r) else { continue };
            if pts.iter().any(|&x| kernel.point_contact(Disk::new(c, rad), x, tol) == Contact::Overlapping) {
                continue;
            }
            if finder.intruder(c, rad, tol).is_some() {
                continue;
            }
            let feet: Vec<BoundaryPos> = finder.touching(c, rad).iter().map(|f| position(shape, f)).collect();
            let Some(children) = s.split(shape, disk, &feet, c, cuts) else { continue };
            // Progress: every piece has fewer parts and zero-length arcs.
            let whole = leaf_size(shape, s);
            if children.len() >= 2 && children.iter().all(|ch| leaf_size(shape, ch) < whole) {
                return Some((Cut { center: c, radius: rad }, children));
            }
        }
    }
    None
}

/// [`decompose`] with leaves of up to `leaf_parts` original parts.
#[cfg(any(test, feature = "internals"))]
pub fn decompose_with(shape: &Shape2d, seed: u64, leaf_parts: usize) -> Result<Decomposition, AugmentError> {
    let finder = DiskFinder::new(shape);
    Ok(decompose_in(&finder, &augment(&finder)?, seed, leaf_parts))
}

/// [`decompose_with`] on the maximal disks of an existing `finder` (its
/// index is built once for every decomposition of the same shape),
/// starting from the augmented domain `aug` of its shape.
pub fn decompose_in<K: AxisKernel>(
    finder: &DiskFinder<K>,
    aug: &Augmentation,
    seed: u64,
    leaf_parts: usize,
) -> Decomposition {
    let mut out = Decomposition { cuts: aug.cuts.clone(), ..Decomposition::default() };
    if aug.cuts.is_empty() {
        divide_into(finder, &mut out, vec![aug.boundary.clone()], seed, leaf_parts);
    } else {
        let tour = Tour::new(finder.shape(), &aug.boundary);
        divide_along(finder, &mut out, vec![tour.root()], seed, leaf_parts, &tour);
    }
    out
}

/// Divides each of `roots` (subshapes bounded by `out`'s cuts, or the
/// whole loop) until every piece is a leaf of up to `leaf_parts` original
/// parts or stuck, appending the new cuts, leaves and stuck subshapes to
/// `out`. A root that is already small enough is a leaf as it is.
pub fn divide_into<K: AxisKernel>(
    finder: &DiskFinder<K>,
    out: &mut Decomposition,
    roots: Vec<Subshape>,
    seed: u64,
    leaf_parts: usize,
) {
    // Plain subshapes hold no range: the empty cycle is never looked into.
    divide_along(finder, out, roots.into_iter().map(Ranged::from).collect(), seed, leaf_parts, &Tour::default());
}

/// [`divide_into`] for subshapes that may hold ranges of the augmented
/// cycle `tour`; leaves and stuck subshapes come out expanded.
fn divide_along<K: AxisKernel>(
    finder: &DiskFinder<K>,
    out: &mut Decomposition,
    roots: Vec<Ranged>,
    seed: u64,
    leaf_parts: usize,
    tour: &Tour,
) {
    let shape = finder.shape();
    let mut todo = roots;
    // Depth-first with an explicit stack: cut ids depend only on the order
    // of cuts, which is fixed by the seed.
    while let Some(mut s) = todo.pop() {
        if s.has_ranges() && tour.expanded_len(&s) <= EXPAND_BELOW {
            s = tour.expand(&s).into();
        }
        let parts = parts_in(shape, &s, tour);
        // Reflex vertices between auxiliary arcs are zero-length arcs: they
        // count towards a leaf's size like original parts.
        // A lobe's tip within a few tolerances of its one dividing disk is
        // a leaf however many parts it has: cutting it again would leave
        // bands of rounding between nearly equal disks. (A band hugged by
        // its two disks is divided on: the base case solves it, or else
        // stands the straight edge between its ports for its axis.)
        // A range holds many pieces: never a lobe's tip.
        if parts + points_in(shape, &s, tour) <= leaf_parts
            || s.plain().is_some_and(|p| {
                // Only one dividing disk makes a tip: count before measuring.
                p.pieces.iter().filter(|q| matches!(q, Piece::Aux { .. })).count() == 1
                    && matches!(
                        hugged(shape, &p, &out.cuts, Tolerance::new(shape.tolerance()).hugged_tip()),
                        Some(Hugged::Tip(_))
                    )
            })
        {
            out.leaves.push(tour.expand(&s));
            continue;
        }
        let mut rng = Mix(seed_of(seed, &s));
        let points = points_in(shape, &s, tour);
        let found = (0..ATTEMPTS + ((parts + points) as u32) / 4)
            .find_map(|_| {
                // Reflex single points are picked as often as parts: a
                // cloud of point sites has almost nothing else.
                if rng.below(parts + points) < points {
                    return fan_cut(finder, &s, parts + points, (&out.cuts, tour), &mut rng);
                }
                let (pos, range) = pick_point(shape, &s, tour, &mut rng)?;
                let at = ElementRef { loop_index: pos.loop_index, element: pos.element };
                let d = finder.max_disk(at, pos.t);
                cut_with(finder, &s, parts, (&out.cuts, tour), &d, pos, range)
            })
            .or_else(|| {
                let whole = tour.expand(&s);
                let (cut, children) = cluster_cut(finder, &whole, &reflex_points(shape, &whole), &out.cuts)?;
                Some((cut, children.into_iter().map(Ranged::from).collect()))
            });
        match found {
            Some((cut, children)) => {
                out.cuts.push(cut);
                todo.extend(children);
            }
            None => out.stuck.push(tour.expand(&s)),
        }
    }
}

/// Size of a subshape as the leaf rule counts it: original parts plus
/// reflex vertices between auxiliary arcs.
pub fn leaf_size(shape: &Shape2d, s: &Subshape) -> usize {
    original_parts(shape, s) + reflex_points(shape, s).len()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{samples, ShapeOptions};

    fn boundary_distance(shape: &Shape2d, p: crate::kernel::Point) -> f64 {
        shape.loops()[0].elements().map(|e| e.closest_point(p).0).fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn smooth_shapes_divide_down_to_leaves_with_maximal_disks() {
        for n in [20, 100, 400, 2000] {
            let shape = Shape2d::from_bulge_loops(samples::flower_arcs(n), &ShapeOptions::default()).unwrap();
            let d = decompose(&shape, 7).unwrap();
            let tol = 1e-9 * shape.bbox().diagonal();
            for c in &d.cuts {
                // Every dividing disk is a maximal disk: empty, touching.
                assert!((boundary_distance(&shape, c.center) - c.radius).abs() <= tol, "{n}: {c:?}");
            }
            assert!(d.leaves.iter().all(|l| original_parts(&shape, l) <= LEAF_PARTS));
            // Leaves cover the shape: each cut adds (k − 1) disks of area.
            assert!(d.cuts.len() >= n / 4, "{n}: only {} cuts", d.cuts.len());
            // A few subshapes still need the rules not built yet (multi-branching,
            // reflex clusters); they must stay rare.
            assert!(d.stuck.len() * 50 <= d.leaves.len() + 10, "{n}: {} stuck of {}", d.stuck.len(), d.leaves.len());
            // Same seed, same result.
            let again = decompose(&shape, 7).unwrap();
            assert_eq!(again.cuts, d.cuts);
        }
    }

    #[test]
    fn polygons_with_reflex_vertices() {
        for seed in 0..10 {
            let shape = Shape2d::from_bulge_loops(samples::star_polygon(60, seed), &ShapeOptions::default()).unwrap();
            let d = decompose(&shape, seed).unwrap();
            assert!(d.stuck.len() <= 3, "{seed}: {} stuck of {}", d.stuck.len(), d.leaves.len());
            let tol = 1e-9 * shape.bbox().diagonal();
            for c in &d.cuts {
                assert!((boundary_distance(&shape, c.center) - c.radius).abs() <= tol, "{c:?}");
            }
        }
    }
}
