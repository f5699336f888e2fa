//! The triangle tree's queries against oracles that share nothing with
//! it: brute force over all triangles with other formulas (closest
//! points, rays), analytic solids and solid-angle sums (inside), and an
//! exact rational search for common points (self-intersections).

use medax::kernel::{BBox3, Point3};
use medax::shape::mesh_samples::{cuboid, sphere, torus, union, Soup};
use medax::shape::TriangleTree;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;

fn points(soup: &Soup) -> Vec<Point3> {
    soup.0.iter().map(|&p| Point3::from_array(p)).collect()
}

fn corners(soup: &Soup, t: usize) -> [Point3; 3] {
    soup.1[t].map(|v| Point3::from_array(soup.0[v as usize]))
}

/// A torus, a sphere in its hole and a box beside it: three disjoint
/// closed surfaces.
fn scene(n: usize) -> Soup {
    union(&[torus(3.0, 1.0, 2 * n, n), sphere([0.0, 0.0, 0.0], 1.5, n, n), cuboid([5.0, 5.0, -1.0], [7.0, 7.0, 1.0])])
}

fn random_in(rng: &mut SmallRng, b: BBox3, margin: f64) -> Point3 {
    let mut c = |lo: f64, hi: f64| rng.gen_range(lo - margin..hi + margin);
    Point3::new(c(b.min.x, b.max.x), c(b.min.y, b.max.y), c(b.min.z, b.max.z))
}

/// Distance² from `p` to the segment `ab`.
fn segment_distance2(p: Point3, a: Point3, b: Point3) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.norm2()).clamp(0.0, 1.0);
    (a + ab * t - p).norm2()
}

/// Distance² from `p` to a triangle: to its plane when the foot lies
/// inside, else to the nearest edge.
fn triangle_distance2(p: Point3, [a, b, c]: [Point3; 3]) -> f64 {
    let n = (b - a).cross(c - a);
    let foot = p - n * ((p - a).dot(n) / n.norm2());
    let inside = [(a, b), (b, c), (c, a)].iter().all(|&(u, v)| (v - u).cross(foot - u).dot(n) >= 0.0);
    if inside {
        (foot - p).norm2()
    } else {
        segment_distance2(p, a, b).min(segment_distance2(p, b, c)).min(segment_distance2(p, c, a))
    }
}

#[test]
fn closest_points_match_brute_force() {
    let soup = scene(12);
    let tree = TriangleTree::from_arrays(&soup.0, &soup.1);
    let mut rng = SmallRng::seed_from_u64(1);
    let queries: Vec<Point3> = (0..10_000).map(|_| random_in(&mut rng, tree.bbox(), 1.0)).collect();
    let found = tree.closest_points(&queries);
    queries.par_iter().zip(&found).for_each(|(&p, c)| {
        let c = c.expect("a closest point");
        let best = (0..soup.1.len()).map(|t| triangle_distance2(p, corners(&soup, t))).fold(f64::INFINITY, f64::min);
        // 1e-12 relative, except that a constructed point carries the
        // rounding of its coordinates (δ ≈ 1e-15 at this scale), which
        // moves the squared distance by about 2·d·δ close to the surface.
        let tol = 1e-12 * best + 1e-14 * best.sqrt();
        assert!((c.squared_distance - best).abs() <= tol, "{p:?}: {} vs {best}", c.squared_distance);
        assert!(((c.point - p).norm2() - c.squared_distance).abs() <= tol);
        assert!(triangle_distance2(c.point, corners(&soup, c.triangle as usize)) <= 1e-24);
    });
}

/// Ray parameter of the hit with the triangle's plane, if the hit lies
/// inside it (barycentric coordinates from areas).
fn ray_plane_hit(o: Point3, d: Point3, [a, b, c]: [Point3; 3]) -> Option<f64> {
    let n = (b - a).cross(c - a);
    let t = (a - o).dot(n) / d.dot(n);
    if !t.is_finite() || t < 0.0 {
        return None;
    }
    let x = o + d * t;
    let inside = [(a, b), (b, c), (c, a)].iter().all(|&(u, v)| (v - u).cross(x - u).dot(n) >= 0.0);
    inside.then_some(t)
}

