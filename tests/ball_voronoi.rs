//! Voronoi diagrams of point, segment and polygon sites under polygon balls,
//! against an oracle that shares nothing with the algorithm: brute-force
//! gauge distances to every site (`Ball2::distance`,
//! `Ball2::distance_to_segment`) and bisection between points with
//! different nearest sites.

use medax::kernel::Point;
use medax::polymetric::{voronoi_with_ball, BallVoronoi, BallVoronoiError, BallVoronoiOptions};
use medax::shape::{Ball2, SiteId, Sites, Vertex};
use rand::{Rng, SeedableRng};

fn v(p: Point) -> Vertex {
    Vertex { p, bulge: 0.0 }
}

/// Gauge distance from `c` to a site, by brute force (regions: their
/// boundary; every probe lies outside them).
fn site_distance(ball: &Ball2, sites: &Sites, s: SiteId, c: Point) -> f64 {
    let chain = |vs: &[Vertex], closed: bool| {
        let n = vs.len();
        let m = if closed { n } else { n - 1 };
        (0..m).map(|i| ball.distance_to_segment(c, vs[i].p, vs[(i + 1) % n].p)).fold(f64::INFINITY, f64::min)
    };
    match s {
        SiteId::Point(i) => ball.distance(c, sites.points[i]),
        SiteId::Curve(i) => chain(&sites.curves[i], false),
        SiteId::Region(i) => chain(&sites.regions[i], true),
        SiteId::Frame => f64::INFINITY,
    }
}

fn all_sites(sites: &Sites) -> Vec<SiteId> {
    let mut out: Vec<SiteId> = (0..sites.points.len()).map(SiteId::Point).collect();
    out.extend((0..sites.curves.len()).map(SiteId::Curve));
    out.extend((0..sites.regions.len()).map(SiteId::Region));
    out
}

/// The nearest site and its distance, and the distance of the second.
fn nearest(ball: &Ball2, sites: &Sites, c: Point) -> (SiteId, f64, f64) {
    let mut best = (SiteId::Frame, f64::INFINITY, f64::INFINITY);
    for s in all_sites(sites) {
        let d = site_distance(ball, sites, s, c);
        if d < best.1 {
            best = (s, d, best.1);
        } else if d < best.2 {
            best.2 = d;
        }
    }
    best
}

fn inside_region(sites: &Sites, c: Point) -> bool {
    sites.regions.iter().any(|r| {
        let mut w = false;
        for i in 0..r.len() {
            let (a, b) = (r[i].p, r[(i + 1) % r.len()].p);
            if (a.y > c.y) != (b.y > c.y) && c.x < a.x + (c.y - a.y) / (b.y - a.y) * (b.x - a.x) {
                w = !w;
            }
        }
        w
    })
}

fn seg_dist(p: Point, a: Point, b: Point) -> f64 {
    let d = b - a;
    let t = ((p - a).dot(d) / d.dot(d)).clamp(0.0, 1.0);
    (p - (a + d * t)).norm()
}

