//! Maximal disks checked by oracles that share nothing with the contact
//! constructions: brute-force distance from the centre to every element,
//! winding numbers for "inside", and bisection along the inward normal on
//! that distance.

mod common;

use common::{bisected_radius, boundary_distance, circle, inside, poly, rect, shape, star, v};
use medax::kernel::Point;
use medax::plane::DiskFinder;
use medax::shape::{samples, ElementRef, JointKind, Shape2d, ShapeOptions};
use rand::{Rng, SeedableRng};

#[derive(Default)]
struct Tally {
    disks: usize,
    corners: usize,
    leaves: usize,
}

/// Grows disks at `count` random points (and at every vertex with `s` = 0)
/// and checks each against the oracles.
fn check_shape(s: &Shape2d, count: usize, seed: u64, tally: &mut Tally) {
    let finder = DiskFinder::new(s);
    let diag = s.bbox().diagonal();
    let tol = 1e-9 * diag;
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let elements: Vec<ElementRef> = s
        .loops()
        .iter()
        .enumerate()
        .flat_map(|(l, lp)| (0..lp.len()).map(move |i| ElementRef { loop_index: l, element: i }))
        .collect();
    for k in 0..count {
        let at = elements[rng.gen_range(0..elements.len())];
        let frac = if k % 5 == 0 { 0.0 } else { rng.gen_range(0.05..0.95) };
        let d = finder.max_disk(at, frac);
        let (p, n) = finder.boundary_point(at, frac);
        let ctx = format!("element {at:?} at {frac}: {d:?}");
        if frac == 0.0 && s.joint(at.loop_index, at.element) == JointKind::Convex {
            // The maximal disk at a convex corner is the corner.
            assert!(d.radius == 0.0 && d.center == p && d.footpoints.len() == 2, "{ctx}");
            tally.corners += 1;
            continue;
        }
        assert!(d.radius.is_finite() && d.radius > 0.0, "{ctx}");
        // Grown from p along n.
        assert!((d.center - (p + n * d.radius)).norm() <= tol, "{ctx}");
        // The disk is empty and touches: distance to the boundary = radius.
        let dist = boundary_distance(s, d.center);
        assert!((dist - d.radius).abs() <= tol, "{ctx}: boundary distance {dist}");
        assert!(inside(s, d.center), "{ctx}: centre outside");
        // Maximal along its normal: a slightly larger disk would not fit.
        if !d.leaf_arc {
            let t = bisected_radius(s, p, n, diag);
            assert!((t - d.radius).abs() <= 1e-6 * diag, "{ctx}: bisection says {t}");
        }
        // Footpoints: the point grown from first, all on the circle.
        assert_eq!(d.footpoints[0].element, at, "{ctx}");
        for f in &d.footpoints {
            assert!((f.point.dist(d.center) - d.radius).abs() <= 2.0 * finder.contact_tolerance(), "{ctx}");
        }
        assert!(d.leaf_arc || d.footpoints.len() >= 2, "{ctx}");
        tally.disks += 1;
        tally.leaves += d.leaf_arc as usize;
    }
}

#[test]
fn random_star_polygons() {
    let mut t = Tally::default();
    for seed in 0..30 {
        let s = shape(vec![star(5 + (seed as usize * 7) % 200, seed)]);
        check_shape(&s, 60, seed, &mut t);
    }
    assert!(t.disks + t.corners == 1800 && t.disks > 1500 && t.corners > 100, "{} {}", t.disks, t.corners);
}

#[test]
fn smooth_biarc_curves_have_leaf_arcs() {
    let mut t = Tally::default();
    for n in [10, 40, 200, 2000] {
        let s = shape(samples::flower_arcs(n));
        check_shape(&s, 200, n as u64, &mut t);
    }
    assert!(t.leaves > 0, "no leaf arc met: {}", t.leaves);
}

#[test]
fn arcs_bulging_both_ways_with_corners() {
    let mut t = Tally::default();
    let mut rng = rand::rngs::SmallRng::seed_from_u64(9);
    let mut built = 0;
    for seed in 0..200 {
        let mut l = star(6 + seed % 30, 1000 + seed as u64);
        for x in l.iter_mut() {
            if rng.gen_bool(0.6) {
                x.bulge = rng.gen_range(-0.4..0.4);
            }
        }
        let Ok(s) = Shape2d::from_bulge_loops(vec![l], &ShapeOptions::default()) else { continue };
        built += 1;
        check_shape(&s, 30, seed as u64, &mut t);
    }
    assert!(built > 60, "only {built} valid shapes");
}

#[test]
fn regular_polygons_branch_at_the_centre() {
    for n in [3usize, 4, 6, 7, 12] {
        let pts: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                (a.cos(), a.sin())
            })
            .collect();
        let s = shape(vec![poly(&pts)]);
        let finder = DiskFinder::new(&s);
        // From the middle of a side: the incircle, touching all n sides.
        let d = finder.max_disk(ElementRef { loop_index: 0, element: 0 }, 0.5);
        let inradius = (std::f64::consts::PI / n as f64).cos();
        assert!((d.radius - inradius).abs() < 1e-12 && d.center.norm() < 1e-12, "{n}: {d:?}");
        assert_eq!(d.footpoints.len(), n, "{n}: {d:?}");
        let mut t = Tally::default();
        check_shape(&s, 50, n as u64, &mut t);
    }
}