#[test]
fn first_hits_match_brute_force() {
    let soup = scene(16);
    let tree = TriangleTree::from_arrays(&soup.0, &soup.1);
    let mut rng = SmallRng::seed_from_u64(2);
    let mut hits = 0;
    for _ in 0..3000 {
        let o = random_in(&mut rng, tree.bbox(), 2.0);
        // Toward a random point of the scene's box, to hit often.
        let d = random_in(&mut rng, tree.bbox(), 0.0) - o;
        let best = (0..soup.1.len())
            .filter_map(|t| ray_plane_hit(o, d, corners(&soup, t)))
            .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.min(t))));
        match (tree.first_hit(o, d), best) {
            (None, None) => {}
            (Some(h), Some(t)) => {
                assert!((h.t - t).abs() <= 1e-9 * t.max(1.0), "{o:?} {d:?}: {} vs {t}", h.t);
                assert!((h.point - (o + d * h.t)).norm() <= 1e-12 * (1.0 + h.t));
                assert!(ray_plane_hit(o, d, corners(&soup, h.triangle as usize)).is_some());
                hits += 1;
            }
            (h, t) => panic!("{o:?} {d:?}: tree {h:?}, brute force {t:?}"),
        }
    }
    assert!(hits > 1000, "{hits}");
}

/// Generalized winding number (sum of solid angles, `f64`): about 1
/// inside a closed outward surface, 0 outside.
fn winding_number(soup: &Soup, p: Point3) -> f64 {
    let total: f64 = (0..soup.1.len())
        .map(|t| {
            let [a, b, c] = corners(soup, t).map(|v| v - p);
            let (la, lb, lc) = (a.norm(), b.norm(), c.norm());
            let den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
            2.0 * a.dot(b.cross(c)).atan2(den)
        })
        .sum();
    total / (4.0 * std::f64::consts::PI)
}

/// Crossings of the ray `o + t·d` with the surface, counted in `f64`;
/// `None` when a hit comes near an edge or the ray nearly grazes a
/// triangle, where rounding could miscount.
fn ray_parity(soup: &Soup, o: Point3, d: Point3) -> Option<bool> {
    let mut odd = false;
    for t in 0..soup.1.len() {
        let [a, b, c] = corners(soup, t);
        let n = (b - a).cross(c - a);
        let along = d.dot(n);
        if along.abs() < 1e-9 * d.norm() * n.norm() {
            return None;
        }
        let s = (a - o).dot(n) / along;
        if s.abs() < 1e-9 {
            return None;
        }
        if s < 0.0 {
            continue;
        }
        let x = o + d * s;
        let w = [(a, b), (b, c), (c, a)].map(|(u, v)| (v - u).cross(x - u).dot(n) / n.norm2());
        if w.iter().all(|&w| w > 1e-9) {
            odd = !odd;
        } else if w.iter().all(|&w| w > -1e-9) {
            return None;
        }
    }
    Some(odd)
}

#[test]
fn inside_matches_analytic_solids_and_winding_numbers() {
    let n = 24;
    let soup = scene(n);
    let tree = TriangleTree::from_arrays(&soup.0, &soup.1);
    // The facets lie within this band around the smooth surfaces.
    let step = std::f64::consts::PI / n as f64;
    let band = 4.0 * (1.0 - step.cos()) * 2.0 + 1e-9;
    let mut rng = SmallRng::seed_from_u64(3);
    let (mut counts, mut near) = ([0; 2], 0);
    let queries: Vec<Point3> = (0..4000).map(|_| random_in(&mut rng, tree.bbox(), 0.5)).collect();
    let answers = tree.inside_many(&queries);
    for (&p, &answer) in queries.iter().zip(&answers) {
        let tube = ((p.x * p.x + p.y * p.y).sqrt() - 3.0).hypot(p.z) - 1.0;
        let ball = p.norm() - 1.5;
        let boxed = [(p.x, 5.0, 7.0), (p.y, 5.0, 7.0), (p.z, -1.0, 1.0)]
            .iter()
            .map(|&(v, lo, hi)| (lo - v).max(v - hi))
            .fold(f64::NEG_INFINITY, f64::max);
        let analytic = [tube, ball, boxed];
        if analytic.iter().any(|d| d.abs() < band) {
            // Near the facets: brute-force parity along a few rays, and
            // the solid angles.
            let parity = (0..8).find_map(|_| {
                let d = Point3::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
                ray_parity(&soup, p, d)
            });
            assert_eq!(answer, Some(parity.expect("a clean ray")), "{p:?}");
            let w = winding_number(&soup, p);
            if (w - w.round()).abs() < 1e-6 {
                assert_eq!(answer, Some(w.round() == 1.0), "{p:?}: winding number {w}");
            }
            near += 1;
            continue;
        }
        let expected = analytic.iter().any(|&d| d < 0.0);
        assert_eq!(answer, Some(expected), "{p:?}");
        counts[expected as usize] += 1;
    }
    assert!(counts.iter().all(|&c| c > 200) && near > 100, "{counts:?} {near}");
}

