//! The offset, pocket and V-carve writers on real results: JSON and DXF read
//! back to the very same doubles (loops, regions, rings, paths), SVG arcs
//! stay arcs.

use medax::cam::{pocket, vcarve, PocketOptions, VCarveOptions};
use medax::io::dxf::read_dxf;
use medax::io::RawVertex;
use medax::plane::offsets_to_dxf;
use medax::plane::offsets_to_json;
use medax::plane::{layer_colour, offsets_to_svg};
use medax::plane::{medial_axis, AxisOptions, OffsetOptions, Offsets};
use medax::shape::{Shape2d, ShapeOptions, Vertex};
use serde_json::Value;

/// A plate whose top is an arc, with a round and a square hole: offsets
/// with arcs everywhere and thirds in the coordinates.
fn plate() -> Shape2d {
    Shape2d::from_json_str(
        r#"{"loops": [[[0, 0], [8, 0], [8, 5, 0.2], [0, 5]], [[2, 2, 1], [3, 2, 1]],
            [[5, 1.5], [6.5, 1.5], [6.5, 3], [5, 3]]]}"#,
        &ShapeOptions::default(),
    )
    .unwrap()
}

fn triples(l: &[Vertex]) -> Vec<[f64; 3]> {
    l.iter().map(|v| [v.p.x, v.p.y, v.bulge]).collect()
}

fn json_loops(v: &Value) -> Vec<Vec<[f64; 3]>> {
    serde_json::from_value(v.clone()).unwrap()
}

fn raw(l: &[Vertex]) -> Vec<RawVertex> {
    l.iter().map(|&v| RawVertex::from(v)).collect()
}

#[test]
fn offsets_json_and_dxf_read_back_exactly() {
    let shape = plate();
    let offsets = Offsets::new(&shape, &OffsetOptions { outer_reach: 1.0 / 3.0, ..OffsetOptions::default() }).unwrap();
    let layers = offsets.layers(&[1.0 / 3.0, 0.7, -1.0 / 3.0, 10.0]).unwrap();
    assert!(layers[3].is_empty());
    let text = offsets_to_json(&layers);
    let doc: Value = serde_json::from_str(&text).unwrap();
    // The streamed text is what writing the document as one `Value` gives
    // (sorted keys, shortest round-trip numbers): the format is unchanged.
    assert_eq!(text, serde_json::to_string(&doc).unwrap() + "\n");
    let entries = doc["offsets"].as_array().unwrap();
    assert_eq!(entries.len(), layers.len());
    for (e, layer) in entries.iter().zip(&layers) {
        assert_eq!(*e, layer.to_json_value());
        assert_eq!(e["distance"].as_f64(), Some(layer.distance));
        assert_eq!(e["area"].as_f64(), Some(layer.area()));
        let loops: Vec<Vec<[f64; 3]>> = layer.loops.iter().map(|l| triples(&l.vertices)).collect();
        assert_eq!(json_loops(&e["loops"]), loops);
        let regions = e["regions"].as_array().unwrap();
        assert_eq!(regions.len(), layer.regions.len());
        for (r, want) in regions.iter().zip(&layer.regions) {
            assert_eq!(r["outer"].as_u64(), Some(want.outer as u64));
            let holes: Vec<usize> = serde_json::from_value(r["holes"].clone()).unwrap();
            assert_eq!(holes, want.holes);
        }
    }
    // DXF: one closed polyline per loop, in layer order, the same doubles.
    let drawing = read_dxf(&offsets_to_dxf(&layers)).unwrap();
    let want: Vec<Vec<RawVertex>> = layers.iter().flat_map(|l| &l.loops).map(|l| raw(&l.vertices)).collect();
    assert_eq!(drawing.polylines.iter().map(|p| p.vertices.clone()).collect::<Vec<_>>(), want);
    assert!(drawing.polylines.iter().all(|p| p.closed));
    // SVG: the grey axis, and each layer one path in its own colour with a
    // move per loop; the round hole (radius 1/2) grows into an arc of radius
    // 1/2 + 1/3 at distance 1/3, the outer offset at -1/3 rounds the
    // corners with arcs of radius 1/3.
    let axis = medial_axis(&shape, &AxisOptions::default()).unwrap();
    let svg = offsets_to_svg(&shape, &axis, &layers, 600.0, 1e-3);
    assert!(svg.contains("#9aa5b1"), "the grey axis");
    let layer_path = |k: usize| {
        let paths: Vec<&str> = svg
            .lines()
            .filter(|l| l.starts_with("<path") && l.contains(&format!("stroke=\"{}\"", layer_colour(k))))
            .collect();
        assert_eq!(paths.len(), 1, "layer {k}: one path in its colour");
        paths[0].to_string()
    };
    let arc_radii = |path: &str| -> Vec<f64> {
        path.split('A').skip(1).map(|t| t.split(' ').next().unwrap().parse().unwrap()).collect()
    };
    for (k, radius) in [(0, 0.5 + 1.0 / 3.0), (2, 1.0 / 3.0)] {
        let path = layer_path(k);
        assert_eq!(path.matches('M').count(), layers[k].loops.len(), "layer {k}: a move per loop");
        let radii = arc_radii(&path);
        assert!(radii.iter().any(|r| (r - radius).abs() < 1e-6), "layer {k}: no arc of radius {radius} in {radii:?}");
    }
    assert!(
        svg.lines().all(|l| !l.contains(&format!("stroke=\"{}\"", layer_colour(3)))),
        "the empty layer draws nothing"
    );
}

