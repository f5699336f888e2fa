//! Usage example: trimmed offsets, a pocket and a V-carve of one shape, and
//! the pocket's rings as G-code with exact arcs (G2/G3).
//!
//! ```sh
//! cargo run --release --example usage_offsets            # writes into the current directory
//! cargo run --release --example usage_offsets -- out/
//! ```
//!
//! The shape is built in code from bulge loops (the layout offsets come
//! back in). One medial axis serves every distance, the pocket and the
//! V-carve. Writes `usage_pocket.svg`, `usage_pocket.dxf`,
//! `usage_pocket.nc` and `usage_vcarve.svg`. Only the public API is used.

use std::error::Error;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use medax::cam::{pocket, vcarve, PocketOptions, PocketOrder, VCarveOptions};
use medax::kernel::Point;
use medax::plane::{medial_axis, AxisOptions, OffsetOptions, Offsets};
use medax::shape::{Shape2d, ShapeOptions, Vertex};

/// What the example found (the test in `tests/usage_examples.rs` checks it).
pub struct Report {
    /// (distance, loop count, area) per offset asked for.
    pub layers: Vec<(f64, usize, f64)>,
    /// Rings of the pocket.
    pub rings: usize,
    /// Area the pocketing tool cannot reach.
    pub uncut_area: f64,
    /// V-carve paths.
    pub vcarve_paths: usize,
    /// The files written.
    pub written: Vec<PathBuf>,
}

/// A 10 × 6 plate with rounded right-hand corners (bulge tan(90°/4)), a
/// round hole and a triangular island.
pub fn plate() -> Result<Shape2d, Box<dyn Error>> {
    let v = |x, y, bulge| Vertex { p: Point::new(x, y), bulge };
    let quarter = (std::f64::consts::PI / 8.0).tan();
    let outer = vec![
        v(0.0, 0.0, 0.0),
        v(9.0, 0.0, quarter),
        v(10.0, 1.0, 0.0),
        v(10.0, 5.0, quarter),
        v(9.0, 6.0, 0.0),
        v(0.0, 6.0, 0.0),
    ];
    // Two half circles (bulge 1) make the round hole.
    let round_hole = vec![v(2.0, 3.0, 1.0), v(3.5, 3.0, 1.0)];
    let island = vec![v(6.0, 1.5, 0.0), v(8.0, 3.0, 0.0), v(6.0, 4.5, 0.0)];
    Ok(Shape2d::from_bulge_loops(vec![outer, round_hole, island], &ShapeOptions::default())?)
}

/// Appends the moves along one closed bulge loop to `gcode`: G1 for a
/// segment, G2/G3 (clockwise/counter-clockwise) for an arc with its centre
/// as I/J relative to the arc's start, as most controllers read them.
fn loop_gcode(gcode: &mut String, vertices: &[Vertex]) {
    let start = vertices[0].p;
    let _ = writeln!(gcode, "G0 X{:.4} Y{:.4}", start.x, start.y);
    for (i, a) in vertices.iter().enumerate() {
        let b = vertices[(i + 1) % vertices.len()].p;
        if a.bulge == 0.0 {
            let _ = writeln!(gcode, "G1 X{:.4} Y{:.4}", b.x, b.y);
            continue;
        }
        // bulge = tan(sweep / 4); the centre lies off the chord's midpoint
        // along its left normal, by chord · (1 − bulge²) / (4 · bulge).
        let (dx, dy) = (b.x - a.p.x, b.y - a.p.y);
        let k = (1.0 - a.bulge * a.bulge) / (4.0 * a.bulge);
        let centre = (a.p.x + dx / 2.0 - dy * k, a.p.y + dy / 2.0 + dx * k);
        let code = if a.bulge > 0.0 { "G3" } else { "G2" };
        let _ = writeln!(gcode, "{code} X{:.4} Y{:.4} I{:.4} J{:.4}", b.x, b.y, centre.0 - a.p.x, centre.1 - a.p.y);
    }
}

