//! Deterministic sample shapes for tests, benchmarks and demos. Each
//! returns bulge loops (outer first) that are valid by construction.

use crate::kernel::Point;
use crate::shape::model::bulge_loop::Vertex;
use crate::util::mix::Mix;
use std::f64::consts::TAU;

mod fourier;
mod glyphs;
mod strip;

pub use fourier::{fourier_biarcs, fourier_curve, fourier_with_holes};
pub use glyphs::text_plate;
pub use strip::nearly_straight_strip;

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

/// Bulge of the arc from `p` to `q` that leaves `p` along unit tangent `t`,
/// and the arc's end tangent.
fn arc_from_tangent(p: Point, t: Point, q: Point) -> (f64, Point) {
    let chord = q - p;
    let half = t.cross(chord).atan2(t.dot(chord));
    let (s, c) = half.sin_cos();
    let u = chord.unit();
    ((half / 2.0).tan(), Point::new(c * u.x - s * u.y, s * u.x + c * u.y))
}

/// The two arcs of the equal-parameter biarc from `p0` (unit tangent `t0`)
/// to `p1` (unit tangent `t1`): tangent-continuous at both ends and at the
/// joint. Returns the joint point and the two bulges.
fn biarc(p0: Point, t0: Point, p1: Point, t1: Point) -> (Point, f64, f64) {
    let v = p1 - p0;
    let t = t0 + t1;
    let denom = 2.0 * (1.0 - t0.dot(t1));
    // d solves |v − d·(t0 + t1)| = 2d: the two control legs have length d.
    let d = if denom.abs() < 1e-12 {
        v.norm2() / (4.0 * v.dot(t1))
    } else {
        (-v.dot(t) + (v.dot(t).powi(2) + denom * v.norm2()).sqrt()) / denom
    };
    let joint = (p0 + t0 * d + p1 - t1 * d) * 0.5;
    let (b1, tj) = arc_from_tangent(p0, t0, joint);
    let (b2, _) = arc_from_tangent(joint, tj, p1);
    (joint, b1, b2)
}

/// The closed loop of biarcs through `samples` (point, unit tangent), two
/// arcs per sample, tangent-continuous at every joint up to rounding.
fn biarc_loop(samples: &[(Point, Point)]) -> Vec<Vertex> {
    let m = samples.len();
    let mut verts = Vec::with_capacity(2 * m);
    for i in 0..m {
        let (p0, t0) = samples[i];
        let (p1, t1) = samples[(i + 1) % m];
        let (joint, b1, b2) = biarc(p0, t0, p1, t1);
        verts.push(Vertex { p: p0, bulge: b1 });
        verts.push(Vertex { p: joint, bulge: b2 });
    }
    verts
}