/// Soundness: along every edge between two sites, both are at the edge's
/// radius and none is nearer. Completeness: between two random points
/// with different nearest sites, the point where the nearest site changes
/// lies on an edge between sites.
fn check(sites: &Sites, ball: &Ball2, vd: &BallVoronoi, probes: usize, seed: u64) {
    let diag = sites.bbox().diagonal();
    let tol = 1e-9 * diag;
    let mut checked = 0;
    for i in vd.site_edges() {
        let e = &vd.axis.edges[i];
        let (a, b) = (&vd.axis.nodes[e.from], &vd.axis.nodes[e.to]);
        for t in [0.0, 0.3, 0.5, 0.8, 1.0] {
            let c = a.at + (b.at - a.at) * t;
            let r = a.r + (b.r - a.r) * t;
            for s in vd.edges[i].sides {
                let d = site_distance(ball, sites, s, c);
                assert!((d - r).abs() < tol, "edge {i} at {c:?}: {s} at {d}, radius {r}");
            }
            let (s, d, _) = nearest(ball, sites, c);
            assert!(d > r - tol, "edge {i} at {c:?} (radius {r}): {s} nearer, at {d}");
            checked += 1;
        }
    }
    assert!(checked > 0, "no edge between sites");
    let site_segments: Vec<(Point, Point)> = vd
        .site_edges()
        .map(|i| (vd.axis.nodes[vd.axis.edges[i].from].at, vd.axis.nodes[vd.axis.edges[i].to].at))
        .collect();
    let bb = sites.bbox();
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let mut pt = || {
        Point::new(
            rng.gen_range(bb.min.x - 0.3 * diag..bb.max.x + 0.3 * diag),
            rng.gen_range(bb.min.y - 0.3 * diag..bb.max.y + 0.3 * diag),
        )
    };
    // Nearest-site queries against the brute force.
    for _ in 0..probes {
        let p = pt();
        if inside_region(sites, p) {
            continue;
        }
        let (s, d, second) = nearest(ball, sites, p);
        let (got, gd, foot) = vd.nearest_site(p).expect("a nearest site");
        assert!((gd - d).abs() < tol, "nearest site of {p:?}: {got} at {gd}, brute force {s} at {d}");
        assert!(got == s || second - d < tol, "nearest site of {p:?}: {got}, brute force {s} ({d} vs {second})");
        assert!((ball.distance(p, foot) - gd).abs() < tol, "foot {foot:?} of {p:?} is not at the distance {gd}");
        assert!(site_distance(ball, sites, got, foot) < tol, "foot {foot:?} is not on {got}");
    }
    // Regions: each edge between sites once on each side's walk, in the
    // direction that keeps the site on the left; one closed walk each.
    for i in vd.site_edges() {
        let [l, r] = vd.edges[i].sides;
        for (site, fwd) in [(l, true), (r, false)] {
            if site == SiteId::Frame && vd.auto_frame {
                continue;
            }
            let region = vd.region(site).unwrap_or_else(|| panic!("no region for {site}"));
            let n = region.boundary.iter().filter(|&&b| b == (i, fwd)).count();
            assert_eq!(n, 1, "edge {i} appears {n} times on the walk of {site}");
        }
    }
    for region in &vd.regions {
        assert!(region.walks <= 1, "region of {} is {} walks", region.site, region.walks);
        for w in region.boundary.windows(2) {
            let end = |(i, fwd): (usize, bool)| if fwd { vd.axis.edges[i].to } else { vd.axis.edges[i].from };
            let start = |(i, fwd): (usize, bool)| if fwd { vd.axis.edges[i].from } else { vd.axis.edges[i].to };
            assert_eq!(end(w[0]), start(w[1]), "the walk of {} breaks", region.site);
        }
    }
    let mut crossings = 0;
    for _ in 0..probes {
        let (p, q) = (pt(), pt());
        if inside_region(sites, p) || inside_region(sites, q) {
            continue;
        }
        let (sp, sq) = (nearest(ball, sites, p).0, nearest(ball, sites, q).0);
        if sp == sq {
            continue;
        }
        let (mut lo, mut hi) = (p, q);
        for _ in 0..80 {
            let m = (lo + hi) * 0.5;
            if nearest(ball, sites, m).0 == sp {
                lo = m;
            } else {
                hi = m;
            }
        }
        // A change through a region (the segment crossing a site) is no
        // Voronoi edge.
        if inside_region(sites, lo) || (nearest(ball, sites, lo).1 < tol) {
            continue;
        }
        // Outside general position two sites can tie on a whole region;
        // where the diagram splits it (at either end of that region) is the
        // perturbation's choice.
        let u = (q - p) * (1e-6 * diag / (q - p).norm());
        let tie = |c: Point| {
            let (_, d1, d2) = nearest(ball, sites, c);
            d2 - d1 < 1e-12 * diag
        };
        if tie(lo - u) || tie(lo + u) {
            continue;
        }
        let gap = site_segments.iter().map(|&(a, b)| seg_dist(lo, a, b)).fold(f64::INFINITY, f64::min);
        assert!(gap < 1e-7 * diag, "the nearest site changes from {sp} at {lo:?}, {gap} from every edge");
        crossings += 1;
    }
    assert!(crossings > probes / 10, "only {crossings} crossings probed");
}

