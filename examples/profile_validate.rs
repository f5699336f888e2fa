//! Times parsing and validation phases on sample shapes:
//! `cargo run --release --example profile_validate -- N`.
use medax::shape::{samples, Shape2d, ShapeOptions};
use std::time::Instant;

fn main() {
    let n: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(1_000_000);
    for (name, loops) in [
        ("star", samples::star_polygon(n, 1)),
        ("flower", samples::flower_arcs(n)),
        ("comb", samples::slanted_comb(n / 4, (n / 8) as f64)),
    ] {
        let s = Shape2d::from_bulge_loops(loops.clone(), &ShapeOptions::default()).unwrap();
        let json = s.to_json();
        let t = Instant::now();
        let _ = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).unwrap();
        let validate = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let _ = medax::io::json::read_loops(&json).unwrap();
        let parse = t.elapsed().as_secs_f64();
        println!("{name:8} n={n}: validate {validate:.3} s, json parse {parse:.3} s");
    }
}
