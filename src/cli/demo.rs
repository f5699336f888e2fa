//! The demo: what `cargo run --release` does with no arguments.

use super::info::report;
use medax::plane::{medial_axis, AxisOptions, AxisPicture};
use medax::shape::{Shape2d, ShapeOptions};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// A profile with arcs, a round notch, a step and a V cut.
pub const DEMO_SHAPE: &str = include_str!("demo_shape.json");

pub fn run(output: &Path) -> Result<(), ExitCode> {
    let bug = |what: String| {
        eprintln!("medax: demo: {what} (a bug)");
        ExitCode::from(70)
    };
    let shape = Shape2d::from_json_str(DEMO_SHAPE, &ShapeOptions::default()).map_err(|e| bug(e.to_string()))?;
    out!("medax {} demo: the embedded profile", medax::VERSION);
    super::put(&report(&shape));
    let t = Instant::now();
    let axis = medial_axis(&shape, &AxisOptions::default()).map_err(|e| bug(e.to_string()))?;
    out!(
        "medial axis: {} nodes, {} edges in {:.1} ms",
        axis.nodes.len(),
        axis.edges.len(),
        t.elapsed().as_secs_f64() * 1e3
    );
    let pic = AxisPicture { width_px: 900.0, tolerance: 1e-4 * shape.bbox().diagonal(), disks: true };
    super::write_file(output, &axis.to_svg(&shape, &pic))?;
    out!("wrote picture: {}", std::fs::canonicalize(output).unwrap_or(output.to_path_buf()).display());
    Ok(())
}
