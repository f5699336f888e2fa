//! Medial axes of shapes with holes (thesis 2.3.1, augmented domains),
//! checked by the oracle that shares nothing with the algorithm: every
//! sample at its radius from the boundary, one independent cycle per hole,
//! and the maximal disk at random points of every loop (holes included)
//! centred on the axis.

mod common;

use common::oracle::check;
use common::{circle, poly, rect, same_axis_moved, shape, v};
use medax::kernel::Disk;
use medax::kernel::Point;
use medax::plane::internals::augment;
use medax::plane::{medial_axis, AxisOptions, DiskFinder, MedialAxis2d, NodeKind};
use medax::shape::{samples, Vertex};
use rand::{Rng, SeedableRng};

fn axis_of(loops: Vec<Vec<Vertex>>) -> (medax::shape::Shape2d, MedialAxis2d) {
    let s = shape(loops);
    let a = medial_axis(&s, &AxisOptions::default()).expect("axis");
    (s, a)
}

#[test]
fn one_circular_hole_in_a_square() {
    // A symmetric case: the augmenting disk below the hole touches the
    // bottom edge only; the axis is a cycle round the hole with four
    // spokes to the corners.
    let (s, a) = axis_of(vec![rect(-2.0, -2.0, 2.0, 2.0), circle(0.0, 0.0, 1.0)]);
    check(&s, &a, 400, 1);
    assert_eq!(a.nodes.iter().filter(|n| n.kind == NodeKind::Corner).count(), 4);
    // The cycle passes below the hole at radius 0.5, the augmenting disk.
    // Four branch points on the diagonals, each touching two sides and the
    // hole: √2·(2 − r) = 1 + r.
    let r = (2.0 * 2f64.sqrt() - 1.0) / (2f64.sqrt() + 1.0);
    let branches: Vec<_> = a.nodes.iter().filter(|n| n.kind == NodeKind::Branch).collect();
    assert_eq!(branches.len(), 4, "{branches:?}");
    assert!(branches.iter().all(|n| (n.radius - r).abs() < 1e-9 && (n.point.x.abs() - (2.0 - r)).abs() < 1e-9));
    let below = a
        .sampled(&s, 1e-6)
        .into_iter()
        .flatten()
        .any(|Disk { center: c, radius: r }| c.dist(Point::new(0.0, -1.5)) < 1e-6 && (r - 0.5).abs() < 1e-6);
    assert!(below, "the cycle passes through the augmenting disk's centre");
}

#[test]
fn polygon_holes_with_vertices_lowest() {
    // Triangles and a diamond: the lowest points are reflex vertices of
    // the shape, where the augmenting disk is one of the vertex's fan.
    let tri = |x: f64, y: f64| poly(&[(x, y), (x + 0.4, y + 0.7), (x + 0.8, y + 0.1)]);
    let diamond = poly(&[(3.0, 0.5), (3.5, 1.2), (3.0, 1.9), (2.5, 1.2)]);
    let (s, a) = axis_of(vec![rect(0.0, 0.0, 5.0, 3.0), tri(0.5, 0.4), tri(1.4, 1.6), diamond]);
    check(&s, &a, 400, 2);
}

#[test]
fn hexagon_with_a_centred_hole_has_a_symmetric_axis() {
    // The hexagon's bottom is a convex corner straight below the hole's
    // lowest point: the straight-down disk touches both edges beside it
    // and the hole (three contacts); the augmentation turns its "down",
    // and so cuts the shape with no symmetry at all. The axis must still
    // have every symmetry of the loops, their vertices included (a vertex
    // of the hole is a joint of the axis): a circle of two half arcs has
    // the half turn and the mirrors in both axes, one of six arcs with
    // vertices facing the hexagon's sides all six turns and six mirrors.
    let hex: Vec<(f64, f64)> = (0..6)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 6.0 - std::f64::consts::FRAC_PI_2;
            (3.0 * t.cos(), 3.0 * t.sin())
        })
        .collect();
    let sixths: Vec<Vertex> = (0..6)
        .map(|k| {
            let t = std::f64::consts::FRAC_PI_3 * k as f64;
            v(t.cos(), t.sin(), (std::f64::consts::PI / 12.0).tan())
        })
        .collect();
    for (hole, turns) in [(circle(0.0, 0.0, 1.0), vec![0, 3]), (sixths, (0..6).collect())] {
        let arcs = hole.len();
        let (s, a) = axis_of(vec![poly(&hex), hole]);
        check(&s, &a, 400, 3);
        // A cycle round the hole with a spoke to each corner.
        let kinds = |k: NodeKind| a.nodes.iter().filter(|n| n.kind == k).count();
        assert_eq!((kinds(NodeKind::Corner), kinds(NodeKind::Branch)), (6, 6), "{arcs} arcs: {:?}", a.nodes);
        for k in turns {
            let t = std::f64::consts::FRAC_PI_3 * k as f64;
            let what = format!("{arcs} arcs, turned {k}·60°");
            same_axis_moved(&a, &a, |p, r| (turned(p, t), r), 1e-9, &what);
            let mirror = |p: Point| turned(Point::new(-p.x, p.y), t);
            same_axis_moved(&a, &a, |p, r| (mirror(p), r), 1e-9, &format!("{what}, mirrored"));
        }
    }
}

