//! Voronoi diagrams of region sites (thesis 2.3, Observation 6), checked
//! by oracles that share nothing with the algorithm: distances to the
//! sites by scanning every element, nearest sites of random points against
//! the regions' boundary walks (winding numbers of their samples), and the
//! axis oracle of tests/common on the frame with the sites as holes.

mod common;

use common::oracle::check;
use common::{circle, poly, rect};
use medax::kernel::Disk;
use medax::kernel::{FilteredKernel, Point};
use medax::plane::{voronoi, SiteId, Sites, VoronoiDiagram, VoronoiError, VoronoiOptions};
use medax::shape::{Element, Loop, ShapeError, Vertex};
use rand::{Rng, SeedableRng};

fn regions(loops: Vec<Vec<Vertex>>) -> Sites {
    Sites { regions: loops, ..Sites::default() }
}

fn vd_of(sites: &Sites) -> VoronoiDiagram {
    voronoi(sites, &VoronoiOptions::default()).expect("voronoi")
}

/// Every site's elements, by site (a point as a zero-length segment).
fn site_elements(sites: &Sites) -> Vec<(SiteId, Vec<Element>)> {
    let regions =
        sites.regions.iter().enumerate().map(|(i, r)| (SiteId::Region(i), Loop::new(r.clone()).elements().collect()));
    let curves = sites.curves.iter().enumerate().map(|(i, c)| {
        (SiteId::Curve(i), c.windows(2).map(|w| Element::from_bulge(w[0].p, w[1].p, w[0].bulge)).collect())
    });
    let points =
        sites.points.iter().enumerate().map(|(i, &p)| (SiteId::Point(i), vec![Element::from_bulge(p, p, 0.0)]));
    regions.chain(curves).chain(points).collect()
}

/// Distance from `p` to each site, by scanning.
fn site_distances(els: &[(SiteId, Vec<Element>)], p: Point) -> Vec<(SiteId, f64)> {
    els.iter().map(|(s, es)| (*s, es.iter().map(|e| e.closest_point(p).0).fold(f64::INFINITY, f64::min))).collect()
}

fn inside_some_site(sites: &Sites, p: Point) -> bool {
    let k = FilteredKernel;
    sites.regions.iter().any(|r| Loop::new(r.clone()).winding_number(&k, p) != 0)
}

/// Winding number of `p` around a closed polyline.
fn winding(poly: &[Point], p: Point) -> i32 {
    let mut w = 0;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        let side = (b - a).cross(p - a);
        if a.y <= p.y && b.y > p.y && side > 0.0 {
            w += 1;
        } else if a.y > p.y && b.y <= p.y && side < 0.0 {
            w -= 1;
        }
    }
    w
}

/// The closed polyline of a region's boundary walk.
fn region_polygon(vd: &VoronoiDiagram, site: SiteId, tol: f64) -> Vec<Point> {
    let r = vd.region(site).expect("region");
    let mut out = Vec::new();
    for &(i, fwd) in &r.boundary {
        let mut s: Vec<Point> =
            vd.axis.edges[i].sample(vd.shape(), &vd.axis.nodes, tol).into_iter().map(|d| d.center).collect();
        if !fwd {
            s.reverse();
        }
        out.extend(s);
    }
    out
}

/// Everything the oracles can say about one diagram: the axis oracle on
/// the framed shape; each kept edge's samples equidistant from the two
/// sites it separates and no nearer to any other; every region one closed
/// walk round its site; random points in the region of their nearest site
/// and the library's nearest-site query agreeing with the scan.
fn check_diagram(sites: &Sites, vd: &VoronoiDiagram, probes: usize, seed: u64) {
    check(vd.shape(), &vd.axis, 100, seed);
    let els = site_elements(sites);
    let site_box = vd.shape().loops()[1..].iter().fold(medax::kernel::BBox::EMPTY, |b, l| b.union(&l.bbox()));
    let diag = site_box.diagonal().max(1.0);
    let tol = 1e-8 * diag;
    for i in vd.diagram_edges(true) {
        let e = &vd.axis.edges[i];
        let v = vd.edges[i];
        for Disk { center: c, radius: r } in e.sample(vd.shape(), &vd.axis.nodes, 1e-4 * diag) {
            let d = site_distances(&els, c);
            let nearest = d.iter().map(|x| x.1).fold(f64::INFINITY, f64::min);
            let dist_of = |s: SiteId| d.iter().find(|x| x.0 == s).map(|x| x.1).unwrap();
            assert!((nearest - r).abs() <= tol, "edge {i}: sample {c:?} radius {r}, nearest site at {nearest}");
            for s in v.sides {
                assert!((dist_of(s) - r).abs() <= tol, "edge {i} {v:?}: {s} at {} not {r}", dist_of(s));
            }
        }
    }
    for r in &vd.regions {
        assert_eq!(r.walks, 1, "{}: {} walks", r.site, r.walks);
        let n = r.boundary.len();
        for k in 0..n {
            let end = |(i, fwd): (usize, bool), head: bool| {
                let e = &vd.axis.edges[i];
                if fwd == head {
                    e.to
                } else {
                    e.from
                }
            };
            assert_eq!(end(r.boundary[k], true), end(r.boundary[(k + 1) % n], false), "{}: walk breaks", r.site);
        }
    }
    check_face_order(vd, diag);
    let polys: Vec<(SiteId, Vec<Point>)> =
        vd.regions.iter().map(|r| (r.site, region_polygon(vd, r.site, 1e-6 * diag))).collect();
    let frame = &vd.shape().loops()[0];
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let (lo, hi) = (site_box.min - Point::new(diag, diag), site_box.max + Point::new(diag, diag));
    let mut tried = 0;
    while tried < probes {
        let p = Point::new(rng.gen_range(lo.x..hi.x), rng.gen_range(lo.y..hi.y));
        if inside_some_site(sites, p) {
            continue;
        }
        let d = site_distances(&els, p);
        let frame_d = frame.elements().map(|e| e.closest_point(p).0).fold(f64::INFINITY, f64::min);
        let mut sorted = d.clone();
        sorted.sort_by(|a, b| a.1.total_cmp(&b.1));
        // Clear of every tie and of the frame's own region.
        if sorted.len() > 1 && sorted[1].1 - sorted[0].1 < 1e-6 * diag || frame_d <= sorted[0].1 + 1e-6 * diag {
            continue;
        }
        tried += 1;
        let (want, want_d) = sorted[0];
        let (got, got_d, foot) = vd.nearest_site(p).expect("a nearest site");
        assert_eq!(got, want, "nearest site of {p:?}");
        assert!((got_d - want_d).abs() <= tol && (foot.dist(p) - want_d).abs() <= tol);
        for (s, poly) in &polys {
            // The walk goes counter-clockwise round its site.
            let w = winding(poly, p);
            assert_eq!(w, i32::from(*s == want), "{p:?} (nearest {want}) in the walk of {s}: winding {w}");
        }
    }
}

