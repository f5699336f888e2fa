//! Do two boundary elements cross, touch or come closer than a tolerance?
//!
//! The closest approach of two disjoint circular arcs or segments is attained
//! at an endpoint of one of them or at a pair of points on their supporting
//! primitives' common normal (for a segment and an arc: the arc point whose
//! normal is perpendicular to the line; for two arcs: points on the line of
//! centres). Crossings are intersection points of the supporting primitives.
//! So a handful of candidate points decides the question; every candidate is
//! re-measured with [`Element::closest_point`] on both elements, which also
//! discards spurious intersection points produced by ill-conditioned
//! constructions (nearly tangent circles, nearly parallel lines).

use crate::kernel::element::Element;
use crate::kernel::{construct, Point};
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::bulge_loop::LoopKind;
use crate::shape::model::error::ElementRef;

/// Where elements `ra` and `rb` of `loops` cross or come within `tol`,
/// ignoring the surroundings (64 × `tol`) of the vertices they share as
/// consecutive elements of one loop; `None` when they keep apart.
pub(crate) fn element_pair_approach(loops: &[Loop], ra: ElementRef, rb: ElementRef, tol: f64) -> Option<Point> {
    let curve = |r: ElementRef| loops[r.loop_index].kind() == LoopKind::Curve;
    if curve(ra) || curve(rb) {
        return curve_pair_approach(loops, ra, rb, tol);
    }
    region_pair_approach(loops, ra, rb, tol)
}

/// [`element_pair_approach`] when one element is on a curve site. A curve
/// loop's way back lies on its way out: only the way out is checked, as
/// an open chain (its first and last elements do not meet).
fn curve_pair_approach(loops: &[Loop], ra: ElementRef, rb: ElementRef, tol: f64) -> Option<Point> {
    let back = |r: ElementRef| {
        let l = &loops[r.loop_index];
        l.kind() == LoopKind::Curve && 2 * r.element >= l.len()
    };
    if back(ra) || back(rb) {
        return None;
    }
    if ra.loop_index != rb.loop_index {
        return region_pair_approach(loops, ra, rb, tol);
    }
    let (i, j) = (ra.element.min(rb.element), ra.element.max(rb.element));
    let (ea, eb) = (loops[ra.loop_index].element(i), loops[ra.loop_index].element(j));
    let joint = [ea.end()];
    let shared = if j == i + 1 { &joint[..] } else { &joint[..0] };
    if j == i + 1 && joint_cones_apart(&ea, &eb) {
        return None;
    }
    approach_point(&ea, &eb, tol, shared, 64.0 * tol)
}

/// [`element_pair_approach`] for elements of regions (or of two loops).
fn region_pair_approach(loops: &[Loop], ra: ElementRef, rb: ElementRef, tol: f64) -> Option<Point> {
    let ea = loops[ra.loop_index].element(ra.element);
    let eb = loops[rb.loop_index].element(rb.element);
    let mut shared = [Point::default(); 2];
    let mut k = 0;
    if ra.loop_index == rb.loop_index {
        let n = loops[ra.loop_index].len();
        if (ra.element + 1) % n == rb.element {
            shared[k] = ea.end();
            k += 1;
        }
        if (rb.element + 1) % n == ra.element {
            shared[k] = ea.start();
            k += 1;
        }
    }
    if k == 1 {
        let (into, out) =
            if (ra.element + 1) % loops[ra.loop_index].len() == rb.element { (&ea, &eb) } else { (&eb, &ea) };
        if joint_cones_apart(into, out) {
            return None;
        }
    }
    approach_point(&ea, &eb, tol, &shared[..k], 64.0 * tol)
}

