//! The axis and Voronoi diagrams under polygon balls at scale (slow tier:
//! `cargo test --release --test ball_scale -- --ignored`; scripts/test-all
//! runs it): generated families of 10^4 and 10^5 edges the unit tests never
//! see — spiky stars, polygons sampled from smooth curves (long runs of
//! nearly collinear edges), plates of random polygonal holes — under the
//! square, a 12-gon, the triangle and an asymmetric pentagon, against the
//! brute-force oracle of `common::ball_oracle` on a random sample of edges
//! and probes (the oracle is linear in the shape per point).

mod common;

use common::ball_oracle::{check_complete, check_sound};
use medax::kernel::Point;
use medax::polymetric::{medial_axis_with_ball, voronoi_with_ball, BallVoronoiOptions};
use medax::shape::{samples, Ball2, Shape2d, ShapeOptions, SiteId, Sites, Vertex};
use rand::{Rng, SeedableRng};
use std::f64::consts::TAU;

fn balls() -> Vec<(&'static str, Ball2)> {
    vec![
        ("square", Ball2::square()),
        ("12-gon", Ball2::regular(12, 0.3).unwrap()),
        ("triangle", Ball2::triangle()),
        (
            "pentagon",
            Ball2::new(&[
                Point::new(1.0, -0.2),
                Point::new(0.7, 0.9),
                Point::new(-0.5, 1.1),
                Point::new(-1.3, 0.1),
                Point::new(-0.2, -0.8),
            ])
            .unwrap(),
        ),
    ]
}

fn polygon(pts: impl IntoIterator<Item = Point>) -> Vec<Vertex> {
    pts.into_iter().map(|p| Vertex { p, bulge: 0.0 }).collect()
}

/// A closed curve r(θ) = 1 + Σ a_j cos(jθ + φ_j) (j = 2..7) sampled at `n`
/// angles: a polygon of short, nearly collinear edges.
fn smooth_polygon(n: usize, seed: u64) -> Vec<Vec<Vertex>> {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let terms: Vec<(f64, f64)> =
        (2..8).map(|j| (rng.gen_range(0.0..0.25) / j as f64, rng.gen_range(0.0..TAU))).collect();
    let r = |t: f64| 1.0 + terms.iter().enumerate().map(|(j, &(a, f))| a * ((j + 2) as f64 * t + f).cos()).sum::<f64>();
    vec![polygon((0..n).map(|i| {
        let t = TAU * i as f64 / n as f64;
        Point::new(r(t) * t.cos(), r(t) * t.sin())
    }))]
}

/// A k × k plate with a random convex polygon (3 to 9 vertices, turned at
/// random) in each cell, clockwise.
fn plate(k: usize, seed: u64) -> Vec<Vec<Vertex>> {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let s = k as f64;
    let mut loops = vec![polygon([Point::new(0.0, 0.0), Point::new(s, 0.0), Point::new(s, s), Point::new(0.0, s)])];
    for i in 0..k {
        for j in 0..k {
            let m = rng.gen_range(3..10);
            let r = rng.gen_range(0.15..0.4);
            let turn = rng.gen_range(0.0..TAU);
            let c = Point::new(i as f64 + 0.5, j as f64 + 0.5);
            loops.push(polygon((0..m).map(|q| {
                let a = turn - TAU * (q as f64 + rng.gen_range(0.1..0.9)) / m as f64;
                c + Point::new(a.cos(), a.sin()) * r
            })));
        }
    }
    loops
}

fn run(name: &str, loops: Vec<Vec<Vertex>>, samples_per_ball: usize) {
    let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid shape");
    for (ball_name, ball) in balls() {
        let axis = medial_axis_with_ball(&shape, &ball).unwrap_or_else(|e| panic!("{name} under the {ball_name}: {e}"));
        assert!(axis.edges.len() >= shape.element_count() / 2, "{name} under the {ball_name}: too few edges");
        check_sound(&shape, &ball, &axis, samples_per_ball, 3);
        check_complete(&shape, &ball, &axis, samples_per_ball / 10, 5);
    }
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn stars_at_1e4_and_1e5() {
    run("star of 10^4", samples::star_polygon(10_000, 31), 300);
    run("star of 10^5", samples::star_polygon(100_000, 32), 100);
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn polygons_of_smooth_curves_at_1e4_and_1e5() {
    run("smooth polygon of 10^4", smooth_polygon(10_000, 41), 300);
    run("smooth polygon of 10^5", smooth_polygon(100_000, 42), 100);
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn plates_of_polygonal_holes() {
    // 20 × 20 and 60 × 60 holes: about 2,400 and 22,000 edges.
    run("plate of 400 holes", plate(20, 51), 300);
    run("plate of 3,600 holes", plate(60, 52), 100);
}

#[test]
#[ignore = "slow tier: scripts/test-all runs it in release"]
fn voronoi_of_many_points() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(61);
    let points: Vec<Point> =
        (0..20_000).map(|_| Point::new(rng.gen_range(0.0..10.0), rng.gen_range(0.0..10.0))).collect();
    let sites = Sites { points: points.clone(), ..Sites::default() };
    for (ball_name, ball) in balls() {
        let vd = voronoi_with_ball(&sites, &ball, &BallVoronoiOptions::default())
            .unwrap_or_else(|e| panic!("20,000 points under the {ball_name}: {e}"));
        // Along sampled edges between points both are at the radius and
        // none is nearer (brute force over all points).
        let edges: Vec<usize> = vd.site_edges().collect();
        assert!(edges.len() >= 2 * points.len(), "{ball_name}: {} edges", edges.len());
        for _ in 0..200 {
            let i = edges[rng.gen_range(0..edges.len())];
            let e = &vd.axis.edges[i];
            let (a, b) = (&vd.axis.nodes[e.from], &vd.axis.nodes[e.to]);
            let t = rng.gen_range(0.0..1.0);
            let (c, r) = (a.at + (b.at - a.at) * t, a.r + (b.r - a.r) * t);
            let tol = 1e-9 * 15.0;
            for s in vd.edges[i].sides {
                let SiteId::Point(k) = s else { panic!("{ball_name}: edge {i} between points has side {s}") };
                let d = ball.distance(c, points[k]);
                assert!((d - r).abs() < tol, "{ball_name}: edge {i}: point {k} at {d}, radius {r}");
            }
            let nearest = points.iter().map(|&p| ball.distance(c, p)).fold(f64::INFINITY, f64::min);
            assert!(nearest > r - tol, "{ball_name}: edge {i}: a point nearer ({nearest}) than the radius {r}");
        }
        // Nearest sites against the brute force.
        for _ in 0..200 {
            let p = Point::new(rng.gen_range(-1.0..11.0), rng.gen_range(-1.0..11.0));
            let (_, d, _) = vd.nearest_site(p).expect("a nearest site");
            let best = points.iter().map(|&q| ball.distance(p, q)).fold(f64::INFINITY, f64::min);
            assert!((d - best).abs() < 1e-12 * 15.0, "{ball_name}: nearest to {p:?}: {d} against {best}");
        }
    }
}
