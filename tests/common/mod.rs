//! Shape builders shared by the integration tests.
#![allow(dead_code)]

pub mod ball_oracle;
pub mod c_header;
pub mod ffi;
pub mod maximal_oracle;
pub mod offset_oracle;
pub mod oracle;
pub mod rational;
pub mod solids;

use medax::kernel::Point;
use medax::plane::{AxisNode, MedialAxis2d};
use medax::shape::Vertex;
use rand::{Rng, SeedableRng};
use std::f64::consts::TAU;

pub fn v(x: f64, y: f64, bulge: f64) -> Vertex {
    Vertex { p: Point::new(x, y), bulge }
}

pub fn poly(pts: &[(f64, f64)]) -> Vec<Vertex> {
    pts.iter().map(|&(x, y)| v(x, y, 0.0)).collect()
}

/// A counter-clockwise axis-aligned rectangle.
pub fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<Vertex> {
    poly(&[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
}

/// A circle as two counter-clockwise half arcs.
pub fn circle(cx: f64, cy: f64, r: f64) -> Vec<Vertex> {
    vec![v(cx + r, cy, 1.0), v(cx - r, cy, 1.0)]
}

/// A random star-shaped polygon around the origin: simple by construction
/// (distinct sorted angles, positive radii).
pub fn star(n: usize, seed: u64) -> Vec<Vertex> {
    let mut rng = rand::rngs::SmallRng::seed_from_u64(seed);
    let mut angles: Vec<f64> = (0..n).map(|_| rng.gen_range(0.0..TAU)).collect();
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    angles
        .iter()
        .map(|&a| {
            let r = rng.gen_range(0.3..1.0);
            v(r * a.cos(), r * a.sin(), 0.0)
        })
        .collect()
}

/// Exact orientation sign of r relative to p→q, by integer-free brute force
/// in extended precision: the inputs are small dyadic numbers in these tests,
/// so f64 products and sums stay exact except near degeneracy, which the
/// generator avoids by perturbation.
fn orient(p: Point, q: Point, r: Point) -> f64 {
    (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)
}

fn segments_meet(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (o1, o2, o3, o4) = (orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b));
    o1 * o2 <= 0.0 && o3 * o4 <= 0.0
}

/// O(n²) oracle for polygons: does any pair of non-adjacent edges meet?
/// Independent of medax's index, tolerances and predicates.
pub fn polygon_self_intersects(p: &[Vertex]) -> bool {
    let n = p.len();
    for i in 0..n {
        for j in i + 1..n {
            if j == i + 1 || (i == 0 && j == n - 1) {
                continue;
            }
            let (a, b) = (p[i].p, p[(i + 1) % n].p);
            let (c, d) = (p[j].p, p[(j + 1) % n].p);
            if segments_meet(a, b, c, d) {
                return true;
            }
        }
    }
    false
}

/// A validated shape (panics on invalid test input).
pub fn shape(loops: Vec<Vec<Vertex>>) -> medax::shape::Shape2d {
    medax::shape::Shape2d::from_bulge_loops(loops, &medax::shape::ShapeOptions::default()).expect("valid test shape")
}

/// Distance from `p` to the whole boundary, by scanning every element: an
/// oracle that shares nothing with the library's searches.
pub fn boundary_distance(s: &medax::shape::Shape2d, p: Point) -> f64 {
    s.loops().iter().flat_map(|l| l.elements()).map(|e| e.closest_point(p).0).fold(f64::INFINITY, f64::min)
}

/// Inside the shape by winding numbers with the exact kernel.
pub fn inside(s: &medax::shape::Shape2d, p: Point) -> bool {
    let k = medax::kernel::FilteredKernel;
    s.loops().iter().map(|l| l.winding_number(&k, p)).sum::<i32>() == 1
}

/// The largest t for which the disk of radius t at `p + t·n` stays inside
/// the boundary (distance from its centre at least t, up to rounding of
/// coordinates: 1e-12 × `diag`), by bisection on [`boundary_distance`].
pub fn bisected_radius(s: &medax::shape::Shape2d, p: Point, n: Point, diag: f64) -> f64 {
    bisect_radius(|q| boundary_distance(s, q), p, n, 4.0 * diag, diag)
}

/// The largest t ≤ `reach` for which `distance(p + t·n) ≥ t` up to
/// 1e-12 × `diag`: doubled from 1e-9 × `diag` while it fits, then 80
/// bisection steps.
pub fn bisect_radius(distance: impl Fn(Point) -> f64, p: Point, n: Point, reach: f64, diag: f64) -> f64 {
    let fits = |t: f64| distance(p + n * t) >= t - 1e-12 * diag;
    // Grown from below first (the disks along the normal are nested, so
    // `fits` holds up to the answer and fails beyond): centres far beyond
    // the answer make a nearest-item search sweep most of a grid.
    let (mut lo, mut hi) = (0.0, 1e-9 * diag);
    while hi < reach && fits(hi) {
        lo = hi;
        hi *= 2.0;
    }
    hi = hi.min(reach);
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Asserts that `got` is the axis `want` of a moved copy of its shape,
/// `back` taking each node of `got` (centre, radius) back to where `want`
/// has it: as many nodes and edges, each node within `tol` (in position and
/// radius) of its own node of the same kind in `want` (so the radii are
/// alike as multisets too), and the edges joining the nodes their ends are
/// taken to.
pub fn same_axis_moved(
    want: &MedialAxis2d,
    got: &MedialAxis2d,
    back: impl Fn(Point, f64) -> (Point, f64),
    tol: f64,
    what: &str,
) {
    let counts = |a: &MedialAxis2d| (a.nodes.len(), a.edges.len());
    assert_eq!(counts(got), counts(want), "{what}: (nodes, edges)");
    let taken: Vec<usize> = got
        .nodes
        .iter()
        .map(|n| {
            let (p, r) = back(n.point, n.radius);
            let gap = |m: &AxisNode| (m.point.x - p.x).abs().max((m.point.y - p.y).abs()).max((m.radius - r).abs());
            let same_kind = want.nodes.iter().enumerate().filter(|(_, m)| m.kind == n.kind);
            let (i, g) =
                same_kind.map(|(i, m)| (i, gap(m))).min_by(|x, y| x.1.total_cmp(&y.1)).unwrap_or((0, f64::INFINITY));
            assert!(
                g <= tol,
                "{what}: {:?} node at {p:?} radius {r} has no counterpart (nearest off by {g:e})",
                n.kind
            );
            i
        })
        .collect();
    let mut once = taken.clone();
    once.sort_unstable();
    once.dedup();
    assert_eq!(once.len(), taken.len(), "{what}: two nodes taken to one");
    let pairs = |ends: Vec<(usize, usize)>| {
        let mut e: Vec<(usize, usize)> = ends.into_iter().map(|(a, b)| (a.min(b), a.max(b))).collect();
        e.sort_unstable();
        e
    };
    let moved = pairs(got.edges.iter().map(|e| (taken[e.from], taken[e.to])).collect());
    assert_eq!(moved, pairs(want.edges.iter().map(|e| (e.from, e.to)).collect()), "{what}: edges");
}

/// Two 4 × 4 squares joined by a neck of half-width `w` and length 2.
pub fn square_dumbbell(w: f64) -> Vec<Vertex> {
    poly(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 2.0 - w),
        (6.0, 2.0 - w),
        (6.0, 0.0),
        (10.0, 0.0),
        (10.0, 4.0),
        (6.0, 4.0),
        (6.0, 2.0 + w),
        (4.0, 2.0 + w),
        (4.0, 4.0),
        (0.0, 4.0),
    ])
}