/// Which polygon sites have a vertex on the convex hull of all vertices
/// (monotone chain, collinear hull points kept).
fn hull_sites(sites: &Sites) -> Vec<bool> {
    let mut pts: Vec<(Point, usize)> =
        sites.regions.iter().enumerate().flat_map(|(i, r)| r.iter().map(move |v| (v.p, i))).collect();
    pts.sort_by(|a, b| a.0.x.total_cmp(&b.0.x).then(a.0.y.total_cmp(&b.0.y)));
    let mut on = vec![false; sites.regions.len()];
    for order in [false, true] {
        let mut chain: Vec<(Point, usize)> = Vec::new();
        let it: Box<dyn Iterator<Item = &(Point, usize)>> =
            if order { Box::new(pts.iter().rev()) } else { Box::new(pts.iter()) };
        for &q in it {
            while chain.len() >= 2 && {
                let (a, b) = (chain[chain.len() - 2].0, chain[chain.len() - 1].0);
                (b - a).cross(q.0 - a) < -1e-12
            } {
                chain.pop();
            }
            chain.push(q);
        }
        for (_, i) in chain {
            on[i] = true;
        }
    }
    on
}

/// Every region walk goes round its face as a planar graph's face is
/// walked: at each node it leaves by the first of all the node's edges
/// clockwise from the one it came in by (directions from the edges'
/// samples, not from the library's choice).
fn check_face_order(vd: &VoronoiDiagram, diag: f64) {
    let nodes = &vd.axis.nodes;
    // The direction edge i leaves node `at` in: towards its first sample
    // clear of the node.
    let leaving = |i: usize, at: usize| {
        let e = &vd.axis.edges[i];
        let mut s = e.sample(vd.shape(), nodes, 1e-7 * diag);
        if e.to == at {
            s.reverse();
        }
        let p = nodes[at].point;
        let q = s.iter().map(|x| x.center).find(|q| q.dist(p) > 1e-6 * diag).unwrap_or(s[s.len() - 1].center);
        (q - p).unit()
    };
    let mut at_node: Vec<Vec<usize>> = vec![Vec::new(); nodes.len()];
    for (i, e) in vd.axis.edges.iter().enumerate() {
        at_node[e.from].push(i);
        if e.to != e.from {
            at_node[e.to].push(i);
        }
    }
    let cw = |a: Point, b: Point| (a.y.atan2(a.x) - b.y.atan2(b.x)).rem_euclid(std::f64::consts::TAU);
    for r in &vd.regions {
        let n = r.boundary.len();
        for k in 0..n {
            let ((i, fwd), (j, _)) = (r.boundary[k], r.boundary[(k + 1) % n]);
            let e = &vd.axis.edges[i];
            let v = if fwd { e.to } else { e.from };
            if at_node[v].len() < 3 {
                continue;
            }
            let back = leaving(i, v);
            let first = at_node[v]
                .iter()
                .filter(|&&x| x != i)
                .min_by(|&&a, &&b| cw(back, leaving(a, v)).total_cmp(&cw(back, leaving(b, v))))
                .copied();
            assert_eq!(
                first,
                Some(j),
                "{}: at node {v} ({:?}) the walk leaves by {j}, not the face's next edge",
                r.site,
                nodes[v].point
            );
        }
    }
}

fn squares_grid(k: usize, size: f64, pitch: f64, jitter: f64, seed: u64) -> Sites {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let mut out = Vec::new();
    for i in 0..k {
        for j in 0..k {
            let mut shake = || if jitter > 0.0 { rng.gen_range(0.0..jitter) } else { 0.0 };
            let (x, y) = (i as f64 * pitch + shake(), j as f64 * pitch + shake());
            out.push(rect(x, y, x + size, y + size));
        }
    }
    regions(out)
}

