//! Voronoi sites besides holes (thesis 2.3, Observation 6): open curve
//! sites, stored as two-sided loops. Stage 1: curves of segments.

mod common;

use common::{oracle, poly, rect, v};
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions, NodeKind};
use medax::shape::{JointKind, LoopKind, Shape2d, ShapeError, ShapeOptions, Vertex};

fn sites(loops: Vec<Vec<Vertex>>, curves: Vec<Vec<Vertex>>) -> Result<Shape2d, ShapeError> {
    Shape2d::from_sites(loops, curves, Vec::new(), &ShapeOptions::default())
}

#[test]
fn a_segment_site_validates_as_a_two_sided_loop() {
    let s = sites(vec![rect(0.0, 0.0, 10.0, 10.0)], vec![poly(&[(3.0, 5.0), (7.0, 5.0)])]).unwrap();
    assert_eq!(s.loops().len(), 2);
    assert_eq!(s.kind(1), LoopKind::Curve);
    assert_eq!(s.loops()[1].len(), 2);
    // Both ends are cusps: reflex, fan of π.
    assert_eq!(s.joint(1, 0), JointKind::Reflex);
    assert_eq!(s.joint(1, 1), JointKind::Reflex);
    // A bent polyline: each inner vertex once convex (inside the bend) and
    // once reflex (outside it).
    let s = sites(vec![rect(0.0, 0.0, 10.0, 10.0)], vec![poly(&[(2.0, 2.0), (5.0, 6.0), (8.0, 2.0)])]).unwrap();
    let lp = &s.loops()[1];
    assert_eq!(lp.len(), 4);
    let kinds: Vec<JointKind> = (0..4).map(|v| s.joint(1, v)).collect();
    assert_eq!(kinds[0], JointKind::Reflex);
    assert_eq!(kinds[2], JointKind::Reflex);
    let mut inner = [kinds[1], kinds[3]];
    inner.sort_by_key(|k| *k as u8);
    assert_eq!(inner, [JointKind::Convex, JointKind::Reflex]);
}

#[test]
fn curve_sites_that_cross_or_touch_are_refused() {
    let sq = || vec![rect(0.0, 0.0, 10.0, 10.0)];
    // Through the outer boundary.
    assert!(sites(sq(), vec![poly(&[(3.0, 5.0), (12.0, 5.0)])]).is_err());
    // Two curves crossing.
    assert!(sites(sq(), vec![poly(&[(3.0, 5.0), (7.0, 5.0)]), poly(&[(5.0, 3.0), (5.0, 7.0)])]).is_err());
    // A curve crossing itself.
    assert!(sites(sq(), vec![poly(&[(2.0, 2.0), (8.0, 8.0), (8.0, 2.0), (2.0, 8.0)])]).is_err());
    // A curve folding back onto itself (an inner cusp).
    assert!(sites(sq(), vec![poly(&[(2.0, 5.0), (8.0, 5.0), (4.0, 5.0)])]).is_err());
    // Inside a hole.
    let holed = vec![rect(0.0, 0.0, 10.0, 10.0), rect(2.0, 2.0, 8.0, 8.0)];
    assert!(matches!(sites(holed, vec![poly(&[(4.0, 5.0), (6.0, 5.0)])]), Err(ShapeError::HoleInsideHole { .. })));
    // Outside the shape.
    assert!(matches!(sites(sq(), vec![poly(&[(14.0, 5.0), (16.0, 5.0)])]), Err(ShapeError::HoleOutside { .. })));
}

