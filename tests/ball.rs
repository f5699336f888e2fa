//! Unit balls of the plane (thesis 3.1): validation names the vertex at
//! fault, the presets are the distances they claim, the gauge is a convex
//! gauge, distances to segments match dense sampling, and the contact
//! features are decided exactly.

use medax::kernel::Point;
use medax::shape::{Ball2, BallError, Feature};
use rand::{Rng, SeedableRng};

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

fn pts(xy: &[(f64, f64)]) -> Vec<Point> {
    xy.iter().map(|&(x, y)| p(x, y)).collect()
}

#[test]
fn bad_balls_name_the_vertex() {
    let err = |xy: &[(f64, f64)]| Ball2::new(&pts(xy)).unwrap_err();
    assert_eq!(err(&[(1.0, 0.0), (0.0, 1.0)]), BallError::TooFewVertices { count: 2 });
    assert_eq!(err(&[(1.0, 0.0), (0.0, 1.0), (f64::NAN, 0.0)]), BallError::NonFinite { vertex: 2 });
    assert_eq!(err(&[(1.0, 0.0), (0.0, 1.0), (0.0, 1.0), (-1.0, -1.0)]), BallError::Repeated { vertex: 2 });
    // A square with a vertex in the middle of its top edge.
    let square_plus = [(1.0, -1.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)];
    assert_eq!(err(&square_plus), BallError::Collinear { vertex: 2 });
    // A dart: vertex 2 turns the other way.
    let dart = [(2.0, 0.0), (0.0, 2.0), (0.5, 0.0), (0.0, -2.0)];
    assert_eq!(err(&dart), BallError::NotConvex { vertex: 2 });
    // A pentagram turns left at every vertex but winds round twice.
    let star: Vec<(f64, f64)> = (0..5)
        .map(|i| {
            ((i as f64 * 4.0 * std::f64::consts::PI / 5.0).cos(), (i as f64 * 4.0 * std::f64::consts::PI / 5.0).sin())
        })
        .collect();
    assert!(matches!(err(&star), BallError::NotConvex { .. }), "{:?}", err(&star));
    // The origin on the edge from vertex 0, then beyond the edge from vertex 1.
    assert_eq!(err(&[(-1.0, 0.0), (1.0, 0.0), (0.0, 1.0)]), BallError::OriginNotInside { vertex: 0, on_edge: true });
    assert_eq!(err(&[(1.0, 1.0), (2.0, 1.0), (1.0, 2.0)]), BallError::OriginNotInside { vertex: 0, on_edge: false });
    // Clockwise input is the same ball; errors still name vertices as given.
    assert_eq!(err(&[(0.0, 1.0), (1.0, 0.0), (-1.0, 0.0)]), BallError::OriginNotInside { vertex: 1, on_edge: true });
    let cw = Ball2::new(&pts(&[(1.0, 1.0), (1.0, -1.0), (-1.0, -1.0), (-1.0, 1.0)])).unwrap();
    assert_eq!(cw.gauge(p(0.3, -0.7)), Ball2::square().gauge(p(0.3, -0.7)));
    assert!(Ball2::regular(2, 0.0).is_err() && Ball2::regular(5, f64::INFINITY).is_err());
    // Too thin for f64 distances: the origin 1e-13 of the size from the
    // edge from vertex 0; a subnormal coordinate.
    assert_eq!(err(&[(-1.0, -1e-13), (1.0, -1e-13), (0.0, 1.0)]), BallError::IllConditioned { vertex: 0 });
    assert_eq!(err(&[(1.0, 0.0), (0.0, 1.0), (-1.0, -1e-310)]), BallError::IllConditioned { vertex: 2 });
    for e in [err(&star), err(&dart), BallError::InvalidArgument { what: "x".into() }] {
        assert!(!e.to_string().is_empty());
    }
}

