//! Runs the usage examples of `examples/` (the ones a user copies from, see
//! examples/README.md): each is compiled into this test as a module and its
//! `run` called with a fresh output directory, so a broken example fails
//! `cargo test`, not only a user who tries it.

#[allow(dead_code)]
#[path = "../examples/usage_axis.rs"]
mod usage_axis;

#[allow(dead_code)]
#[path = "../examples/usage_offsets.rs"]
mod usage_offsets;

use std::path::PathBuf;

use medax::shape::{Shape2d, ShapeOptions};

fn out_dir(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn assert_written(files: &[PathBuf]) {
    for f in files {
        let len = std::fs::metadata(f).map(|m| m.len()).unwrap_or(0);
        assert!(len > 0, "{} was not written", f.display());
    }
}

#[test]
fn usage_axis_runs() {
    let shape = Shape2d::from_json_str(usage_axis::PLATE, &ShapeOptions::default()).unwrap();
    let report = usage_axis::run(&shape, &out_dir("usage_axis")).unwrap();
    // Two holes: two independent cycles.
    assert_eq!(report.edges + 1, report.nodes + 2);
    // One corner node per convex vertex: the plate's four (the square
    // hole's corners are reflex seen from the plate).
    assert_eq!(report.kinds[1], 4);
    assert!(report.kinds[0] >= 4);
    assert!(report.largest_radius > 0.5 && report.largest_radius < 2.5);
    assert_written(&report.written);
}

#[test]
fn usage_offsets_runs() {
    let shape = usage_offsets::plate().unwrap();
    let report = usage_offsets::run(&shape, &out_dir("usage_offsets")).unwrap();
    assert_eq!(report.layers.len(), 5);
    // Outwards the area grows, inwards it shrinks with the distance.
    let areas: Vec<f64> = report.layers.iter().map(|&(_, _, a)| a).collect();
    assert!(areas.windows(2).all(|w| w[0] > w[1]), "areas {areas:?}");
    assert!(areas[0] > shape.area());
    assert!(report.rings > 3);
    assert!(report.uncut_area >= 0.0);
    assert!(report.vcarve_paths > 0);
    assert_written(&report.written);
    let gcode = std::fs::read_to_string(&report.written[2]).unwrap();
    assert!(gcode.contains("G3") || gcode.contains("G2"), "the rings round arcs, so there are arc moves");
    // Every G2/G3 centre (start + I, J) is as far from the arc's start as
    // from its end: the centre of the element's own circle (to the 10^-4 the
    // file is written with).
    let word = |line: &str, key: char| -> Option<f64> {
        line.split_whitespace().find(|w| w.starts_with(key)).and_then(|w| w[1..].parse().ok())
    };
    let (mut at, mut arcs) = ((0.0, 0.0), 0);
    for line in gcode.lines() {
        let (Some(x), Some(y)) = (word(line, 'X'), word(line, 'Y')) else { continue };
        if line.starts_with("G2") || line.starts_with("G3") {
            let (i, j) = (word(line, 'I').unwrap(), word(line, 'J').unwrap());
            let c = (at.0 + i, at.1 + j);
            let (r0, r1) = ((at.0 - c.0).hypot(at.1 - c.1), (x - c.0).hypot(y - c.1));
            assert!((r0 - r1).abs() <= 3e-4, "{line}: radius {r0} at the start, {r1} at the end");
            arcs += 1;
        }
        at = (x, y);
    }
    assert!(arcs > 0);
}
