//! Voronoi diagrams from sites files: arbitrary text through the sites
//! reader, and small structured sets of region sites on a grid (collinear,
//! cocircular and nearly touching set-ups are common). No panic, no hang;
//! every diagram it returns has each kept edge's samples as far from the
//! sites it separates as their radius (brute force), and every region one
//! closed walk. Typed errors are allowed.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::Point;
use medax::plane::voronoi::{voronoi, SiteId, Sites, VoronoiOptions};
use medax::plane::voronoi_json::read_sites;
use medax::shape::{Loop, Vertex};

#[derive(Arbitrary, Debug)]
enum Input {
    Text(String),
    Grid { regions: Vec<Vec<(i8, i8, i8)>>, seed: u8 },
}

fuzz_target!(|input: Input| {
    let (sites, boundary, seed) = match input {
        Input::Text(t) => match read_sites(&t) {
            Ok((s, b)) if s.len() <= 6 && s.regions.iter().all(|r| r.len() <= 16) => (s, b, 0),
            _ => return,
        },
        Input::Grid { regions, seed } => {
            let regions = regions
                .iter()
                .take(5)
                .map(|r| {
                    r.iter()
                        .take(8)
                        .map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 })
                        .collect()
                })
                .collect();
            (Sites { regions, ..Sites::default() }, None, seed)
        }
    };
    let mut opts = VoronoiOptions { boundary, ..VoronoiOptions::default() };
    opts.axis.seed = seed as u64;
    let Ok(vd) = voronoi(&sites, &opts) else { return };
    let loops: Vec<(SiteId, Loop)> =
        sites.regions.iter().enumerate().map(|(i, r)| (SiteId::Region(i), Loop::new(r.clone()))).collect();
    let frame = vd.shape().loops()[0].clone();
    let dist = |s: SiteId, c: Point| {
        let l = if s == SiteId::Frame { &frame } else { &loops.iter().find(|x| x.0 == s).unwrap().1 };
        l.elements().map(|e| e.closest_point(c).0).fold(f64::INFINITY, f64::min)
    };
    let diag = vd.shape().bbox().diagonal();
    for i in vd.diagram_edges(true) {
        let e = &vd.axis.edges[i];
        for (c, r) in e.sample(vd.shape(), &vd.axis.nodes, 1e-3 * diag) {
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