/// Two disks of radius `r` with centres 6 apart joined by a neck of
/// half-width `w`: two segments and two major arcs.
pub fn disk_dumbbell(r: f64, w: f64) -> Vec<Vertex> {
    let x1 = (r * r - w * w).sqrt();
    let beta = (w / r).asin();
    let bulge = 1.0 / (beta / 2.0).tan();
    vec![v(x1, -w, 0.0), v(6.0 - x1, -w, bulge), v(6.0 - x1, w, 0.0), v(x1, w, bulge)]
}

/// A 6 × 2 stadium: two half circles and two segments.
pub fn stadium() -> Vec<Vertex> {
    vec![v(0.0, 0.0, 0.0), v(4.0, 0.0, 1.0), v(4.0, 2.0, 0.0), v(0.0, 2.0, 1.0)]
}

/// The loops of the CLI's embedded demo shape.
pub fn demo_shape() -> Vec<Vec<Vertex>> {
    let text =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/src/cli/demo_shape.json")).expect("demo shape");
    let s =
        medax::shape::Shape2d::from_json_str(&text, &medax::shape::ShapeOptions::default()).expect("demo shape valid");
    s.loops().iter().map(|l| l.vertices().to_vec()).collect()
}

/// The DXF files under `root`, recursively, sorted (case-insensitive
/// extension).
pub fn dxf_files(root: &std::path::Path) -> Vec<std::path::PathBuf> {
    let mut files = Vec::new();
    let mut dirs = vec![root.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            let p = entry.path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.extension().is_some_and(|e| e.eq_ignore_ascii_case("dxf")) {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}
