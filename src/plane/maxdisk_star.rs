//! `maxdisk*` (thesis 2.2.2.1, Figures 2.5–2.7): when the maximal disk D
//! grown at a point of element a touches only a and a neighbouring part a',
//! cutting with it leaves one subshape as large as before (a redundant
//! cut). The disk is then slid along the bisector of a and a', away from
//! where they meet, until it touches a third element: that disk D* touches
//! three or more parts and divides (a branch point, or a point where the
//! defining pair changes, Figure 2.6).
//!
//! The thesis finds D* by iterating tritangent constructions over the
//! elements that overlap the current candidate. Here the slide follows the
//! bisector by its footpoint parametrisation (kernel::bisector), checks
//! that each disk stays empty with a nearest-element query, and bisects the
//! parameter where emptiness first fails, to 2^-50 of the step. The result
//! is exact up to that bisection; the exact kernel will replace the last
//! step by the Apollonius construction of the three sites.

use super::maxdisk::{DiskFinder, Footpoint};
use crate::kernel::apollonius::Site;
use crate::kernel::bisector::bisector_point;
use crate::kernel::Point;
use crate::shape::{Element, JointKind};

/// What a disk touching `f` sees there: the element's line or circle, or a
/// point at a reflex vertex.
pub fn site_of(finder: &DiskFinder, f: &Footpoint) -> Site {
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
    match e {
        // The interior is left of travel.
        Element::Segment(s) => Site::Line { a: s.a, n: (s.b - s.a).unit().perp() },
        // A counter-clockwise arc has its centre on the interior side:
        // interior disks are nested in its circle.
        Element::Arc(a) => Site::Circle { o: a.center, r: a.radius, outside: !a.is_ccw() },
    }
}

/// The footpoint parameter of a disk centred `c` on site `a` (inverse of
/// [`footpoint`](crate::kernel::bisector::footpoint)).
fn param_on(a: &Site, c: Point, touch: Point) -> f64 {
    match *a {
        Site::Line { a, n } => (touch - a).dot(-n.perp()),
        Site::Point(q) => {
            let d = c - q;
            d.y.atan2(d.x)
        }
        Site::Circle { o, .. } => {
            let d = touch - o;
            d.y.atan2(d.x)
        }
    }
}

/// Slides the disk (`c`, `r`) touching `fa` and `fb` along their bisector,
/// away from `junction` (a point between the two footpoints on the side
/// the redundant cut came from), to the first disk that touches a third
/// element or whose contact with `fa`'s or `fb`'s element reaches that
/// element's end (where the pair defining the axis changes). Returns its
/// centre and radius, or `None` if the bisector ends (no tangent disk)
/// first.
pub fn slide_to_third(
    finder: &DiskFinder,
    fa: &Footpoint,
    fb: &Footpoint,
    c: Point,
    r: f64,
    junction: Point,
) -> Option<(Point, f64)> {
    let (sa, sb) = (site_of(finder, fa), site_of(finder, fb));
    let u0 = param_on(&sa, c, fa.point);
    let empty_tol = 1e-12 * finder.shape().bbox().diagonal();
    let shape = finder.shape();
    let element = |f: &Footpoint| shape.loops()[f.element.loop_index].element(f.element.element);
    let (ea, eb) = (element(fa), element(fb));
    let on = |e: &Element, q: Point| e.closest_point(q).0 <= finder.contact_tolerance();
    // A disk counts while it is empty and still touches both elements
    // (not only their supporting lines or circles).
    let empty = |u: f64| -> Option<(Point, f64, bool)> {
        let (c, r) = bisector_point(&sa, &sb, u)?;
        let (_, d) = finder.nearest(c)?;
        let touches = on(&ea, sa.contact(c, r)) && on(&eb, sb.contact(c, r));
        Some((c, r, d >= r - empty_tol && touches))
    };
    // The direction that moves the centre away from the junction.
    let h0 = match sa {
        Site::Line { .. } => 1e-3 * r.max(empty_tol),
        _ => 1e-3,
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
    // March with steps that move the centre by 2–20 % of the radius.
    let (mut lo, mut h) = (u0, h0);
    let (mut prev_c, mut prev_r) = (c, r);
    for _ in 0..2_000 {
        let u = lo + dir * h;
        let (cc, rr, ok) = empty(u)?;
        let moved = cc.dist(prev_c);
        if moved > 0.2 * prev_r && h > 1e-15 {
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
            return bisector_point(&sa, &sb, lo);
        }
        lo = u;
        (prev_c, prev_r) = (cc, rr);
        if moved < 0.02 * prev_r {
            h *= 2.0;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::bisector::footpoint as fp;
    use crate::shape::{ElementRef, Shape2d, ShapeOptions, Vertex};

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
                assert!((param_on(&s, c, p) - u).abs() < 1e-12, "{s:?} {u}");
            }
        }
    }

    #[test]
    fn slides_from_a_corner_disk_to_the_branch_point() {
        // A 4 × 2 rectangle: the disk grown near the bottom-left corner
        // touches the bottom and the left side (a redundant cut); sliding
        // away from the corner reaches the disk touching the top: radius 1,
        // centre (1, 1).
        let v = |x: f64, y: f64| Vertex { p: Point::new(x, y), bulge: 0.0 };
        let shape = Shape2d::from_bulge_loops(
            vec![vec![v(0.0, 0.0), v(4.0, 0.0), v(4.0, 2.0), v(0.0, 2.0)]],
            &ShapeOptions::default(),
        )
        .unwrap();
        let finder = DiskFinder::new(&shape);
        let d = finder.max_disk(ElementRef { loop_index: 0, element: 0 }, 0.1);
        assert_eq!(d.footpoints.len(), 2, "{d:?}");
        let (c, r) =
            slide_to_third(&finder, &d.footpoints[0], &d.footpoints[1], d.center, d.radius, Point::new(0.0, 0.0))
                .unwrap();
        assert!(c.dist(Point::new(1.0, 1.0)) < 1e-9 && (r - 1.0).abs() < 1e-9, "{c:?} {r}");
        assert_eq!(finder.touching(c, r).len(), 3);
    }
}
