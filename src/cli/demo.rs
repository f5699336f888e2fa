//! The demo: what `cargo run --release` does with no arguments.

use super::info::report;
use medax::shape::{Shape2d, ShapeOptions};
use std::path::Path;
use std::process::ExitCode;

/// A plate with arcs, a semicircular notch, a step, a round hole and a slot.
pub const DEMO_SHAPE: &str = include_str!("demo_shape.json");

pub fn run(output: &Path) -> Result<(), ExitCode> {
    let shape = Shape2d::from_json_str(DEMO_SHAPE, &ShapeOptions::default()).map_err(|e| {
        eprintln!("medax: demo shape rejected (a bug): {e}");
        ExitCode::from(70)
    })?;
    println!("medax {} demo: the embedded plate", medax::VERSION);
    print!("{}", report(&shape));
    super::write_file(output, &shape.to_svg(900.0))?;
    println!("wrote picture: {}", std::fs::canonicalize(output).unwrap_or(output.to_path_buf()).display());
    Ok(())
}