#[test]
fn points_on_the_surface_have_no_side_and_cavities_are_outside() {
    let outer = cuboid([0.0, 0.0, 0.0], [4.0, 4.0, 4.0]);
    let mut cavity = cuboid([1.0, 1.0, 1.0], [3.0, 3.0, 3.0]);
    cavity.1.iter_mut().for_each(|t| t.swap(1, 2));
    let soup = union(&[outer, cavity]);
    let tree = TriangleTree::from_arrays(&soup.0, &soup.1);
    let p = Point3::new;
    for on in
        [p(0.0, 0.0, 0.0), p(2.0, 2.0, 4.0), p(4.0, 1.0, 2.5), p(2.0, 2.0, 0.0), p(1.0, 2.0, 2.0), p(3.0, 3.0, 1.5)]
    {
        assert_eq!(tree.inside(on), None, "{on:?}");
    }
    assert_eq!(tree.inside(p(0.5, 0.5, 0.5)), Some(true));
    assert_eq!(tree.inside(p(2.0, 2.0, 2.0)), Some(false));
    assert_eq!(tree.inside(p(3.5, 2.0, 2.0)), Some(true));
    // In the planes of faces and of diagonals, off the surface.
    assert_eq!(tree.inside(p(5.0, 2.0, 4.0)), Some(false));
    assert_eq!(tree.inside(p(0.5, 0.5, 3.0)), Some(true));
    assert_eq!(tree.inside(p(2.0, 2.0, 3.5)), Some(true));
    assert_eq!(tree.inside(p(-1e-300, 2.0, 2.0)), Some(false));
    assert_eq!(tree.inside(p(1e-300, 2.0, 2.0)), Some(true));
}

// An exact oracle for self-intersections: the points common to two
// triangles are the solutions `x ≥ 0` of a linear system in their
// barycentric coordinates; its corners (basic feasible solutions) come
// from every square subsystem solved exactly in rationals. Coordinates
// must be small integers.

type Q = (i128, i128);

fn q(n: i128, d: i128) -> Q {
    fn gcd(a: i128, b: i128) -> i128 {
        if b == 0 {
            a.abs()
        } else {
            gcd(b, a % b)
        }
    }
    let g = gcd(n, d).max(1) * d.signum();
    (n / g, d / g)
}