/// True when `into` (ending at vertex v) and `out` (starting at v) cannot
/// come within `tol` of each other farther than 64·`tol` from v.
///
/// Seen from v, an arc's points lie in the cone between its tangent at v and
/// its chord (tangent–chord angle = half the sweep). If the two cones are
/// separated by an angle γ, a point at distance d ≥ 64·tol from v is at
/// least d·sin γ from the other element; sin γ > 1/64 makes that exceed tol.
fn joint_cones_apart(into: &Element, out: &Element) -> bool {
    let v = into.end();
    let cone_a = (-into.end_tangent(), (into.start() - v).unit());
    let cone_b = (out.start_tangent(), (out.end() - v).unit());
    // Cones at least half a turn wide are rare (arcs over 360°·…); leave
    // them to the full test.
    let narrow = |(p, q): (Point, Point)| p.dot(q) > -0.999;
    if !(narrow(cone_a) && narrow(cone_b)) {
        return false;
    }
    let inside = |(p, q): (Point, Point), x: Point| {
        let w = p.cross(q);
        // A segment's cone is a single ray; whether another ray meets it is
        // left to the pairwise angle test below.
        w != 0.0 && p.cross(x) * w >= 0.0 && x.cross(q) * w >= 0.0 && p.dot(x) + q.dot(x) > -1e-12
    };
    if [cone_b.0, cone_b.1].iter().any(|&x| inside(cone_a, x))
        || [cone_a.0, cone_a.1].iter().any(|&x| inside(cone_b, x))
    {
        return false;
    }
    const MIN_SIN: f64 = 1.0 / 64.0;
    let apart = |x: Point, y: Point| x.dot(y) < 0.0 || x.cross(y).abs() > MIN_SIN;
    [cone_a.0, cone_a.1].iter().all(|&x| [cone_b.0, cone_b.1].iter().all(|&y| apart(x, y)))
}

