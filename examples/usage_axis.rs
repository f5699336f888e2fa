//! Usage example: the medial axis of a shape, read node by node and edge by
//! edge, written as SVG and JSON.
//!
//! ```sh
//! cargo run --release --example usage_axis                     # the built-in plate
//! cargo run --release --example usage_axis -- part.dxf out/    # your own shape
//! ```
//!
//! Without arguments it uses a plate with a round hole, a square hole and
//! an arc on its right side; a JSON, DXF or SVG file given instead is read
//! by its content. It prints what the axis holds and writes
//! `usage_axis.svg` and `usage_axis.json` into the output directory (the
//! current one by default). Only `medax::plane` and `medax::shape` are used.

use std::error::Error;
use std::path::{Path, PathBuf};

use medax::plane::{medial_axis, AxisOptions, AxisPicture, NodeKind, Primitive};
use medax::shape::{Shape2d, ShapeOptions};

/// An 8 × 5 plate whose right side bulges out, with a round hole (two half
/// circles) and a square hole, in the medax JSON format: loop 0 is the
/// outer boundary, every further loop a hole, vertices `[x, y, bulge]`.
pub const PLATE: &str = r#"{"loops": [
  [[0, 0], [8, 0], [8, 5, 0.2], [0, 5]],
  [[2, 2, 1], [3, 2, 1]],
  [[5, 1.5], [6.5, 1.5], [6.5, 3], [5, 3]]
]}"#;

/// Names a primitive in the input's numbering: medax stores the outer loop
/// counter-clockwise and holes clockwise, reversing loops given the other
/// way, and `Primitive` indexes the stored loops.
fn describe(shape: &Shape2d, p: Primitive) -> String {
    let (l, i) = (p.loop_index(), p.index());
    match p {
        Primitive::Element { .. } => format!("loop {l} element {}", shape.input_element_index(l, i)),
        Primitive::Vertex { .. } => format!("loop {l} vertex {}", shape.input_vertex_index(l, i)),
    }
}

/// What the example found (the test in `tests/usage_examples.rs` checks it).
pub struct Report {
    /// Node count of the axis.
    pub nodes: usize,
    /// Edge count of the axis.
    pub edges: usize,
    /// Nodes of each kind: branch, corner, leaf, joint.
    pub kinds: [usize; 4],
    /// Radius of the largest maximal disk (the largest inscribed circle).
    pub largest_radius: f64,
    /// The files written.
    pub written: Vec<PathBuf>,
}

/// Computes the axis of `shape`, prints a summary and writes the SVG and
/// JSON files into `out_dir`.
pub fn run(shape: &Shape2d, out_dir: &Path) -> Result<Report, Box<dyn Error>> {
    let (segments, arcs) = shape.element_counts();
    println!(
        "shape: {} loops ({} holes), {segments} segments, {arcs} arcs, area {:.4}",
        shape.loops().len(),
        shape.holes().len(),
        shape.area()
    );

    // The seed fixes the divide step's random choices: the same seed gives
    // the same axis bit for bit, whatever the number of threads (rayon's
    // pool, RAYON_NUM_THREADS).
    let axis = medial_axis(shape, &AxisOptions::default())?;

    let mut kinds = [0usize; 4];
    for node in &axis.nodes {
        let k = match node.kind {
            NodeKind::Branch => 0,
            NodeKind::Corner => 1,
            NodeKind::Leaf => 2,
            NodeKind::Joint => 3,
        };
        kinds[k] += 1;
    }
    println!(
        "axis: {} nodes ({} branch, {} corner, {} leaf, {} joint), {} edges",
        axis.nodes.len(),
        kinds[0],
        kinds[1],
        kinds[2],
        kinds[3],
        axis.edges.len()
    );
    // One independent cycle round each hole, a tree without holes.
    assert_eq!(axis.edges.len() + 1, axis.nodes.len() + shape.holes().len());

    // Every node carries its maximal disk: the largest one is the largest
    // circle that fits in the shape (the deepest point of a V-carve, the
    // last ring of a pocket).
    let deepest = axis.nodes.iter().max_by(|a, b| a.radius.total_cmp(&b.radius)).ok_or("the axis has no nodes")?;
    println!(
        "largest inscribed circle: centre ({:.4}, {:.4}), radius {:.4}",
        deepest.point.x, deepest.point.y, deepest.radius
    );

    // Edges are conics between two boundary primitives; between their end
    // nodes they are evaluated on demand, sampled to a chordal tolerance.
    let tol = 1e-4 * shape.bbox().diagonal();
    for (i, edge) in axis.edges.iter().enumerate().take(5) {
        let samples = edge.sample(shape, &axis.nodes, tol);
        let (rmin, rmax) =
            samples.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), d| (lo.min(d.radius), hi.max(d.radius)));
        println!(
            "edge {i}: node {} -> node {}, {:?} between {} and {}, {} samples, radius {rmin:.4} to {rmax:.4}",
            edge.from,
            edge.to,
            edge.kind,
            describe(shape, edge.sites[0]),
            describe(shape, edge.sites[1]),
            samples.len()
        );
    }
    if axis.edges.len() > 5 {
        println!("... {} more edges", axis.edges.len() - 5);
    }

    std::fs::create_dir_all(out_dir)?;
    let svg = out_dir.join("usage_axis.svg");
    let picture = AxisPicture { width_px: 800.0, tolerance: tol, disks: true };
    std::fs::write(&svg, axis.to_svg(shape, &picture))?;
    // The JSON layout is documented in the README ("medax axis").
    let json = out_dir.join("usage_axis.json");
    std::fs::write(&json, axis.to_json(shape, tol))?;
    println!("wrote {} and {}", svg.display(), json.display());

    Ok(Report {
        nodes: axis.nodes.len(),
        edges: axis.edges.len(),
        kinds,
        largest_radius: deepest.radius,
        written: vec![svg, json],
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let options = ShapeOptions::default();
    // Shapes are validated when they are built: an invalid one is an error
    // that names the loop and element at fault.
    let shape = match args.first() {
        Some(path) => Shape2d::from_file(path, &options)?,
        None => Shape2d::from_json_str(PLATE, &options)?,
    };
    let out_dir = PathBuf::from(args.get(1).map_or(".", String::as_str));
    let report = run(&shape, &out_dir)?;
    println!(
        "{} nodes, {} edges, {} branch points, largest radius {:.4}, {} files",
        report.nodes,
        report.edges,
        report.kinds[0],
        report.largest_radius,
        report.written.len()
    );
    Ok(())
}
