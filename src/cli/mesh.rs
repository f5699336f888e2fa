//! `medax info` on a solid (.obj, .off, .stl, .ply): the validation report
//! or the typed error.

use medax::io::mesh::{write_obj, write_off, write_ply, MeshFormat};
use medax::shape::{Mesh3d, MeshError, MeshOptions};
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// True when `path` names a mesh file by its extension.
pub fn is_mesh(path: &Path) -> bool {
    MeshFormat::from_path(path).is_some()
}

/// The report of a valid solid.
pub fn report(m: &Mesh3d) -> String {
    let b = m.bbox();
    let r = m.report();
    let mut out = String::new();
    let cavities = m.components().iter().filter(|c| c.depth % 2 == 1).count();
    out += &format!(
        "valid solid: {} component(s) ({} cavit{})\n",
        m.components().len(),
        cavities,
        if cavities == 1 { "y" } else { "ies" }
    );
    out += &format!("vertices: {}, triangles: {}\n", m.positions().len(), m.triangles().len());
    out += &format!("volume: {}\narea: {}\n", m.volume(), m.area());
    out += &format!(
        "bounding box: [{}, {}] x [{}, {}] x [{}, {}]\n",
        b.min.x, b.max.x, b.min.y, b.max.y, b.min.z, b.max.z
    );
    const SHOWN: usize = 10;
    for (i, c) in m.components().iter().enumerate().take(SHOWN) {
        let role = if c.depth % 2 == 1 { "cavity" } else { "solid" };
        out += &format!(
            "  component {i}: {role}, {} triangles, genus {}, volume {}{}\n",
            c.triangles,
            c.genus,
            c.volume,
            c.parent.map_or(String::new(), |p| format!(", inside component {p}"))
        );
    }
    if m.components().len() > SHOWN {
        out += &format!("  … ({} components in all)\n", m.components().len());
    }
    for (n, what) in [
        (r.welded, "vertices welded onto an equal one"),
        (r.unused_vertices, "vertices used by no face, dropped"),
        (r.polygons_triangulated, "polygon faces cut into triangles"),
        (r.triangles_reoriented, "triangles reversed to agree with their neighbours"),
        (r.components_reversed, "components reversed to face out of the material"),
    ] {
        if n > 0 {
            out += &format!("{what}: {n}\n");
        }
    }
    out
}

fn load(path: &Path) -> Result<Mesh3d, ExitCode> {
    Mesh3d::from_path(path, &MeshOptions::default()).map_err(|e| {
        eprintln!("medax: {}: {e}", path.display());
        match e {
            MeshError::Io { .. } => ExitCode::from(3),
            _ => ExitCode::from(1),
        }
    })
}

pub fn run_convert(input: &Path, output: &Path) -> Result<(), ExitCode> {
    let mesh = load(input)?;
    let p: Vec<[f64; 3]> = mesh.positions().iter().map(|q| q.to_array()).collect();
    let t = mesh.triangles();
    let bytes = match MeshFormat::from_path(output) {
        Some(MeshFormat::Obj) => write_obj(&p, t).into_bytes(),
        Some(MeshFormat::Off) => write_off(&p, t).into_bytes(),
        Some(MeshFormat::Ply) => write_ply(&p, t, true),
        _ => {
            eprintln!("medax: {}: write .obj, .off or .ply", output.display());
            return Err(ExitCode::from(2));
        }
    };
    std::fs::write(output, bytes).map_err(|e| {
        eprintln!("medax: cannot write {}: {e}", output.display());
        ExitCode::from(3)
    })?;
    out!("wrote {} ({} vertices, {} triangles)", output.display(), p.len(), t.len());
    Ok(())
}

pub fn run_info(path: &Path) -> Result<(), ExitCode> {
    let t = Instant::now();
    let mesh = load(path)?;
    super::put(&report(&mesh));
    out!("read and validated in {:.3} s", t.elapsed().as_secs_f64());
    Ok(())
}
