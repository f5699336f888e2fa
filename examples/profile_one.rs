//! Validates one sample shape once, and optionally computes its medial
//! axis (for profilers):
//! `cargo run --release --example profile_one -- star|flower|comb|holes|plate N [axis [LEAF_PARTS]]`
//! (`MEDAX_SEED` picks the random star, `MEDAX_AXIS_SEED` the divide step's
//! random choices).
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{samples, Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(100_000);
    let loops = match args.get(1).map(String::as_str) {
        Some("flower") => samples::flower_arcs(n),
        Some("comb") => samples::slanted_comb(n / 4, (n / 8) as f64),
        Some("holes") => {
            samples::random_holes(n, std::env::var("MEDAX_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1))
        }
        Some("plate") => samples::perforated_plate(n),
        _ => samples::star_polygon(n, std::env::var("MEDAX_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1)),
    };
    let t = std::time::Instant::now();
    let s = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("valid sample");
    println!("{} elements validated in {:.3} s", s.element_count(), t.elapsed().as_secs_f64());
    if args.get(3).map(String::as_str) == Some("axis") {
        let t = std::time::Instant::now();
        let leaf_parts = args.get(4).and_then(|s| s.parse().ok()).unwrap_or(AxisOptions::default().leaf_parts);
        let seed =
            std::env::var("MEDAX_AXIS_SEED").ok().and_then(|v| v.parse().ok()).unwrap_or(AxisOptions::default().seed);
        match medial_axis(&s, &AxisOptions { leaf_parts, seed }) {
            Ok(a) => println!("axis: {} nodes in {:.3} s", a.nodes.len(), t.elapsed().as_secs_f64()),
            Err(e) => println!("axis failed after {:.3} s: {e}", t.elapsed().as_secs_f64()),
        }
    }
}
