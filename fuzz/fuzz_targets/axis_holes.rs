//! The medial axis of shapes with holes (thesis 2.3.1): a square with up
//! to four arbitrary holes on the grid (collinear, cocircular and
//! symmetric set-ups are common, and holes nearly touch each other and
//! the square). No panic, no hang; every axis it returns is connected with
//! one independent cycle per hole and each sample's brute-force distance
//! to the boundary is its radius. A typed `AxisError` is allowed.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::Disk;
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{Shape2d, ShapeOptions, Vertex};

#[derive(Arbitrary, Debug)]
struct Input {
    holes: Vec<Vec<(i8, i8, i8)>>,
    seed: u8,
}

fuzz_target!(|input: Input| {
    let corner = |x: f64, y: f64| Vertex { p: Point::new(x, y), bulge: 0.0 };
    let mut loops = vec![vec![corner(-130.0, -130.0), corner(130.0, -130.0), corner(130.0, 130.0), corner(-130.0, 130.0)]];
    for h in input.holes.iter().take(4) {
        loops.push(
            h.iter()
                .take(8)
                .map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 })
                .collect(),
        );
    }
    let Ok(shape) = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()) else { return };
    let opts = AxisOptions { seed: input.seed as u64, ..AxisOptions::default() };
    let Ok(axis) = medial_axis(&shape, &opts) else { return };
    let diag = shape.bbox().diagonal();
    let tol = 1e-9 * diag;
    let holes = shape.loops().len() - 1;
    assert_eq!(axis.nodes.len() + holes, axis.edges.len() + 1);
    for pl in axis.sampled(&shape, 1e-3 * diag) {
        for Disk { center: c, radius: r } in pl {
            let d = shape
                .loops()
                .iter()
                .flat_map(|l| l.elements())
                .map(|e| e.closest_point(c).0)
                .fold(f64::INFINITY, f64::min);
            assert!((d - r).abs() <= tol, "sample {c:?} r {r} distance {d}");
        }
    }
});
