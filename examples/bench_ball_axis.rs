//! Time of the polygon-ball axis on star polygons: `cargo run --release
//! --example bench_ball_axis -- N K [SEED]`.
use medax::polymetric::medial_axis_with_ball;
use medax::shape::{samples, Ball2, Shape2d, ShapeOptions};
use std::time::Instant;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let n: usize = a.get(1).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let k: usize = a.get(2).and_then(|s| s.parse().ok()).unwrap_or(4);
    let seed: u64 = a.get(3).and_then(|s| s.parse().ok()).unwrap_or(1);
    let s = Shape2d::from_bulge_loops(samples::star_polygon(n, seed), &ShapeOptions::default()).unwrap();
    let rot: f64 = a.get(4).and_then(|s| s.parse().ok()).unwrap_or(0.1);
    let ball = Ball2::regular(k, rot).unwrap();
    let t = Instant::now();
    let ax = medial_axis_with_ball(&s, &ball).unwrap();
    let dt = t.elapsed().as_secs_f64();
    let t2 = Instant::now();
    let eu = medax::plane::medial_axis(&s, &Default::default()).unwrap();
    let dt2 = t2.elapsed().as_secs_f64();
    println!(
        "n {n} k {k}: {} nodes {} edges {:?} jumps {} in {:.3} s ({:.2} us/segment); euclidean {:.3} s, {} edges",
        ax.nodes.len(),
        ax.edges.len(),
        ax.kind_counts(),
        ax.jump_count(),
        dt,
        dt * 1e6 / n as f64,
        dt2,
        eu.edges.len()
    );
}