#[test]
fn two_squares_are_split_by_their_bisector() {
    let sites = regions(vec![rect(0.0, 0.0, 1.0, 1.0), rect(3.0, 0.0, 4.0, 1.0)]);
    let vd = vd_of(&sites);
    assert!(vd.complete && vd.auto_frame);
    check_diagram(&sites, &vd, 300, 1);
    // The line x = 2 between the facing sides, running to infinity at both
    // ends: two frontier nodes.
    let between: Vec<usize> = vd.diagram_edges(false).into_iter().filter(|&i| !vd.edges[i].self_edge).collect();
    assert!(!between.is_empty());
    for &i in &between {
        for Disk { center: c, .. } in vd.axis.edges[i].sample(vd.shape(), &vd.axis.nodes, 1e-6) {
            if c.y > -0.5 && c.y < 1.5 {
                assert!((c.x - 2.0).abs() < 1e-9, "{c:?}");
            }
        }
    }
    assert_eq!(vd.frontier.iter().filter(|&&f| f).count(), 2);
    assert!(vd.regions.iter().all(|r| r.unbounded));
}

#[test]
fn cocircular_circles_meet_in_one_vertex() {
    // Four equal circles at the corners of a square: their four bisectors
    // meet at the centre, a vertex of degree four (or two branch points
    // within the merge tolerance joined by a vanishing edge).
    let sites =
        regions(vec![circle(0.0, 0.0, 0.5), circle(3.0, 0.0, 0.5), circle(3.0, 3.0, 0.5), circle(0.0, 3.0, 0.5)]);
    let vd = vd_of(&sites);
    check_diagram(&sites, &vd, 400, 2);
    let centre: Vec<_> = vd.axis.nodes.iter().filter(|n| n.point.dist(Point::new(1.5, 1.5)) < 1e-6).collect();
    assert!(!centre.is_empty(), "no vertex at the centre");
    assert!(centre.iter().all(|n| (n.radius - (1.5 * 2f64.sqrt() - 0.5)).abs() < 1e-9));
    // The inner site-only vertex is enclosed: no region of the four is
    // bounded (each is on the hull), and the centre is in none.
    assert!(vd.regions.iter().all(|r| r.unbounded));
}

#[test]
fn a_region_inside_the_hull_is_bounded() {
    let sites = regions(vec![
        rect(0.0, 0.0, 1.0, 1.0),
        rect(6.0, 0.0, 7.0, 1.0),
        rect(3.0, 5.0, 4.0, 6.0),
        circle(3.5, 2.2, 0.4),
    ]);
    let vd = vd_of(&sites);
    check_diagram(&sites, &vd, 400, 3);
    assert!(!vd.region(SiteId::Region(3)).unwrap().unbounded);
    assert!(vd.region(SiteId::Region(0)).unwrap().unbounded);
}

#[test]
fn a_u_shaped_site_has_self_edges_that_the_switch_drops() {
    let u = poly(&[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)]);
    let sites = regions(vec![u, circle(6.0, 1.5, 0.5)]);
    let vd = vd_of(&sites);
    check_diagram(&sites, &vd, 300, 4);
    let r = vd.region(SiteId::Region(0)).unwrap();
    assert!(!r.self_edges.is_empty(), "the mouth of the U");
    // The self-edge in the mouth runs up the line x = 1.5 and on to
    // infinity (the hull bridges the mouth).
    let mouth = r.self_edges.iter().any(|&i| {
        vd.axis.edges[i]
            .sample(vd.shape(), &vd.axis.nodes, 1e-6)
            .iter()
            .any(|d| (d.center.x - 1.5).abs() < 1e-9 && d.center.y > 3.0)
    });
    assert!(mouth);
    let with = vd.diagram_edges(true);
    let without = vd.diagram_edges(false);
    assert!(without.len() < with.len());
    assert!(without.iter().all(|&i| !vd.edges[i].self_edge));
    assert!(vd.to_json(1e-3, false).len() < vd.to_json(1e-3, true).len());
}

#[test]
fn the_streamed_json_is_the_document_a_value_tree_writes() {
    // Regions, an open curve (whose way back carries "side": "back") and
    // points: every kind of site and edge the format has.
    let u = poly(&[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)]);
    let v = |x: f64, y: f64, bulge: f64| Vertex { p: Point::new(x, y), bulge };
    let sites = Sites {
        regions: vec![u, circle(6.0, 1.5, 0.5)],
        curves: vec![vec![v(0.0, 5.0, 0.3), v(2.0, 5.5, 0.0), v(4.0, 5.0, 0.0)]],
        points: vec![Point::new(5.0, 4.0), Point::new(-1.0, 2.0)],
    };
    let vd = vd_of(&sites);
    for self_edges in [true, false] {
        let text = vd.to_json(1e-3, self_edges);
        let doc: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(text, serde_json::to_string(&doc).unwrap() + "\n");
        assert!(text.contains("\"side\":\"back\"") && text.contains("\"curve\":0") && text.contains("\"point\":1"));
        assert_eq!(doc["edges"].as_array().unwrap().len(), vd.diagram_edges(self_edges).len());
    }
}

#[test]
fn a_site_in_the_mouth_of_a_u_joins_its_boundary_through_self_edges() {
    // The disc's region is enclosed by the U's; the U's boundary has an
    // outer and an inner part, joined only through the self-edge in the
    // mouth above the disc (found by the fuzz target: two walks).
    let u = poly(&[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)]);
    let sites = regions(vec![u, circle(1.5, 1.6, 0.3)]);
    let vd = vd_of(&sites);
    check_diagram(&sites, &vd, 400, 14);
    let disc = vd.region(SiteId::Region(1)).unwrap();
    assert!(!disc.unbounded && disc.self_edges.is_empty());
    let u_region = vd.region(SiteId::Region(0)).unwrap();
    assert!(u_region.unbounded && !u_region.self_edges.is_empty());
    for &i in &u_region.self_edges {
        let twice = u_region.boundary.iter().filter(|&&(j, _)| j == i).count();
        assert_eq!(twice, 2, "self-edge {i} walked once each way");
    }
}