fn balls(rng: &mut rand::rngs::SmallRng) -> Vec<Ball2> {
    let k = rng.gen_range(3..9);
    let mut angles: Vec<f64> =
        (0..k).map(|i| (i as f64 + rng.gen_range(0.1..0.9)) * std::f64::consts::TAU / k as f64).collect();
    angles.sort_by(f64::total_cmp);
    let pts: Vec<Point> = angles.iter().map(|a| Point::new(a.cos(), a.sin()) * rng.gen_range(0.6..1.4)).collect();
    vec![
        Ball2::square(),
        Ball2::triangle(),
        Ball2::regular(7, 0.2).unwrap(),
        Ball2::new(&pts).unwrap_or(Ball2::diamond()),
    ]
}

#[test]
fn random_points_under_several_balls() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(1);
    for seed in 0..4u64 {
        let n = [3, 10, 40, 150][seed as usize];
        let points: Vec<Point> = (0..n).map(|_| Point::new(rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0))).collect();
        let sites = Sites { points, ..Sites::default() };
        for ball in balls(&mut rng) {
            let vd = voronoi_with_ball(&sites, &ball, &BallVoronoiOptions::default()).expect("diagram");
            check(&sites, &ball, &vd, 200, seed);
        }
    }
}

#[test]
fn segments_points_and_polygons_together() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(2);
    for seed in 0..4u64 {
        // Sites in cells of a grid, so they never touch.
        let mut sites = Sites::default();
        for i in 0..6 {
            for j in 0..6 {
                let o = Point::new(i as f64, j as f64);
                let at = |x: f64, y: f64| o + Point::new(x, y);
                match rng.gen_range(0..4) {
                    0 => sites.points.push(at(rng.gen_range(0.1..0.9), rng.gen_range(0.1..0.9))),
                    1 => sites.curves.push(vec![
                        v(at(rng.gen_range(0.1..0.45), rng.gen_range(0.1..0.9))),
                        v(at(rng.gen_range(0.55..0.9), rng.gen_range(0.1..0.9))),
                    ]),
                    2 => sites.curves.push(vec![
                        v(at(0.1, rng.gen_range(0.1..0.9))),
                        v(at(0.5, rng.gen_range(0.1..0.9))),
                        v(at(0.9, rng.gen_range(0.1..0.9))),
                    ]),
                    _ => sites.regions.push(vec![
                        v(at(rng.gen_range(0.1..0.4), rng.gen_range(0.1..0.4))),
                        v(at(rng.gen_range(0.6..0.9), rng.gen_range(0.1..0.4))),
                        v(at(rng.gen_range(0.6..0.9), rng.gen_range(0.6..0.9))),
                        v(at(rng.gen_range(0.1..0.4), rng.gen_range(0.6..0.9))),
                    ]),
                }
            }
        }
        for ball in balls(&mut rng) {
            let vd = voronoi_with_ball(&sites, &ball, &BallVoronoiOptions::default())
                .unwrap_or_else(|e| panic!("seed {seed} ball {:?}: {e}\n{sites:?}", ball.vertices()));
            check(&sites, &ball, &vd, 300, seed);
        }
    }
}

