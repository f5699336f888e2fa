//! Reading and validating solids at scale (issue 19's benchmark; figures in
//! docs/PERFORMANCE.md, "Solids"): tori of 10^4–10^6 triangles, built from
//! arrays (welding, topology, orientation, nesting, facts), from binary STL
//! bytes (unshared corners: welding does the work), from OFF text and from
//! binary PLY, medians of 3 runs, with the growth exponent.
//!
//! A second table times the tree's queries from Rust on the same tori:
//! `TriangleTree` build alone, then on the solid's tree 10^5 closest points
//! and exact inside tests, in two families of points ("near": within 0.01
//! of the surface; "box": uniform in the bounding box), and the ball radius
//! at the points found inside under `Ball3::tetrahedron()` and under the
//! hull of 66 points of a Fibonacci sphere (128 facets; the geodesic balls
//! have 80 or 320), against closest points alone and against closest
//! points and inside tests (the Euclidean query) at the same inside points
//! (ctest/bench_mesh.cpp times the C API beside CGAL on the same family).
//! A third table times the exact contacts (`exact_contacts_many`: the
//! same search, then the triangles near the answer again in exact
//! arithmetic) against the `f64` ball radius on the first 10^4 inside
//! points, with how often the floating filter had to give way.
//!
//! `cargo run --release --example bench_mesh -- [threads] [max_triangles] [exact]`
//! (`exact`: the third table and the maximal* balls only; `queries`: the
//! second table only)

use medax::io::mesh::{write_off, write_ply, MeshFormat};
use medax::kernel::Point3;
use medax::shape::mesh_samples::torus;
use medax::shape::{Ball3, ContactKind3, Mesh3d, MeshOptions, TriangleTree};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Median of 3 runs, or of the runs made once they took 20 s together.
fn time(f: impl Fn()) -> f64 {
    let mut runs = Vec::new();
    while runs.len() < 3 && runs.iter().sum::<f64>() < 20.0 {
        let t = Instant::now();
        f();
        runs.push(t.elapsed().as_secs_f64());
    }
    median(runs)
}

/// 10^5 points within 0.01 of the surface (a uniform point of a random
/// triangle moved along its normal) and 10^5 uniform in the box.
fn families(v: &[[f64; 3]], t: &[[u32; 3]], seed: u64) -> [(&'static str, Vec<Point3>); 2] {
    let mut rng = SmallRng::seed_from_u64(seed);
    let p = |i: u32| Point3::from_array(v[i as usize]);
    let near = (0..100_000)
        .map(|_| {
            let [a, b, c] = t[rng.gen_range(0..t.len())].map(p);
            let (s, w): (f64, f64) = (rng.gen::<f64>().sqrt(), rng.gen());
            let n = (b - a).cross(c - a);
            a * (1.0 - s) + b * (s * (1.0 - w)) + c * (s * w) + n * (rng.gen_range(-0.01..0.01) / n.norm())
        })
        .collect();
    let (lo, hi) = (0..3).fold(([f64::MAX; 3], [f64::MIN; 3]), |(mut lo, mut hi), k| {
        v.iter().for_each(|q| (lo[k], hi[k]) = (lo[k].min(q[k]), hi[k].max(q[k])));
        (lo, hi)
    });
    let mut coord = |k: usize| rng.gen_range(lo[k]..hi[k]);
    let in_box = (0..100_000).map(|_| Point3::new(coord(0), coord(1), coord(2))).collect();
    [("near", near), ("box", in_box)]
}

/// The hull of 66 points of a Fibonacci sphere: 2·66 − 4 = 128 facets.
fn fibonacci_ball() -> Ball3 {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let pts: Vec<Point3> = (0..66)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / 66.0;
            let r = (1.0 - z * z).sqrt();
            Point3::new(r * (golden * i as f64).cos(), r * (golden * i as f64).sin(), z)
        })
        .collect();
    Ball3::from_points(&pts).expect("the Fibonacci sphere's hull is a ball")
}