#[test]
fn presets_are_the_distances_they_claim() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(3);
    let (square, diamond) = (Ball2::square(), Ball2::diamond());
    for _ in 0..1000 {
        let x = p(rng.gen_range(-5.0..5.0), rng.gen_range(-5.0..5.0));
        let linf = x.x.abs().max(x.y.abs());
        assert!((square.gauge(x) - linf).abs() <= 1e-15 * linf, "{x:?}");
        let l1 = x.x.abs() + x.y.abs();
        assert!((diamond.gauge(x) - l1).abs() <= 1e-15 * l1, "{x:?}");
        // A regular k-gon lies between the circle of radius cos(π/k) and
        // the unit circle.
        for k in [3, 8, 64, 1000] {
            let g = Ball2::regular(k, 0.3).unwrap().gauge(x);
            let slack = 1.0 / (std::f64::consts::PI / k as f64).cos();
            let e = x.norm();
            assert!(g >= e * (1.0 - 1e-12) && g <= e * slack * (1.0 + 1e-12), "k {k}: {g} vs {e}");
        }
    }
    let hexagon =
        Ball2::new(&pts(&[(2.0, 0.0), (1.0, 1.5), (-1.0, 1.5), (-2.0, 0.0), (-1.0, -1.5), (1.0, -1.5)])).unwrap();
    assert!(square.is_symmetric() && diamond.is_symmetric() && hexagon.is_symmetric());
    assert!(!Ball2::triangle().is_symmetric() && !Ball2::regular(5, 0.0).unwrap().is_symmetric());
    assert_eq!(Ball2::triangle().len(), 3);
}

#[test]
fn the_gauge_is_a_convex_gauge_and_the_mirror_swaps_direction() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(5);
    for round in 0..200 {
        // A random convex ball: sorted angles, random radii, convex hull
        // by keeping only left turns would be work; use a regular polygon
        // stretched by a random linear map instead (still convex).
        let k = rng.gen_range(3..12);
        let (a, b, c, d) =
            (rng.gen_range(0.5..2.0), rng.gen_range(-0.5..0.5), rng.gen_range(-0.5..0.5), rng.gen_range(0.5..2.0));
        let shift = p(rng.gen_range(-0.2..0.2), rng.gen_range(-0.2..0.2));
        let verts: Vec<Point> = Ball2::regular(k, rng.gen_range(0.0..1.0))
            .unwrap()
            .vertices()
            .iter()
            .map(|v| p(a * v.x + b * v.y, c * v.x + d * v.y) + shift)
            .collect();
        let ball = Ball2::new(&verts).unwrap_or_else(|e| panic!("round {round}: {e}"));
        for v in ball.vertices() {
            assert!((ball.gauge(*v) - 1.0).abs() < 1e-12);
        }
        let mirror = ball.mirrored();
        for _ in 0..50 {
            let x = p(rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0));
            let y = p(rng.gen_range(-3.0..3.0), rng.gen_range(-3.0..3.0));
            let s = rng.gen_range(0.0..10.0);
            assert!((ball.gauge(x * s) - s * ball.gauge(x)).abs() <= 1e-12 * (1.0 + s * ball.gauge(x)));
            assert!(ball.gauge(x + y) <= ball.gauge(x) + ball.gauge(y) + 1e-12);
            assert!((ball.distance(x, y) - mirror.distance(y, x)).abs() <= 1e-12 * (1.0 + ball.distance(x, y)));
            // Inside the placed ball exactly when the distance is at most r.
            let r = ball.distance(x, y);
            let placed = ball.placed(x, r * 1.000001);
            let inside =
                (0..placed.len()).all(|i| (placed[(i + 1) % placed.len()] - placed[i]).cross(y - placed[i]) >= 0.0);
            assert!(inside, "{x:?} {y:?}");
        }
    }
}

#[test]
fn distance_to_a_segment_matches_dense_sampling() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(8);
    for ball in [Ball2::square(), Ball2::triangle(), Ball2::regular(7, 0.2).unwrap(), Ball2::regular(64, 0.0).unwrap()]
    {
        for _ in 0..300 {
            let mut q = || p(rng.gen_range(-4.0..4.0), rng.gen_range(-4.0..4.0));
            let (c, a, b) = (q(), q(), q());
            let got = ball.distance_to_segment(c, a, b);
            const N: usize = 20_000;
            let sampled =
                (0..=N).map(|i| ball.distance(c, a + (b - a) * (i as f64 / N as f64))).fold(f64::INFINITY, f64::min);
            // The minimum is attained, so sampling can only be above it, by
            // at most the gauge's growth over half a step.
            let step = ball.gauge(b - a).max(ball.gauge(a - b)) / N as f64;
            assert!(got <= sampled + 1e-12 && sampled - got <= step + 1e-12, "{c:?} {a:?} {b:?}: {got} vs {sampled}");
        }
    }
}

