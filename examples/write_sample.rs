//! Writes a sample shape as medax JSON: `cargo run --release --example
//! write_sample -- KIND N OUT.json` with KIND = star | flower | plate | comb |
//! holes | fourier | circle | fholes | text | strip (fourier and circle:
//! radial Fourier curves, lobed or nearly circular, the latter within
//! `MEDAX_SPREAD` of a circle; fholes: a lobed curve with `MEDAX_HOLES`
//! holes of its kind, default 40; text: a plate of letters drawn with a
//! round pen; strip: a long band whose sides stray `MEDAX_SPREAD` from
//! straight; seed from `MEDAX_SEED`, default 1).

use medax::shape::{samples, Shape2d, ShapeOptions};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() != 4 {
        eprintln!("usage: write_sample star|flower|plate|comb|holes|fourier|circle|fholes|text|strip N OUT.json");
        std::process::exit(2);
    }
    let n: usize = args[2].parse().expect("N must be a whole number");
    let env = |name: &str, default: f64| std::env::var(name).ok().and_then(|s| s.parse().ok()).unwrap_or(default);
    let seed = env("MEDAX_SEED", 1.0) as u64;
    let loops = match args[1].as_str() {
        "star" => samples::star_polygon(n, seed),
        "flower" => samples::flower_arcs(n),
        "plate" => samples::perforated_plate(((n as f64) / 2.0).sqrt().ceil() as usize),
        "comb" => samples::slanted_comb(n / 4, (n / 8) as f64),
        "holes" => samples::random_holes(n, seed),
        "fourier" => samples::fourier_biarcs(n, seed),
        "circle" => samples::fourier_curve(n, seed, env("MEDAX_SPREAD", 1e-3)),
        "fholes" => samples::fourier_with_holes(n, env("MEDAX_HOLES", 40.0) as usize, seed),
        "text" => samples::text_plate(n, seed),
        "strip" => samples::nearly_straight_strip(n, seed, env("MEDAX_SPREAD", 1e-3)),
        other => panic!("unknown kind {other}"),
    };
    let shape = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).expect("samples are valid");
    std::fs::write(&args[3], shape.to_json()).expect("write output");
    eprintln!("wrote {} elements to {}", shape.element_count(), args[3]);
}
