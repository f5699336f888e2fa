//! Arbitrary bulge loops (coordinates on a coarse grid so that touching,
//! collinear and repeated vertices are common) through validation. Valid
//! shapes must satisfy the invariants the validator promises, checked here
//! by brute force with an independent test.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::Point;
use medax::shape::{Shape2d, ShapeOptions, Vertex};

#[derive(Arbitrary, Debug)]
struct Input {
    loops: Vec<Vec<(i8, i8, i8)>>,
    raw: Option<Vec<(f64, f64, f64)>>,
}

fuzz_target!(|input: Input| {
    let mut loops: Vec<Vec<Vertex>> = input
        .loops
        .iter()
        .take(6)
        .map(|l| {
            l.iter()
                .take(40)
                .map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 })
                .collect()
        })
        .collect();
    if let Some(raw) = &input.raw {
        loops.push(raw.iter().take(40).map(|&(x, y, b)| Vertex { p: Point::new(x, y), bulge: b }).collect());
    }
    let Ok(shape) = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()) else { return };
    // Independent check: sampled boundary points of different, non-adjacent
    // elements stay apart by more than the tolerance.
    let tol = shape.tolerance();
    let mut samples = Vec::new();
    for (li, l) in shape.loops().iter().enumerate() {
        for (i, e) in l.elements().enumerate() {
            for k in 1..8 {
                samples.push((li, i, l.len(), e.point_at(k as f64 / 8.0)));
            }
        }
    }
    for (a, &(la, ia, na, pa)) in samples.iter().enumerate() {
        for &(lb, ib, _, pb) in &samples[a + 1..] {
            let adjacent = la == lb && (ia == ib || (ia + 1) % na == ib || (ib + 1) % na == ia);
            if !adjacent {
                assert!(pa.dist(pb) > tol * 0.5, "valid shape has touching elements {la}/{ia} and {lb}/{ib}");
            }
        }
    }
    assert!(shape.area() > 0.0);
});
