//! Shape validation benchmark: time per element and growth exponent for
//! sample shapes of 10^3..10^6 elements, with 1 and 2 threads.
//! `cargo bench --bench validate` (add `-- quick` to stop at 10^5).
//! Figures go to docs/PERFORMANCE.md; timings never go in tests.

use medax::shape::{samples, Shape2d, ShapeOptions, Vertex};
use std::time::Instant;

fn best_of(runs: usize, loops: &[Vec<Vertex>]) -> f64 {
    (0..runs)
        .map(|_| {
            let l = loops.to_vec();
            let t = Instant::now();
            let s = Shape2d::from_bulge_loops(l, &ShapeOptions::default()).expect("samples are valid");
            let dt = t.elapsed().as_secs_f64();
            std::hint::black_box(s);
            dt
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let quick = std::env::args().any(|a| a == "quick");
    let sizes: &[usize] = if quick { &[1_000, 10_000, 100_000] } else { &[1_000, 10_000, 100_000, 1_000_000] };
    type Gen = fn(usize) -> Vec<Vec<Vertex>>;
    let kinds: [(&str, Gen); 4] = [
        ("flower arcs (C1)", samples::flower_arcs),
        ("star polygon", |n| samples::star_polygon(n, 1)),
        ("plate with holes", |n| samples::perforated_plate(((n as f64) / 2.0).sqrt().ceil() as usize)),
        ("slanted comb", |n| samples::slanted_comb(n / 4, (n / 8) as f64)),
    ];
    println!("| shape | n | 1 thread | 2 threads | µs/element (2 thr) |");
    println!("|---|---:|---:|---:|---:|");
    for (name, gen) in kinds {
        let mut pts = Vec::new();
        for &n in sizes {
            let loops = gen(n);
            let count: usize = loops.iter().map(Vec::len).sum();
            let runs = if n >= 1_000_000 { 1 } else { 3 };
            let mut t = [0.0; 2];
            for (k, threads) in [1, 2].into_iter().enumerate() {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
                t[k] = pool.install(|| best_of(runs, &loops));
            }
            println!("| {name} | {count} | {:.4} s | {:.4} s | {:.3} |", t[0], t[1], t[1] * 1e6 / count as f64);
            pts.push(((count as f64).ln(), t[1].ln()));
        }
        println!("| {name}: growth exponent over n ≥ 10^4 | | | | {:.2} |", slope(&pts[1..]));
    }
}

/// Least-squares slope of (log n, log t) points: the growth exponent.
fn slope(pts: &[(f64, f64)]) -> f64 {
    let m = pts.len() as f64;
    let (mx, my) = pts.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0 / m, a.1 + p.1 / m));
    let (num, den) = pts.iter().fold((0.0, 0.0), |a, p| (a.0 + (p.0 - mx) * (p.1 - my), a.1 + (p.0 - mx).powi(2)));
    num / den
}
