//! Unit balls of space (issue 19): the presets are the polytopes they
//! claim (counts and volumes against closed forms), hulls of random clouds
//! pass a brute-force oracle decided with the exact `plane_side`, coplanar
//! inputs merge into their true facets, bad inputs are typed errors, and
//! the gauge is the least r with q ∈ p + r·B.

use medax::kernel::orient3::{collinear3, plane_side, PlaneSide};
use medax::kernel::Point3;
use medax::shape::{Ball3, BallError, Feature3};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::collections::HashSet;

fn p(x: f64, y: f64, z: f64) -> Point3 {
    Point3::new(x, y, z)
}

/// The volume as the sum of the pyramids from the origin over fans of the
/// facets (not from the stored planes).
fn volume(b: &Ball3) -> f64 {
    let v = b.vertices();
    b.facets()
        .iter()
        .map(|f| {
            let c = &f.vertices;
            (1..c.len() - 1).map(|i| v[c[0]].dot(v[c[i]].cross(v[c[i + 1]])) / 6.0).sum::<f64>()
        })
        .sum()
}

/// The combinatorial invariants every ball keeps: Euler's formula, each
/// edge's facets run along it in opposite directions and are not coplanar,
/// facets are convex polygons, stars go round each vertex through its
/// edges, planes match the corners.
fn check_structure(b: &Ball3) {
    let (v, e, f) = (b.vertices().len() as i64, b.edges().len() as i64, b.facets().len() as i64);
    assert_eq!(v - e + f, 2, "Euler: {v} {e} {f}");
    let vs = b.vertices();
    let runs = |facet: usize, a: usize, c: usize| {
        let poly = &b.facets()[facet].vertices;
        (0..poly.len()).any(|i| poly[i] == a && poly[(i + 1) % poly.len()] == c)
    };
    for edge in b.edges() {
        let [a, c] = edge.vertices;
        assert!(a < c);
        assert!(runs(edge.facets[0], a, c) && runs(edge.facets[1], c, a), "{edge:?}");
        let (f0, f1) = (&b.facets()[edge.facets[0]].vertices, &b.facets()[edge.facets[1]].vertices);
        assert!(
            f1.iter().any(|&w| plane_side(vs[f0[0]], vs[f0[1]], vs[f0[2]], vs[w]) == PlaneSide::Below),
            "coplanar neighbours {edge:?}"
        );
    }
    for (k, facet) in b.facets().iter().enumerate() {
        let c = &facet.vertices;
        let m = c.len();
        assert!(m >= 3 && c[0] == *c.iter().min().unwrap());
        for i in 0..m {
            let (x, y, z) = (vs[c[i]], vs[c[(i + 1) % m]], vs[c[(i + 2) % m]]);
            assert!(!collinear3(x, y, z), "facet {k} has a straight corner");
            // Convex and counter-clockwise seen from outside: each turn is
            // positive about the outward normal.
            assert!((y - x).cross(z - y).dot(facet.normal) > 0.0, "facet {k} turns the wrong way");
        }
        assert!((facet.normal.norm() - 1.0).abs() < 1e-12);
        let scale = b.circumradius();
        for &i in c {
            assert!((facet.normal.dot(vs[i]) - facet.offset).abs() < 1e-12 * scale, "facet {k} plane");
        }
    }
    for i in 0..vs.len() {
        let star = b.facets_around(i);
        let degree = b.edges().iter().filter(|e| e.vertices.contains(&i)).count();
        assert!(star.len() >= 3 && star.len() == degree, "vertex {i}: {star:?}");
        let distinct: HashSet<usize> = star.iter().copied().collect();
        assert_eq!(distinct.len(), star.len());
        // Counter-clockwise seen from outside: consecutive normals turn
        // positively about any direction into the vertex's cone; the sum
        // of the star's normals is one.
        let axis = star.iter().fold(Point3::default(), |s, &f| s + b.facets()[f].normal);
        for j in 0..star.len() {
            let (n0, n1) = (b.facets()[star[j]].normal, b.facets()[star[(j + 1) % star.len()]].normal);
            assert!(n0.cross(n1).dot(axis) > 0.0, "vertex {i} star order");
        }
    }
}