fn check(loops: Vec<Vec<Vertex>>, curves: Vec<Vec<Vertex>>) -> medax::plane::MedialAxis2d {
    let s = sites(loops, curves).unwrap();
    let axis = medial_axis(&s, &AxisOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    oracle::check(&s, &axis, 400, 7);
    axis
}

#[test]
fn a_square_with_a_horizontal_segment_site() {
    let axis = check(vec![rect(0.0, 0.0, 10.0, 10.0)], vec![poly(&[(3.0, 5.0), (7.0, 5.0)])]);
    // By symmetry the segment's region is bounded by a cycle with four
    // branch points (where the square's corner bisectors meet it).
    let branches = axis.nodes.iter().filter(|n| n.kind == NodeKind::Branch).count();
    assert!(branches >= 4, "{branches}");
}

#[test]
fn slanted_segments_and_bent_polylines() {
    let sq = || vec![rect(0.0, 0.0, 10.0, 10.0)];
    check(sq(), vec![poly(&[(2.3, 3.1), (7.2, 6.4)])]);
    check(sq(), vec![poly(&[(2.0, 2.0), (5.0, 6.0), (8.0, 2.5)])]);
    check(sq(), vec![poly(&[(2.0, 7.0), (4.0, 3.0), (6.0, 6.5), (8.1, 3.2)])]);
}

#[test]
fn several_segment_sites_and_a_hole() {
    let curves =
        vec![poly(&[(1.0, 1.0), (4.0, 2.0)]), poly(&[(6.0, 7.0), (9.0, 8.5)]), poly(&[(1.5, 8.0), (3.0, 6.0)])];
    check(vec![rect(0.0, 0.0, 10.0, 10.0), rect(5.0, 2.0, 7.0, 4.0)], curves);
}

#[test]
fn a_segment_site_in_a_circle() {
    check(vec![vec![v(5.0, 0.0, 1.0), v(-5.0, 0.0, 1.0)]], vec![poly(&[(-1.0, 0.5), (1.5, -0.2)])]);
    let _ = Point::default();
}

/// Random non-crossing segment and polyline sites in a square (kept apart
/// by a grid of cells), every leaf size and a few seeds, under the oracle.
#[test]
fn random_segment_sites_under_the_oracle() {
    random_sites(11, 0.0);
}

#[test]
fn random_curve_sites_with_arcs_under_the_oracle() {
    random_sites(12, 0.5);
}

fn random_sites(seed: u64, arcs: f64) {
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let mut shapes = 0;
    for round in 0..60 {
        let cells = 2 + round % 4;
        let side = 10.0 / cells as f64;
        let mut curves = Vec::new();
        for cx in 0..cells {
            for cy in 0..cells {
                if rng.gen_bool(0.3) {
                    continue;
                }
                let (x0, y0) = (cx as f64 * side, cy as f64 * side);
                let k = rng.gen_range(1..4);
                let pts: Vec<(f64, f64)> = (0..=k)
                    .map(|_| (x0 + side * rng.gen_range(0.1..0.9), y0 + side * rng.gen_range(0.1..0.9)))
                    .collect();
                let mut c = poly(&pts);
                for x in c.iter_mut() {
                    if rng.gen_bool(arcs) {
                        x.bulge = rng.gen_range(-0.8..0.8);
                    }
                }
                curves.push(c);
            }
        }
        let s = match sites(vec![rect(0.0, 0.0, 10.0, 10.0)], curves) {
            Ok(s) => s,
            // A random polyline may cross itself, an arc bulge out of its cell.
            Err(ShapeError::Intersection { first, second, .. })
                if first.loop_index == second.loop_index || arcs > 0.0 =>
            {
                continue
            }
            Err(e) => panic!("round {round}: {e}"),
        };
        for (seed, leaf_parts) in [(1u64, 3usize), (2, 8), (3, 32)] {
            let axis = medial_axis(&s, &AxisOptions { seed, leaf_parts }).unwrap_or_else(|e| {
                panic!(
                    "round {round} seed {seed} leaf {leaf_parts}: {e}\n{:?}",
                    s.loops().iter().skip(1).map(|l| l.vertices().to_vec()).collect::<Vec<_>>()
                )
            });
            oracle::check(&s, &axis, 200, seed);
        }
        shapes += 1;
    }
    assert!(shapes >= 15, "{shapes}");
}

#[test]
fn the_axis_of_a_horizontal_segment_site_by_hand() {
    // Square [0,10]², segment (3,5)-(7,5). Above the segment's middle the
    // axis is the parabola-free bisector of the segment and the top side:
    // the point (5, 7.5), radius 2.5.
    let s = sites(vec![rect(0.0, 0.0, 10.0, 10.0)], vec![poly(&[(3.0, 5.0), (7.0, 5.0)])]).unwrap();
    let axis = medial_axis(&s, &AxisOptions::default()).unwrap();
    let lines = axis.sampled(&s, 1e-6);
    let near = oracle::axis_distance(&lines, Point::new(5.0, 7.5));
    assert!(near < 1e-6, "{near}");
    let near = oracle::axis_distance(&lines, Point::new(5.0, 2.5));
    assert!(near < 1e-6, "{near}");
    // Right of the segment: the point (8.5, 5) is 1.5 from the end and the wall.
    let near = oracle::axis_distance(&lines, Point::new(8.5, 5.0));
    assert!(near < 1e-6, "{near}");
    // No axis on the segment itself.
    assert!(oracle::axis_distance(&lines, Point::new(5.0, 5.0)) > 1.0);
    assert_eq!(axis.edges.len(), axis.nodes.len(), "one cycle");
}

/// Stage 3 probe: curve sites with arcs (a C, an S, a polyline with an arc).
#[test]
fn curve_sites_with_arcs() {
    let sq = || vec![rect(0.0, 0.0, 10.0, 10.0)];
    // A C: three quarters of the circle of radius 2 round (5, 5).
    let c = vec![v(7.0, 5.0, (3.0 * std::f64::consts::PI / 8.0).tan()), v(5.0, 3.0, 0.0)];
    check(sq(), vec![c]);
    // The same C the other way round.
    let c = vec![v(5.0, 3.0, -(3.0 * std::f64::consts::PI / 8.0).tan()), v(7.0, 5.0, 0.0)];
    check(sq(), vec![c]);
    // An S of two half circles.
    check(sq(), vec![vec![v(2.0, 5.0, 1.0), v(5.0, 5.0, -1.0), v(8.0, 5.0, 0.0)]]);
    // Segment, arc, segment.
    check(sq(), vec![vec![v(2.0, 2.0, 0.0), v(4.0, 6.0, 0.4), v(7.0, 6.5, 0.0), v(8.0, 2.0, 0.0)]]);
}

/// Many short segment sites (one per cell of a grid), several seeds.
#[test]
fn a_hundred_segment_sites() {
    use rand::{Rng, SeedableRng};
    for seed in 0..6u64 {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(100 + seed);
        let cells = 10;
        let side = 10.0 / cells as f64;
        let mut curves = Vec::new();
        for cx in 0..cells {
            for cy in 0..cells {
                let (x0, y0) = (cx as f64 * side, cy as f64 * side);
                let p = |rng: &mut rand::rngs::SmallRng| {
                    (x0 + side * rng.gen_range(0.1..0.9), y0 + side * rng.gen_range(0.1..0.9))
                };
                let (a, b) = (p(&mut rng), p(&mut rng));
                curves.push(poly(&[a, b]));
            }
        }
        let s = sites(vec![rect(0.0, 0.0, 10.0, 10.0)], curves).unwrap();
        let axis = medial_axis(&s, &AxisOptions { seed, ..AxisOptions::default() })
            .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
        oracle::check(&s, &axis, 500, seed);
    }
}

fn with_points(loops: Vec<Vec<Vertex>>, curves: Vec<Vec<Vertex>>, points: &[(f64, f64)]) -> medax::plane::MedialAxis2d {
    let pts = points.iter().map(|&(x, y)| Point::new(x, y)).collect();
    let s = Shape2d::from_sites(loops, curves, pts, &ShapeOptions::default()).unwrap();
    let axis = medial_axis(&s, &AxisOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    oracle::check(&s, &axis, 400, 7);
    // The joints where a point's fan was cut in the base case are merged
    // away: no node of two edges with the same pair of primitives.
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); axis.nodes.len()];
    for (i, e) in axis.edges.iter().enumerate() {
        at[e.from].push(i);
        at[e.to].push(i);
    }
    for (v, es) in at.iter().enumerate() {
        if let [a, b] = es[..] {
            let (sa, sb) = (axis.edges[a].sites, axis.edges[b].sites);
            assert!(sa != sb && sa != [sb[1], sb[0]], "pass-through node {:?}", axis.nodes[v]);
        }
    }
    axis
}