/// `p` turned by `angle` radians about the origin.
fn turned(p: Point, angle: f64) -> Point {
    let (sin, cos) = angle.sin_cos();
    Point::new(p.x * cos - p.y * sin, p.x * sin + p.y * cos)
}

#[test]
fn random_holes_of_arcs_and_segments() {
    for (k, seed) in [(1, 1), (2, 2), (3, 3), (5, 4), (8, 5), (12, 6)] {
        let (s, a) = axis_of(samples::random_holes(k, seed));
        let r = check(&s, &a, 300, seed);
        assert!(r.samples > 10 * k * k, "{k}: {} samples", r.samples);
    }
}

#[test]
fn perforated_plates_of_regular_grids() {
    // Cocircular contacts everywhere: four holes meet at every cell corner.
    for k in [1, 2, 3, 4, 6] {
        let (s, a) = axis_of(samples::perforated_plate(k));
        check(&s, &a, 300, k as u64);
    }
}

#[test]
fn holes_nearly_touching_each_other_and_the_outside() {
    // Gaps of 1e-4 of the size: thin necks between holes and towards the
    // outer boundary, where the augmenting disks are tiny.
    let (s, a) = axis_of(vec![
        rect(0.0, 0.0, 4.0, 2.0),
        circle(1.0, 1.0, 0.9999),
        poly(&[(2.0001, 0.2), (3.5, 0.2), (3.5, 1.8), (2.0001, 1.8)]),
    ]);
    check(&s, &a, 400, 7);
}

#[test]
fn holes_stacked_so_each_disk_lands_on_the_next() {
    // Each hole's augmenting disk touches the hole below it: the chain of
    // loops reaches the outer boundary only through all the others.
    let mut loops = vec![rect(0.0, 0.0, 2.0, 11.0)];
    for k in 0..10 {
        let y = 0.6 + k as f64;
        loops.push(poly(&[(0.7, y), (1.3, y + 0.1), (1.2, y + 0.7), (0.75, y + 0.6)]));
    }
    let (s, a) = axis_of(loops);
    check(&s, &a, 400, 8);
}

#[test]
fn same_axis_under_transformations_with_holes() {
    let base = samples::random_holes(3, 9);
    let (s, a) = axis_of(base.clone());
    check(&s, &a, 100, 9);
    // Holes listed in another order, each starting at another vertex.
    let mut shuffled: Vec<Vec<Vertex>> = vec![base[0].clone()];
    for h in base[1..].iter().rev() {
        let mut h = h.clone();
        h.rotate_left(1);
        shuffled.push(h);
    }
    same_axis_moved(&a, &axis_of(shuffled).1, |p, r| (p, r), 1e-9, "reordered");
    // Every loop reversed (the library normalises orientation).
    let reversed: Vec<Vec<Vertex>> = base
        .iter()
        .map(|l| {
            let n = l.len();
            (0..n).map(|i| v(l[(n - i) % n].p.x, l[(n - i) % n].p.y, -l[(n - 1 - i) % n].bulge)).collect()
        })
        .collect();
    same_axis_moved(&a, &axis_of(reversed).1, |p, r| (p, r), 1e-9, "reversed");
    for (k, d) in [(1e-3, 0.0), (1e3, 0.0), (1.0, 1e4)] {
        let moved: Vec<Vec<Vertex>> =
            base.iter().map(|l| l.iter().map(|w| v(w.p.x * k + d, w.p.y * k + d, w.bulge)).collect()).collect();
        let back = |p: Point, r: f64| (Point::new((p.x - d) / k, (p.y - d) / k), r / k);
        let tol = if d != 0.0 { 1e-7 } else { 1e-9 };
        same_axis_moved(&a, &axis_of(moved).1, back, tol, &format!("scaled {k} moved {d}"));
    }
    // Turned: the one transform that changes the augmentation, whose disks
    // grow "down" from each hole's lowest point (another point, touching
    // other loops, once the shape turns) and so cut other subshapes.
    let augmenting = |loops: Vec<Vec<Vertex>>| augment(&DiskFinder::new(&shape(loops))).expect("augmented").cuts;
    let own = augmenting(base.clone());
    for t in [0.3, std::f64::consts::FRAC_PI_2, 2.1] {
        let turned_loops: Vec<Vec<Vertex>> = base
            .iter()
            .map(|l| {
                l.iter()
                    .map(|w| {
                        let p = turned(w.p, t);
                        v(p.x, p.y, w.bulge)
                    })
                    .collect()
            })
            .collect();
        let mut back = augmenting(turned_loops.clone()).into_iter().map(|c| turned(c.center, -t));
        assert!(back.any(|c| own.iter().all(|o| o.center.dist(c) > 1e-6)), "turned {t} rad: the same augmenting disks");
        same_axis_moved(&a, &axis_of(turned_loops).1, |p, r| (turned(p, -t), r), 1e-9, &format!("turned {t} rad"));
    }
}

