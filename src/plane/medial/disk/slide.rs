//! `maxdisk*` (thesis 2.2.2.1, Figures 2.5–2.7): when the maximal disk D
//! grown at a point of element a touches only a and a neighbouring part a',
//! cutting with it leaves one subshape as large as before (a redundant
//! cut). The disk is then slid along the bisector of a and a', away from
//! where they meet, until it touches a third element: that disk D* touches
//! three or more parts and divides (a branch point, or a point where the
//! defining pair changes, Figure 2.6).
//!
//! The thesis finds D* by iterating tritangent constructions over the
//! elements that overlap the current candidate, and so does this module:
//! an upper bound on where the slide stops (where a contact leaves its
//! element) shrinks by the Apollonius disk of the two sites and the element
//! nearest to the candidate's centre until the candidate is empty; one
//! nearest-element query per construction, whatever the distance travelled
//! (long thin channels are where a march would take thousands of steps).
//! A march along the bisector with a bisection at the end is kept as the
//! fallback for the rare constructions that fail numerically (measured:
//! none of 351 slides on a random star polygon of 10^4 vertices, 1 in 60
//! at 3·10^4).

use crate::kernel::apollonius::Site;
use crate::kernel::bisector::footpoint_param_at;
use crate::kernel::construct::unwrap_near;
use crate::kernel::direction::angle_of;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::Disk;
use crate::kernel::{AxisKernel, Contact, Point};
use crate::plane::axis::Primitive;
use crate::plane::medial::disk::maximal::{DiskFinder, Footpoint};
use crate::shape::{Element, ElementRef, JointKind};

/// What a disk touching `f` sees there: the element's line or circle, or a
/// point at a reflex vertex.
pub fn site_of<K: AxisKernel>(finder: &DiskFinder<K>, f: &Footpoint) -> Site {
    let shape = finder.shape();
    let lp = &shape.loops()[f.element.loop_index];
    let e = lp.element(f.element.element);
    let tol = finder.contact_tolerance();
    let n = lp.len();
    let at_vertex = if f.point.dist(e.start()) <= tol {
        Some(f.element.element)
    } else if f.point.dist(e.end()) <= tol {
        Some((f.element.element + 1) % n)
    } else {
        None
    };
    if let Some(v) = at_vertex {
        if shape.joint(f.element.loop_index, v) == JointKind::Reflex {
            return Site::Point(lp.vertices()[v].p);
        }
    }
    Primitive::of_element(f.element).site(shape)
}