#[test]
fn degenerate_axes_circles_stadiums_rounded_rectangles() {
    let mut t = Tally::default();
    // A circle: every disk is the circle itself.
    let c = shape(vec![circle(0.0, 0.0, 2.0)]);
    let finder = DiskFinder::new(&c);
    let d = finder.max_disk(ElementRef { loop_index: 0, element: 1 }, 0.3);
    assert!(d.leaf_arc && (d.radius - 2.0).abs() < 1e-12 && d.center.norm() < 1e-12, "{d:?}");
    check_shape(&c, 20, 1, &mut t);
    // A stadium: two half circles and two segments.
    let stadium = shape(vec![vec![v(0.0, 0.0, 0.0), v(4.0, 0.0, 1.0), v(4.0, 2.0, 0.0), v(0.0, 2.0, 1.0)]]);
    check_shape(&stadium, 100, 2, &mut t);
    // A rounded rectangle: quarter circles at the corners.
    let b = (std::f64::consts::PI / 8.0).tan();
    let rr = shape(vec![vec![
        v(1.0, 0.0, 0.0),
        v(5.0, 0.0, b),
        v(6.0, 1.0, 0.0),
        v(6.0, 2.0, b),
        v(5.0, 3.0, 0.0),
        v(1.0, 3.0, b),
        v(0.0, 2.0, 0.0),
        v(0.0, 1.0, b),
    ]]);
    check_shape(&rr, 100, 3, &mut t);
    // A rectangle: the disk at mid-side of the long side touches both long sides.
    let r = shape(vec![rect(0.0, 0.0, 10.0, 2.0)]);
    let d = DiskFinder::new(&r).max_disk(ElementRef { loop_index: 0, element: 0 }, 0.5);
    assert!((d.radius - 1.0).abs() < 1e-12 && d.footpoints.len() == 2, "{d:?}");
    check_shape(&r, 50, 4, &mut t);
}

#[test]
fn holes_and_dense_teeth() {
    let mut t = Tally::default();
    let plate = shape(samples::perforated_plate(6));
    check_shape(&plate, 300, 5, &mut t);
    let comb = shape(samples::slanted_comb(40, 10.0));
    check_shape(&comb, 300, 6, &mut t);
    let mut with_holes = vec![rect(0.0, 0.0, 10.0, 10.0)];
    with_holes.push(circle(3.0, 3.0, 1.0).into_iter().rev().map(|x| v(x.p.x, x.p.y, -1.0)).collect());
    with_holes.push(poly(&[(6.0, 6.0), (6.0, 8.0), (8.0, 8.0), (8.0, 6.0)]));
    check_shape(&shape(with_holes), 300, 7, &mut t);
}

#[test]
fn reflex_vertices() {
    // An L shape: the reflex vertex at (1, 1).
    let l = shape(vec![poly(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)])]);
    let finder = DiskFinder::new(&l);
    // Grown from the reflex vertex along the normal of the element that
    // starts there (from (1,1) to (1,2), normal pointing to −x).
    let d = finder.max_disk(ElementRef { loop_index: 0, element: 3 }, 0.0);
    assert!((d.radius - 0.5).abs() < 1e-12 && d.center.dist(Point::new(0.5, 1.0)) < 1e-12, "{d:?}");
    let mut t = Tally::default();
    check_shape(&l, 200, 8, &mut t);
}

#[test]
fn a_needle_thinner_than_the_tolerance_is_touched_from_its_own_side() {
    // A reflex needle 0.6 tall and 6e-6 wide at its base rises into a unit
    // square; near its tip its two sides are closer than the tolerance. A
    // disk tangent to the left side there lies within the tolerance of the
    // right side's line too, but reaches it only through the needle: the
    // right side is not a contact.
    let w = 6e-6;
    let s = shape(vec![poly(&[
        (0.0, 0.0),
        (0.5 - w / 2.0, 0.0),
        (0.5, 0.6),
        (0.5 + w / 2.0, 0.0),
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
    ])]);
    let finder = DiskFinder::new(&s);
    let lp = &s.loops()[0];
    let left = lp.element(1);
    let q = left.point_at(1.0 - 8e-5 / 0.6);
    let n = (left.end() - left.start()).unit().perp();
    let r = 0.05;
    let c = q + n * r;
    let tol = 1e-9 * s.bbox().diagonal();
    // The oracle sees both sides within the tolerance of the circle.
    let right = lp.element(2);
    assert!((right.closest_point(c).0 - r).abs() <= tol, "the right side is within the tolerance");
    assert!(right.closest_point(c).1.dist(q) > tol, "at a footpoint of its own");
    let feet = finder.touching(c, r);
    assert!(feet.iter().any(|f| f.element.element == 1), "{feet:?}");
    assert!(feet.iter().all(|f| f.element.element != 2), "{feet:?}");
}
