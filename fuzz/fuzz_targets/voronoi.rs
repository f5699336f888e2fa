//! Voronoi diagrams from sites files: arbitrary text through the sites
//! reader, and small structured sets of points, curves and regions on a
//! grid (collinear, cocircular and nearly touching set-ups are common). No panic, no hang;
//! every diagram it returns has each kept edge's samples as far from the
//! sites it separates as their radius (brute force), and every region one
//! closed walk. Typed errors are allowed.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::Disk;
use medax::kernel::Point;
use medax::plane::{voronoi, SiteId, Sites, VoronoiOptions};
use medax::plane::read_sites;
use medax::shape::{Element, Loop, Vertex};

#[derive(Arbitrary, Debug)]
enum Input {
    Text(String),
    Grid { regions: Vec<Vec<(i8, i8, i8)>>, curves: Vec<Vec<(i8, i8, i8)>>, points: Vec<(i8, i8)>, seed: u8 },
}

fuzz_target!(|input: Input| {
    let (sites, boundary, seed) = match input {
        Input::Text(t) => match read_sites(&t) {
            Ok((s, b)) if s.len() <= 12 && s.regions.iter().chain(&s.curves).all(|r| r.len() <= 16) => (s, b, 0),
            _ => return,
        },
        Input::Grid { regions, curves, points, seed } => {
            let chains = |v: &[Vec<(i8, i8, i8)>]| -> Vec<Vec<Vertex>> {
                v.iter()
                    .take(5)
                    .map(|r| {
                        r.iter()
                            .take(8)
                            .map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 })
                            .collect()
                    })
                    .collect()
            };
            let points = points.iter().take(12).map(|&(x, y)| Point::new(x as f64, y as f64)).collect();
            (Sites { regions: chains(&regions), curves: chains(&curves), points }, None, seed)
        }
    };
    let mut opts = VoronoiOptions { boundary, ..VoronoiOptions::default() };
    opts.axis.seed = seed as u64;
    let Ok(vd) = voronoi(&sites, &opts) else { return };
    // Each site's elements from the input (a point as a zero-length
    // segment), the frame's from the diagram's shape.
    let mut elements: Vec<(SiteId, Vec<Element>)> =
        sites.regions.iter().enumerate().map(|(i, r)| (SiteId::Region(i), Loop::new(r.clone()).elements().collect())).collect();
    for (i, c) in sites.curves.iter().enumerate() {
        elements.push((SiteId::Curve(i), c.windows(2).map(|w| Element::from_bulge(w[0].p, w[1].p, w[0].bulge)).collect()));
    }
    for (i, &p) in sites.points.iter().enumerate() {
        elements.push((SiteId::Point(i), vec![Element::from_bulge(p, p, 0.0)]));
    }
    elements.push((SiteId::Frame, vd.shape().loops()[0].elements().collect()));
    let dist = |s: SiteId, c: Point| {
        let es = &elements.iter().find(|x| x.0 == s).unwrap().1;
        es.iter().map(|e| e.closest_point(c).0).fold(f64::INFINITY, f64::min)
    };
    let diag = vd.shape().bbox().diagonal();
    for i in vd.diagram_edges(true) {
        let e = &vd.axis.edges[i];
        for Disk { center: c, radius: r } in e.sample(vd.shape(), &vd.axis.nodes, 1e-3 * diag) {
            for s in vd.edges[i].sides {
                let d = dist(s, c);
                assert!((d - r).abs() <= 1e-8 * diag, "edge {i}: {s} at {d}, radius {r}");
            }
        }
    }
    for r in &vd.regions {
        assert!(r.walks <= 1, "{}: {} walks", r.site, r.walks);
    }
});
