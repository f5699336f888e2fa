//! How the divide step cuts one subshape (thesis 2.2.1–2.2.2): where a
//! random maximal disk is grown, when its cut divides, what replaces a
//! redundant cut (`maxdisk*`) or a leaf arc's disk, and the circle through
//! three reflex points that cuts a reflex cluster. `divide.rs` schedules
//! these over the subshape tree.

use crate::kernel::fan::Fan;
use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Contact, Point};
use crate::plane::medial::decompose::parts::{foot_at_convex_corner, original_parts, parts_in, position, reflex_point};
use crate::plane::medial::decompose::subshape::{chain_holds, BoundaryPos, ChainParts, Cut, CutIds, Piece, Subshape};
use crate::plane::medial::decompose::tour::{Ranged, Span, Tour};
use crate::plane::medial::disk::maximal::{DiskFinder, Footpoint, MaxDisk};
use crate::plane::medial::disk::slide::slide_to_third;
use crate::shape::{ElementRef, JointKind, Shape2d};
use crate::util::mix::Mix;

/// Attempts with different random points before a subshape counts as stuck.
pub(super) const ATTEMPTS: u32 = 12;

/// A seed for a subshape: its first piece and the caller's seed, so that
/// the choice does not depend on the order in which subshapes are cut.
pub(super) fn seed_of<C: CutIds + ?Sized>(seed: u64, s: &Ranged, cuts: &C) -> u64 {
    let mut h = seed ^ 0x5851_f42d_4c95_7f2d;
    for p in s.spans.iter().take(2) {
        let (a, b) = match *p {
            Span::Piece(Piece::Chain { from, to }) => ((from.element as u64) << 32 ^ from.t.to_bits(), to.t.to_bits()),
            // The disk itself, not its id: ids depend on the order in
            // which subshapes are cut.
            Span::Piece(Piece::Aux { disk }) => {
                let c = cuts[disk];
                (c.center.x.to_bits() ^ c.radius.to_bits().rotate_left(29), c.center.y.to_bits())
            }
            Span::Range { from, to } => ((from as u64) << 32 ^ 0x746f_7572, to as u64),
        };
        h = (h ^ a).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ b;
    }
    h
}