#[test]
fn a_hundred_and_a_thousand_holes() {
    // Plates of 10 × 10 and 32 × 32 cells, a random hole in each (circles,
    // polygons, rounded triangles): the augmented cycle is long and the
    // divide step cuts it through ranges.
    for (k, probes) in [(10, 400), (32, 300)] {
        let (s, a) = axis_of(samples::random_holes(k, 40 + k as u64));
        let r = check(&s, &a, probes, k as u64);
        assert_eq!(s.loops().len(), k * k + 1);
        assert!(r.samples > 20 * k * k, "{k}: {} samples", r.samples);
    }
}

#[test]
fn the_oracles_grid_agrees_with_a_scan() {
    // The grid only prunes: its distances are the brute-force ones, for
    // points inside, outside and far off the shape.
    let s = shape(samples::random_holes(6, 11));
    let b = common::oracle::Boundary::new(&s);
    let bb = s.bbox();
    let mut rng = rand::rngs::SmallRng::seed_from_u64(3);
    for _ in 0..2000 {
        let p = Point::new(
            bb.min.x + rng.gen_range(-1.0..2.0) * bb.width(),
            bb.min.y + rng.gen_range(-1.0..2.0) * bb.height(),
        );
        assert_eq!(b.distance(p), common::boundary_distance(&s, p), "{p:?}");
        assert_eq!(b.inside(p), common::inside(&s, p), "{p:?}");
    }
}

#[test]
fn augmenting_disks_meeting_at_one_vertex() {
    // From the CGAL cross-check: a hole's lowest vertex is also where the
    // augmenting disk of the hole above lands, on the near side of the
    // vertex's fan. The boundary cycle must walk round the lower hole
    // before taking that disk; taken in the wrong order, subshapes held a
    // whole hole without the boundary facing it and base cases broke down.
    for name in ["seed2_holed_36", "seed5_holed_7", "seed12345_holed_9"] {
        let path = format!("{}/tests/data/holed_{name}.json", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        let s = medax::shape::Shape2d::from_json_str(&text, &medax::shape::ShapeOptions::default()).unwrap();
        let a = medial_axis(&s, &AxisOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        check(&s, &a, 200, 12);
    }
}

#[test]
fn disks_landing_on_a_reflex_vertex_of_the_outer_loop() {
    // Review findings: the cycle's last chain and first arc meet at the
    // apex (opened pieces must wrap round the cycle's end), and two
    // augmenting disks at one vertex leave a single point between their
    // arcs that shares its position with the chain beyond them.
    for (twin, extra) in [(false, false), (false, true), (true, false), (true, true)] {
        let (s, a) = axis_of(samples::spike_holes(twin, extra));
        check(&s, &a, 300, 13);
        for seed in 1..6 {
            let b = medial_axis(&s, &AxisOptions { seed, ..AxisOptions::default() })
                .unwrap_or_else(|e| panic!("twin {twin} extra {extra} seed {seed}: {e}"));
            assert_eq!(b.edges.len() + 1, b.nodes.len() + s.loops().len() - 1);
        }
    }
}

#[test]
fn a_row_of_holes_each_landing_on_the_outer_loop() {
    // Every augmenting disk lands on the outer loop's bottom edge: a loop
    // with hundreds of contacts, found by binary search.
    let h = 300;
    let mut loops = vec![vec![v(0.0, 0.0, 0.0), v(h as f64, 0.0, 0.0), v(h as f64, 1.0, 0.0), v(0.0, 1.0, 0.0)]];
    for i in 0..h {
        let x = i as f64 + 0.5 + 0.05 * ((i * 7919 % 13) as f64 / 13.0 - 0.5);
        let y = 0.5 + 0.05 * ((i * 104_729 % 17) as f64 / 17.0 - 0.5);
        let r = 0.3 + 0.02 * ((i * 31 % 11) as f64 / 11.0);
        loops.push(vec![v(x + r, y, -1.0), v(x - r, y, -1.0)]);
    }
    let (s, a) = axis_of(loops);
    check(&s, &a, 300, 14);
}