/// Slides the disk `start` touching `fa` and `fb` along their bisector,
/// away from `junction` (a point between the two footpoints on the side
/// the redundant cut came from), to the first disk that touches a third
/// element or whose contact with `fa`'s or `fb`'s element reaches that
/// element's end (where the pair defining the axis changes), or `None`
/// if the bisector ends (no tangent disk) first.
pub fn slide_to_third<K: AxisKernel>(
    finder: &DiskFinder<K>,
    fa: &Footpoint,
    fb: &Footpoint,
    start: Disk,
    junction: Point,
) -> Option<Disk> {
    let Disk { center: c, radius: r } = start;
    let k = finder.kernel();
    let (sa, sb) = (site_of(finder, fa), site_of(finder, fb));
    let u0 = footpoint_param_at(&sa, c, fa.point);
    let empty_tol = Tolerance::slide_emptiness(finder.shape().bbox().diagonal());
    let shape = finder.shape();
    let element = |f: &Footpoint| shape.loops()[f.element.loop_index].element(f.element.element);
    let (ea, eb) = (element(fa), element(fb));
    let on = |e: &Element, q: Point| e.closest_point(q).0 <= finder.contact_tolerance();
    // A disk counts while it is empty and still touches both elements
    // (not only their supporting lines or circles).
    let empty = |u: f64| -> Option<(Point, f64, bool)> {
        let (c, r) = k.bisector_point(&sa, &sb, u)?.parts();
        let (near, _) = finder.nearest(c)?;
        let touches = on(&ea, sa.contact(c, r)) && on(&eb, sb.contact(c, r));
        let nearest = shape.loops()[near.loop_index].element(near.element);
        Some((c, r, k.element_contact(Disk::new(c, r), &nearest, empty_tol) != Contact::Overlapping && touches))
    };
    // The direction that moves the centre away from the junction.
    let h0 = match sa {
        Site::Line { .. } => Tolerance::slide_probe() * r.max(empty_tol),
        _ => Tolerance::slide_probe(),
    };
    let away = |u: f64| empty(u).map(|(cc, _, _)| cc.dist(junction));
    let dir = match (away(u0 + h0), away(u0 - h0)) {
        (Some(p), Some(m)) => {
            if p >= m {
                1.0
            } else {
                -1.0
            }
        }
        (Some(_), None) => 1.0,
        (None, Some(_)) => -1.0,
        (None, None) => return None,
    };
    if let Some(found) = jump_to_third(finder, [fa, fb], [&sa, &sb], start, u0, dir) {
        return Some(found);
    }
    // Fallback: march with steps that move the centre by 2–20 % of the
    // radius (slow in long thin channels, where the disk travels many
    // radii), then bisect where the disk stops being empty.
    let (mut lo, mut h) = (u0, h0);
    let (mut prev_c, mut prev_r) = (c, r);
    for _ in 0..2_000 {
        let u = lo + dir * h;
        let (cc, rr, ok) = empty(u)?;
        let moved = cc.dist(prev_c);
        if moved > 0.2 * prev_r && h > Tolerance::least_step() {
            h *= 0.5;
            continue;
        }
        if !ok {
            // Bisect between the last empty disk and this one.
            let mut hi = u;
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                match empty(mid) {
                    Some((_, _, true)) => lo = mid,
                    _ => hi = mid,
                }
            }
            return k.bisector_point(&sa, &sb, lo);
        }
        lo = u;
        (prev_c, prev_r) = (cc, rr);
        if moved < 0.02 * prev_r {
            h *= 2.0;
        }
    }
    None
}

/// Constructions tried before the slide falls back to marching.
const JUMPS: usize = 24;