/// The library's frame keeps every vertex: a caller's frame four times as
/// far out gives the same vertices between sites.
#[test]
fn the_frame_keeps_every_vertex() {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(3);
    for seed in 0..3u64 {
        let points: Vec<Point> =
            (0..30).map(|_| Point::new(rng.gen_range(0.0..1.0), rng.gen_range(0.0..0.3))).collect();
        let sites = Sites { points, ..Sites::default() };
        for ball in balls(&mut rng) {
            let vd = voronoi_with_ball(&sites, &ball, &BallVoronoiOptions::default()).unwrap();
            let far = 4.0 * vd.axis.nodes.iter().map(|n| n.at.x.abs().max(n.at.y.abs())).fold(0.0, f64::max);
            let boundary =
                [(-far, -far), (far, -far), (far, far), (-far, far)].map(|(x, y)| v(Point::new(x, y))).to_vec();
            let big = voronoi_with_ball(
                &sites,
                &ball,
                &BallVoronoiOptions { boundary: Some(boundary), ..Default::default() },
            )
            .unwrap();
            // Vertices: nodes where three edges between sites meet.
            let vertices = |d: &BallVoronoi| {
                let mut deg = vec![0; d.axis.nodes.len()];
                for i in d
                    .edges
                    .iter()
                    .enumerate()
                    .filter(|(_, e)| !e.self_edge && !e.sides.contains(&SiteId::Frame))
                    .map(|(i, _)| i)
                {
                    deg[d.axis.edges[i].from] += 1;
                    deg[d.axis.edges[i].to] += 1;
                }
                let mut at: Vec<(f64, f64)> = (0..deg.len())
                    .filter(|&n| deg[n] >= 3)
                    .map(|n| (d.axis.nodes[n].at.x, d.axis.nodes[n].at.y))
                    .collect();
                at.sort_by(|a, b| a.partial_cmp(b).unwrap());
                at
            };
            let (a, b) = (vertices(&vd), vertices(&big));
            assert_eq!(a.len(), b.len(), "seed {seed} ball {:?}", ball.vertices());
            for (p, q) in a.iter().zip(&b) {
                assert!((p.0 - q.0).abs() < 1e-9 && (p.1 - q.1).abs() < 1e-9, "{p:?} against {q:?}");
            }
            check(&sites, &ball, &vd, 100, seed);
        }
    }
}

#[test]
fn rectilinear_sites_under_the_square() {
    // Outside general position: equal coordinates everywhere.
    let mut sites = Sites::default();
    for i in 0..5 {
        for j in 0..5 {
            let (x, y) = (2.0 * i as f64, 2.0 * j as f64);
            if (i + j) % 2 == 0 {
                sites.points.push(Point::new(x, y));
            } else {
                sites.curves.push(vec![v(Point::new(x - 0.5, y)), v(Point::new(x + 0.5, y))]);
            }
        }
    }
    let vd = voronoi_with_ball(&sites, &Ball2::square(), &BallVoronoiOptions::default()).expect("diagram");
    check(&sites, &Ball2::square(), &vd, 300, 4);
}

#[test]
fn bad_input_is_named() {
    let ball = Ball2::square();
    let o = BallVoronoiOptions::default();
    assert_eq!(voronoi_with_ball(&Sites::default(), &ball, &o).unwrap_err(), BallVoronoiError::NoSites);
    let arc = Sites {
        curves: vec![vec![Vertex { p: Point::new(0.0, 0.0), bulge: 0.5 }, v(Point::new(1.0, 0.0))]],
        ..Sites::default()
    };
    assert_eq!(
        voronoi_with_ball(&arc, &ball, &o).unwrap_err(),
        BallVoronoiError::Arc { site: SiteId::Curve(0), element: 0 }
    );
    let nan = Sites { points: vec![Point::new(0.0, 0.0), Point::new(f64::NAN, 1.0)], ..Sites::default() };
    assert!(matches!(
        voronoi_with_ball(&nan, &ball, &o).unwrap_err(),
        BallVoronoiError::Invalid { site: Some(SiteId::Point(1)), .. }
    ));
    let twice = Sites { points: vec![Point::new(0.0, 0.0), Point::new(0.0, 0.0)], ..Sites::default() };
    assert!(matches!(voronoi_with_ball(&twice, &ball, &o).unwrap_err(), BallVoronoiError::Invalid { .. }));
}
