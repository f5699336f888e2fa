//! The medial axis of convex solids under polyhedral balls
//! (`medax::space::medial_axis_3d`), against a brute-force oracle that
//! shares nothing with the library (`common::maximal_oracle`): every axis
//! vertex is inside and its radius is the largest ball there (least gauge
//! over every triangle); from random face points the maximal* ball's
//! centre lies on the axis triangles (completeness). Solids with reflex
//! edges: `space_axis_reflex.rs`.

mod common;

use common::maximal_oracle::{balls, least_gauge, oracle_radius, planes, to_triangle, vf_anchor};
use medax::kernel::Point3;
use medax::shape::mesh_samples::cuboid;
use medax::shape::{Ball3, Faces, Mesh3d, MeshOptions};
use medax::space::medial_axis_3d;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

/// The convex hull of `points` as a solid (the hull of a ball's points).
fn hull_solid(points: &[Point3]) -> Mesh3d {
    let hull = Ball3::from_points(points).unwrap();
    let v: Vec<[f64; 3]> = hull.vertices().iter().map(|p| [p.x, p.y, p.z]).collect();
    let mut indices = Vec::new();
    let mut starts = vec![0u32];
    for f in hull.facets() {
        indices.extend(f.vertices.iter().map(|&i| i as u32));
        starts.push(indices.len() as u32);
    }
    Mesh3d::from_polygons(&v, Faces { indices: &indices, starts: &starts, lines: &[] }, &MeshOptions::default())
        .unwrap()
}

fn convex_solids() -> Vec<(&'static str, Mesh3d)> {
    let mut rng = SmallRng::seed_from_u64(3);
    let mut jitter = |p: [f64; 3]| {
        Point3::new(p[0], p[1], p[2]) * 3.0
            + Point3::new(rng.gen_range(-0.1..0.1), rng.gen_range(-0.1..0.1), rng.gen_range(-0.1..0.1))
    };
    let octahedron: Vec<Point3> =
        [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
            .map(&mut jitter)
            .to_vec();
    let mut rng = SmallRng::seed_from_u64(4);
    let cloud: Vec<Point3> = (0..30)
        .map(|_| {
            let v = Point3::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
            Point3::new(2.0 * v.x, 1.2 * v.y, v.z) * (1.0 / v.norm())
        })
        .collect();
    let (bv, bt) = cuboid([0.0, 0.0, 0.0], [3.0, 2.0, 1.5]);
    vec![
        ("perturbed octahedron", hull_solid(&octahedron)),
        ("hull of 30 points on an ellipsoid", hull_solid(&cloud)),
        ("box", Mesh3d::from_triangles(&bv, &bt, &MeshOptions::default()).unwrap()),
    ]
}

#[test]
fn axis_vertices_are_largest_balls_and_every_maximal_ball_lies_on_the_axis() {
    let mut rng = SmallRng::seed_from_u64(56);
    for (solid, m) in convex_solids() {
        let diag = m.bbox().diagonal();
        let tris: Vec<[Point3; 3]> = m.triangles().iter().map(|t| t.map(|i| m.positions()[i as usize])).collect();
        for (name, ball) in balls() {
            let what = format!("{solid}, {name}");
            let axis = medial_axis_3d(&m, &ball).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert!(!axis.sheets.is_empty() && !axis.triangles.is_empty(), "{what}: empty axis");
            let pl = planes(&ball);
            for (i, q) in axis.vertices.iter().enumerate() {
                let c = Point3::new(q[0], q[1], q[2]);
                let inside = tris.iter().all(|t| (t[1] - t[0]).cross(t[2] - t[0]).dot(c - t[0]) <= 1e-9 * diag);
                assert!(inside, "{what}: axis vertex {i} at {c:?} outside");
                let r = tris.iter().map(|&t| least_gauge(&ball, &pl, c, t)).fold(f64::INFINITY, f64::min);
                assert!(
                    (r - q[3]).abs() <= 1e-9 * diag,
                    "{what}: vertex {i}: radius {} but the largest ball is {r}",
                    q[3]
                );
            }
            let at = |k: u32| {
                let v = axis.vertices[k as usize];
                Point3::new(v[0], v[1], v[2])
            };
            for _ in 0..12 {
                let face = rng.gen_range(0..m.triangles().len());
                let anchor = vf_anchor(&m, &ball, face);
                let (u, w) = (rng.gen_range(0.02..0.96f64), rng.gen_range(0.02..0.96f64));
                let (u, w) = if u + w < 0.98 { (u, w) } else { (0.98 - w, 0.98 - u) };
                let [a, b, c] = tris[face];
                let p = a + (b - a) * u + (c - a) * w;
                let rho = oracle_radius(&m, &ball, &pl, face, anchor, p);
                let centre = p - ball.vertices()[anchor] * rho;
                let off = axis.triangles.iter().map(|t| to_triangle(centre, t.map(at))).fold(f64::INFINITY, f64::min);
                assert!(
                    off <= 1e-7 * diag,
                    "{what}: the maximal* ball at face {face} {p:?} is centred {off} off the axis"
                );
            }
            eprintln!(
                "{what}: {} vertices, {} triangles, {} sheets",
                axis.vertices.len(),
                axis.triangles.len(),
                axis.sheets.len()
            );
        }
    }
}
