//! Checks the inner offsets of a large shape file against nearest-element
//! distances (the maximal-disk index, not the axis the offsets are trimmed
//! from): every offset vertex and element middle lies at distance ρ from
//! the boundary, and the areas shrink with ρ.
//! `cargo run --release --example offset_probe -- SHAPE.json RHO1,RHO2,...`
use medax::plane::{DiskFinder, OffsetOptions, Offsets};
use medax::shape::Element;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&args[1]).expect("readable shape file");
    let shape = medax::plane::shape_or_sites(&text).expect("a valid shape file");
    let rhos: Vec<f64> = args[2].split(',').map(|s| s.parse().expect("a distance")).collect();
    let offsets = Offsets::new(&shape, &OffsetOptions::default()).expect("offsets");
    let finder = DiskFinder::new(&shape);
    let diag = shape.bbox().diagonal();
    for &rho in &rhos {
        let layer = offsets.layer(rho).expect("layer");
        let mut worst: f64 = 0.0;
        let mut at = String::new();
        let mut points = 0usize;
        for l in &layer.loops {
            let n = l.vertices.len();
            for i in 0..n {
                let (a, b) = (l.vertices[i], l.vertices[(i + 1) % n]);
                let e = Element::from_bulge(a.p, b.p, a.bulge);
                for p in (0..16).map(|k| e.point_at(k as f64 / 16.0)) {
                    let (er, d) = finder.nearest(p).map_or((None, f64::INFINITY), |(er, d)| (Some(er), d));
                    if (d - rho).abs() > worst {
                        worst = (d - rho).abs();
                        at = format!(
                            "offset element {i} {:?} -> {:?} bulge {}, point {p:?}, nearest {er:?}",
                            a.p, b.p, a.bulge
                        );
                    }
                    points += 1;
                }
            }
        }
        let area: f64 = layer.loops.iter().map(|l| l.area).sum();
        println!(
            "rho {rho}: {} loops, {points} points, worst |dist - rho| {:.2e} ({:.2e} of the diagonal), area {area:.9}",
            layer.loops.len(),
            worst,
            worst / diag
        );
        if std::env::var_os("MEDAX_PROBE_DETAIL").is_some() {
            println!("  worst at {at}");
        }
    }
}