#[test]
fn pocket_json_and_dxf_read_back_exactly() {
    let offsets = Offsets::new(&plate(), &OffsetOptions::default()).unwrap();
    let p = pocket(&offsets, &PocketOptions::new(0.2, 0.3)).unwrap();
    assert!(p.rings.len() >= 3);
    let text = p.to_json();
    let doc: Value = serde_json::from_str(&text).unwrap();
    // Streamed, it is the text a `Value` tree writes: the format is unchanged.
    assert_eq!(text, serde_json::to_string(&doc).unwrap() + "\n");
    let rings = doc["rings"].as_array().unwrap();
    assert_eq!(rings.len(), p.rings.len());
    for (r, want) in rings.iter().zip(&p.rings) {
        assert_eq!(r["level"].as_u64(), Some(want.level as u64));
        assert_eq!(r["distance"].as_f64(), Some(want.distance));
        assert_eq!(r["parent"].as_u64().map(|i| i as usize), want.parent);
        let children: Vec<usize> = serde_json::from_value(r["children"].clone()).unwrap();
        assert_eq!(children, want.children);
        let loops: Vec<Vec<[f64; 3]>> = want.loops.iter().map(|l| triples(&l.vertices)).collect();
        assert_eq!(json_loops(&r["loops"]), loops);
    }
    let order: Vec<usize> = serde_json::from_value(doc["order"].clone()).unwrap();
    assert_eq!(order, p.order);
    assert_eq!(doc["truncated"].as_bool(), Some(p.truncated));
    let uncut = doc["uncut"].as_array().unwrap();
    assert_eq!(uncut.len(), p.uncut.len());
    for (u, want) in uncut.iter().zip(&p.uncut) {
        assert_eq!(u["area"].as_f64(), Some(want.area));
        let loops: Vec<Vec<[f64; 3]>> = want.loops.iter().map(|l| triples(l)).collect();
        assert_eq!(json_loops(&u["loops"]), loops);
    }
    // DXF: the rings in machining order, then the uncut regions.
    let mut want: Vec<Vec<RawVertex>> =
        p.order.iter().flat_map(|&i| &p.rings[i].loops).map(|l| raw(&l.vertices)).collect();
    want.extend(p.uncut.iter().flat_map(|u| &u.loops).map(|l| raw(l)));
    let drawing = read_dxf(&p.to_dxf()).unwrap();
    assert_eq!(drawing.polylines.iter().map(|p| p.vertices.clone()).collect::<Vec<_>>(), want);
}

