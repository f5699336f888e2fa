//! Point and segment sites on a small integer grid (equal coordinates,
//! collinear sites, segments parallel to ball edges) under random polygon
//! balls: the Voronoi diagram or a typed error, never a panic; a diagram
//! returned is sound (at both ends of every edge between sites, both
//! sites lie at the edge's radius by brute-force gauge distance, and none
//! nearer), the nearest site of a few points is at the brute-force
//! distance, every region's walk is closed, and its JSON and SVG are
//! written.
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::kernel::Point;
use medax::polymetric::{voronoi_with_ball, BallVoronoiOptions};
use medax::shape::{Ball2, SiteId, Sites, Vertex};

fuzz_target!(|input: (Vec<(i8, i8)>, Vec<(i8, i8, i8, i8)>, Vec<(i8, i8)>)| {
    let (points, segments, ball) = input;
    if points.len() + segments.len() > 24 || ball.len() > 12 {
        return;
    }
    let grid = |x: i8, y: i8| Point::new(f64::from(x) / 4.0, f64::from(y) / 4.0);
    let Ok(ball) = Ball2::new(&ball.iter().map(|&(x, y)| grid(x, y)).collect::<Vec<_>>()) else { return };
    let sites = Sites {
        points: points.iter().map(|&(x, y)| grid(x, y)).collect(),
        curves: segments
            .iter()
            .map(|&(a, b, c, d)| vec![Vertex { p: grid(a, b), bulge: 0.0 }, Vertex { p: grid(c, d), bulge: 0.0 }])
            .collect(),
        ..Sites::default()
    };
    let Ok(vd) = voronoi_with_ball(&sites, &ball, &BallVoronoiOptions::default()) else { return };
    let dist = |s: SiteId, c: Point| match s {
        SiteId::Point(i) => ball.distance(c, sites.points[i]),
        SiteId::Curve(i) => ball.distance_to_segment(c, sites.curves[i][0].p, sites.curves[i][1].p),
        _ => f64::INFINITY,
    };
    let inradius = ball.inradius();
    let all: Vec<SiteId> =
        (0..sites.points.len()).map(SiteId::Point).chain((0..sites.curves.len()).map(SiteId::Curve)).collect();
    for i in vd.site_edges() {
        let e = &vd.axis.edges[i];
        for n in [&vd.axis.nodes[e.from], &vd.axis.nodes[e.to]] {
            // Rounding the node's position moves distances by its size
            // over the inradius.
            let tol = 1e-9 * (n.at.norm() + n.r + 1.0) / inradius.min(1.0);
            for s in vd.edges[i].sides {
                assert!((dist(s, n.at) - n.r).abs() <= tol, "{s} at {:?}: {} against {}", n.at, dist(s, n.at), n.r);
            }
            for &s in &all {
                assert!(dist(s, n.at) >= n.r - tol, "{s} nearer than the radius {} at {:?}", n.r, n.at);
            }
        }
    }
    for &(x, y) in points.iter().take(4) {
        let p = grid(y, x) + Point::new(0.1, -0.05);
        let (s, d, _) = vd.nearest_site(p).expect("a nearest site");
        let best = all.iter().map(|&t| dist(t, p)).fold(f64::INFINITY, f64::min);
        let tol = 1e-9 * (p.norm() + best + 1.0) / inradius.min(1.0);
        assert!((d - best).abs() <= tol && (dist(s, p) - best).abs() <= tol, "nearest to {p:?}: {s} at {d}, best {best}");
    }
    for r in &vd.regions {
        assert!(r.walks <= 1, "region of {} in {} walks", r.site, r.walks);
    }
    let mut out = Vec::new();
    vd.write_json(true, &mut out).expect("JSON to memory");
    let _ = vd.to_svg(300.0, true);
});
