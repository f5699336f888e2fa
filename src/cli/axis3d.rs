//! `medax axis3d`: the medial axis of a solid under a space ball, as the
//! JSON contract of the README, an OBJ mesh, or a PLY whose vertices carry
//! the radius and a colour by radius (blue small, red large) for a mesh
//! viewer.

use super::query3d::{feature_json, kind_name, parse_ball, part_json};
use super::{write_file, write_streamed};
use medax::io::mesh::write_obj;
use medax::shape::{Ball3, Mesh3d, MeshOptions};
use medax::space::{axis3d_svg, medial_axis_3d_watched, radius_rgb, Axis3, Opposite, Watch};
use serde_json::json;
use std::io::Write;
use std::path::Path;
use std::process::ExitCode;

/// The axis JSON: vertices `[x, y, z, r]`, triangles, and the sheets with
/// their triangles and two contact classes.
fn axis_json(axis: &Axis3) -> serde_json::Value {
    let sheets: Vec<_> = axis
        .sheets
        .iter()
        .map(|s| {
            let classes: Vec<_> = s.classes.iter().map(class_json).collect();
            json!({"kind": if s.jump { "jump_sheet" } else { "sheet" }, "triangles": s.triangles, "classes": classes})
        })
        .collect();
    json!({"vertices": axis.vertices, "triangles": axis.triangles, "sheets": sheets})
}

/// A contact class: its kind (`VF`, `EE`, `FV`), the ball's feature
/// (`{"vertex": i}`, `{"edge": k}`, `{"facet": f}`) and the surface's
/// (`{"face": t}`, `{"edge": [i, j]}`, `{"vertex": i}`).
fn class_json(c: &Opposite) -> serde_json::Value {
    json!({"kind": kind_name(c.kind), "ball": feature_json(c.ball), "surface": part_json(c.surface)})
}

/// PLY (ASCII) with a `radius` and an RGB colour per vertex.
fn write_ply_radius(w: &mut impl Write, axis: &Axis3) -> std::io::Result<()> {
    let (lo, hi) =
        axis.vertices.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v[3]), h.max(v[3])));
    let span = if hi > lo { hi - lo } else { 1.0 };
    writeln!(w, "ply\nformat ascii 1.0\ncomment medax axis3d: the medial axis, coloured by radius")?;
    writeln!(w, "element vertex {}", axis.vertices.len())?;
    writeln!(w, "property double x\nproperty double y\nproperty double z\nproperty double radius")?;
    writeln!(w, "property uchar red\nproperty uchar green\nproperty uchar blue")?;
    writeln!(w, "element face {}\nproperty list uchar uint vertex_indices\nend_header", axis.triangles.len())?;
    for v in &axis.vertices {
        let [r, g, b] = radius_rgb((v[3] - lo) / span);
        writeln!(w, "{} {} {} {} {r} {g} {b}", v[0], v[1], v[2], v[3])?;
    }
    for t in &axis.triangles {
        writeln!(w, "3 {} {} {}", t[0], t[1], t[2])?;
    }
    Ok(())
}

/// The axis, with a line of progress on stderr every five seconds while
/// it runs (a large solid takes minutes).
fn axis_with_progress(mesh: &Mesh3d, ball: &Ball3, threads: Option<usize>) -> Result<Axis3, String> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| format!("cannot start threads: {e}"))?;
    let watch = Watch::default();
    std::thread::scope(|scope| {
        let job = scope.spawn(|| pool.install(|| medial_axis_3d_watched(mesh, ball, &watch)));
        let start = std::time::Instant::now();
        let mut said = 0;
        while !job.is_finished() {
            std::thread::sleep(std::time::Duration::from_millis(50));
            let secs = start.elapsed().as_secs();
            if secs >= 5 * (said + 1) {
                said = secs / 5;
                eprintln!("medax: axis3d {:.0} % of the contact domains ({secs} s)", 100.0 * watch.fraction());
            }
        }
        job.join().map_err(|_| "the axis computation panicked (a defect)".to_string())?.map_err(|e| e.to_string())
    })
}

pub fn run(
    mesh_path: &Path,
    ball: &str,
    threads: Option<usize>,
    json_out: Option<&Path>,
    obj: Option<&Path>,
    ply: Option<&Path>,
    svg: Option<&Path>,
) -> Result<(), ExitCode> {
    let fail = |msg: String, code: u8| {
        eprintln!("medax: {msg}");
        ExitCode::from(code)
    };
    let ball = parse_ball(ball).map_err(|m| fail(m, 2))?;
    let mesh = Mesh3d::from_path(mesh_path, &MeshOptions::default())
        .map_err(|e| fail(format!("{}: {e}", mesh_path.display()), 1))?;
    let start = std::time::Instant::now();
    let axis =
        axis_with_progress(&mesh, &ball, threads).map_err(|e| fail(format!("{}: {e}", mesh_path.display()), 1))?;
    eprintln!(
        "medax: axis of {} triangles: {} sheets, {} triangles, {} vertices in {:.3} s",
        mesh.triangles().len(),
        axis.sheets.len(),
        axis.triangles.len(),
        axis.vertices.len(),
        start.elapsed().as_secs_f64()
    );
    if let Some(p) = obj {
        let pos: Vec<[f64; 3]> = axis.vertices.iter().map(|v| [v[0], v[1], v[2]]).collect();
        write_file(p, &write_obj(&pos, &axis.triangles))?;
    }
    if let Some(p) = ply {
        write_streamed(p, |w| write_ply_radius(w, &axis))?;
    }
    if let Some(p) = svg {
        write_file(p, &axis3d_svg(&mesh, &axis, 900.0))?;
    }
    let text = axis_json(&axis).to_string();
    match json_out {
        Some(p) => write_file(p, &text),
        None if obj.is_none() && ply.is_none() && svg.is_none() => {
            super::put(&text);
            super::put("\n");
            Ok(())
        }
        None => Ok(()),
    }
}