#[test]
fn vcarve_json_and_dxf_carry_depths_exactly() {
    let shape = plate();
    let axis = medial_axis(&shape, &AxisOptions::default()).unwrap();
    let opts = VCarveOptions { angle_deg: 60.0, max_depth: 0.4, tolerance: 0.0 };
    let v = vcarve(&shape, &axis, &opts).unwrap();
    assert!(!v.paths.is_empty() && !v.flat.is_empty());
    let text = v.to_json();
    let doc: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(text, serde_json::to_string(&doc).unwrap() + "\n");
    assert_eq!(doc["max_depth"].as_f64(), Some(0.4));
    assert_eq!(doc["flat_radius"].as_f64(), Some(v.flat_radius()));
    let paths: Vec<Vec<[f64; 3]>> = serde_json::from_value(doc["paths"].clone()).unwrap();
    assert_eq!(paths, v.paths.iter().map(|p| p.points.clone()).collect::<Vec<_>>());
    let flat: Vec<Vec<[f64; 3]>> = v.flat.loops.iter().map(|l| triples(&l.vertices)).collect();
    assert_eq!(json_loops(&doc["flat"]["loops"]), flat);
    // Without a cap, max_depth is null.
    let uncapped = VCarveOptions { max_depth: f64::INFINITY, ..opts };
    let free = vcarve(&shape, &axis, &uncapped).unwrap();
    let text = free.to_json();
    let doc: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(text, serde_json::to_string(&doc).unwrap() + "\n");
    assert!(doc["max_depth"].is_null());
    // DXF: a 3D polyline per path at z = -depth (the 2D reader skips them),
    // the flat rings as closed LWPOLYLINEs at elevation -max_depth.
    let text = v.to_dxf();
    assert_eq!(text.matches("\nPOLYLINE\n").count(), v.paths.len());
    assert_eq!(text.matches("\n 38\n-0.4\n").count(), v.flat.loops.len());
    let deepest = v.paths.iter().flat_map(|p| &p.points).map(|p| p[2]).fold(0.0, f64::max);
    assert!(text.contains(&format!("\n 30\n{}\n", -deepest)));
    let drawing = read_dxf(&text).unwrap();
    let want: Vec<Vec<RawVertex>> = v.flat.loops.iter().map(|l| raw(&l.vertices)).collect();
    assert_eq!(drawing.polylines.iter().map(|p| p.vertices.clone()).collect::<Vec<_>>(), want);
}

/// The DXF of a smooth curve's offsets (where disks hug stretches of
/// nearly concentric arcs), read back, lies at each distance from the
/// boundary at points along every arc: what a CAM reader takes for G2/G3
/// (bulge → centre) is the offset itself. Distances by brute force over
/// the boundary's elements.
#[test]
fn dxf_offsets_of_a_smooth_curve_lie_at_their_distances() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/offset_arc_merge_blob_2000.json");
    let shape = Shape2d::from_json_str(&std::fs::read_to_string(path).unwrap(), &ShapeOptions::default()).unwrap();
    let offsets = Offsets::new(&shape, &OffsetOptions::default()).unwrap();
    let distances = [0.02, 0.1];
    let layers = offsets.layers(&distances).unwrap();
    let drawing = read_dxf(&offsets_to_dxf(&layers)).unwrap();
    assert_eq!(drawing.polylines.len(), 2);
    let boundary: Vec<medax::shape::Element> = shape.loops().iter().flat_map(|l| l.elements()).collect();
    let diag = shape.bbox().diagonal();
    for (poly, d) in drawing.polylines.iter().zip(distances) {
        let vs = &poly.vertices;
        for (i, a) in vs.iter().enumerate().step_by(7) {
            let b = &vs[(i + 1) % vs.len()];
            let e = medax::shape::Element::from_bulge(
                medax::kernel::Point::new(a.x, a.y),
                medax::kernel::Point::new(b.x, b.y),
                a.bulge,
            );
            for k in 0..8 {
                let q = e.point_at(k as f64 / 8.0);
                let dist = boundary.iter().map(|x| x.closest_point(q).0).fold(f64::INFINITY, f64::min);
                assert!((dist - d).abs() <= 1e-9 * diag, "offset {d}, element {i}: {q:?} at {dist}");
            }
        }
    }
}
