//! The whole medial axis (divide, base cases, conquer, final checks) per
//! element on smooth biarc flowers and random star polygons, 1 and 2
//! threads, with the share of the divide step, and the growth exponent
//! (least-squares slope of log time over log n, n ≥ 10^4).
//! `cargo bench --bench axis`; figures go to docs/PERFORMANCE.md.
//! `MEDAX_BENCH_MAX_N` caps the sizes (default 10^6).

use medax::plane::internals::decompose_with;
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{samples, Shape2d, ShapeOptions, Vertex};
use std::time::Instant;

fn slope(points: &[(f64, f64)]) -> f64 {
    let k = points.len() as f64;
    let (sx, sy) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| (a + x.ln(), b + y.ln()));
    let (mx, my) = (sx / k, sy / k);
    let num: f64 = points.iter().map(|&(x, y)| (x.ln() - mx) * (y.ln() - my)).sum();
    let den: f64 = points.iter().map(|&(x, _)| (x.ln() - mx).powi(2)).sum();
    num / den
}

fn main() {
    let max_n: usize = std::env::var("MEDAX_BENCH_MAX_N").ok().and_then(|s| s.parse().ok()).unwrap_or(1_000_000);
    type Gen = fn(usize) -> Vec<Vec<Vertex>>;
    let kinds: [(&str, Gen, &[usize]); 2] = [
        ("flower arcs (C1)", samples::flower_arcs, &[1_000, 10_000, 100_000, 1_000_000]),
        ("star polygon", |n| samples::star_polygon(n, 3), &[1_000, 10_000, 30_000, 100_000]),
    ];
    println!("| shape | n | threads | axis | µs per element | divide share | nodes |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    let mut growth = Vec::new();
    for (name, gen, sizes) in kinds {
        let mut points = [Vec::new(), Vec::new()];
        for &n in sizes.iter().filter(|&&n| n <= max_n) {
            let s = Shape2d::from_bulge_loops(gen(n), &ShapeOptions::default()).expect("samples are valid");
            for threads in [1, 2] {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("pool");
                let t = Instant::now();
                let axis = pool.install(|| medial_axis(&s, &AxisOptions::default()));
                let total = t.elapsed().as_secs_f64();
                let share = if threads == 1 {
                    let t = Instant::now();
                    pool.install(|| {
                        decompose_with(&s, AxisOptions::default().seed, AxisOptions::default().leaf_parts)
                            .expect("no holes")
                    });
                    format!("{:.0} %", 100.0 * (t.elapsed().as_secs_f64() / total).min(1.0))
                } else {
                    "".to_string()
                };
                let nodes = match &axis {
                    Ok(a) => {
                        if n >= 10_000 {
                            points[threads - 1].push((s.element_count() as f64, total));
                        }
                        a.nodes.len().to_string()
                    }
                    Err(e) => format!("failed: {e}"),
                };
                println!(
                    "| {name} | {} | {threads} | {:.3} s | {:.1} | {share} | {nodes} |",
                    s.element_count(),
                    total,
                    total * 1e6 / s.element_count() as f64,
                );
            }
        }
        for (t, p) in points.iter().enumerate() {
            if p.len() >= 2 {
                growth.push(format!("{name}, {} thread(s): n^{:.2}", t + 1, slope(p)));
            }
        }
    }
    for g in growth {
        println!("growth {g}");
    }
}