fn queries(max: usize) {
    let o = MeshOptions::default();
    let balls = [Ball3::tetrahedron(), fibonacci_ball()];
    println!(
        "\nTree queries, 10^5 points per family (balls: {} and {} facets):\n",
        balls[0].facets().len(),
        balls[1].facets().len()
    );
    println!("| triangles | points | tree build | closest | inside | inside points | closest there | inside there | tetra ball | 128-facet ball | ball / closest (tetra, 128) | ball / (closest + inside) (tetra, 128) |");
    println!("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in [10_000usize, 100_000, 1_000_000].into_iter().filter(|&n| n <= max) {
        let b = ((n / 4) as f64).sqrt().round() as usize;
        let (v, t) = torus(3.0, 1.0, 2 * b, b);
        let build = time(|| {
            TriangleTree::from_arrays(&v, &t);
        });
        let mesh = Mesh3d::from_triangles(&v, &t, &o).unwrap();
        let tree = mesh.tree();
        for (family, pts) in families(&v, &t, 20261207 + n as u64) {
            let closest = time(|| {
                tree.closest_points(&pts);
            });
            let inside_t = time(|| {
                tree.inside_many(&pts);
            });
            let sides = tree.inside_many(&pts);
            let inner: Vec<Point3> =
                pts.iter().zip(&sides).filter(|(_, s)| **s == Some(true)).map(|(p, _)| *p).collect();
            let closest_in = time(|| {
                tree.closest_points(&inner);
            });
            let inside_in = time(|| {
                tree.inside_many(&inner);
            });
            let [tetra, fib] = [0, 1].map(|k| {
                time(|| {
                    tree.ball_radii(&inner, &balls[k]);
                })
            });
            println!(
                "| {} | {family} | {build:.4} s | {closest:.4} s | {inside_t:.4} s | {} | {closest_in:.4} s | {inside_in:.4} s | {tetra:.4} s | {fib:.4} s | {:.2}, {:.2} | {:.2}, {:.2} |",
                t.len(),
                inner.len(),
                tetra / closest_in,
                fib / closest_in,
                tetra / (closest_in + inside_in),
                fib / (closest_in + inside_in)
            );
        }
    }
}

fn exact(max: usize) {
    let balls = [Ball3::tetrahedron(), fibonacci_ball()];
    println!("\nExact contacts at 10^4 inside points (\"near\" family), against the f64 ball radius:\n");
    println!(
        "| triangles | ball | f64 radius | exact contacts | ratio | non-regular contacts | flat | largest gap to f64 |"
    );
    println!("|---:|---|---:|---:|---:|---:|---:|---:|");
    for n in [10_000usize, 100_000, 1_000_000].into_iter().filter(|&n| n <= max) {
        let b = ((n / 4) as f64).sqrt().round() as usize;
        let (v, t) = torus(3.0, 1.0, 2 * b, b);
        let mesh = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
        let tree = mesh.tree();
        let [(_, pts), _] = families(&v, &t, 20261207 + n as u64);
        let sides = tree.inside_many(&pts);
        let inner: Vec<Point3> =
            pts.iter().zip(&sides).filter(|(_, s)| **s == Some(true)).map(|(p, _)| *p).take(10_000).collect();
        for (name, ball) in [("tetra", &balls[0]), ("128 facets", &balls[1])] {
            let f = time(|| {
                tree.ball_radii(&inner, ball);
            });
            let e = time(|| {
                tree.exact_contacts_many(&inner, ball);
            });
            let got = tree.exact_contacts_many(&inner, ball);
            let regular = [ContactKind3::VertexFace, ContactKind3::EdgeEdge, ContactKind3::FaceVertex];
            let odd = got.iter().flatten().filter(|x| x.contacts.iter().any(|c| !regular.contains(&c.kind))).count();
            let flat = got.iter().flatten().filter(|x| x.flat).count();
            let radii = tree.ball_radii(&inner, ball);
            let gap = got
                .iter()
                .zip(&radii)
                .map(|(x, r)| match (x, r) {
                    (Some(x), Some(r)) => (x.radius - r.radius).abs(),
                    _ => f64::INFINITY,
                })
                .fold(0.0, f64::max);
            println!("| {} | {name} | {f:.4} s | {e:.4} s | {:.1} | {odd} | {flat} | {gap:.1e} |", t.len(), e / f);
        }
    }
}

