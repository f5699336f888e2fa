//! Trimmed offsets (thesis 2.4) of arbitrary valid bulge shapes on the
//! grid, with up to two holes (collinear, cocircular and symmetric set-ups
//! are common, so are distances at which loops split, merge or vanish):
//! `Offsets::new` with an outer reach, then a few inner and outer layers.
//! No panic, no hang; a typed `OffsetError` is allowed (a reported
//! breakdown is not a wrong answer). Every layer it returns has closed,
//! finite loops without elements shorter than the tolerance, each loop in
//! exactly one region with the right sign of area, nothing beyond
//! `max_inner_distance`, and every vertex and
//! element midpoint at the layer's distance from the boundary within
//! 1e-9 × diagonal (brute force over the shape's elements).
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use medax::kernel::Point;
use medax::plane::{AxisOptions, OffsetOptions, Offsets};
use medax::shape::{Element, Shape2d, ShapeOptions, Vertex};

#[derive(Arbitrary, Debug)]
struct Input {
    outer: Vec<(i8, i8, i8)>,
    holes: Vec<Vec<(i8, i8, i8)>>,
    /// Inner distances as fractions (/255) of half the diagonal (beyond
    /// the largest inscribed radius too).
    inner: Vec<u8>,
    /// Outer distances as fractions (/255) of the reach.
    outer_d: Vec<u8>,
    /// The outer reach as a fraction (/255) of the diagonal.
    reach: u8,
    seed: u8,
}

fn verts(v: &[(i8, i8, i8)], max: usize) -> Vec<Vertex> {
    v.iter().take(max).map(|&(x, y, b)| Vertex { p: Point::new(x as f64, y as f64), bulge: b as f64 / 64.0 }).collect()
}

fuzz_target!(|input: Input| {
    let mut loops = vec![verts(&input.outer, 24)];
    loops.extend(input.holes.iter().take(2).map(|h| verts(h, 8)));
    let Ok(shape) = Shape2d::from_bulge_loops(loops, &ShapeOptions::default()) else { return };
    let diag = shape.bbox().diagonal();
    let reach = diag * input.reach as f64 / 255.0;
    let opts = OffsetOptions { axis: AxisOptions { seed: input.seed as u64, ..AxisOptions::default() }, outer_reach: reach };
    let Ok(off) = Offsets::new(&shape, &opts) else { return };
    let m = off.max_inner_distance();
    assert!(m.is_finite() && m <= diag, "largest inscribed radius {m}");
    let distances = input
        .inner
        .iter()
        .take(3)
        .map(|&f| 0.5 * diag * f as f64 / 255.0)
        .chain(input.outer_d.iter().take(2).map(|&f| -reach * f as f64 / 255.0));
    let elements: Vec<Element> = shape.loops().iter().flat_map(|l| l.elements()).collect();
    let dist = |q: Point| elements.iter().map(|e| e.closest_point(q).0).fold(f64::INFINITY, f64::min);
    let tol = 1e-9 * diag;
    for d in distances {
        let Ok(layer) = off.layer(d) else { continue };
        assert_eq!(layer.distance, d);
        assert!(d <= m + tol || layer.is_empty(), "loops at {d} beyond the largest inscribed radius {m}");
        // And something at every distance short of it, and outwards.
        assert!(d >= m - 1e-6 * diag || !layer.is_empty(), "nothing at {d}, below the largest inscribed radius {m}");
        let mut owner = vec![usize::MAX; layer.loops.len()];
        for (r, reg) in layer.regions.iter().enumerate() {
            for &i in std::iter::once(&reg.outer).chain(&reg.holes) {
                assert!(i < owner.len() && owner[i] == usize::MAX, "loop {i} named twice or out of range");
                owner[i] = r;
                assert_eq!(layer.loops[i].region, r);
            }
            assert!(layer.loops[reg.outer].area > 0.0, "outer loop with area {}", layer.loops[reg.outer].area);
            assert!(reg.holes.iter().all(|&h| layer.loops[h].area < 0.0), "hole with positive area");
        }
        assert!(owner.iter().all(|&o| o != usize::MAX), "a loop in no region");
        for l in &layer.loops {
            let n = l.vertices.len();
            assert!(n >= 2 && l.area.is_finite() && l.area != 0.0, "degenerate loop {:?}", l.vertices);
            for i in 0..n {
                let (a, b) = (l.vertices[i], l.vertices[(i + 1) % n]);
                assert!(a.p.is_finite() && a.bulge.is_finite(), "non-finite vertex {a:?}");
                assert!(a.p.dist(b.p) >= shape.tolerance(), "element {i} from {:?} to {:?} shorter than the tolerance", a.p, b.p);
                let e = Element::from_bulge(a.p, b.p, a.bulge);
                assert!(e.length() >= shape.tolerance(), "element {i} of length {} at {:?}", e.length(), a.p);
                for q in [a.p, e.point_at(0.5)] {
                    let defect = dist(q) - d.abs();
                    assert!(defect.abs() <= tol, "distance {d}: point {q:?} is {defect:e} off");
                }
            }
        }
    }
});
