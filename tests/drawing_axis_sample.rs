//! Medial axes of real drawings: 100 DXF files spread evenly over
//! LibreCAD's part library (Debian `librecad-data`), every shape each one
//! gives checked end to end. Made-up shapes in the other tests miss what
//! drafting produces (near-tangent arcs, tiny fillets, slivers, coordinates
//! far from the origin); here each shape must survive a JSON round trip
//! through validation again, and its axis must pass the oracle of
//! tests/common, which shares nothing with the construction.

mod common;

use common::oracle::{check, Boundary};
use medax::plane::{medial_axis, AxisOptions};
use medax::shape::{Drawing2d, DrawingOptions, Shape2d, ShapeOptions};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

const LIBRARY: &str = "/usr/share/librecad";
const SAMPLE: usize = 100;
/// Enough to reach most elements of a typical part without making the
/// brute-force bisection dominate the run.
const PROBES: usize = 200;

fn drawing(f: &Path) -> Option<Drawing2d> {
    Drawing2d::from_file(f, &ShapeOptions::default(), &DrawingOptions::default()).ok().filter(|d| !d.shapes.is_empty())
}

/// Re-validates `s`, computes its axis and runs the oracle: the worst
/// node's distance error and the worst off-axis probe, both relative to
/// the diagonal. The oracle panics on a mismatch.
fn check_shape(s: &Shape2d, seed: u64) -> Result<(f64, f64), String> {
    let again =
        Shape2d::from_json_str(&s.to_json(), &ShapeOptions::default()).map_err(|e| format!("revalidate: {e}"))?;
    let counts = |s: &Shape2d| (s.loops().len(), s.element_count());
    if counts(&again) != counts(s) {
        return Err(format!("revalidate: (loops, elements) {:?} became {:?}", counts(s), counts(&again)));
    }
    let axis = medial_axis(s, &AxisOptions::default()).map_err(|e| format!("axis: {e}"))?;
    let diag = s.bbox().diagonal();
    let report = check(s, &axis, PROBES, seed);
    let b = Boundary::new(s);
    let node_err = axis.nodes.iter().map(|n| (b.distance(n.point) - n.radius).abs()).fold(0.0, f64::max);
    Ok((node_err / diag, report.nested.1 / diag))
}

#[test]
fn axes_of_a_sample_of_the_librecad_library_pass_the_oracle() {
    let root = Path::new(LIBRARY);
    if !root.exists() {
        eprintln!("skipped: {LIBRARY} is not installed (Debian package librecad-data)");
        return;
    }
    let with_shapes: Vec<PathBuf> = common::dxf_files(root).into_iter().filter(|f| drawing(f).is_some()).collect();
    assert!(with_shapes.len() >= SAMPLE, "only {} files give a shape", with_shapes.len());
    let k = with_shapes.len() / SAMPLE;
    let (mut shapes, mut elements, mut worst_node, mut worst_probe) = (0, 0, 0.0f64, 0.0f64);
    let mut failures = Vec::new();
    for f in with_shapes.iter().step_by(k).take(SAMPLE) {
        for (i, s) in drawing(f).expect("read again").shapes.iter().enumerate() {
            shapes += 1;
            elements += s.element_count();
            // One shape's failure must not hide the others'.
            let outcome = catch_unwind(AssertUnwindSafe(|| check_shape(s, shapes as u64)));
            match outcome.unwrap_or_else(|p| {
                Err(p
                    .downcast_ref::<String>()
                    .cloned()
                    .or(p.downcast_ref::<&str>().map(|m| m.to_string()))
                    .unwrap_or_default())
            }) {
                Ok((node, probe)) => {
                    worst_node = worst_node.max(node);
                    worst_probe = worst_probe.max(probe);
                }
                Err(e) => failures.push(format!("{} shape {i} ({} elements): {e}", f.display(), s.element_count())),
            }
        }
    }
    eprintln!(
        "{SAMPLE} of {} files with shapes (every {k}th): {shapes} shapes, {elements} elements; worst node \
         |distance - radius| {worst_node:.1e} and worst off-axis probe {worst_probe:.1e} of the diagonal",
        with_shapes.len()
    );
    assert!(failures.is_empty(), "{} shapes failed:\n{}", failures.len(), failures.join("\n"));
}