#[test]
fn a_point_site_in_a_square() {
    let s = Shape2d::from_sites(
        vec![rect(0.0, 0.0, 10.0, 10.0)],
        vec![],
        vec![Point::new(4.0, 5.5)],
        &ShapeOptions::default(),
    )
    .unwrap();
    assert_eq!(s.kind(1), LoopKind::Point);
    assert_eq!(s.joint(1, 0), JointKind::Reflex);
    let axis = with_points(vec![rect(0.0, 0.0, 10.0, 10.0)], vec![], &[(4.0, 5.5)]);
    assert_eq!(axis.edges.len(), axis.nodes.len(), "one cycle");
    // The centre (the square's own branch point) is no longer on the axis:
    // the point is nearer; the axis passes between them.
    let lines = axis.sampled(
        &Shape2d::from_sites(
            vec![rect(0.0, 0.0, 10.0, 10.0)],
            vec![],
            vec![Point::new(4.0, 5.5)],
            &ShapeOptions::default(),
        )
        .unwrap(),
        1e-6,
    );
    assert!(oracle::axis_distance(&lines, Point::new(4.0, 5.5)) > 1.0);
}

#[test]
fn a_few_point_sites() {
    let sq = || vec![rect(0.0, 0.0, 10.0, 10.0)];
    with_points(sq(), vec![], &[(3.0, 4.0), (7.0, 6.5)]);
    with_points(sq(), vec![], &[(0.5, 0.5), (9.3, 9.1), (5.0, 5.0)]);
    // Symmetric: two points on a horizontal line (their augmenting disks
    // see each other's point straight below? no: side by side).
    with_points(sq(), vec![], &[(3.0, 5.0), (7.0, 5.0)]);
    // Stacked: one point straight above another.
    with_points(sq(), vec![], &[(5.0, 3.0), (5.0, 7.0)]);
    // With a segment site and a hole.
    with_points(
        vec![rect(0.0, 0.0, 10.0, 10.0), rect(6.0, 6.0, 8.0, 8.0)],
        vec![poly(&[(1.0, 2.0), (4.0, 3.0)])],
        &[(2.0, 7.0), (8.0, 2.0)],
    );
}