/// Brute-force hull oracle, exact: every point on the inner side of (or
/// on) every facet's plane, every facet exactly planar, every vertex one of
/// the points, vertices plus dropped points account for all.
fn check_hull(b: &Ball3, points: &[Point3]) {
    check_structure(b);
    let vs = b.vertices();
    for (k, f) in b.facets().iter().enumerate() {
        let c = &f.vertices;
        let (x, y, z) = (vs[c[0]], vs[c[1]], vs[c[2]]);
        for &w in c {
            assert_eq!(plane_side(x, y, z, vs[w]), PlaneSide::On, "facet {k} not planar");
        }
        for (i, &q) in points.iter().enumerate() {
            assert_ne!(plane_side(x, y, z, q), PlaneSide::Above, "point {i} outside facet {k}");
        }
        assert_eq!(plane_side(x, y, z, p(0.0, 0.0, 0.0)), PlaneSide::Below, "origin not inside facet {k}");
    }
    let given: HashSet<[u64; 3]> = points.iter().map(|q| q.to_array().map(f64::to_bits)).collect();
    assert!(vs.iter().all(|v| given.contains(&v.to_array().map(f64::to_bits))));
    assert_eq!(vs.len() + b.dropped_points(), points.len());
    // Vertices keep the order given.
    let pos: Vec<usize> = vs.iter().map(|v| points.iter().position(|q| q == v).unwrap()).collect();
    assert!(pos.windows(2).all(|w| w[0] < w[1]));
}

/// q ∈ p + r·B by the corners' own planes (not the stored ones), with
/// slack `tol` relative to the ball's size.
fn holds(b: &Ball3, p: Point3, r: f64, q: Point3, tol: f64) -> bool {
    let vs = b.vertices();
    b.facets().iter().all(|f| {
        let c = &f.vertices;
        let n = (vs[c[1]] - vs[c[0]]).cross(vs[c[2]] - vs[c[0]]);
        let n = n * (1.0 / n.norm());
        n.dot(q - p) <= r * n.dot(vs[c[0]]) + tol
    })
}

fn check_gauge(b: &Ball3, rng: &mut SmallRng) {
    for _ in 0..200 {
        let a = p(rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0));
        let c = p(rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0));
        let r = b.distance(a, c);
        let scale = (c - a).norm();
        assert!(r > 0.0 && holds(b, a, r, c, 1e-12 * scale), "{r}");
        assert!(!holds(b, a, r * (1.0 - 1e-9), c, 0.0), "{r} is not the least");
        assert!((b.gauge(c - a) - r).abs() <= 1e-15 * r);
        // Placed at a with radius r, the ball's vertices are r away.
        for v in b.placed(a, r) {
            assert!((b.distance(a, v) - r).abs() <= 1e-12 * r);
        }
    }
    assert_eq!(b.distance(p(1.0, 2.0, 3.0), p(1.0, 2.0, 3.0)), 0.0);
}

fn check_mirror(b: &Ball3, rng: &mut SmallRng) {
    let m = b.mirrored();
    check_structure(&m);
    assert_eq!(&m.mirrored(), b);
    for _ in 0..100 {
        let a = p(rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0));
        let c = p(rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0));
        let (x, y) = (m.distance(a, c), b.distance(c, a));
        assert!((x - y).abs() <= 1e-12 * y, "{x} {y}");
    }
}