/// A point where `a` and `b` come within `tol` of each other, ignoring
/// places within `exclude_radius` of any point in `exclude` (the vertices the
/// two elements legitimately share). `None` when they stay apart.
pub(crate) fn approach_point(
    a: &Element,
    b: &Element,
    tol: f64,
    exclude: &[Point],
    exclude_radius: f64,
) -> Option<Point> {
    let mut found = None;
    // Near-approach candidates are ignored within `exclude_radius` of a shared
    // vertex (the elements approach each other there by construction), true
    // crossing points only within 2·tol, so a crossing just beside the vertex
    // is still caught.
    let mut consider_as = |q: Point, crossing: bool| {
        if found.is_some() || !q.is_finite() {
            return;
        }
        let radius = if crossing { (2.0 * tol).min(exclude_radius) } else { exclude_radius };
        if exclude.iter().any(|v| v.dist(q) <= radius) {
            return;
        }
        if a.closest_point(q).0 <= tol && b.closest_point(q).0 <= tol {
            found = Some(q);
        }
    };
    // Endpoints of each, projected onto the other.
    for (e, other) in [(a, b), (b, a)] {
        for p in [e.start(), e.end()] {
            let (d, q) = other.closest_point(p);
            if d <= tol {
                consider_as(p.mid(q), false);
            }
        }
    }
    match (a, b) {
        (Element::Segment(s), Element::Segment(t)) => {
            if let Some((p, _, _)) = construct::line_line(s.a, s.b - s.a, t.a, t.b - t.a) {
                consider_as(p, true);
            }
        }
        (Element::Segment(s), Element::Arc(c)) | (Element::Arc(c), Element::Segment(s)) => {
            let u = s.b - s.a;
            for t in construct::line_circle(s.a, u, c.center, c.radius) {
                consider_as(s.a + u * t, true);
            }
            // Closest approach of a line and a circle lies on the normal
            // through the centre.
            let foot = s.a + u * construct::project_param(s.a, s.b, c.center);
            let n = (foot - c.center).unit();
            if n != Point::default() {
                let on_arc = c.center + n * c.radius;
                let (_, q) = Element::Segment(*s).closest_point(on_arc);
                consider_as(on_arc.mid(q), false);
                let (_, q) = Element::Arc(*c).closest_point(foot);
                consider_as(q, false);
            }
        }
        (Element::Arc(c1), Element::Arc(c2)) => {
            for p in construct::circle_circle(c1.center, c1.radius, c2.center, c2.radius) {
                consider_as(p, true);
            }
            let u = (c2.center - c1.center).unit();
            if u != Point::default() {
                for p in [
                    c1.center + u * c1.radius,
                    c1.center - u * c1.radius,
                    c2.center + u * c2.radius,
                    c2.center - u * c2.radius,
                ] {
                    consider_as(p, false);
                }
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Element {
        Element::from_bulge(Point::new(ax, ay), Point::new(bx, by), 0.0)
    }

    #[test]
    fn crossing_segments_meet() {
        let p = approach_point(&seg(0.0, 0.0, 2.0, 2.0), &seg(0.0, 2.0, 2.0, 0.0), 1e-9, &[], 0.0).unwrap();
        assert!(p.dist(Point::new(1.0, 1.0)) < 1e-12);
        assert!(approach_point(&seg(0.0, 0.0, 1.0, 0.0), &seg(0.0, 1.0, 1.0, 1.0), 1e-9, &[], 0.0).is_none());
    }

    #[test]
    fn touching_within_tolerance_is_found() {
        // T-junction with a 1e-10 gap.
        let a = seg(0.0, 0.0, 2.0, 0.0);
        let b = seg(1.0, 1e-10, 1.0, 1.0);
        assert!(approach_point(&a, &b, 1e-9, &[], 0.0).is_some());
        assert!(approach_point(&a, &b, 1e-11, &[], 0.0).is_none());
        // Collinear overlap.
        assert!(approach_point(&a, &seg(1.0, 0.0, 3.0, 0.0), 1e-9, &[], 0.0).is_some());
    }

    #[test]
    fn arc_kissing_a_segment_is_found() {
        // Half circle of radius 1 around (0,1) bulging down to touch y = 0 at x = 0.
        let arc = Element::from_bulge(Point::new(-1.0, 1.0), Point::new(1.0, 1.0), 1.0);
        let line = seg(-5.0, -1e-12, 5.0, -1e-12);
        let p = approach_point(&arc, &line, 1e-9, &[], 0.0).unwrap();
        assert!(p.dist(Point::new(0.0, 0.0)) < 1e-9);
        let below = seg(-5.0, -1e-3, 5.0, -1e-3);
        assert!(approach_point(&arc, &below, 1e-9, &[], 0.0).is_none());
    }

    #[test]
    fn nested_arcs_near_the_line_of_centres() {
        // Two arcs facing each other across a gap of 1e-10 at x = 1.
        let a = Element::from_bulge(Point::new(0.0, -1.0), Point::new(0.0, 1.0), 1.0);
        let b = Element::from_bulge(Point::new(2.0 + 1e-10, 1.0), Point::new(2.0 + 1e-10, -1.0), 1.0);
        assert!(approach_point(&a, &b, 1e-9, &[], 0.0).is_some());
        assert!(approach_point(&a, &b, 1e-11, &[], 0.0).is_none());
    }

    #[test]
    fn joint_cones_separate_corners_but_not_near_reversals() {
        // A right-angle corner of two segments: cones far apart.
        assert!(joint_cones_apart(&seg(0.0, 0.0, 1.0, 0.0), &seg(1.0, 0.0, 1.0, 1.0)));
        // A smooth joint of two short arcs.
        let a = Element::from_bulge(Point::new(-1.0, 0.0), Point::new(0.0, 0.0), 0.1);
        let b = Element::from_bulge(Point::new(0.0, 0.0), Point::new(1.0, 0.0), 0.1);
        assert!(joint_cones_apart(&a, &b));
        // The second segment turns back to within 1/100 rad of the first:
        // too close to rule out a near-touch without the full test.
        assert!(!joint_cones_apart(&seg(0.0, 0.0, 1.0, 0.0), &seg(1.0, 0.0, 0.0, 0.01)));
        // A 270° arc turning left wraps back over the incoming side: its
        // cone (half the sweep, 135°..270°) contains direction 180°.
        let big = (3.0f64 * std::f64::consts::PI / 8.0).tan();
        let left = Element::from_bulge(Point::new(1.0, 0.0), Point::new(1.0, -1.0), big);
        assert!(!joint_cones_apart(&seg(0.0, 0.0, 1.0, 0.0), &left));
        // Turning right it bends away (cone 45°..−90°).
        let right = Element::from_bulge(Point::new(1.0, 0.0), Point::new(1.0, -1.0), -big);
        assert!(joint_cones_apart(&seg(0.0, 0.0, 1.0, 0.0), &right));
    }

    #[test]
    fn shared_vertex_is_excluded() {
        let a = seg(0.0, 0.0, 1.0, 0.0);
        let b = seg(1.0, 0.0, 1.0, 1.0);
        assert!(approach_point(&a, &b, 1e-9, &[Point::new(1.0, 0.0)], 1e-7).is_none());
        assert!(approach_point(&a, &b, 1e-9, &[], 0.0).is_some());
    }
}
