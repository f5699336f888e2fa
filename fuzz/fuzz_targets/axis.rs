//! The whole medial-axis pipeline on arbitrary valid one-loop bulge shapes
//! (grid coordinates, so collinear, cocircular and symmetric set-ups are
//! common): no panic, no hang, and every axis it returns passes the oracle
//! of tests/axis.rs: each sample's brute-force distance to the boundary is
//! its radius, and the graph is a tree. A typed `AxisError` is allowed
//! (reported breakdowns are not wrong answers); a wrong axis is a crash.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::Disk;
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{Shape2d, ShapeOptions, Vertex};

#[derive(Arbitrary, Debug)]
struct Input {
    vertices: Vec<(i8, i8, i8)>,
    seed: u8,
}

fuzz_target!(|input: Input| {
    let lp: Vec<Vertex> = input
        .vertices
        .iter()
        .take(24)
        .map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 })
        .collect();
    let Ok(shape) = Shape2d::from_bulge_loops(vec![lp], &ShapeOptions::default()) else { return };
    let opts = AxisOptions { seed: input.seed as u64, ..AxisOptions::default() };
    let Ok(axis) = medial_axis(&shape, &opts) else { return };
    let diag = shape.bbox().diagonal();
    let tol = 1e-9 * diag;
    assert_eq!(axis.nodes.len(), axis.edges.len() + 1);
    for pl in axis.sampled(&shape, 1e-3 * diag) {
        for Disk { center: c, radius: r } in pl {
            let d = shape.loops()[0].elements().map(|e| e.closest_point(c).0).fold(f64::INFINITY, f64::min);
            assert!((d - r).abs() <= tol, "sample {c:?} r {r} distance {d}");
        }
    }
});
