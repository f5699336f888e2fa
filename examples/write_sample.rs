//! Writes a sample shape as medax JSON: `cargo run --release --example
//! write_sample -- KIND N OUT.json` with KIND = star | flower | plate | comb |
//! holes | fourier | circle (the last two: radial Fourier curves, lobed or
//! nearly circular; seed from `MEDAX_SEED`, default 1, as for star).

use medax::shape::{samples, Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 4 {
        eprintln!("usage: write_sample star|flower|plate|comb|holes|fourier|circle N OUT.json");
        std::process::exit(2);
    }
    let n: usize = args[2].parse().expect("N must be a whole number");
    let seed = std::env::var("MEDAX_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(1);
    let loops = match args[1].as_str() {
        "star" => samples::star_polygon(n, seed),
        "flower" => samples::flower_arcs(n),
        "plate" => samples::perforated_plate(((n as f64) / 2.0).sqrt().ceil() as usize),
        "comb" => samples::slanted_comb(n / 4, (n / 8) as f64),
        "holes" => samples::random_holes(n, 1),
        "fourier" => samples::fourier_biarcs(n, seed),
        "circle" => samples::fourier_curve(
            n,
            seed,
            std::env::var("MEDAX_SPREAD").ok().and_then(|s| s.parse().ok()).unwrap_or(1e-3),
        ),
        other => panic!("unknown kind {other}"),
    };
    let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("samples are valid");
    std::fs::write(&args[3], shape.to_json()).expect("write output");
    eprintln!("wrote {} elements to {}", shape.element_count(), args[3]);
}