/// The slide of [`slide_to_third`] by constructions instead of steps.
///
/// The first event along the bisector is an upper bound `hi` that only
/// shrinks: it starts at the nearer place where a contact leaves its
/// element (or a reflex vertex's fan of normals), and whenever the disk at
/// `hi` holds part of the boundary, the element nearest to its centre must
/// have been touched first somewhere before `hi` (the start disk is
/// empty): the Apollonius disk tangent to `sa`, `sb` and that element's
/// line, circle or end points moves `hi` there. The first empty disk is
/// returned, usually after one to three constructions, whatever the
/// distance travelled. `None` (then the caller marches) when a
/// construction fails numerically.
// Not inlined: inlined into `slide_to_third`, valgrind (CTest's memcheck
// runs) reports a conditional jump on uninitialised bytes of the caller's
// frame. The source reads only initialised values (safe Rust, no unsafe
// here), so it is taken for a read the optimiser hoisted out of a branch;
// in its own frame the report goes away. Keep the memcheck runs green.
#[inline(never)]
fn jump_to_third<K: AxisKernel>(
    finder: &DiskFinder<K>,
    [fa, fb]: [&Footpoint; 2],
    [sa, sb]: [&Site; 2],
    start: Disk,
    u0: f64,
    dir: f64,
) -> Option<Disk> {
    let Disk { center: c0, radius: r0 } = start;
    let k = finder.kernel();
    let shape = finder.shape();
    let tol = finder.contact_tolerance();
    let element = |r: ElementRef| shape.loops()[r.loop_index].element(r.element);
    let (ea, eb) = (element(fa.element), element(fb.element));
    let on = |e: &Element, q: Point| e.closest_point(q).0 <= tol;
    // How far along the slide a footpoint parameter on `sa` lies; angles
    // signed, as a slide turns a footpoint around a vertex or an arc's
    // centre by less than half a turn (a reflex fan is narrower than π).
    let angular = !matches!(sa, Site::Line { .. });
    let wrap = |turns: bool, d: f64| if turns { unwrap_near(d, 0.0) } else { d };
    let ahead = |u: f64| wrap(angular, (u - u0) * dir);
    let min_ahead = if angular { Tolerance::least_turn() } else { tol };
    // A disk (c, r) counts if it lies on this branch of the bisector.
    let on_branch = |c: Point, r: f64| -> Option<f64> {
        let u = footpoint_param_at(sa, c, sa.contact(c, r));
        let (cb, rb) = k.bisector_point(sa, sb, u)?.parts();
        let near = Tolerance::new(tol).slide_match();
        (cb.dist(c) <= near && (rb - r).abs() <= near).then_some(u)
    };
    // Keeps the disk (c, r) in `best` if it comes first, before `bound`
    // (`best.0` is how far ahead it lies; infinite while there is none).
    let offer = |best: &mut (f64, Point, f64), c: Point, r: f64, bound: f64| -> bool {
        let Some(u) = on_branch(c, r) else { return false };
        let d = ahead(u);
        let better = d > min_ahead && d < bound && d < best.0;
        if better {
            *best = (d, c, r);
        }
        better
    };
    // Where each contact leaves its range, ahead in that site's own
    // parameter (the direction a small step moves it): the nearer such
    // place bounds the slide. A contact already at the end of its range
    // (a maximal disk grown at a reflex vertex touches at the end of its
    // fan) ends the slide where it starts: the defining pair changes there.
    let scale = if angular { 1.0 } else { r0 };
    let (c1, r1) = k.bisector_point(sa, sb, u0 + dir * Tolerance::slide_direction_step() * scale)?.parts();
    let mut best = (f64::INFINITY, Point::default(), 0.0);
    for &(f, s, other) in [(fa, sa, sb), (fb, sb, sa)].iter() {
        let turns = !matches!(s, Site::Line { .. });
        let here = footpoint_param_at(s, c0, s.contact(c0, r0));
        let forward = wrap(turns, footpoint_param_at(s, c1, s.contact(c1, r1)) - here).signum();
        // A point site's fan is a whole turn: a contact there never leaves it.
        if shape.kind(f.element.loop_index) == crate::shape::LoopKind::Point {
            continue;
        }
        let mut open = false;
        for &u in contact_range(finder, f, s).iter() {
            if wrap(turns, u - here) * forward <= if turns { Tolerance::least_turn() } else { tol } {
                continue;
            }
            open = true;
            if let Some(Disk { center: c, radius: r }) = k.bisector_point(s, other, u) {
                offer(&mut best, c, r, f64::INFINITY);
            }
        }
        if !open {
            return Some(start);
        }
    }
    for _ in 0..JUMPS {
        let (bound, c, r) = best;
        if !bound.is_finite() {
            return None;
        }
        let (hit, _) = finder.nearest(c)?;
        if k.element_contact(Disk::new(c, r), &element(hit), tol) != Contact::Overlapping {
            // Empty; the contacts stay on their elements by construction,
            // checked again against rounding.
            return (on(&ea, sa.contact(c, r)) && on(&eb, sb.contact(c, r))).then_some(Disk::new(c, r));
        }
        let e = element(hit);
        let interior = Primitive::of_element(hit).site(shape);
        let mut moved = false;
        for s3 in [interior, Site::Point(e.start()), Site::Point(e.end())].iter() {
            let point = matches!(s3, Site::Point(_));
            let solutions = k.tritangent_disks([*sa, *sb, *s3]);
            for &Disk { center: c3, radius: r3 } in solutions.iter() {
                if point || on(&e, s3.contact(c3, r3)) {
                    moved |= offer(&mut best, c3, r3, bound);
                }
            }
        }
        if !moved {
            return None;
        }
    }
    None
}