/// A smooth (C1) closed curve of `n` circular arcs (n rounded up to even):
/// biarcs between `n/2` points of the flower r(θ) = 1 + 0.3·sin(k·θ), with
/// k = max(7, n/20000) lobes so that arcs keep bulging beyond the default
/// tolerance at large n. Every joint is tangent-continuous up to rounding.
pub fn flower_arcs(n: usize) -> Vec<Vec<Vertex>> {
    let m = n.max(8).div_ceil(2);
    let k = (2 * m / 20_000).max(7) as f64;
    let curve = |t: f64| {
        let r = 1.0 + 0.3 * (k * t).sin();
        Point::new(r * t.cos(), r * t.sin())
    };
    let tangent = |t: f64| {
        let (r, dr) = (1.0 + 0.3 * (k * t).sin(), 0.3 * k * (k * t).cos());
        Point::new(dr * t.cos() - r * t.sin(), dr * t.sin() + r * t.cos()).unit()
    };
    let samples: Vec<(Point, Point)> =
        (0..m).map(|i| TAU * i as f64 / m as f64).map(|t| (curve(t), tangent(t))).collect();
    vec![biarc_loop(&samples)]
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

/// A `k × k` grid of cells in a square of side `k`, each holding one hole
/// at a random offset: a circle (two half arcs), a random convex polygon
/// of 3–8 vertices, or a rounded triangle (segments and arcs), chosen by
/// `seed`. Jittered so that no two augmenting disks or branch points are
/// symmetric by construction; the outer square's bottom edge has a
/// slightly lowered midpoint (a nearly flat convex corner).
pub fn random_holes(k: usize, seed: u64) -> Vec<Vec<Vertex>> {
    let k = k.max(1);
    let s = k as f64;
    let mut rng = Mix(seed ^ 0x686f_6c65);
    let p = |x: f64, y: f64| Point::new(x, y);
    let v = |q: Point, bulge: f64| Vertex { p: q, bulge };
    let mut loops = vec![vec![
        v(p(0.0, 0.0), 0.0),
        v(p(s * 0.5, -0.01 * s), 0.0),
        v(p(s, 0.0), 0.0),
        v(p(s, s), 0.0),
        v(p(0.0, s), 0.0),
    ]];
    for i in 0..k {
        for j in 0..k {
            let r = 0.12 + 0.2 * rng.next();
            let c = p(i as f64 + 0.5 + (0.4 - r) * (rng.next() - 0.5), j as f64 + 0.5 + (0.4 - r) * (rng.next() - 0.5));
            let turn = TAU * rng.next();
            let at = |a: f64, rad: f64| c + Point::new((turn + a).cos(), (turn + a).sin()) * rad;
            // Clockwise, as holes are stored (the library normalises anyway).
            let hole = match rng.below(3) {
                0 => vec![v(at(0.0, r), -1.0), v(at(TAU / 2.0, r), -1.0)],
                1 => {
                    let m = 3 + rng.below(6);
                    (0..m).map(|q| v(at(-TAU * (q as f64 + 0.3 * rng.next()) / m as f64, r), 0.0)).collect()
                }
                _ => {
                    // A triangle with its corners rounded: segment, arc, segment, ...
                    let mut out = Vec::new();
                    for q in 0..3 {
                        let a = -TAU * q as f64 / 3.0;
                        out.push(v(at(a + 0.25, r), -(0.5f64.tan() / 1.0).min(0.6) * 0.5));
                        out.push(v(at(a - 0.25, r), 0.0));
                    }
                    out
                }
            };
            loops.push(hole);
        }
    }
    loops
}

/// A 30 × 10 box whose outer loop starts at the apex of an upward spike
/// (a reflex vertex where the augmented boundary cycle begins and ends),
/// with small circular holes just above the apex: three, or with `twin`
/// two whose augmenting disks both land on the apex. `many` adds 30 holes
/// so that the cycle is long enough to be cut through ranges.
pub fn spike_holes(twin: bool, many: bool) -> Vec<Vec<Vertex>> {
    let v = |x: f64, y: f64, bulge: f64| Vertex { p: Point::new(x, y), bulge };
    let circle = |x: f64, y: f64, r: f64| vec![v(x + r, y, -1.0), v(x - r, y, -1.0)];
    let mut loops = vec![vec![
        v(5.5, 1.0, 0.0),
        v(6.0, 0.0, 0.0),
        v(30.0, 0.0, 0.0),
        v(30.0, 10.0, 0.0),
        v(0.0, 10.0, 0.0),
        v(0.0, 0.0, 0.0),
        v(5.0, 0.0, 0.0),
    ]];
    if twin {
        loops.push(circle(5.2, 2.0, 0.25));
        loops.push(circle(5.8, 2.0, 0.25));
    } else {
        loops.push(circle(5.5, 2.0, 0.5));
        loops.push(circle(4.3, 2.1, 0.3));
        loops.push(circle(6.8, 2.2, 0.3));
    }
    if many {
        for i in 0..6 {
            for j in 0..5 {
                let (x, y) = (9.0 + 3.5 * i as f64 + 0.1 * j as f64, 2.0 + 1.7 * j as f64 + 0.05 * i as f64);
                loops.push(circle(x, y, 0.4));
            }
        }
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{JointKind, Shape2d, ShapeOptions};

    #[test]
    fn fourier_curves_are_valid_smooth_and_follow_their_series() {
        for seed in 1..6 {
            let shape = Shape2d::from_bulge_loops(fourier_biarcs(2000, seed), &ShapeOptions::default())
                .unwrap_or_else(|e| panic!("seed {seed}: {e}"));
            assert_eq!(shape.element_count(), 2000);
            // Every joint is tangent-continuous, and the curve stays round
            // the origin within the radii the scaling allows.
            assert!((0..2000).all(|k| shape.joint(0, k) == JointKind::Smooth), "seed {seed}");
            for v in shape.loops()[0].vertices() {
                let r = v.p.norm();
                assert!((0.2 - 1e-9..=1.8 + 1e-9).contains(&r), "seed {seed}: radius {r}");
            }
        }
        // The same seed gives the same curve, another seed another one.
        assert_eq!(fourier_biarcs(100, 3), fourier_biarcs(100, 3));
        assert_ne!(fourier_biarcs(100, 3), fourier_biarcs(100, 4));
    }

    #[test]
    fn holes_letters_and_strips_are_valid_at_the_size_asked() {
        for seed in 1..4 {
            let opts = ShapeOptions::default();
            let holes = Shape2d::from_bulge_loops(fourier_with_holes(20_000, 40, seed), &opts).expect("valid");
            assert_eq!(holes.loops().len(), 41, "seed {seed}: every hole finds room");
            // More holes than arcs to share: the outer curve keeps half.
            let crowded = Shape2d::from_bulge_loops(fourier_with_holes(1_000, 200, seed), &opts).expect("valid");
            assert!(crowded.loops()[0].len() >= 500 && crowded.loops().len() > 1);
            assert!((19_900..=20_100).contains(&holes.element_count()), "{}", holes.element_count());
            let text = Shape2d::from_bulge_loops(text_plate(20_000, seed), &opts).expect("valid");
            assert!((17_000..=23_000).contains(&text.element_count()), "{}", text.element_count());
            // Letters have sharp turns and round joins: corners and smooth
            // joints both occur.
            let joints = text.joint_counts();
            assert!(joints[JointKind::Convex as usize] > 0 && joints[JointKind::Smooth as usize] > 0);
            for spread in [1e-3, 0.0] {
                let strip =
                    Shape2d::from_bulge_loops(nearly_straight_strip(20_000, seed, spread), &opts).expect("valid");
                assert_eq!(strip.element_count(), 20_000);
                let b = strip.bbox();
                // 0.2 apart over 5000 samples, and a half circle of radius 1/2 at each end.
                assert!((b.width() - 999.8 - 1.0).abs() < 0.1 && (b.height() - 1.0).abs() < 0.1, "{b:?}");
            }
        }
    }
}
