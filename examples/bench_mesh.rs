//! Reading and validating solids at scale (issue 19's benchmark; figures in
//! docs/PERFORMANCE.md, "Solids"): tori of 10^4–10^6 triangles, built from
//! arrays (welding, topology, orientation, nesting, facts), from binary STL
//! bytes (unshared corners: welding does the work), from OFF text and from
//! binary PLY, medians of 3 runs, with the growth exponent.
//!
//! `cargo run --release --example bench_mesh -- [threads] [max_triangles]`

use medax::io::mesh::{write_off, write_ply, MeshFormat};
use medax::shape::mesh_samples::torus;
use medax::shape::{Mesh3d, MeshOptions};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn time(f: impl Fn()) -> f64 {
    median(
        (0..3)
            .map(|_| {
                let t = Instant::now();
                f();
                t.elapsed().as_secs_f64()
            })
            .collect(),
    )
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
}