/// Computes offsets, a pocket and a V-carve of `shape`, prints a summary
/// and writes the files into `out_dir`.
pub fn run(shape: &Shape2d, out_dir: &Path) -> Result<Report, Box<dyn Error>> {
    // Compute the axis once and hand it to every consumer: offsets,
    // pocket and V-carve all follow it.
    let axis = medial_axis(shape, &AxisOptions::default())?;
    // Outer offsets (negative distances) are inner offsets of the shape's
    // complement, whose axis needs to know how far out they will be asked
    // for: here up to 0.5.
    let outer = OffsetOptions { outer_reach: 0.5, ..OffsetOptions::default() };
    let offsets = Offsets::from_axis(shape, &axis)?.with_outer(shape, &outer)?;
    println!("largest inscribed radius {:.4}", offsets.max_inner_distance());

    // Positive distances go inwards. The layers are computed in parallel.
    let distances = [-0.5, 0.25, 0.5, 1.0, 2.0];
    let mut layers = Vec::new();
    for layer in offsets.layers(&distances)? {
        let holes = layer.loops.iter().filter(|l| l.is_hole()).count();
        println!(
            "offset {:>5}: {} loops ({} holes) in {} regions, area {:.4}",
            layer.distance,
            layer.loops.len(),
            holes,
            layer.regions.len(),
            layer.area()
        );
        // A region is one connected piece of what is left: an outer loop
        // (counter-clockwise) and the holes in it (clockwise), indices into
        // `layer.loops`.
        for (k, region) in layer.regions.iter().enumerate() {
            let outer = &layer.loops[region.outer];
            println!(
                "  region {k}: outer loop of {} vertices, area {:.4}, {} holes",
                outer.vertices.len(),
                outer.area,
                region.holes.len()
            );
        }
        layers.push((layer.distance, layer.loops.len(), layer.area()));
    }

    // A tool of radius 0.2 with a stepover of 0.3, from the wall inwards.
    let options = PocketOptions { order: PocketOrder::OutsideIn, ..PocketOptions::new(0.2, 0.3) };
    let rings = pocket(&offsets, &options)?;
    println!(
        "pocket: {} rings in {} levels, uncut area {:.6} in {} regions",
        rings.rings.len(),
        rings.level_count(),
        rings.uncut_area(),
        rings.uncut.len()
    );
    // Plan moves only: a real program adds the plunge and retract (Z) and
    // feeds that suit its machine.
    let mut gcode = String::from("G21 G90 G17\n");
    for &i in &rings.order {
        let ring = &rings.rings[i];
        let _ = writeln!(gcode, "(ring {i}, level {}, distance {:.4})", ring.level, ring.distance);
        for l in &ring.loops {
            loop_gcode(&mut gcode, &l.vertices);
        }
    }
    gcode.push_str("M2\n");

    // A 60° V-bit no deeper than 0.4: where the walls are farther apart the
    // bottom is flat, bounded by the offset at 0.4 · tan(30°).
    let carve = vcarve(shape, &axis, &VCarveOptions { angle_deg: 60.0, max_depth: 0.4, tolerance: 0.0 })?;
    println!(
        "v-carve: {} paths, deepest {:.4}, flat bottom from radius {:.4} ({} loops)",
        carve.paths.len(),
        carve.deepest(),
        carve.flat_radius(),
        carve.flat.loops.len()
    );

    std::fs::create_dir_all(out_dir)?;
    let tol = 1e-4 * shape.bbox().diagonal();
    let files = [
        ("usage_pocket.svg", rings.to_svg(shape, &axis, 800.0, tol)),
        ("usage_pocket.dxf", rings.to_dxf()),
        ("usage_pocket.nc", gcode),
        ("usage_vcarve.svg", carve.to_svg(shape, &axis, 800.0, tol)),
    ];
    let mut written = Vec::new();
    for (name, text) in files {
        let path = out_dir.join(name);
        std::fs::write(&path, text)?;
        println!("wrote {}", path.display());
        written.push(path);
    }

    Ok(Report {
        layers,
        rings: rings.rings.len(),
        uncut_area: rings.uncut_area(),
        vcarve_paths: carve.paths.len(),
        written,
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let out_dir = PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| ".".into()));
    let report = run(&plate()?, &out_dir)?;
    println!(
        "{} offsets, {} rings, uncut area {:.6}, {} v-carve paths, {} files",
        report.layers.len(),
        report.rings,
        report.uncut_area,
        report.vcarve_paths,
        report.written.len()
    );
    Ok(())
}
