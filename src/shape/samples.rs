//! Deterministic sample shapes for tests, benchmarks and demos. Each
//! returns bulge loops (outer first) that are valid by construction.

use super::bulge_loop::Vertex;
use crate::kernel::Point;
use std::f64::consts::TAU;

/// A small deterministic generator (SplitMix64) so samples need no crate.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A star-shaped polygon with `n` vertices at evenly spaced angles and
/// random radii in [0.5, 1): simple by construction, every second corner
/// reflex on average.
pub fn star_polygon(n: usize, seed: u64) -> Vec<Vec<Vertex>> {
    let mut rng = Mix(seed);
    let n = n.max(3);
    vec![(0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            let r = 0.5 + 0.5 * rng.next();
            Vertex { p: Point::new(r * a.cos(), r * a.sin()), bulge: 0.0 }
        })
        .collect()]
}

/// A smooth (C1 within ~1e-9 rad for n ≥ 1000) closed curve of `n` circular
/// arcs: the flower r(θ) = 1 + 0.3·sin(7θ). Each arc starts tangent to the
/// true curve, so joints are smooth up to the sampling error O((1/n)²).
pub fn flower_arcs(n: usize) -> Vec<Vec<Vertex>> {
    let n = n.max(8);
    let curve = |t: f64| {
        let r = 1.0 + 0.3 * (7.0 * t).sin();
        Point::new(r * t.cos(), r * t.sin())
    };
    let tangent = |t: f64| {
        let (r, dr) = (1.0 + 0.3 * (7.0 * t).sin(), 2.1 * (7.0 * t).cos());
        Point::new(dr * t.cos() - r * t.sin(), dr * t.sin() + r * t.cos())
    };
    let pts: Vec<(Point, Point)> = (0..n).map(|i| TAU * i as f64 / n as f64).map(|t| (curve(t), tangent(t))).collect();
    vec![(0..n)
        .map(|i| {
            let (p, t) = pts[i];
            let chord = pts[(i + 1) % n].0 - p;
            // Start tangent = chord turned by −sweep/2.
            let half = t.cross(chord).atan2(t.dot(chord));
            Vertex { p, bulge: (half / 2.0).tan() }
        })
        .collect()]
}

/// A plate with a `k × k` grid of circular holes, each hole two half arcs:
/// `2·k²` hole arcs plus the 4 outer segments.
pub fn perforated_plate(k: usize) -> Vec<Vec<Vertex>> {
    let k = k.max(1);
    let s = k as f64;
    let mut loops = vec![vec![
        Vertex { p: Point::new(0.0, 0.0), bulge: 0.0 },
        Vertex { p: Point::new(s, 0.0), bulge: 0.0 },
        Vertex { p: Point::new(s, s), bulge: 0.0 },
        Vertex { p: Point::new(0.0, s), bulge: 0.0 },
    ]];
    for i in 0..k {
        for j in 0..k {
            let c = Point::new(i as f64 + 0.5, j as f64 + 0.5);
            loops.push(vec![
                Vertex { p: c + Point::new(0.3, 0.0), bulge: -1.0 },
                Vertex { p: c - Point::new(0.3, 0.0), bulge: -1.0 },
            ]);
        }
    }
    loops
}

/// A comb of `teeth` slanted teeth of length `len`: long parallel elements
/// whose bounding boxes overlap heavily. The worst case for box-based
/// intersection checks (each edge's box meets ~`len` others).
pub fn slanted_comb(teeth: usize, len: f64) -> Vec<Vec<Vertex>> {
    let mut v = Vec::with_capacity(4 * teeth + 2);
    let p = |x: f64, y: f64| Vertex { p: Point::new(x, y), bulge: 0.0 };
    for i in 0..teeth {
        let x = 2.0 * i as f64;
        v.push(p(x, 0.0));
        v.push(p(x + len, len));
        v.push(p(x + 1.0 + len, len));
        v.push(p(x + 1.0, 0.0));
    }
    v.push(p(2.0 * teeth as f64, 0.0));
    v.push(p(2.0 * teeth as f64, -1.0));
    v.push(p(0.0, -1.0));
    // Orientation: walking the teeth left to right along the top is
    // clockwise; the library normalises it anyway.
    vec![v]
}
