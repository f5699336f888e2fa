//! `medax query3d`: for each point of a JSON file, which side of a solid it
//! lies on, the closest surface point and, under a space ball, the largest
//! ball at it, as JSON.

use medax::io::mesh::read_mesh;
use medax::kernel::Point3;
use medax::shape::{Ball3, ContactKind3, ExactContacts, Feature3, Mesh3d, MeshOptions, SurfacePart};
use rayon::prelude::*;
use serde_json::{json, Value};
use std::path::Path;
use std::process::ExitCode;

/// The space ball a name or file gives: `tetrahedron` (`tetra`), `cube`,
/// `octahedron` (`octa`), `icosahedron` (`icosa`), `geodesic:N`, or a mesh
/// file whose vertices' hull is the ball; `@RX,RY,RZ` after it turns it
/// (a rotation vector in radians, as `Ball3::rotated`): presets are
/// aligned with the axes, and so are most CAD solids, which puts a ball
/// edge or facet parallel to a face (outside general position).
pub fn parse_ball(spec: &str) -> Result<Ball3, String> {
    // A file name may hold an `@` too: a rotation only when three numbers
    // follow the last one.
    if let Some((name, turn)) = spec.rsplit_once('@') {
        let r: Result<Vec<f64>, _> = turn.split(',').map(|x| x.trim().parse::<f64>()).collect();
        if let Ok([x, y, z]) = r.as_deref() {
            return parse_ball(name)?.rotated([*x, *y, *z]).map_err(|e| format!("--ball {spec}: {e}"));
        }
    }
    match spec {
        "tetra" | "tetrahedron" => return Ok(Ball3::tetrahedron()),
        "cube" => return Ok(Ball3::cube()),
        "octa" | "octahedron" => return Ok(Ball3::octahedron()),
        "icosa" | "icosahedron" => return Ok(Ball3::icosahedron()),
        _ => {}
    }
    if let Some(n) = spec.strip_prefix("geodesic:") {
        let n: usize = n.parse().map_err(|_| format!("--ball {spec}: geodesic:N wants a facet count"))?;
        return Ball3::geodesic(n).map_err(|e| format!("--ball {spec}: {e}"));
    }
    let bytes = std::fs::read(spec).map_err(|e| {
        format!("--ball {spec}: not tetra, cube, octa, icosa or geodesic:N, and not a readable mesh file ({e})")
    })?;
    let raw = read_mesh(&bytes, medax::io::mesh::MeshFormat::from_path(Path::new(spec)))
        .map_err(|e| format!("--ball {spec}: {e}"))?;
    let points: Vec<Point3> = raw.positions.iter().map(|&p| Point3::from_array(p)).collect();
    Ball3::from_points(&points).map_err(|e| format!("--ball {spec}: {e}"))
}

fn read_points(path: &Path) -> Result<Vec<Point3>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let v: Value = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let list =
        v["points"].as_array().ok_or_else(|| format!("{}: wants {{\"points\": [[x, y, z], ...]}}", path.display()))?;
    list.iter()
        .enumerate()
        .map(|(i, p)| {
            let c: Vec<f64> = p.as_array().map(|a| a.iter().filter_map(Value::as_f64).collect()).unwrap_or_default();
            match c[..] {
                [x, y, z] if c.iter().all(|v| v.is_finite()) => Ok(Point3::new(x, y, z)),
                _ => Err(format!("{}: point {i} is not three finite numbers", path.display())),
            }
        })
        .collect()
}

pub(super) fn kind_name(k: ContactKind3) -> &'static str {
    match k {
        ContactKind3::VertexFace => "VF",
        ContactKind3::EdgeEdge => "EE",
        ContactKind3::FaceVertex => "FV",
        ContactKind3::VertexEdge => "VE",
        ContactKind3::EdgeVertex => "EV",
        ContactKind3::VertexVertex => "VV",
    }
}

/// A ball feature as JSON: `{"vertex"|"edge"|"facet": i}`.
pub(super) fn feature_json(f: Feature3) -> Value {
    match f {
        Feature3::Vertex(i) => json!({ "vertex": i }),
        Feature3::Edge(i) => json!({ "edge": i }),
        Feature3::Facet(i) => json!({ "facet": i }),
    }
}

/// A surface feature as JSON: `{"vertex": v}`, `{"edge": [a, b]}` or
/// `{"face": t}`.
pub(super) fn part_json(p: SurfacePart) -> Value {
    match p {
        SurfacePart::Vertex(v) => json!({ "vertex": v }),
        SurfacePart::Edge(e) => json!({ "edge": e }),
        SurfacePart::Face(t) => json!({ "face": t }),
    }
}

/// The exact contacts as JSON: `[{"kind", "ball": {"vertex"|"edge"|"facet": i},
/// "surface": {"vertex": v}|{"edge": [a, b]}|{"face": t}, "triangle", "point", "flat"}, ...]`.
fn contacts_json(x: &ExactContacts) -> Value {
    let list: Vec<Value> = x
        .contacts
        .iter()
        .map(|c| {
            let (ball, surface) = (feature_json(c.ball), part_json(c.surface));
            json!({"kind": kind_name(c.kind), "ball": ball, "surface": surface, "triangle": c.triangle,
                   "point": c.point.to_array(), "flat": c.flat})
        })
        .collect();
    Value::Array(list)
}

pub fn run(
    mesh_path: &Path,
    ball: Option<&str>,
    points: &Path,
    exact: bool,
    json_out: Option<&Path>,
) -> Result<(), ExitCode> {
    let fail = |msg: String, code: u8| {
        eprintln!("medax: {msg}");
        ExitCode::from(code)
    };
    let ball = ball.map(parse_ball).transpose().map_err(|m| fail(m, 2))?;
    let mesh = Mesh3d::from_path(mesh_path, &MeshOptions::default())
        .map_err(|e| fail(format!("{}: {e}", mesh_path.display()), 1))?;
    let points = read_points(points).map_err(|m| fail(m, 2))?;
    // The ball prepared once for all points (its facet graph and
    // direction table), not once per point.
    let reach = ball.as_ref().map(|b| b.reach());
    let results: Vec<Value> = points
        .par_iter()
        .map(|&p| {
            let side = mesh.inside(p);
            let c = mesh.tree().closest_point(p).expect("a valid solid has triangles");
            let mut r = json!({
                "inside": side == Some(true),
                "on_surface": side.is_none(),
                "distance": c.squared_distance.sqrt(),
                "closest": c.point.to_array(),
            });
            if let (Some(b), Some(true), true) = (&reach, side, exact) {
                let x = mesh.tree().exact_contacts(p, b).expect("a valid solid has triangles");
                r["ball_radius"] = json!(x.radius);
                let first = x.contacts[0];
                r["contact"] =
                    json!({"point": first.point.to_array(), "triangle": first.triangle, "kind": kind_name(first.kind)});
                r["contacts"] = contacts_json(&x);
            } else if let (Some(b), Some(true)) = (&reach, side) {
                let k = mesh.tree().ball_radius_with(p, b).expect("a valid solid has triangles");
                r["ball_radius"] = json!(k.radius);
                r["contact"] = json!({"point": k.point.to_array(), "triangle": k.triangle, "kind": kind_name(k.kind)});
            }
            r
        })
        .collect();
    let inside = results.iter().filter(|r| r["inside"] == json!(true)).count();
    let doc = json!({ "results": results });
    match json_out {
        Some(path) => {
            super::write_file(path, &doc.to_string())?;
            out!("{} points, {inside} inside; wrote {}", points.len(), path.display());
        }
        None => out!("{doc}"),
    }
    Ok(())
}