/// Maximal* balls at 10^4 surface points (a random point of a random
/// triangle, a random ball vertex), `f64` against exact: time, how many
/// grew, and the largest gap between their radii (absolute: the `f64`
/// error is rounding of coordinates of size 4, about 10^-16 each, which
/// is large against the radii near the surface).
fn maximal(max: usize) {
    let balls = [Ball3::tetrahedron(), fibonacci_ball()];
    println!("\nMaximal* balls at 10^4 surface points, f64 against exact:\n");
    println!("| triangles | ball | f64 | exact | ratio | grown | exact contacts per ball | radii apart by > 1e-9 | largest gap to f64 |");
    println!("|---:|---|---:|---:|---:|---:|---:|---:|---:|");
    for n in [10_000usize, 100_000, 1_000_000].into_iter().filter(|&n| n <= max) {
        let b = ((n / 4) as f64).sqrt().round() as usize;
        let (v, t) = torus(3.0, 1.0, 2 * b, b);
        let mesh = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
        let tree = mesh.tree();
        let mut rng = SmallRng::seed_from_u64(54 + n as u64);
        for (name, ball) in [("tetra", &balls[0]), ("128 facets", &balls[1])] {
            // A point of a triangle by its parameters: exact on the plane
            // for `maximal_ball_exact_on`, rounded for the f64 query.
            let asked: Vec<(usize, (f64, f64), Point3, usize)> = (0..10_000)
                .map(|_| {
                    let tri = rng.gen_range(0..t.len());
                    let [a, b, c] = t[tri].map(|i| Point3::from_array(v[i as usize]));
                    let (s, w): (f64, f64) = (rng.gen::<f64>().sqrt(), rng.gen());
                    let uv = (s * (1.0 - w), s * w);
                    (tri, uv, a + (b - a) * uv.0 + (c - a) * uv.1, rng.gen_range(0..ball.vertices().len()))
                })
                .collect();
            let reach = ball.reach();
            let f = time(|| {
                asked.iter().for_each(|&(_, _, p, k)| {
                    tree.maximal_ball_with(p, k, &reach);
                })
            });
            let e = time(|| {
                asked.iter().for_each(|&(tri, uv, _, k)| {
                    tree.maximal_ball_exact_on(t[tri].map(|i| Point3::from_array(v[i as usize])), uv, k, &reach);
                })
            });
            let (mut grown, mut contacts, mut gap, mut differ) = (0usize, 0usize, 0.0f64, 0usize);
            for &(tri, uv, p, k) in &asked {
                let (x, y) = (
                    tree.maximal_ball_with(p, k, &reach).unwrap(),
                    tree.maximal_ball_exact_on(t[tri].map(|i| Point3::from_array(v[i as usize])), uv, k, &reach),
                );
                let Some(y) = y else {
                    gap = f64::INFINITY;
                    continue;
                };
                if x.radius > 0.0 && x.radius.is_finite() {
                    grown += 1;
                    contacts += y.opposite.len();
                    gap = gap.max((x.radius - y.radius).abs());
                    differ += ((x.radius - y.radius).abs() > 1e-9 * y.radius) as usize;
                }
            }
            let per = contacts as f64 / grown.max(1) as f64;
            println!(
                "| {} | {name} | {f:.3} s | {e:.3} s | {:.1} | {grown} | {per:.2} | {differ} | {gap:.1e} |",
                t.len(),
                e / f
            );
        }
    }
}

fn stl(v: &[[f64; 3]], t: &[[u32; 3]]) -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out.extend((t.len() as u32).to_le_bytes());
    for tri in t {
        out.extend([0u8; 12]);
        for &i in tri {
            for c in v[i as usize] {
                out.extend((c as f32).to_le_bytes());
            }
        }
        out.extend([0u8; 2]);
    }
    out
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let threads: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0);
    let max: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1_000_000);
    if threads > 0 {
        rayon::ThreadPoolBuilder::new().num_threads(threads).build_global().unwrap();
    }
    if args.get(3).map(String::as_str) == Some("exact") {
        exact(max);
        maximal(max);
        return;
    }
    if args.get(3).map(String::as_str) == Some("queries") {
        queries(max);
        return;
    }
    println!("| triangles | arrays | binary STL | OFF | binary PLY | µs per triangle (arrays) |");
    println!("|---:|---:|---:|---:|---:|---:|");
    let o = MeshOptions::default();
    let mut points = Vec::new();
    for n in [10_000usize, 100_000, 1_000_000].into_iter().filter(|&n| n <= max) {
        // 2·a·b triangles with a = 2b.
        let b = ((n / 4) as f64).sqrt().round() as usize;
        let (v, t) = torus(3.0, 1.0, 2 * b, b);
        let arrays = time(|| {
            Mesh3d::from_triangles(&v, &t, &o).unwrap();
        });
        let stl_bytes = stl(&v, &t);
        let stl_t = time(|| {
            Mesh3d::from_bytes(&stl_bytes, Some(MeshFormat::Stl), &o).unwrap();
        });
        let off = write_off(&v, &t);
        let off_t = time(|| {
            Mesh3d::from_bytes(off.as_bytes(), Some(MeshFormat::Off), &o).unwrap();
        });
        let ply = write_ply(&v, &t, true);
        let ply_t = time(|| {
            Mesh3d::from_bytes(&ply, Some(MeshFormat::Ply), &o).unwrap();
        });
        println!(
            "| {} | {arrays:.3} s | {stl_t:.3} s | {off_t:.3} s | {ply_t:.3} s | {:.2} |",
            t.len(),
            arrays * 1e6 / t.len() as f64
        );
        points.push((t.len() as f64, arrays));
    }
    if points.len() >= 2 {
        let (a, b) = (points[0], points[points.len() - 1]);
        println!("growth exponent (arrays): {:.2}", (b.1 / a.1).ln() / (b.0 / a.0).ln());
    }
    queries(max);
    exact(max);
    maximal(max);
}