#[test]
fn a_single_site_has_no_edges_to_others() {
    let sites = regions(vec![circle(2.0, 3.0, 1.0)]);
    let vd = vd_of(&sites);
    assert!(vd.complete);
    assert!(vd.diagram_edges(true).is_empty());
    let r = vd.region(SiteId::Region(0)).unwrap();
    assert!(r.unbounded && r.self_edges.is_empty());
    assert_eq!(vd.nearest_site(Point::new(10.0, 3.0)).map(|n| (n.0, n.1)), Some((SiteId::Region(0), 7.0)));
}

#[test]
fn grids_and_nearly_touching_sites() {
    // A regular grid (many cocircular quadruples, collinear sides on the
    // hull) and a jittered one.
    for (k, jitter, seed) in [(4, 0.0, 5), (6, 0.4, 6)] {
        let sites = squares_grid(k, 0.6, 1.0, jitter, seed);
        let vd = vd_of(&sites);
        check_diagram(&sites, &vd, 300, seed);
        assert!(vd.complete);
        // A region is unbounded exactly when its site reaches the convex
        // hull of all sites.
        let on_hull = hull_sites(&sites);
        for r in &vd.regions {
            let SiteId::Region(i) = r.site else { panic!() };
            assert_eq!(r.unbounded, on_hull[i], "{}", r.site);
        }
        if jitter == 0.0 {
            assert_eq!(on_hull.iter().filter(|&&h| !h).count(), (k - 2) * (k - 2));
        }
    }
    // Two sites 1e-4 apart, and one 1e-4 from a caller's boundary.
    let sites = regions(vec![rect(0.0, 0.0, 1.0, 1.0), rect(1.0001, 0.0, 2.0, 1.0)]);
    check_diagram(&sites, &vd_of(&sites), 200, 7);
    let opts = VoronoiOptions { boundary: Some(rect(-1.0, -0.0001 - 1.0, 3.0, 3.0)), ..VoronoiOptions::default() };
    let near_frame = regions(vec![rect(0.0, -1.0, 1.0, 0.0), circle(2.0, 1.0, 0.5)]);
    let vd = voronoi(&near_frame, &opts).expect("voronoi");
    assert!(!vd.auto_frame && vd.complete);
    check(vd.shape(), &vd.axis, 200, 8);
    assert!(vd.region(SiteId::Frame).is_some(), "a caller's boundary is a site with a region");
}

#[test]
fn nearly_collinear_sites_grow_the_frame() {
    // Three small circles nearly on a line: the Voronoi vertex of all
    // three lies far below (radius ~ 1/(2 × sag)); the first frame misses
    // it, the frame grows until it is inside.
    let sag = 0.02;
    let sites = regions(vec![circle(0.0, 0.0, 0.1), circle(1.0, sag, 0.1), circle(2.0, 0.0, 0.1)]);
    let vd = vd_of(&sites);
    assert!(vd.complete);
    check_diagram(&sites, &vd, 200, 9);
    let at_frame: Vec<bool> = (0..vd.axis.nodes.len())
        .map(|n| {
            vd.axis
                .edges
                .iter()
                .zip(&vd.edges)
                .any(|(e, v)| (e.from == n || e.to == n) && v.sides.contains(&SiteId::Frame))
        })
        .collect();
    let far = (0..vd.axis.nodes.len())
        .filter(|&n| !at_frame[n] && vd.axis.nodes[n].point.y < -10.0 && vd.axis.nodes[n].radius > 10.0)
        .count();
    let shape_diag = vd.shape().bbox().diagonal();
    assert_eq!(far, 1, "the far vertex (frame diagonal {shape_diag})");
}

#[test]
fn the_frame_keeps_every_vertex_of_a_much_larger_one() {
    // The site-only vertices (nodes with no frame edge) of the auto frame
    // and of a caller's circle 50 times larger agree.
    let sites = squares_grid(5, 0.5, 1.0, 0.45, 10);
    let auto = vd_of(&sites);
    let big: Vec<Vertex> = circle(2.5, 2.5, 400.0);
    let given = voronoi(&sites, &VoronoiOptions { boundary: Some(big), ..VoronoiOptions::default() }).unwrap();
    let (a, b) = (site_vertices(&auto), site_vertices(&given));
    assert_eq!(a.len(), b.len());
    for (p, q) in a.iter().zip(&b) {
        assert!((p.0 - q.0).abs() < 1e-9 && (p.1 - q.1).abs() < 1e-9 && (p.2 - q.2).abs() < 1e-9, "{p:?} {q:?}");
    }
}

