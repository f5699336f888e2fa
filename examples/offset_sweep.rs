//! Offsets of fresh smooth biarc curves (with and without holes) and
//! stars, checked at 16 points along every offset element against
//! nearest-element distances: how many shapes have a wrong layer.
//! `cargo run --release --example offset_sweep -- [SEEDS] [FIRST_SEED]`
use medax::plane::{DiskFinder, OffsetOptions, Offsets};
use medax::shape::{samples, Element, Shape2d, Vertex};

fn worst(shape: &Shape2d, rho: f64, offsets: &Offsets, finder: &DiskFinder) -> Result<f64, String> {
    let layer = offsets.layer(rho).map_err(|e| e.to_string())?;
    let mut worst: f64 = 0.0;
    for l in &layer.loops {
        let n = l.vertices.len();
        for i in 0..n {
            let (a, b) = (l.vertices[i], l.vertices[(i + 1) % n]);
            let e = Element::from_bulge(a.p, b.p, a.bulge);
            for k in 0..16 {
                let d = finder.nearest(e.point_at(k as f64 / 16.0)).map_or(f64::INFINITY, |(_, d)| d);
                worst = worst.max((d - rho).abs());
            }
        }
    }
    Ok(worst / shape.bbox().diagonal())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let seeds: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(20);
    let first: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(500);
    let (mut shapes, mut bad) = (0, 0);
    for seed in first..first + seeds {
        let n = [1000, 2000, 4000][(seed % 3) as usize];
        let families: Vec<(String, Vec<Vec<Vertex>>)> = vec![
            (format!("fourier {n} seed {seed}"), samples::fourier_biarcs(n, seed)),
            (format!("fourier {n} 3 holes seed {seed}"), samples::fourier_with_holes(n, 3, seed)),
            (format!("near circle 1e-3 {n} seed {seed}"), samples::fourier_curve(n, seed, 1e-3)),
            (format!("star 200 seed {seed}"), samples::star_polygon(200, seed)),
        ];
        for (name, loops) in families {
            let shape = Shape2d::from_bulge_loops(loops, &medax::shape::ShapeOptions::default()).expect("valid");
            let offsets = match Offsets::new(&shape, &OffsetOptions::default()) {
                Ok(o) => o,
                Err(e) => {
                    println!("{name}: offsets refused: {e}");
                    bad += 1;
                    shapes += 1;
                    continue;
                }
            };
            let finder = DiskFinder::new(&shape);
            let m = offsets.max_inner_distance();
            shapes += 1;
            let mut fails = Vec::new();
            for f in [0.005, 0.01, 0.03, 0.1, 0.25, 0.5, 0.8] {
                match worst(&shape, f * m, &offsets, &finder) {
                    Ok(w) if w <= 1e-9 => {}
                    Ok(w) => fails.push(format!("{f}: {w:.1e}")),
                    Err(e) => fails.push(format!("{f}: {e}")),
                }
            }
            if !fails.is_empty() {
                bad += 1;
                println!("{name}: {}", fails.join(", "));
            }
        }
    }
    println!("{bad} of {shapes} shapes with a wrong layer");
}