#[test]
fn presets_are_the_polytopes_they_claim() {
    let mut rng = SmallRng::seed_from_u64(19);
    let phi: f64 = (1.0 + 5f64.sqrt()) / 2.0;
    let cases = [
        ("tetrahedron", Ball3::tetrahedron(), (4, 6, 4), 8.0 / 3.0, 3f64.sqrt(), 1.0 / 3f64.sqrt()),
        ("cube", Ball3::cube(), (8, 12, 6), 8.0, 3f64.sqrt(), 1.0),
        ("octahedron", Ball3::octahedron(), (6, 12, 8), 4.0 / 3.0, 1.0, 1.0 / 3f64.sqrt()),
        (
            "icosahedron",
            Ball3::icosahedron(),
            (12, 30, 20),
            5.0 / 12.0 * (3.0 + 5f64.sqrt()) * 8.0,
            (1.0 + phi * phi).sqrt(),
            phi * phi / 3f64.sqrt(),
        ),
    ];
    for (name, b, (v, e, f), vol, circ, inr) in cases {
        assert_eq!((b.vertices().len(), b.edges().len(), b.facets().len()), (v, e, f), "{name}");
        assert!((volume(&b) - vol).abs() < 1e-12 * vol, "{name}: {}", volume(&b));
        assert!((b.circumradius() - circ).abs() < 1e-12 && (b.inradius() - inr).abs() < 1e-12, "{name}");
        assert_eq!(b.dropped_points(), 0);
        assert_eq!(b.is_symmetric(), name != "tetrahedron", "{name}");
        check_structure(&b);
        check_gauge(&b, &mut rng);
        check_mirror(&b, &mut rng);
        // Turned, the ball keeps its shape and turns its distances.
        let turned = b.rotated([0.3, -0.5, 0.7]).unwrap();
        check_structure(&turned);
        assert!((volume(&turned) - vol).abs() < 1e-12 * vol);
        let quarter = b.rotated([0.0, 0.0, std::f64::consts::FRAC_PI_2]).unwrap();
        let rz = |q: Point3| p(-q.y, q.x, q.z);
        for _ in 0..50 {
            let a = p(rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0));
            let c = p(rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0));
            let (x, y) = (quarter.distance(rz(a), rz(c)), b.distance(a, c));
            assert!((x - y).abs() < 1e-12 * y, "{name}: {x} {y}");
        }
        assert_eq!(b.rotated([0.0; 3]).unwrap(), b);
    }
    assert_eq!(Ball3::cube().distance(p(1.0, 1.0, 1.0), p(4.0, -1.0, 0.5)), 3.0);
    assert_eq!(Ball3::octahedron().distance(p(1.0, 1.0, 1.0), p(4.0, -1.0, 0.5)), 5.5);
    // The tetrahedron reaches a corner at gauge 1, the opposite way at 3.
    let t = Ball3::tetrahedron();
    assert!((t.gauge(p(1.0, 1.0, 1.0)) - 1.0).abs() < 1e-15 && (t.gauge(p(-1.0, -1.0, -1.0)) - 3.0).abs() < 1e-15);
}

#[test]
fn geodesic_spheres_have_the_closed_form_counts() {
    let mut rng = SmallRng::seed_from_u64(7);
    let mut last = 0.0;
    for (ask, k) in [(1, 0), (20, 0), (21, 1), (320, 2), (1000, 3)] {
        let b = Ball3::geodesic(ask).unwrap();
        let q = 1usize << (2 * k);
        assert_eq!((b.vertices().len(), b.edges().len(), b.facets().len()), (10 * q + 2, 30 * q, 20 * q), "{ask}");
        assert!(b.facets().iter().all(|f| f.vertices.len() == 3));
        assert!(b.vertices().iter().all(|v| (v.norm() - 1.0).abs() < 1e-15));
        let vol = volume(&b);
        assert!(vol >= last && vol < 4.0 / 3.0 * std::f64::consts::PI, "{vol}");
        last = vol;
        assert!(b.is_symmetric());
        check_structure(&b);
        check_gauge(&b, &mut rng);
    }
    // Level 3 is within 2% of the sphere's volume.
    assert!(last > 0.98 * 4.0 / 3.0 * std::f64::consts::PI);
    assert!(matches!(Ball3::geodesic(20 * 4usize.pow(5) + 1), Err(BallError::InvalidArgument { .. })));
    assert!(matches!(Ball3::cube().rotated([f64::NAN, 0.0, 0.0]), Err(BallError::InvalidArgument { .. })));
}

/// A cloud round an off-centre origin: a tetrahedron about the origin
/// (so the origin is inside) and the rest in a shifted box, on a grid of
/// step 1/4 when `grid` (repeats, coplanar and collinear points galore).
fn cloud(rng: &mut SmallRng, n: usize, grid: bool) -> Vec<Point3> {
    let shift = p(rng.gen_range(-0.5..0.5), rng.gen_range(-0.5..0.5), rng.gen_range(-0.5..0.5));
    let coord = |rng: &mut SmallRng| {
        let c: f64 = rng.gen_range(-1.0..1.0);
        if grid {
            (c * 4.0).round() / 4.0
        } else {
            c
        }
    };
    let mut out: Vec<Point3> = [[1.0, 1.0, 1.0], [1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]]
        .iter()
        .map(|&[x, y, z]| p(x, y, z) * rng.gen_range(0.3..0.6))
        .collect();
    while out.len() < n {
        let q = p(coord(rng), coord(rng), coord(rng)) + if grid { p(0.0, 0.0, 0.0) } else { shift };
        out.push(q);
    }
    // Mix the tetrahedron in so it does not seed the hull.
    let i = rng.gen_range(0..n);
    out.swap(0, i);
    out
}

