//! Convex solids from small sets of points on an integer grid (coplanar
//! and collinear points, faces parallel to ball facets: far from general
//! position), L-shaped prisms (a reflex edge: EE classes) with a cut
//! corner, height and shear from the input, and polycubes of up to 12
//! cells on a 3 × 3 × 2 grid, jittered or not (concave corners, saddles,
//! valleys: FV classes), under the preset balls and
//! random hulls: the 3D medial axis or a typed error, never a panic or a
//! hang; an axis returned is sound (every vertex inside, its radius the
//! largest ball there).
#![no_main]

use libfuzzer_sys::fuzz_target;
use medax::kernel::Point3;
use medax::shape::mesh_samples::{l_prism, polycube};
use medax::shape::{Ball3, Faces, Mesh3d, MeshOptions};
use medax::space::medial_axis_3d;

fn grid(v: &[(i8, i8, i8)]) -> Vec<Point3> {
    v.iter().map(|&(x, y, z)| Point3::new(f64::from(x) / 4.0, f64::from(y) / 4.0, f64::from(z) / 4.0)).collect()
}

fuzz_target!(|input: (Vec<(i8, i8, i8)>, u8, Vec<(i8, i8, i8)>)| {
    let (points, which, ball_points) = input;
    if points.len() < 4 || points.len() > 12 || ball_points.len() > 10 {
        return;
    }
    let ball = match which % 5 {
        0 => Ball3::tetrahedron(),
        1 => Ball3::cube(),
        2 => Ball3::octahedron(),
        3 => Ball3::tetrahedron().rotated([0.3, 0.2, -0.4]).unwrap(),
        _ => match Ball3::from_points(&grid(&ball_points)) {
            Ok(b) => b,
            Err(_) => return,
        },
    };
    if which & 0x40 != 0 {
        // A polycube; with 0x20 every vertex moved by up to ±0.12 (a
        // fixed pattern), so no two faces are coplanar.
        let cells: Vec<[i32; 3]> = points
            .iter()
            .map(|&(x, y, z)| [i32::from(x).rem_euclid(3), i32::from(y).rem_euclid(3), i32::from(z).rem_euclid(2)])
            .collect();
        let (mut v, t) = polycube(&cells, 1.0);
        if which & 0x20 != 0 {
            for (i, p) in v.iter_mut().enumerate() {
                for (k, x) in p.iter_mut().enumerate() {
                    *x += (((i * 7919 + k * 104_729) % 17) as f64 / 16.0 - 0.5) * 0.24;
                }
            }
        }
        let Ok(m) = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()) else { return };
        check(&m, &ball);
        return;
    }
    if which & 0x80 != 0 {
        // An L prism: the square [0, 4]² less the corner from (cx, cy),
        // extruded to a height, sheared.
        let q = |v: i8| 1.0 + f64::from(v.rem_euclid(24)) / 8.0;
        let (cx, cy, h) = points.first().map_or((2.0, 2.0, 1.0), |&(x, y, z)| (q(x), q(y), q(z)));
        let shear = points.get(1).map_or(0.0, |&(x, _, _)| f64::from(x) / 64.0);
        let (v, t) = l_prism(4.0, [cx, cy], h, shear);
        let Ok(m) = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()) else { return };
        check(&m, &ball);
        return;
    }
    // The hull of the points, as a solid.
    let Ok(hull) =
        Ball3::from_points(&grid(&points).iter().map(|&p| p + Point3::new(0.01, 0.02, 0.03)).collect::<Vec<_>>())
    else {
        return;
    };
    let v: Vec<[f64; 3]> = hull.vertices().iter().map(|p| [p.x, p.y, p.z]).collect();
    let mut indices = Vec::new();
    let mut starts = vec![0u32];
    for f in hull.facets() {
        indices.extend(f.vertices.iter().map(|&i| i as u32));
        starts.push(indices.len() as u32);
    }
    let Ok(m) =
        Mesh3d::from_polygons(&v, Faces { indices: &indices, starts: &starts, lines: &[] }, &MeshOptions::default())
    else {
        return;
    };
    check(&m, &ball);
});

/// The axis or a typed error; every vertex returned inside with the
/// largest ball's radius.
fn check(m: &Mesh3d, ball: &Ball3) {
    let Ok(axis) = medial_axis_3d(m, ball) else { return };
    let tris: Vec<[Point3; 3]> = m.triangles().iter().map(|t| t.map(|i| m.positions()[i as usize])).collect();
    let diag = m.bbox().diagonal();
    for q in &axis.vertices {
        let c = Point3::new(q[0], q[1], q[2]);
        assert!(
            m.tree().inside(c) != Some(false) || tris.iter().any(|t| near(c, *t, 1e-6 * diag)),
            "vertex {q:?} outside"
        );
        let r = m.tree().ball_radius(c, ball).map_or(f64::NAN, |b| b.radius);
        assert!((r - q[3]).abs() <= 1e-6 * diag, "vertex {q:?}: largest ball {r}");
    }
}

/// Whether `c` lies within `tol` of the plane of `t` (a vertex on the
/// surface, where the side test may say either).
fn near(c: Point3, t: [Point3; 3], tol: f64) -> bool {
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    (n.dot(c - t[0]) / n.norm()).abs() <= tol
}