#[test]
fn metamorphic_translate_scale_reorder() {
    let base = vec![
        rect(0.0, 0.0, 1.0, 1.0),
        circle(3.0, 0.7, 0.6),
        poly(&[(1.0, 3.0), (2.0, 2.5), (2.5, 4.0)]),
        circle(4.0, 3.5, 0.3),
    ];
    let count = |vd: &VoronoiDiagram| {
        let mut radii: Vec<f64> = vd
            .diagram_edges(true)
            .iter()
            .flat_map(|&i| [vd.axis.edges[i].from, vd.axis.edges[i].to])
            .map(|n| vd.axis.nodes[n].radius)
            .collect();
        radii.sort_by(f64::total_cmp);
        radii.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
        radii
    };
    let vd0 = vd_of(&regions(base.clone()));
    check_diagram(&regions(base.clone()), &vd0, 200, 11);
    let r0 = count(&vd0);
    let moved: Vec<Vec<Vertex>> = base
        .iter()
        .map(|l| l.iter().map(|v| Vertex { p: v.p * 1000.0 + Point::new(1e5, -3e4), bulge: v.bulge }).collect())
        .collect();
    let vd1 = vd_of(&regions(moved.clone()));
    check_diagram(&regions(moved), &vd1, 200, 12);
    let r1: Vec<f64> = count(&vd1).iter().map(|r| r / 1000.0).collect();
    assert_eq!(r0.len(), r1.len());
    assert!(r0.iter().zip(&r1).all(|(a, b)| (a - b).abs() < 1e-9), "{r0:?} {r1:?}");
    let mut rev = base.clone();
    rev.reverse();
    let vd2 = vd_of(&regions(rev.clone()));
    check_diagram(&regions(rev), &vd2, 200, 13);
    let r2 = count(&vd2);
    assert!(r0.len() == r2.len() && r0.iter().zip(&r2).all(|(a, b)| (a - b).abs() < 1e-9));
}

#[test]
fn random_sites_up_to_a_hundred() {
    for (k, seed) in [(3, 21), (7, 22), (10, 23)] {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
        let mut out = Vec::new();
        for i in 0..k {
            for j in 0..k {
                let (x, y) = (i as f64 + rng.gen_range(0.3..0.7), j as f64 + rng.gen_range(0.3..0.7));
                let r = rng.gen_range(0.05..0.25);
                out.push(if rng.gen_bool(0.5) { circle(x, y, r) } else { rect(x - r, y - r, x + r, y + r * 0.7) });
            }
        }
        let sites = regions(out);
        let vd = vd_of(&sites);
        assert!(vd.complete, "k = {k}");
        check_diagram(&sites, &vd, 300, seed);
    }
}

#[test]
fn bad_sites_get_typed_errors_naming_the_site() {
    assert_eq!(voronoi(&Sites::default(), &VoronoiOptions::default()).unwrap_err(), VoronoiError::NoSites);
    let overlapping = regions(vec![rect(0.0, 0.0, 1.0, 1.0), circle(5.0, 5.0, 1.0), rect(0.5, 0.5, 2.0, 2.0)]);
    match voronoi(&overlapping, &VoronoiOptions::default()).unwrap_err() {
        VoronoiError::Invalid { site: Some(SiteId::Region(r)), error } => {
            assert!(r == 0 || r == 2, "{r}");
            assert!(matches!(error, ShapeError::Intersection { .. } | ShapeError::HoleInsideHole { .. }), "{error}");
        }
        e => panic!("{e}"),
    }
    let nested = regions(vec![rect(0.0, 0.0, 4.0, 4.0), rect(1.0, 1.0, 2.0, 2.0)]);
    let e = voronoi(&nested, &VoronoiOptions::default()).unwrap_err();
    assert!(matches!(e, VoronoiError::Invalid { site: Some(SiteId::Region(_)), .. }), "{e}");
    let outside = VoronoiOptions { boundary: Some(rect(0.0, 0.0, 1.0, 1.0)), ..VoronoiOptions::default() };
    let e = voronoi(&regions(vec![circle(5.0, 5.0, 1.0)]), &outside).unwrap_err();
    assert!(matches!(e, VoronoiError::Invalid { site: Some(SiteId::Region(0)), .. }), "{e}");
    let on_region =
        Sites { points: vec![Point::new(0.5, 0.5)], regions: vec![rect(0.0, 0.0, 1.0, 1.0)], ..Sites::default() };
    let e = voronoi(&on_region, &VoronoiOptions::default()).unwrap_err();
    assert!(matches!(e, VoronoiError::Invalid { site: Some(SiteId::Point(0)), .. }), "{e}");
    let crossing =
        Sites { curves: vec![poly(&[(0.0, 0.0), (2.0, 2.0)]), poly(&[(0.0, 2.0), (2.0, 0.0)])], ..Sites::default() };
    let e = voronoi(&crossing, &VoronoiOptions::default()).unwrap_err();
    assert!(matches!(e, VoronoiError::Invalid { site: Some(SiteId::Curve(_)), .. }), "{e}");
    let same = Sites { points: vec![Point::new(1.0, 1.0), Point::new(1.0, 1.0)], ..Sites::default() };
    assert!(voronoi(&same, &VoronoiOptions::default()).is_err(), "two points at one place");
    let folded = Sites { curves: vec![poly(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)])], ..Sites::default() };
    assert!(voronoi(&folded, &VoronoiOptions::default()).is_err(), "a curve folding back on itself");
    let nan = regions(vec![poly(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)])]);
    assert!(voronoi(&nan, &VoronoiOptions::default()).is_err());
}

fn points(pts: &[(f64, f64)]) -> Sites {
    Sites { points: pts.iter().map(|&(x, y)| Point::new(x, y)).collect(), ..Sites::default() }
}

/// The branch nodes no frame edge reaches: the Voronoi vertices of the
/// sites, as (x, y, r) sorted.
fn site_vertices(vd: &VoronoiDiagram) -> Vec<(f64, f64, f64)> {
    let mut touches_frame = vec![false; vd.axis.nodes.len()];
    let mut deg = vec![0; vd.axis.nodes.len()];
    for (e, v) in vd.axis.edges.iter().zip(&vd.edges) {
        for n in [e.from, e.to] {
            deg[n] += 1;
            touches_frame[n] |= v.sides.contains(&SiteId::Frame);
        }
    }
    let mut pts: Vec<(f64, f64, f64)> = (0..vd.axis.nodes.len())
        .filter(|&n| deg[n] >= 3 && !touches_frame[n])
        .map(|n| (vd.axis.nodes[n].point.x, vd.axis.nodes[n].point.y, vd.axis.nodes[n].radius))
        .collect();
    pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    pts
}