/// A random point on a random original part of `s`: the position and the
/// part's fraction range, at a reflex end of the part when it has one.
pub(super) fn pick_point(shape: &Shape2d, s: &Ranged, tour: &Tour, rng: &mut Mix) -> Option<(BoundaryPos, (f64, f64))> {
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
pub(super) fn dividing<C: CutIds + ?Sized>(
    shape: &Shape2d,
    s: &Ranged,
    parts: usize,
    (disk, center, cuts, tour): (usize, Point, &C, &Tour),
    feet: &[BoundaryPos],
) -> Option<Vec<Ranged>> {
    let children = tour.cut(shape, s, disk, feet, center, cuts)?;
    children.iter().all(|c| parts_in(shape, c, tour) < parts).then_some(children)
}

/// Cuts `s` with the maximal disk `d` grown at `pos` (fraction range
/// `lo..hi` of its part), or with what replaces it: the leaf arc's circle,
/// or `maxdisk*` after a redundant cut. `None` when the disk does not divide.
pub(super) fn cut_with<K: AxisKernel, C: CutIds + ?Sized>(
    finder: &DiskFinder<K>,
    s: &Ranged,
    parts: usize,
    (cuts, tour): (&C, &Tour),
    d: &MaxDisk,
    pos: BoundaryPos,
    (lo, hi): (f64, f64),
) -> Option<(Cut, Vec<Ranged>)> {
    let shape = finder.shape();
    let tol = finder.contact_tolerance();
    let disk = cuts.count();
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
    let touch = empty_touching(finder, c, r)?;
    let feet: Vec<BoundaryPos> = touch.iter().map(|f| position(shape, f)).collect();
    if foot_at_convex_corner(shape, &feet, r) {
        return None;
    }
    let children = dividing(shape, s, parts, (disk, c, cuts, tour), &feet)?;
    Some((Cut { center: c, radius: r }, children))
}

/// The subshape's single-point chains that are reflex vertices (the
/// thesis's zero-length arcs between auxiliary arcs), in piece order.
pub(super) fn reflex_points(shape: &Shape2d, s: &Subshape) -> Vec<BoundaryPos> {
    s.pieces.iter().filter_map(|&p| reflex_point(shape, p)).collect()
}

/// A cluster of reflex vertices separated by auxiliary arcs only (thesis
/// 2.2.2.2): fix two neighbouring zero-length arcs and find a third so
/// that the circle through the three holds no other point of the cluster
/// and no boundary at all. That disk touches three (or more) parts and
/// cuts the cluster into smaller pieces. `None` when no such circle is
/// found (the subshape then stays whole for the base-case solver).
pub(super) fn cluster_cut<K: AxisKernel, C: CutIds + ?Sized>(
    finder: &DiskFinder<K>,
    s: &Subshape,
    points: &[BoundaryPos],
    cuts: &C,
) -> Option<(Cut, Vec<Subshape>)> {
    let disk = cuts.count();
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

/// Size of a subshape as the leaf rule counts it: original parts plus
/// reflex vertices between auxiliary arcs.
pub fn leaf_size(shape: &Shape2d, s: &Subshape) -> usize {
    original_parts(shape, s) + reflex_points(shape, s).len()
}

/// A random maximal disk of `s` to choose a balanced cut among: grown from
/// a random point, or from a random reflex end along the middle of the
/// vertex's fan of normals (the direction into the widest part of the
/// shape there, rather than along one of the elements). With the point and its part's fraction range, as
/// [`pick_point`] gives them.
pub(super) fn candidate<K: AxisKernel>(
    finder: &DiskFinder<K>,
    s: &Ranged,
    tour: &Tour,
    rng: &mut Mix,
) -> Option<(MaxDisk, BoundaryPos, (f64, f64))> {
    let shape = finder.shape();
    let (pos, range) = pick_point(shape, s, tour, rng)?;
    let at = ElementRef { loop_index: pos.loop_index, element: pos.element };
    if pos.t != 0.0 && pos.t != 1.0 {
        return Some((finder.max_disk(at, pos.t), pos, range));
    }
    let middle = reflex_fan(finder, pos).direction_at(0.5);
    Some((finder.max_disk_toward(at, pos.t, middle), pos, range))
}

/// The fan of normals at the reflex vertex `pos` (an element's start,
/// `t` = 0, or end, `t` = 1): it turns clockwise from the normal of the
/// element before the vertex to that of the one after (a half turn at a
/// segment site's end).
fn reflex_fan<K: AxisKernel>(finder: &DiskFinder<K>, pos: BoundaryPos) -> Fan {
    let at = ElementRef { loop_index: pos.loop_index, element: pos.element };
    let n = finder.shape().loops()[pos.loop_index].len();
    let (before, after) =
        if pos.t == 0.0 { ((at.element + n - 1) % n, at.element) } else { (at.element, (at.element + 1) % n) };
    let normal = |e: usize, t: f64| finder.boundary_point(ElementRef { element: e, ..at }, t).1;
    Fan::clockwise(normal(before, 1.0), normal(after, 0.0))
}

/// The footpoints of the disk (`c`, `r`) when it is empty and touches
/// the boundary at two or more points with a radius above the contact
/// tolerance: only such a disk can cut.
fn empty_touching<K: AxisKernel>(finder: &DiskFinder<K>, c: Point, r: f64) -> Option<Vec<Footpoint>> {
    let shape = finder.shape();
    let tol = finder.contact_tolerance();
    // Cheapest test first: the footpoints are gathered last.
    let empty = r > tol
        && finder.nearest(c).is_some_and(|(near, _)| {
            let e = shape.loops()[near.loop_index].element(near.element);
            finder.kernel().element_contact(Disk::new(c, r), &e, tol) == Contact::Touching
        });
    empty.then(|| finder.touching(c, r)).filter(|touch| touch.len() >= 2)
}

/// A maximal disk from deep inside a large plain subshape `s`, to choose
/// a balanced cut among. Random points of a spiky polygon fall on its
/// spikes, whose disks peel one spike off at a time: a random star of
/// 10^6 vertices was cut 1 459 times in a row, each cut waiting for the
/// one before, before a random disk first split it in two (8 360 peeling
/// cuts in all). Without auxiliary
/// arcs: the disk grown at the boundary point nearest to the centre of
/// the shape's bounding box, towards it (it holds the empty disk about
/// that centre). Otherwise `s`'s largest dividing disk slid into `s`
/// (`maxdisk*`, along the bisector of the two footpoints that bound its
/// arc) to the first disk touching a third element: the next branch
/// point of the axis beyond that disk, whose footpoints fall far apart
/// on `s`'s chains. `None` when `s` holds ranges or no such disk is found.
pub(super) fn deep_candidate<K: AxisKernel, C: CutIds + ?Sized>(
    finder: &DiskFinder<K>,
    s: &Ranged,
    cuts: &C,
) -> Option<(MaxDisk, BoundaryPos, (f64, f64))> {
    let shape = finder.shape();
    let plain = s.plain()?;
    let m = plain.pieces.len();
    let largest = (0..m)
        .filter_map(|j| match plain.pieces[j] {
            Piece::Aux { disk } => Some((j, cuts[disk])),
            Piece::Chain { .. } => None,
        })
        .max_by(|a, b| a.1.radius.total_cmp(&b.1.radius));
    let mut d = match largest {
        None => grown_towards(finder, shape.bbox().center())?,
        Some((j, disk)) => slid_into(finder, &plain, j, disk)?,
    };
    // The disk is grown at (cut from) a footpoint on one of `s`'s chains,
    // inside one of its parts: put the first such footpoint first.
    let part_of = |pos: BoundaryPos| {
        plain.chains().filter(|&(from, to)| chain_holds(shape, from, to, pos).is_some()).find_map(|(from, to)| {
            ChainParts::new(shape, from, to).iter().find(|&(e, lo, hi)| e == pos.element && lo <= pos.t && pos.t <= hi)
        })
    };
    let (k, pos, (_, lo, hi)) = d.footpoints.iter().enumerate().find_map(|(k, f)| {
        let pos = position(shape, f);
        Some((k, pos, part_of(pos)?))
    })?;
    d.footpoints.swap(0, k);
    Some((d, pos, (lo, hi)))
}

/// The maximal disk grown at the boundary point nearest to `q`, towards
/// `q` (along the element's normal inside an element; at a reflex vertex
/// only when `q`'s direction lies in the vertex's fan).
fn grown_towards<K: AxisKernel>(finder: &DiskFinder<K>, q: Point) -> Option<MaxDisk> {
    let shape = finder.shape();
    let (near, dist) = finder.nearest(q)?;
    if dist.is_nan() || dist <= finder.contact_tolerance() {
        return None;
    }
    let (_, foot) = shape.loops()[near.loop_index].element(near.element).closest_point(q);
    let pos = position(shape, &Footpoint { element: near, point: foot });
    let at = ElementRef { loop_index: pos.loop_index, element: pos.element };
    if pos.t != 0.0 && pos.t != 1.0 {
        return Some(finder.max_disk(at, pos.t));
    }
    let toward = (q - foot) * (1.0 / dist);
    reflex_fan(finder, pos).contains(toward, 0.0).then(|| finder.max_disk_toward(at, pos.t, toward))
}

/// Dividing disk `disk`, whose arc is piece `j` of `s`, slid into `s`
/// between the footpoints that bound the arc (the end of the chain before
/// it and the start of the one after) to a disk touching a third element;
/// with every footpoint of the disk reached, if it is empty.
fn slid_into<K: AxisKernel>(finder: &DiskFinder<K>, s: &Subshape, j: usize, disk: Cut) -> Option<MaxDisk> {
    let shape = finder.shape();
    let m = s.pieces.len();
    let Piece::Chain { to: end_before, .. } = s.pieces[(j + m - 1) % m] else { return None };
    let Piece::Chain { from: start_after, to: end_after } = s.pieces[(j + 1) % m] else { return None };
    let foot = |p: BoundaryPos| Footpoint {
        element: ElementRef { loop_index: p.loop_index, element: p.element },
        point: p.point(shape),
    };
    let (fa, fb) = (foot(end_before), foot(start_after));
    // The slide goes away from the junction: put it across the disk from
    // the middle of the chain after the arc, so the disk moves into `s`.
    let parts = ChainParts::new(shape, start_after, end_after);
    let middle = match parts.is_empty() {
        true => fb.point,
        false => {
            let (e, lo, hi) = parts.get(parts.len() / 2);
            shape.loops()[start_after.loop_index].element(e).point_at(0.5 * (lo + hi))
        }
    };
    let junction = disk.center + (disk.center - middle);
    let Disk { center: c, radius: r } =
        slide_to_third(finder, &fa, &fb, Disk::new(disk.center, disk.radius), junction)?;
    let touch = empty_touching(finder, c, r).filter(|t| t.len() >= 3)?;
    Some(MaxDisk { center: c, radius: r, footpoints: touch, leaf_arc: false })
}