/// Random point clouds (jittered grids: reflex clusters for the divide
/// step), with and without segment sites, every leaf size.
#[test]
fn random_point_sites_under_the_oracle() {
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::SmallRng::seed_from_u64(21);
    for round in 0..24 {
        let cells = 2 + round % 7;
        let side = 10.0 / cells as f64;
        let (mut curves, mut points) = (Vec::new(), Vec::new());
        for cx in 0..cells {
            for cy in 0..cells {
                let (x0, y0) = (cx as f64 * side, cy as f64 * side);
                let mut p = || (x0 + side * rng.gen_range(0.1..0.9), y0 + side * rng.gen_range(0.1..0.9));
                match (round % 3, (cx + cy) % 2) {
                    (1, 0) => curves.push(poly(&[p(), p()])),
                    _ => points.push(Point::new(p().0, p().1)),
                }
            }
        }
        let s =
            Shape2d::from_sites(vec![rect(0.0, 0.0, 10.0, 10.0)], curves, points, &ShapeOptions::default()).unwrap();
        for (seed, leaf_parts) in [(1u64, 3usize), (2, 8), (3, 32)] {
            let axis = medial_axis(&s, &AxisOptions { seed, leaf_parts })
                .unwrap_or_else(|e| panic!("round {round} seed {seed} leaf {leaf_parts}: {e}"));
            oracle::check(&s, &axis, 200, seed);
        }
    }
}

/// A regular grid of points: every Voronoi vertex is a disk through four
/// cocircular points (multi-branching), and every augmenting disk lands on
/// the point straight below.
#[test]
fn a_regular_grid_of_points() {
    for n in [2usize, 3, 6] {
        let pts: Vec<(f64, f64)> = (0..n * n)
            .map(|k| {
                ((k % n) as f64 * 10.0 / n as f64 + 5.0 / n as f64, (k / n) as f64 * 10.0 / n as f64 + 5.0 / n as f64)
            })
            .collect();
        let axis = with_points(vec![rect(0.0, 0.0, 10.0, 10.0)], vec![], &pts);
        assert_eq!(axis.edges.len() + 1, axis.nodes.len() + n * n);
    }
}