/// Corners of `{λ, μ ≥ 0 : Σ λ_i a_i = Σ μ_j b_j, Σ λ = 1, Σ μ = 1}`.
fn common_corners(a: [[i128; 3]; 3], b: [[i128; 3]; 3]) -> Vec<Vec<Q>> {
    let cols: Vec<[i128; 5]> = (0..6)
        .map(|j| {
            let (p, s) = if j < 3 { (a[j], 1) } else { (b[j - 3], -1) };
            [s * p[0], s * p[1], s * p[2], (j < 3) as i128, (j >= 3) as i128]
        })
        .collect();
    let rhs = [0, 0, 0, 1, 1];
    let mut out = Vec::new();
    'subsets: for mask in 1u32..64 {
        let s: Vec<usize> = (0..6).filter(|&j| mask >> j & 1 == 1).collect();
        let k = s.len();
        let mut m: Vec<Vec<Q>> =
            (0..5).map(|r| s.iter().map(|&j| q(cols[j][r], 1)).chain([q(rhs[r], 1)]).collect()).collect();
        for c in 0..k {
            let Some(r) = (c..5).find(|&r| m[r][c].0 != 0) else { continue 'subsets };
            m.swap(c, r);
            let pv = m[c][c];
            m[c] = m[c].iter().map(|&v| q(v.0 * pv.1, v.1 * pv.0)).collect();
            for r in (0..5).filter(|&r| r != c) {
                let f = m[r][c];
                m[r] = (0..=k)
                    .map(|j| q(m[r][j].0 * f.1 * m[c][j].1 - f.0 * m[c][j].0 * m[r][j].1, m[r][j].1 * f.1 * m[c][j].1))
                    .collect();
            }
        }
        if (k..5).any(|r| m[r][k].0 != 0) || (0..k).any(|c| m[c][k].0 < 0) {
            continue;
        }
        let mut x = vec![q(0, 1); 6];
        for (c, &j) in s.iter().enumerate() {
            x[j] = m[c][k];
        }
        out.push(x);
    }
    out
}