#[test]
fn point_sites_single_pair_and_collinear() {
    let one = points(&[(2.0, 3.0)]);
    let vd = vd_of(&one);
    check_diagram(&one, &vd, 100, 30);
    assert!(vd.complete && vd.diagram_edges(true).is_empty());
    // Two points: their bisector, a line crossing the whole frame.
    let two = points(&[(0.0, 0.0), (2.0, 0.0)]);
    let vd = vd_of(&two);
    check_diagram(&two, &vd, 200, 31);
    assert!(vd.complete && site_vertices(&vd).is_empty());
    assert_eq!(vd.frontier.iter().filter(|&&f| f).count(), 2);
    for i in vd.diagram_edges(true) {
        for Disk { center: c, .. } in vd.axis.edges[i].sample(vd.shape(), &vd.axis.nodes, 1e-6) {
            assert!((c.x - 1.0).abs() < 1e-9, "{c:?}");
        }
    }
    // Collinear points: parallel bisectors, no vertex, four frontier nodes.
    let line = points(&[(0.0, 0.0), (1.0, 0.0), (3.0, 0.0)]);
    let vd = vd_of(&line);
    check_diagram(&line, &vd, 200, 32);
    assert!(vd.complete && site_vertices(&vd).is_empty());
    assert_eq!(vd.frontier.iter().filter(|&&f| f).count(), 4);
}

#[test]
fn cocircular_and_grid_points() {
    // Five points on a circle around a sixth: the circle's centre is no
    // vertex (the sixth point is nearer), the five inner vertices are.
    let mut pts: Vec<(f64, f64)> =
        (0..5).map(|k| (2.0 * (k as f64 * 1.2566).cos(), 2.0 * (k as f64 * 1.2566).sin())).collect();
    pts.push((0.0, 0.0));
    let ring = points(&pts);
    let vd = vd_of(&ring);
    check_diagram(&ring, &vd, 300, 33);
    assert_eq!(site_vertices(&vd).len(), 5);
    assert!(!vd.region(SiteId::Point(5)).unwrap().unbounded);
    // A regular 5 x 5 grid: every inner vertex has four points on its
    // circle (one node of degree four, or two within the merge tolerance).
    let grid: Vec<(f64, f64)> = (0..25).map(|k| ((k % 5) as f64, (k / 5) as f64)).collect();
    let g = points(&grid);
    let vd = vd_of(&g);
    assert!(vd.complete);
    check_diagram(&g, &vd, 300, 34);
    let mut centres: Vec<(f64, f64)> =
        site_vertices(&vd).iter().map(|v| ((v.0 * 2.0).round(), (v.1 * 2.0).round())).collect();
    centres.dedup();
    assert_eq!(centres.len(), 16, "the 16 cell centres");
    for v in site_vertices(&vd) {
        assert!((v.2 - 0.5f64.sqrt()).abs() < 1e-9 && (v.0.fract() - 0.5).abs() < 1e-9, "{v:?}");
    }
    let inner = vd.regions.iter().filter(|r| !r.unbounded).count();
    assert_eq!(inner, 9);
}

#[test]
fn random_points_under_the_oracle_and_against_a_larger_frame() {
    for (n, seed) in [(30, 40), (200, 41)] {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
        let pts: Vec<(f64, f64)> = (0..n).map(|_| (rng.gen_range(0.0..10.0), rng.gen_range(0.0..10.0))).collect();
        let sites = points(&pts);
        let vd = vd_of(&sites);
        assert!(vd.complete);
        check_diagram(&sites, &vd, 300, seed);
        // Voronoi vertices of points: every one is the centre of an empty
        // circle through three points, checked by scanning.
        for (x, y, r) in site_vertices(&vd) {
            let d: Vec<f64> = pts.iter().map(|p| (p.0 - x).hypot(p.1 - y)).collect();
            assert!(d.iter().all(|&di| di >= r - 1e-9));
            assert!(d.iter().filter(|&&di| (di - r).abs() < 1e-9).count() >= 3);
        }
        if n == 30 {
            let big = VoronoiOptions { boundary: Some(circle(5.0, 5.0, 1e5)), ..VoronoiOptions::default() };
            let given = voronoi(&sites, &big).unwrap();
            let (a, b) = (site_vertices(&vd), site_vertices(&given));
            let inside: Vec<_> = a.iter().filter(|v| (v.0 - 5.0).hypot(v.1 - 5.0) + v.2 < 1e5).collect();
            assert_eq!(inside.len(), b.len());
            for (p, q) in inside.iter().zip(&b) {
                assert!(
                    (p.0 - q.0).abs() < 1e-6 && (p.1 - q.1).abs() < 1e-6 && (p.2 - q.2).abs() < 1e-6,
                    "{p:?} {q:?}"
                );
            }
        }
    }
}

