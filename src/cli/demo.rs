//! The demo: what `cargo run --release` does with no arguments.

use super::info::report;
use medax::cam::{draw::draw_pocket, pocket, PocketOptions};
use medax::plane::{medial_axis, AxisOptions, AxisPicture, Offsets};
use medax::shape::{draw_joints, shape_document, Shape2d, ShapeOptions};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// A profile with arcs, a round notch, a step and a V cut.
pub const DEMO_SHAPE: &str = include_str!("demo_shape.json");

/// The demo's pocketing tool: radius and stepover in the profile's units
/// (it is 120 × 70), so that a handful of rings show and the V cut and the
/// step leave some material uncut.
const TOOL_RADIUS: f64 = 3.0;
const STEPOVER: f64 = 4.0;

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
    let t = Instant::now();
    let offsets = Offsets::from_axis(&shape, &axis).map_err(|e| bug(e.to_string()))?;
    let rings = pocket(&offsets, &PocketOptions::new(TOOL_RADIUS, STEPOVER)).map_err(|e| bug(e.to_string()))?;
    let uncut = rings.uncut_area();
    let pocket_caption = format!(
        "pocket rings (grey): tool radius {TOOL_RADIUS}, stepover {STEPOVER}: {} rings; uncut (orange) area {uncut:.1}",
        rings.rings.len()
    );
    out!("{pocket_caption}, in {:.1} ms", t.elapsed().as_secs_f64() * 1e3);
    let pic = AxisPicture { width_px: 900.0, tolerance: 1e-4 * shape.bbox().diagonal(), disks: true };
    let mut doc = shape_document(&shape, 0.0, pic.width_px);
    draw_joints(&mut doc, &shape);
    draw_pocket(&mut doc, &rings, Some("#7f8c8d"));
    axis.draw_axis(&mut doc, &shape, &pic);
    doc.caption(0, &axis.picture_caption());
    doc.caption(1, &pocket_caption);
    super::write_file(output, &doc.finish())?;
    out!("wrote picture: {}", std::fs::canonicalize(output).unwrap_or(output.to_path_buf()).display());
    Ok(())
}