/// Every pair that meets other than at shared corners, by the oracle.
fn expected_pairs(soup: &Soup) -> Vec<(u32, u32)> {
    let int = |t: usize| soup.1[t].map(|v| soup.0[v as usize].map(|c| c as i128));
    let mut out = Vec::new();
    for i in 0..soup.1.len() {
        for j in i + 1..soup.1.len() {
            let (ti, tj) = (soup.1[i], soup.1[j]);
            let shared: Vec<usize> = (0..3).filter(|&k| tj.contains(&ti[k])).collect();
            let c = common_corners(int(i), int(j));
            // Beyond shared corners: some common point gives weight to a
            // corner of `i` that is not shared.
            let meets = c.iter().any(|x| (0..3).any(|k| !shared.contains(&k) && x[k].0 > 0));
            if meets {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}

fn self_intersections(soup: &Soup) -> Vec<(u32, u32)> {
    TriangleTree::from_arrays(&soup.0, &soup.1).self_intersections(usize::MAX)
}

#[test]
fn generated_closed_surfaces_do_not_cross_themselves() {
    let soup = scene(160);
    assert!(soup.1.len() >= 100_000, "{}", soup.1.len());
    assert_eq!(self_intersections(&soup), vec![]);
    assert_eq!(self_intersections(&cuboid([0.0; 3], [1.0; 3])), vec![]);
}

/// A tetrahedron with corner `o` and legs of length `s` along the axes,
/// facing outward: faces x = o.x, y = o.y, z = o.z, then the slanted one.
fn tetrahedron(o: [f64; 3], s: f64) -> Soup {
    let v = vec![o, [o[0] + s, o[1], o[2]], [o[0], o[1] + s, o[2]], [o[0], o[1], o[2] + s]];
    (v, vec![[0, 3, 2], [0, 1, 3], [0, 2, 1], [1, 2, 3]])
}

#[test]
fn crossing_solids_give_exactly_the_crossing_pairs() {
    // The second tetrahedron's corner lies inside the first: its three
    // faces at that corner cross the first one's slanted face, nothing else.
    let tetras = union(&[tetrahedron([0.0; 3], 4.0), tetrahedron([1.0; 3], 4.0)]);
    assert_eq!(self_intersections(&tetras), vec![(3, 4), (3, 5), (3, 6)]);
    assert_eq!(expected_pairs(&tetras), vec![(3, 4), (3, 5), (3, 6)]);
    let boxes = union(&[cuboid([0.0; 3], [2.0; 3]), cuboid([1.0; 3], [3.0; 3])]);
    let expected = expected_pairs(&boxes);
    assert!(expected.len() >= 6, "{expected:?}");
    assert_eq!(self_intersections(&boxes), expected);
    // The limit cuts the list.
    assert_eq!(TriangleTree::from_arrays(&boxes.0, &boxes.1).self_intersections(2).len(), 2);
}

#[test]
fn a_corner_pushed_through_the_opposite_face() {
    let mut cube = cuboid([0.0; 3], [4.0; 3]);
    cube.0[7] = [1.0, 2.0, -2.0];
    let expected = expected_pairs(&cube);
    assert!(!expected.is_empty());
    assert!(expected.iter().all(|&(a, b)| cube.1[a as usize].contains(&7) || cube.1[b as usize].contains(&7)));
    assert_eq!(self_intersections(&cube), expected);
}

#[test]
fn touching_coplanar_and_folded_triangles() {
    let tri =
        |t: [[f64; 3]; 3], u: [[f64; 3]; 3]| -> Soup { (t.into_iter().chain(u).collect(), vec![[0, 1, 2], [3, 4, 5]]) };
    let base = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]];
    // Coplanar and overlapping; coplanar and apart.
    assert_eq!(self_intersections(&tri(base, [[1.0, 1.0, 0.0], [5.0, 1.0, 0.0], [1.0, 5.0, 0.0]])), vec![(0, 1)]);
    assert_eq!(self_intersections(&tri(base, [[3.0, 3.0, 0.0], [5.0, 3.0, 0.0], [3.0, 5.0, 0.0]])), vec![]);
    // A corner of one inside the other: touching counts.
    assert_eq!(self_intersections(&tri(base, [[1.0, 1.0, 0.0], [1.0, 1.0, 3.0], [2.0, 1.0, 3.0]])), vec![(0, 1)]);
    assert_eq!(self_intersections(&tri(base, [[1.0, 1.0, 0.5], [1.0, 1.0, 3.0], [2.0, 1.0, 3.0]])), vec![]);
    // Sharing an edge: folded onto each other, flat, creased.
    let pair = |third: [f64; 3]| -> Soup { (vec![base[0], base[1], base[2], third], vec![[0, 1, 2], [1, 0, 3]]) };
    assert_eq!(self_intersections(&pair([1.0, 1.0, 0.0])), vec![(0, 1)]);
    assert_eq!(self_intersections(&pair([1.0, -1.0, 0.0])), vec![]);
    assert_eq!(self_intersections(&pair([1.0, 1.0, 1.0])), vec![]);
    for third in [[1.0, 1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 1.0]] {
        assert_eq!(self_intersections(&pair(third)), expected_pairs(&pair(third)));
    }
}

/// Timings on a million triangles: `cargo test --release --test
/// mesh_queries -- --ignored --nocapture`.
#[test]
#[ignore]
fn timings_on_a_million_triangles() {
    use std::time::Instant;
    let soup = torus(3.0, 1.0, 1000, 500);
    let positions = points(&soup);
    let start = Instant::now();
    let tree = TriangleTree::new(&positions, &soup.1);
    let build = start.elapsed();
    let mut rng = SmallRng::seed_from_u64(4);
    let queries: Vec<Point3> = (0..100_000).map(|_| random_in(&mut rng, tree.bbox(), 0.5)).collect();
    let start = Instant::now();
    let closest = tree.closest_points(&queries);
    let closest_time = start.elapsed();
    // Points within 0.01 of the surface, the common case for offsets.
    let near: Vec<Point3> = (0..100_000)
        .map(|i| positions[i * 7 % positions.len()] + random_in(&mut rng, BBox3::of([Point3::default()]), 0.01))
        .collect();
    let start = Instant::now();
    tree.closest_points(&near);
    let near_time = start.elapsed();
    let start = Instant::now();
    let inside = tree.inside_many(&queries);
    let inside_time = start.elapsed();
    let start = Instant::now();
    let crossings = tree.self_intersections(10);
    let cross_time = start.elapsed();
    println!(
        "{} triangles, {} threads: build {build:?}, index {} bytes/triangle, 1e5 closest points {closest_time:?} (near the surface: {near_time:?}), \
         1e5 inside {inside_time:?}, self-intersections {cross_time:?}",
        soup.1.len(),
        rayon::current_num_threads(),
        tree.index_bytes() / soup.1.len(),
    );
    assert!(crossings.is_empty());
    assert!(closest.iter().all(|c| c.is_some()) && inside.iter().filter(|i| **i == Some(true)).count() > 1000);
}
