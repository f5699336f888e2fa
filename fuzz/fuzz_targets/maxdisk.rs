//! Maximal disks on arbitrary valid bulge shapes (grid coordinates, so that
//! collinear, cocircular and nearly touching elements are common): no panic,
//! and every disk passes the oracle of tests/maxdisk.rs — its centre is as
//! far from the boundary as its radius (brute force over all elements) and
//! inside the shape.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::{FilteredKernel, Point};
use medax::plane::DiskFinder;
use medax::shape::{ElementRef, JointKind, Shape2d, ShapeOptions, Vertex};

#[derive(Arbitrary, Debug)]
struct Input {
    loops: Vec<Vec<(i8, i8, i8)>>,
    probes: Vec<(u16, u8)>,
}

fuzz_target!(|input: Input| {
    let loops: Vec<Vec<Vertex>> = input
        .loops
        .iter()
        .take(4)
        .map(|l| {
            l.iter()
                .take(30)
                .map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 })
                .collect()
        })
        .collect();
    let Ok(shape) = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()) else { return };
    let finder = DiskFinder::new(&shape);
    let refs: Vec<ElementRef> = shape
        .loops()
        .iter()
        .enumerate()
        .flat_map(|(l, lp)| (0..lp.len()).map(move |i| ElementRef { loop_index: l, element: i }))
        .collect();
    let tol = 1e-9 * shape.bbox().diagonal();
    let k = FilteredKernel;
    for &(e, s) in input.probes.iter().take(16) {
        let at = refs[e as usize % refs.len()];
        let frac = s as f64 / 255.0;
        let d = finder.max_disk(at, frac);
        if d.radius == 0.0 {
            let v = if frac == 0.0 { at.element } else { (at.element + 1) % shape.loops()[at.loop_index].len() };
            assert_eq!(shape.joint(at.loop_index, v), JointKind::Convex);
            continue;
        }
        assert!(d.radius.is_finite() && d.radius > 0.0, "{d:?}");
        let dist = shape
            .loops()
            .iter()
            .flat_map(|l| l.elements())
            .map(|e| e.closest_point(d.center).0)
            .fold(f64::INFINITY, f64::min);
        assert!((dist - d.radius).abs() <= tol, "{at:?} at {frac}: {d:?}, boundary distance {dist}");
        let winding: i32 = shape.loops().iter().map(|l| l.winding_number(&k, d.center)).sum();
        assert_eq!(winding, 1, "{at:?} at {frac}: {d:?} centre outside");
    }
});