#[test]
fn hulls_of_random_clouds_pass_the_oracle() {
    for seed in 0..12u64 {
        let mut rng = SmallRng::seed_from_u64(seed);
        for &n in &[10, 40, 200, 2000] {
            for grid in [false, true] {
                if n == 2000 && seed % 4 != 0 {
                    continue;
                }
                let points = cloud(&mut rng, n, grid);
                let b = Ball3::from_points(&points).unwrap_or_else(|e| panic!("seed {seed} n {n}: {e}"));
                check_hull(&b, &points);
                assert_eq!(b, Ball3::from_points(&points).unwrap(), "deterministic");
                if n == 40 {
                    check_gauge(&b, &mut rng);
                    check_mirror(&b, &mut rng);
                }
            }
        }
    }
}

#[test]
fn points_on_a_sphere_are_all_vertices() {
    let mut rng = SmallRng::seed_from_u64(3);
    let points: Vec<Point3> = (0..2000)
        .map(|_| loop {
            let q = p(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
            let r = q.norm();
            if r > 0.1 && r < 1.0 {
                break q * (1.0 / r) + p(0.2, -0.1, 0.3);
            }
        })
        .collect();
    let b = Ball3::from_points(&points).unwrap();
    check_hull(&b, &points);
    assert_eq!(b.vertices().len(), 2000);
    assert!(!b.is_symmetric());
}

#[test]
fn a_grid_cube_has_eight_corners_and_six_squares() {
    let mut grid: Vec<Point3> =
        (0..27).map(|i| p((i % 3) as f64 - 1.0, (i / 3 % 3) as f64 - 1.0, (i / 9) as f64 - 1.0)).collect();
    for seed in 0..5u64 {
        let b = Ball3::from_points(&grid).unwrap();
        check_hull(&b, &grid);
        assert_eq!((b.vertices().len(), b.facets().len(), b.dropped_points()), (8, 6, grid.len() - 8));
        assert!(b.facets().iter().all(|f| f.vertices.len() == 4));
        assert!((volume(&b) - 8.0).abs() < 1e-15);
        // Repeats and edge midpoints given first change nothing.
        let mut rng = SmallRng::seed_from_u64(seed);
        for i in (1..grid.len()).rev() {
            grid.swap(i, rng.gen_range(0..=i));
        }
        grid.push(grid[seed as usize]);
    }
}

#[test]
fn bad_points_are_typed_errors() {
    let err = |pts: &[Point3]| Ball3::from_points(pts).unwrap_err();
    let tri = [p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, 0.0, 1.0)];
    assert_eq!(err(&tri), BallError::TooFewPoints { count: 3 });
    let nan = [p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, f64::NAN, 1.0), p(-1.0, -1.0, -1.0)];
    assert_eq!(err(&nan), BallError::NonFinitePoint { point: 2 });
    assert_eq!(err(&nan).vertex(), Some(2));
    let flat: Vec<Point3> = (0..6).map(|i| p(i as f64, (i * i) as f64, 0.0)).collect();
    assert_eq!(err(&flat), BallError::Flat);
    assert_eq!(err(&[p(1.0, 1.0, 1.0); 5]), BallError::Flat);
    let line: Vec<Point3> = (0..5).map(|i| p(i as f64, 2.0 * i as f64, -(i as f64))).collect();
    assert_eq!(err(&line), BallError::Flat);
    // Tilted planes, exactly: four corners of a skew square.
    let skew = [
        p(0.125, 0.25, 0.375),
        p(1.125, 0.25, 0.875),
        p(0.125, 1.25, -0.125),
        p(1.125, 1.25, 0.375),
        p(0.625, 0.75, 0.375),
    ];
    assert_eq!(err(&skew), BallError::Flat);
    // The box [0, 1] × [−1, 1]²: the origin on its facet x = 0.
    let on: Vec<Point3> = (0..8)
        .map(|i| p((i & 1) as f64, if i & 2 == 0 { -1.0 } else { 1.0 }, if i & 4 == 0 { -1.0 } else { 1.0 }))
        .collect();
    let e = err(&on);
    assert!(matches!(e, BallError::OriginNotInsideHull { on_facet: true, .. }), "{e:?}");
    assert!(e.to_string().contains("on facet"));
    let outside: Vec<Point3> = on.iter().map(|&q| q + p(0.5, 0.0, 0.0)).collect();
    let e = err(&outside);
    assert!(matches!(e, BallError::OriginNotInsideHull { on_facet: false, .. }), "{e:?}");
    assert!(e.to_string().contains("outside"));
    // The facet named is the one whose plane holds the origin: x = 0.
    if let BallError::OriginNotInsideHull { facet, .. } = err(&on) {
        let shifted: Vec<Point3> = on.iter().map(|&q| q - p(0.5, 0.0, 0.0)).collect();
        let b = Ball3::from_points(&shifted).unwrap();
        assert!((b.facets()[facet].normal.x + 1.0).abs() < 1e-15, "{:?}", b.facets()[facet]);
    }
    let thin: Vec<Point3> = on.iter().map(|&q| q - p(1e-14, 0.0, 0.0)).collect();
    assert!(matches!(err(&thin), BallError::ThinFacet { .. }));
    let huge: Vec<Point3> = Ball3::cube().vertices().iter().map(|&q| q * 1e200).collect();
    assert!(matches!(err(&huge), BallError::IllConditioned { .. }));
}