#[test]
fn segment_and_arc_curves_with_self_edges() {
    // Collinear segment sites, a bent polyline (a self-edge bisects its
    // convex side) and a C-shaped arc.
    let sites = Sites {
        curves: vec![
            poly(&[(0.0, 0.0), (1.0, 0.0)]),
            poly(&[(2.0, 0.0), (3.0, 0.0)]),
            poly(&[(4.0, 0.0), (5.0, 0.0)]),
            poly(&[(0.0, 3.0), (1.5, 4.0), (3.0, 3.0)]),
            vec![Vertex { p: Point::new(4.0, 2.0), bulge: 1.5 }, Vertex { p: Point::new(4.0, 4.0), bulge: 0.0 }],
        ],
        ..Sites::default()
    };
    let vd = vd_of(&sites);
    assert!(vd.complete);
    check_diagram(&sites, &vd, 400, 50);
    let bent = vd.region(SiteId::Curve(3)).unwrap();
    assert!(!bent.self_edges.is_empty(), "the bisector below the bend");
    // Between two collinear segments: the line x = 1.5 near them.
    let between = vd.diagram_edges(false).into_iter().any(|i| {
        let v = vd.edges[i];
        v.sides.contains(&SiteId::Curve(0)) && v.sides.contains(&SiteId::Curve(1)) && {
            let s = vd.axis.edges[i].sample(vd.shape(), &vd.axis.nodes, 1e-6);
            let (lo, hi) =
                s.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), d| (a.min(d.center.y), b.max(d.center.y)));
            s.iter().all(|d| (d.center.x - 1.5).abs() < 1e-9) && lo < 0.0 && hi > 0.0
        }
    });
    assert!(between);
}

#[test]
fn mixed_sites_points_curves_regions() {
    for seed in 60..64 {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
        let mut sites = Sites::default();
        for i in 0..6 {
            for j in 0..6 {
                let (x, y) = (i as f64 * 2.0 + rng.gen_range(0.2..0.8), j as f64 * 2.0 + rng.gen_range(0.2..0.8));
                match rng.gen_range(0..4) {
                    0 => sites.points.push(Point::new(x, y)),
                    1 => {
                        sites.curves.push(poly(&[(x, y), (x + rng.gen_range(0.2..1.0), y + rng.gen_range(-0.5..0.5))]))
                    }
                    2 => sites.curves.push(vec![
                        Vertex { p: Point::new(x, y), bulge: rng.gen_range(-0.8..0.8) },
                        Vertex { p: Point::new(x + 0.6, y + 0.3), bulge: rng.gen_range(-0.8..0.8) },
                        Vertex { p: Point::new(x + 0.9, y + 0.9), bulge: 0.0 },
                    ]),
                    _ => sites.regions.push(circle(x + 0.4, y + 0.4, rng.gen_range(0.1..0.4))),
                }
            }
        }
        let vd = vd_of(&sites);
        assert!(vd.complete, "seed {seed}");
        check_diagram(&sites, &vd, 300, seed);
    }
}

