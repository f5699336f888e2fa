//! The largest ball c + r·B inside a solid at a centre, under polytope
//! balls: against the closed form in a box (the face planes' support
//! distances), and on tori under turned and off-centre balls against an
//! independent oracle (dense samples of the surface are never inside the
//! ball, and the contact point lies on the surface at gauge r).

use medax::kernel::Point3;
use medax::shape::mesh_samples::{cuboid, torus};
use medax::shape::{Ball3, Mesh3d, MeshOptions};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn mesh(soup: &(Vec<[f64; 3]>, Vec<[u32; 3]>)) -> Mesh3d {
    Mesh3d::from_triangles(&soup.0, &soup.1, &MeshOptions::default()).unwrap()
}

fn balls() -> Vec<(&'static str, Ball3)> {
    let mut rng = SmallRng::seed_from_u64(3);
    let cloud: Vec<Point3> = (0..40)
        .map(|_| {
            let v = Point3::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
            v * (1.0 / v.norm()) + Point3::new(0.3, -0.2, 0.1)
        })
        .collect();
    vec![
        ("cube", Ball3::cube()),
        ("octahedron", Ball3::octahedron()),
        ("tetrahedron", Ball3::tetrahedron()),
        ("icosahedron", Ball3::icosahedron()),
        ("geodesic 320", Ball3::geodesic(320).unwrap()),
        ("turned cube", Ball3::cube().rotated([0.3, -0.5, 0.9]).unwrap()),
        ("off-centre hull", Ball3::from_points(&cloud).unwrap()),
    ]
}

/// The support of the ball in direction `d`: max over its vertices of v · d.
fn support(ball: &Ball3, d: Point3) -> f64 {
    ball.vertices().iter().map(|v| v.dot(d)).fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn in_a_box_the_radius_is_the_nearest_face_planes_support_distance() {
    let (lo, hi) = ([-1.0, -2.0, 0.5], [3.0, 1.0, 2.0]);
    let m = mesh(&cuboid(lo, hi));
    let mut rng = SmallRng::seed_from_u64(11);
    for (name, ball) in balls() {
        for _ in 0..300 {
            let c = [0, 1, 2].map(|i| rng.gen_range(lo[i]..hi[i]));
            let mut expect = f64::INFINITY;
            for axis in 0..3 {
                let mut e = [0.0; 3];
                e[axis] = 1.0;
                let e = Point3::from_array(e);
                expect = expect.min((hi[axis] - c[axis]) / support(&ball, e));
                expect = expect.min((c[axis] - lo[axis]) / support(&ball, -e));
            }
            let got = m.ball_radius(Point3::from_array(c), &ball);
            assert!(
                (got.radius - expect).abs() <= 1e-12 * expect.max(1e-3),
                "{name} at {c:?}: {} vs {expect}",
                got.radius
            );
        }
    }
}

#[test]
fn on_a_torus_no_surface_sample_is_inside_and_the_contact_is_on_it() {
    let (v, t) = torus(3.0, 1.0, 40, 20);
    let m = mesh(&(v.clone(), t.clone()));
    // Dense samples of every triangle (corners, edge points, interior).
    let mut samples = Vec::new();
    for tri in &t {
        let [a, b, c] = tri.map(|i| Point3::from_array(v[i as usize]));
        for i in 0..=6 {
            for j in 0..=6 - i {
                let (u, w) = (i as f64 / 6.0, j as f64 / 6.0);
                samples.push(a + (b - a) * u + (c - a) * w);
            }
        }
    }
    let longest = t
        .iter()
        .flat_map(|tri| (0..3).map(move |k| (tri[k], tri[(k + 1) % 3])))
        .map(|(a, b)| Point3::from_array(v[a as usize]).dist(Point3::from_array(v[b as usize])))
        .fold(0.0, f64::max);
    let spacing = longest / 6.0;
    let mut rng = SmallRng::seed_from_u64(5);
    for (name, ball) in balls() {
        for _ in 0..40 {
            // A point inside the tube.
            let (u, w, s) = (rng.gen_range(0.0..6.3f64), rng.gen_range(0.0..6.3f64), rng.gen_range(0.0..0.85));
            let r = 3.0 + s * w.cos();
            let c = Point3::new(r * u.cos(), r * u.sin(), s * w.sin());
            assert_eq!(m.inside(c), Some(true));
            let got = m.ball_radius(c, &ball);
            let lowest = samples.iter().map(|&q| ball.gauge(q - c)).fold(f64::INFINITY, f64::min);
            assert!(lowest >= got.radius * (1.0 - 1e-12), "{name}: a sample at gauge {lowest} < {}", got.radius);
            assert!((ball.gauge(got.point - c) - got.radius).abs() <= 1e-12 * got.radius, "{name}");
            let tri = t[got.triangle as usize].map(|i| Point3::from_array(v[i as usize]));
            let n = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
            assert!(n.dot(got.point - tri[0]).abs() <= 1e-12 * n.norm() * 4.0, "{name}: contact off its triangle");
            // The radius is not too small either: every surface point lies
            // within `spacing` of a sample, and the gauge changes by at
            // most |x − y| / inradius.
            assert!(got.radius >= lowest - spacing / ball.inradius(), "{name}: {} vs sampled {lowest}", got.radius);
        }
    }
}
