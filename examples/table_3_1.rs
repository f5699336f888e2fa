//! Table 3.1 of the thesis with medax: the size of the axis under regular
//! k-gons (k = 3, 12, 64, 200) of random star polygons (n = 50 … 1,600
//! vertices, 20 polygons each), as the number of edges |MA| and its ratio
//! to the bound n + r·k (r reflex vertices). Also the time per polygon.
//! `cargo run --release --example table_3_1 [POLYGONS]`
use medax::polymetric::medial_axis_with_ball;
use medax::shape::{samples, Ball2, Shape2d, ShapeOptions};
use std::time::Instant;

fn main() {
    let count: u64 = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let ks = [3usize, 12, 64, 200];
    println!("| n | {} |", ks.map(|k| format!("{k}-gon \\|MA\\| | ratio")).join(" | "));
    println!("|---|{}", "---|---|".repeat(ks.len()));
    let mut failures = 0;
    for n in [50usize, 100, 200, 400, 800, 1600] {
        let mut row = format!("| {n} |");
        for &k in &ks {
            let (mut size, mut ratio, mut done) = (0.0, 0.0, 0.0);
            let t = Instant::now();
            for seed in 0..count {
                let loops = samples::star_polygon(n, 1000 * n as u64 + seed);
                let p: Vec<_> = loops[0].iter().map(|v| v.p).collect();
                let reflex = (0..n).filter(|&i| (p[i] - p[(i + n - 1) % n]).cross(p[(i + 1) % n] - p[i]) < 0.0).count();
                let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("a star is valid");
                let ball = Ball2::regular(k, 0.1 + 0.01 * seed as f64).expect("a regular ball");
                match medial_axis_with_ball(&shape, &ball) {
                    Ok(axis) => {
                        let m = axis.edges.len() as f64;
                        size += m;
                        ratio += m / (n + reflex * k) as f64;
                        done += 1.0;
                    }
                    Err(e) => {
                        failures += 1;
                        eprintln!("n {n} k {k} seed {seed}: {e}");
                    }
                }
            }
            let ms = 1e3 * t.elapsed().as_secs_f64() / count as f64;
            row += &format!(" {:.0} | {:.2} ({ms:.1} ms) |", size / done, ratio / done);
        }
        println!("{row}");
    }
    if failures > 0 {
        println!("{failures} polygons failed");
    }
}