#[test]
fn touching_features() {
    let cube = Ball3::cube();
    let f = |b: &Ball3, n: Point3| b.feature_touching_plane_inexact(n).unwrap();
    match f(&cube, p(0.0, 0.0, 2.0)) {
        Feature3::Facet(k) => assert_eq!(cube.facets()[k].normal, p(0.0, 0.0, 1.0)),
        other => panic!("{other:?}"),
    }
    match f(&cube, p(1.0, 1.0, 0.0)) {
        Feature3::Edge(k) => {
            let [a, b] = cube.edges()[k].vertices;
            let (va, vb) = (cube.vertices()[a], cube.vertices()[b]);
            assert!(va.x == 1.0 && va.y == 1.0 && vb.x == 1.0 && vb.y == 1.0);
        }
        other => panic!("{other:?}"),
    }
    match f(&cube, p(1.0, -2.0, 3.0)) {
        Feature3::Vertex(k) => assert_eq!(cube.vertices()[k], p(1.0, -1.0, 1.0)),
        other => panic!("{other:?}"),
    }
    let t = Ball3::tetrahedron();
    match f(&t, p(-1.0, -1.0, -1.0)) {
        Feature3::Facet(k) => assert!(!t.facets()[k].vertices.iter().any(|&v| t.vertices()[v] == p(1.0, 1.0, 1.0))),
        other => panic!("{other:?}"),
    }
    assert_eq!(cube.feature_touching_plane_inexact(p(0.0, 0.0, 0.0)), None);
}

#[test]
#[ignore = "timing: the largest geodesic spheres (run with --release --ignored)"]
fn large_geodesic_spheres() {
    for (ask, v) in [(5120, 2562), (20480, 10242)] {
        let t = std::time::Instant::now();
        let b = Ball3::geodesic(ask).unwrap();
        assert_eq!((b.vertices().len(), b.facets().len()), (v, ask));
        eprintln!("geodesic({ask}): {:?}", t.elapsed());
    }
}

/// A ball keeps what its queries prepare (`Ball3::reach`), a cache that
/// leaves equality alone and answers the same prepared or not, from any
/// thread.
#[test]
fn a_prepared_ball_equals_its_twin_and_answers_the_same() {
    let (a, b) = (Ball3::geodesic(80).unwrap(), Ball3::geodesic(80).unwrap());
    let t = [Point3::new(2.0, 0.1, 0.3), Point3::new(2.5, 1.0, -0.2), Point3::new(1.8, -0.7, 0.9)];
    let first = a.reach_triangle(Point3::new(0.0, 0.0, 0.0), t);
    assert_eq!(a, b);
    assert_eq!(a.clone(), b);
    let answers: Vec<_> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..4).map(|_| s.spawn(|| b.reach_triangle(Point3::new(0.0, 0.0, 0.0), t))).collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert!(answers.iter().all(|x| *x == first), "{answers:?} vs {first:?}");
}
