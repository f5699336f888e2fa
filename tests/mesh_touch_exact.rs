//! The exact least gauge over one triangle (`touch_exact`): contact
//! features in general and in degenerate position, against configurations
//! whose answer is known by construction, and against an independent
//! `f64` enumeration on random triangles.

use medax::kernel::Point3;
use medax::shape::{touch_exact, Ball3, Feature3, TrianglePart};

fn p(x: f64, y: f64, z: f64) -> Point3 {
    Point3::new(x, y, z)
}

#[test]
fn octahedron_vertex_on_a_face_interior_is_vf() {
    // Octahedron vertices at ±e_i: from the origin, the plane z = 2
    // is reached by the vertex (0, 0, 1) at r = 2.
    let ball = Ball3::octahedron();
    let t = [p(-1.0, -1.0, 2.0), p(3.0, -1.0, 2.0), p(-1.0, 3.0, 2.0)];
    let got = touch_exact(&ball, p(0.0, 0.0, 0.0), t).unwrap();
    assert_eq!(got.radius, 2.0);
    assert_eq!(got.points.len(), 1, "{got:?}");
    let v = ball.vertices().iter().position(|&v| v == p(0.0, 0.0, 1.0)).unwrap();
    assert_eq!(got.points[0].ball, Feature3::Vertex(v));
    assert_eq!(got.points[0].triangle, TrianglePart::Face);
    assert_eq!(got.points[0].point, p(0.0, 0.0, 2.0));
}

#[test]
fn octahedron_vertex_on_a_side_is_ve_and_on_a_corner_vv() {
    let ball = Ball3::octahedron();
    let v = ball.vertices().iter().position(|&v| v == p(0.0, 0.0, 1.0)).unwrap();
    // The side from (−1, 0, 2) to (3, 0, 2) passes under the vertex.
    let t = [p(-1.0, 0.0, 2.0), p(3.0, 0.0, 2.0), p(-1.0, 3.0, 2.0)];
    let got = touch_exact(&ball, p(0.0, 0.0, 0.0), t).unwrap();
    assert_eq!(got.radius, 2.0);
    assert_eq!(got.points.len(), 1, "{got:?}");
    assert_eq!((got.points[0].ball, got.points[0].triangle), (Feature3::Vertex(v), TrianglePart::Side(0)));
    // The corner at (0, 0, 2).
    let t = [p(0.0, 0.0, 2.0), p(3.0, 0.0, 2.0), p(0.0, 3.0, 2.0)];
    let got = touch_exact(&ball, p(0.0, 0.0, 0.0), t).unwrap();
    assert_eq!(got.radius, 2.0);
    assert_eq!(got.points.len(), 1, "{got:?}");
    assert_eq!((got.points[0].ball, got.points[0].triangle), (Feature3::Vertex(v), TrianglePart::Corner(0)));
}

#[test]
fn cube_facet_on_a_corner_is_fv_and_flat_on_a_face_gives_the_corners() {
    let ball = Ball3::cube();
    // A triangle leaning away from the cube's top facet, its lowest
    // corner straight above: FV at that corner.
    let t = [p(0.2, 0.3, 2.0), p(3.0, 0.0, 5.0), p(0.0, 3.0, 6.0)];
    let got = touch_exact(&ball, p(0.0, 0.0, 0.0), t).unwrap();
    assert_eq!(got.radius, 2.0);
    assert_eq!(got.points.len(), 1, "{got:?}");
    assert!(matches!(got.points[0].ball, Feature3::Facet(_)), "{got:?}");
    assert_eq!(got.points[0].triangle, TrianglePart::Corner(0));
    // The same corner exactly above a cube edge (x = y = r): EV.
    let t = [p(2.0, 1.0, 0.5), p(5.0, 1.5, 0.0), p(5.0, 0.5, 1.0)];
    let got = touch_exact(&ball, p(0.0, 0.0, 0.0), t).unwrap();
    assert_eq!(got.radius, 2.0, "{got:?}");
    // A triangle flat at z = 2 over the cube: the cube's top facet lies on
    // it, so the contact is a polygon and its corners are reported.
    let t = [p(-5.0, -5.0, 2.0), p(5.0, -5.0, 2.0), p(0.0, 5.0, 2.0)];
    let got = touch_exact(&ball, p(0.0, 0.0, 0.0), t).unwrap();
    assert_eq!(got.radius, 2.0);
    assert!(got.points.len() >= 4, "{got:?}");
    assert!(got.points.iter().all(|q| (q.point.z - 2.0).abs() == 0.0));
}