#[test]
fn degenerate_scenes_from_the_cgal_cross_check() {
    // Found by ctest/cgal_voronoi: exactly collinear points and segments on
    // one line broke down where their parallel bisectors met a frame
    // thousands of diagonals away; a brick wall of segments and points
    // broke down at the first frame (a larger one is tried).
    for (name, seed) in [("collinear_points", 70), ("collinear_segments", 71), ("brick_wall", 72)] {
        let text =
            std::fs::read_to_string(format!("{}/tests/data/voronoi_{name}.json", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let (sites, boundary) = medax::plane::read_sites(&text).unwrap();
        assert!(boundary.is_none());
        let vd = voronoi(&sites, &VoronoiOptions::default()).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(vd.complete, "{name}");
        check_diagram(&sites, &vd, 200, seed);
    }
}

#[test]
fn the_diagnosis_tools_read_a_sites_file_as_the_diagram_s_first_shape() {
    use medax::plane::shape_or_sites;
    use medax::shape::LoopKind;
    let text = r#"{"curves": [[[0, 0], [1, 0.2]]], "points": [[0.5, 2]], "regions": [[[3, 0], [4, 0], [4, 1]]]}"#;
    let shape = shape_or_sites(text).unwrap();
    let kinds: Vec<LoopKind> = (0..shape.loops().len()).map(|l| shape.kind(l)).collect();
    assert_eq!(kinds, [LoopKind::Region, LoopKind::Region, LoopKind::Curve, LoopKind::Point]);
    // The same shape, frame included, as the diagram computes on.
    let (sites, _) = medax::plane::read_sites(text).unwrap();
    assert_eq!(shape.to_json(), vd_of(&sites).shape().to_json());
    // A given boundary is loop 0; a shape file reads as itself.
    let bounded = shape_or_sites(r#"{"points": [[1, 1]], "boundary": [[0, 0], [3, 0], [3, 3], [0, 3]]}"#).unwrap();
    assert_eq!(bounded.loops()[0].vertices().len(), 4);
    let plain = shape_or_sites(r#"{"loops": [[[0, 0], [3, 0], [3, 3]]]}"#).unwrap();
    assert_eq!(plain.loops().len(), 1);
}

#[test]
fn many_random_segments() {
    // 1 500 random disjoint segments broke down ("no branch point in a
    // pocket": a footpoint at a segment's end exactly opposite the arc
    // before its chain went to the wrong part of the half-turn fan); so
    // did 1 000 of them in a square 4 diagonals wide, in a corner. 3 000
    // random points in a square 1 024 diagonals wide broke down until the
    // branch-point construction was solved near its sites rather than
    // near the mean of their anchors (a frame side's anchor lies 512
    // diagonals away).
    for name in
        ["random_segments_1500", "random_segments_1000_square_4_diagonals", "random_points_3000_square_1024_diagonals"]
    {
        let text =
            std::fs::read_to_string(format!("{}/tests/data/voronoi_{name}.json", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let (sites, boundary) = medax::plane::read_sites(&text).unwrap();
        let opts = VoronoiOptions { boundary, ..VoronoiOptions::default() };
        let vd = voronoi(&sites, &opts).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(vd.complete, "{name}");
        check(vd.shape(), &vd.axis, 20, 80);
        assert!(vd.regions.iter().all(|r| r.walks == 1), "{name}");
    }
}

#[test]
fn review_findings_on_the_frame() {
    // A region given with its first vertex repeated at the end is the
    // same region: complete at the first frame, as without the repeat.
    let mut closed = rect(0.0, 0.0, 1.0, 1.0);
    closed.push(closed[0]);
    let sites = Sites { regions: vec![closed], points: vec![Point::new(3.0, 0.5)], ..Sites::default() };
    assert!(vd_of(&sites).complete);
    // A point a hair inside the common tangent of two circles: its region
    // is bounded by a vertex millions of diagonals away, beyond the
    // frame's limit, and the arcs' sampled hull (which it is outside of)
    // must not make the diagram claim completeness.
    let (r1, r2, d): (f64, f64, f64) = (1.0, 2.0, 10.0);
    let (sin, cos) = ((r2 - r1) / d, (1.0 - ((r2 - r1) / d).powi(2)).sqrt());
    // Upper common tangent: points p with n . p = r1 (circle 1 at the
    // origin), n = (-sin, cos).
    let n = Point::new(-sin, cos);
    let x = 5.0;
    let on = (r1 + n.x * -x) / n.y;
    for (delta, complete) in [(2e-6, false), (0.5, true)] {
        let sites = Sites {
            regions: vec![circle(0.0, 0.0, r1), circle(d, 0.0, r2)],
            points: vec![Point::new(x, on - delta / n.y)],
            ..Sites::default()
        };
        let vd = vd_of(&sites);
        assert_eq!(vd.complete, complete, "delta {delta}");
        check(vd.shape(), &vd.axis, 50, 81);
    }
    // Sites far out in the coordinate range: the frame stays inside it.
    let far = points(&[(0.0, 0.0), (9e8, 0.0), (4.5e8, 2.7e8 + 1.0)]);
    let vd = voronoi(&far, &VoronoiOptions::default()).expect("frame within the coordinate range");
    assert!(vd.shape().bbox().max.x <= 1e9 && vd.shape().bbox().min.x >= -1e9);
    // Non-finite coordinates and an empty curve name their site.
    let inf = points(&[(0.0, 0.0), (f64::INFINITY, 1.0), (1.0, 2.0)]);
    let e = voronoi(&inf, &VoronoiOptions::default()).unwrap_err();
    assert!(matches!(e, VoronoiError::Invalid { site: Some(SiteId::Point(1)), .. }), "{e}");
    let empty = Sites { curves: vec![vec![]], points: vec![Point::new(0.0, 0.0)], ..Sites::default() };
    let e = voronoi(&empty, &VoronoiOptions::default()).unwrap_err();
    assert!(matches!(e, VoronoiError::Invalid { site: Some(SiteId::Curve(0)), .. }), "{e}");
}

#[test]
fn star_sites_walk_their_trees_of_self_edges_in_face_order() {
    // A star-shaped polygon's spikes make trees of self-edges in its
    // region; where several of them leave one node the walk must take
    // them in rotation order (check_face_order).
    for seed in 0..60u64 {
        let star = common::star(40, seed);
        let sites = Sites {
            regions: vec![star],
            points: vec![Point::new(1.6, 0.2), Point::new(-0.4, 1.5)],
            ..Sites::default()
        };
        let vd = vd_of(&sites);
        check_diagram(&sites, &vd, 60, 90 + seed);
    }
}

#[test]
fn a_given_boundary_thousands_of_diagonals_away() {
    // Random points, and short segments one per cell of a grid, in a unit
    // of about 110 model units, inside a square 4 096 and 16 384 of their
    // diagonals wide: broke down ("no branch point in a pocket") while
    // branch points were solved around the mean of their sites' anchors,
    // a square side's lying half the square away.
    let mut rng = rand::rngs::SmallRng::seed_from_u64(41);
    let points: Vec<Point> =
        (0..1500).map(|_| Point::new(rng.gen_range(0.0..77.5), rng.gen_range(0.0..77.5))).collect();
    let mut curves = Vec::new();
    for i in 0..20 {
        for j in 0..20 {
            let mut at =
                || Point::new(4.0 * i as f64 + rng.gen_range(0.2..3.8), 4.0 * j as f64 + rng.gen_range(0.2..3.8));
            curves.push(vec![Vertex { p: at(), bulge: 0.0 }, Vertex { p: at(), bulge: 0.0 }]);
        }
    }
    for (sites, width) in [
        (Sites { points: points.clone(), ..Sites::default() }, 4096.0),
        (Sites { points, ..Sites::default() }, 16384.0),
        (Sites { curves, ..Sites::default() }, 16384.0),
    ] {
        let h = 0.5 * width * 80.0 * std::f64::consts::SQRT_2;
        let square = rect(40.0 - h, 40.0 - h, 40.0 + h, 40.0 + h);
        let opts = VoronoiOptions { boundary: Some(square), ..VoronoiOptions::default() };
        let vd = voronoi(&sites, &opts).unwrap_or_else(|e| panic!("{width} diagonals: {e}"));
        check(vd.shape(), &vd.axis, 20, 43);
        assert!(vd.regions.iter().all(|r| r.walks == 1), "{width} diagonals");
    }
}
