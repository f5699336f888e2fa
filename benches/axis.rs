//! The whole medial axis (divide, base cases, conquer) per element on
//! smooth biarc flowers and random star polygons, 1 and 2 threads, with
//! the share of the divide step. `cargo bench --bench axis`. Figures go to
//! docs/PERFORMANCE.md. Sizes stop where the divide step (whose `maxdisk*`
//! slides still cost a nearest-element query per step) makes a run longer
//! than a few seconds, or where the axis still breaks down.

use medax::plane::divide::decompose_with;
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{samples, Shape2d, ShapeOptions, Vertex};
use std::time::Instant;

fn main() {
    type Gen = fn(usize) -> Vec<Vec<Vertex>>;
    let kinds: [(&str, Gen, &[usize]); 2] = [
        ("flower arcs (C1)", samples::flower_arcs, &[1_000, 3_000, 10_000, 30_000]),
        ("star polygon", |n| samples::star_polygon(n, 3), &[1_000, 3_000, 10_000]),
    ];
    println!("| shape | n | threads | axis | µs per element | divide share | nodes |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (name, gen, sizes) in kinds {
        for &n in sizes {
            let s = Shape2d::from_bulge_loops(gen(n), &ShapeOptions::default()).expect("samples are valid");
            for threads in [1, 2] {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("pool");
                let t = Instant::now();
                let axis = pool.install(|| medial_axis(&s, &AxisOptions::default()));
                let total = t.elapsed().as_secs_f64();
                let t = Instant::now();
                let d = decompose_with(&s, AxisOptions::default().seed, AxisOptions::default().leaf_parts);
                let divide = t.elapsed().as_secs_f64();
                let nodes = match (&axis, d.cuts.is_empty()) {
                    (Ok(a), _) => a.nodes.len().to_string(),
                    (Err(e), _) => format!("failed: {e}"),
                };
                println!(
                    "| {name} | {} | {threads} | {:.3} s | {:.1} | {:.0} % | {nodes} |",
                    s.element_count(),
                    total,
                    total * 1e6 / s.element_count() as f64,
                    100.0 * (divide / total).min(1.0)
                );
            }
        }
    }
}