/// The footpoint parameters on `s` (see [`param_on`]) where a contact at
/// `f` leaves its element: the element's ends, or for a reflex vertex the
/// normals of its two elements, which bound the vertex's fan.
fn contact_range<K: AxisKernel>(finder: &DiskFinder<K>, f: &Footpoint, s: &Site) -> [f64; 2] {
    let shape = finder.shape();
    let lp = &shape.loops()[f.element.loop_index];
    let e = lp.element(f.element.element);
    match *s {
        Site::Line { a, n } => [e.start(), e.end()].map(|q| (q - a).dot(-n.perp())),
        Site::Circle { o, .. } => [e.start(), e.end()].map(|q| angle_of(q - o)),
        Site::Point(q) => {
            let n = lp.len();
            // The vertex is the start or the end of the footpoint's element.
            let v = if q.dist(e.start()) <= q.dist(e.end()) { f.element.element } else { (f.element.element + 1) % n };
            let (before, after) = (lp.element((v + n - 1) % n), lp.element(v));
            [before.end_tangent().perp(), after.start_tangent().perp()].map(angle_of)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::footpoint as fp;
    use crate::shape::{ElementRef, Shape2d, ShapeOptions, Vertex};

    fn polygon(pts: &[(f64, f64)]) -> Shape2d {
        let loop0 = pts.iter().map(|&(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 }).collect();
        Shape2d::from_bulge_loops(vec![loop0], &ShapeOptions::default()).unwrap()
    }

    #[test]
    fn param_on_inverts_footpoint() {
        let sites = [
            Site::Line { a: Point::new(1.0, 2.0), n: Point::new(0.6, 0.8) },
            Site::Point(Point::new(-1.0, 0.5)),
            Site::Circle { o: Point::new(2.0, -1.0), r: 1.5, outside: true },
            Site::Circle { o: Point::new(2.0, -1.0), r: 1.5, outside: false },
        ];
        for s in sites {
            for u in [-2.0, -0.3, 0.0, 0.7, 2.5] {
                let (p, n) = fp(&s, u);
                let c = p + n * 0.75;
                assert!((footpoint_param_at(&s, c, p) - u).abs() < 1e-12, "{s:?} {u}");
            }
        }
    }

    #[test]
    fn slides_from_a_corner_disk_to_the_branch_point() {
        // A 4 × 2 rectangle: the disk grown near the bottom-left corner
        // touches the bottom and the left side (a redundant cut); sliding
        // away from the corner reaches the disk touching the top: radius 1,
        // centre (1, 1).
        let shape = polygon(&[(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (0.0, 2.0)]);
        let finder = DiskFinder::new(&shape);
        let d = finder.max_disk(ElementRef { loop_index: 0, element: 0 }, 0.1);
        assert_eq!(d.footpoints.len(), 2, "{d:?}");
        let start = Disk::new(d.center, d.radius);
        let (c, r) =
            slide_to_third(&finder, &d.footpoints[0], &d.footpoints[1], start, Point::new(0.0, 0.0)).unwrap().parts();
        assert!(c.dist(Point::new(1.0, 1.0)) < 1e-9 && (r - 1.0).abs() < 1e-9, "{c:?} {r}");
        assert_eq!(finder.touching(c, r).len(), 3);
    }

    #[test]
    fn slides_the_length_of_a_needle_in_a_few_constructions() {
        // A needle: apex angle 0.02 rad. From a disk near the apex the slide
        // travels ~99 units while the radius grows from 0.01 to 0.99 (a
        // march of steps of 20 % of the radius needs thousands of them); it
        // must stop at the incircle, the only disk touching all three sides.
        let shape = polygon(&[(0.0, 0.0), (100.0, -1.0), (100.0, 1.0)]);
        let finder = DiskFinder::new(&shape);
        let d = finder.max_disk(ElementRef { loop_index: 0, element: 0 }, 0.01);
        assert_eq!(d.footpoints.len(), 2, "{d:?}");
        let start = Disk::new(d.center, d.radius);
        let (c, r) =
            slide_to_third(&finder, &d.footpoints[0], &d.footpoints[1], start, Point::new(0.0, 0.0)).unwrap().parts();
        let side = 10001f64.sqrt();
        let (incentre, inradius) = (Point::new(100.0 * side / (1.0 + side), 0.0), 100.0 / (1.0 + side));
        assert!(c.dist(incentre) < 1e-9 && (r - inradius).abs() < 1e-9, "{c:?} {r}");
    }
}