#[test]
fn contact_features_are_exact() {
    let square = Ball2::square(); // (1,-1), (1,1), (-1,1), (-1,-1)
    let tiny = f64::from_bits(1); // the smallest subnormal
    assert_eq!(square.support(p(1.0, 0.0)), Feature::Edge(0));
    assert_eq!(square.support(p(1.0, tiny)), Feature::Vertex(1));
    assert_eq!(square.support(p(1.0, -tiny)), Feature::Vertex(0));
    assert_eq!(square.support(p(-1.0, -1.0)), Feature::Vertex(3));
    // A shape's bottom edge (interior above): the square's bottom edge
    // lies on it; tilted by the least amount, a corner does.
    assert_eq!(square.touching_edge(p(0.0, 0.0), p(1.0, 0.0)), Feature::Edge(3));
    assert_eq!(square.touching_edge(p(0.0, 0.0), p(1.0, tiny)), Feature::Vertex(0));
    assert_eq!(square.touching_edge(p(0.0, 0.0), p(1.0, -tiny)), Feature::Vertex(3));
    // A shape vertex seen from the centre: through a corner (VV) or an edge (EV).
    // Coordinates exact in binary: 2.1 - 0.1 is not exactly 2, and the
    // predicates see the numbers as they are.
    let c = p(0.25, 0.5);
    assert_eq!(square.towards(c, p(2.25, 2.5)), Feature::Vertex(1));
    assert_eq!(square.towards(c, p(2.25, 2.5 + 2f64.powi(-51))), Feature::Edge(1));
    assert_eq!(square.towards(c, p(2.25, 1.5)), Feature::Edge(0));
    assert_eq!(square.towards(c, p(-2.0, 0.5)), Feature::Edge(2));
    assert_eq!(square.towards(c, p(0.25 - 0.125, 0.5 - 0.125)), Feature::Vertex(3));
    // The ray towards a vertex at subnormal scale, where (p − c)·v rounds
    // to 0 in floating point.
    let odd = Ball2::new(&pts(&[(-1.0, 0.0), (0.5, 0.5), (0.0, -1.0)])).unwrap();
    assert_eq!(odd.vertices()[1], p(0.5, 0.5));
    let tiny_p = p(f64::from_bits(1), f64::from_bits(1));
    assert_eq!(odd.towards(p(0.0, 0.0), tiny_p), Feature::Vertex(1));
    // The triangle's vertex points up: a horizontal ceiling edge (interior
    // below, so drawn right to left) touches it there.
    assert_eq!(Ball2::triangle().touching_edge(p(1.0, 5.0), p(0.0, 5.0)), Feature::Vertex(0));
    assert_eq!(Ball2::triangle().mirrored().touching_edge(p(1.0, 5.0), p(0.0, 5.0)), Feature::Edge(1));
}

#[test]
fn balls_by_name_and_from_json() {
    assert_eq!(Ball2::parse(" Square ").unwrap(), Ball2::square());
    assert_eq!(Ball2::parse("diamond").unwrap(), Ball2::diamond());
    assert_eq!(Ball2::parse("tri").unwrap(), Ball2::triangle());
    assert_eq!(Ball2::parse("ngon:12").unwrap(), Ball2::regular(12, 0.0).unwrap());
    assert_eq!(Ball2::parse("ngon:8:22.5").unwrap(), Ball2::regular(8, 22.5f64.to_radians()).unwrap());
    // Clockwise as given: stored reversed (the same ball, another start).
    let json = Ball2::parse(r#"{"vertices": [[1, 1], [1, -1], [-1, -1], [-1, 1]]}"#).unwrap();
    assert_eq!(json.vertices()[0], p(-1.0, 1.0));
    for x in [p(0.3, -2.0), p(-1.5, 0.25), p(7.0, 7.5)] {
        assert_eq!(json.gauge(x), Ball2::square().gauge(x));
    }
    for bad in ["circle", "ngon:", "ngon:x", "ngon:5:1:2", "ngon:2"] {
        let e = Ball2::parse(bad).unwrap_err();
        assert!(matches!(e, BallError::InvalidArgument { .. }), "{bad}: {e:?}");
    }
    assert!(Ball2::parse("ngon:5").is_ok());
    assert!(matches!(Ball2::parse(r#"{"vertices": [[1, 1]"#), Err(BallError::Parse(_))));
    assert!(matches!(Ball2::parse(r#"{"corners": []}"#), Err(BallError::Parse(_))));
    assert_eq!(
        Ball2::parse(r#"{"vertices": [[2, 0], [0, 2], [0.5, 0], [0, -2]]}"#),
        Err(BallError::NotConvex { vertex: 2 })
    );
}
