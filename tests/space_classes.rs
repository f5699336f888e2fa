//! Contact classes of solids under polyhedral balls (thesis 3.1.2),
//! checked against what the exact ball queries see, which do not use
//! them: every contact of a ball inscribed in the solid (the largest ball
//! at an inside point, or a maximal* ball grown from a surface point)
//! must belong to a class; the VF classes are the farthest ball vertices
//! by brute force; hand-made solids give the reflex edges and ties
//! expected.

mod common;

use common::rational::{inside_points, integer_meshes};
use common::solids::l_prism;
use medax::kernel::Point3;
use medax::shape::mesh_samples::cuboid;
use medax::shape::{Ball3, ContactKind3, Feature3, Mesh3d, MeshOptions, SurfacePart};
use medax::space::{contact_classes, ContactClass};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

fn mesh(soup: &(Vec<[f64; 3]>, Vec<[u32; 3]>)) -> Mesh3d {
    Mesh3d::from_triangles(&soup.0, &soup.1, &MeshOptions::default()).unwrap()
}

fn balls() -> Vec<(&'static str, Ball3)> {
    let mut rng = SmallRng::seed_from_u64(20);
    let cloud: Vec<Point3> = (0..30)
        .map(|_| {
            let v = Point3::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
            v * (1.0 / v.norm()) + Point3::new(0.2, -0.1, 0.15)
        })
        .collect();
    vec![
        ("tetrahedron", Ball3::tetrahedron()),
        ("cube", Ball3::cube()),
        ("octahedron", Ball3::octahedron()),
        ("turned cube", Ball3::cube().rotated([0.3, -0.5, 0.2]).unwrap()),
        ("geodesic 80", Ball3::geodesic(80).unwrap()),
        ("off-centre hull of 30 points", Ball3::from_points(&cloud).unwrap()),
    ]
}

#[test]
fn every_contact_of_an_inscribed_ball_is_a_class() {
    let mut rng = SmallRng::seed_from_u64(55);
    let mut solids: Vec<(&str, Mesh3d)> = integer_meshes().iter().map(|(n, s)| (*n, mesh(s))).collect();
    solids.push(("L prism", mesh(&l_prism(1.0, 0.0))));
    let (mut checked, mut edge_edge) = (0, 0);
    for (solid, m) in &solids {
        for (name, ball) in balls() {
            let classes = contact_classes(m, &ball);
            let reach = ball.reach();
            let what = format!("{solid}, {name}");
            let mut check = |x: &medax::shape::ExactContact, from: &str| {
                if x.flat
                    || !matches!(x.kind, ContactKind3::VertexFace | ContactKind3::EdgeEdge | ContactKind3::FaceVertex)
                {
                    return;
                }
                assert!(classes.contains(x.ball, x.surface), "{what}: {from} touches by {x:?}, not a class");
                checked += 1;
                edge_edge += usize::from(x.kind == ContactKind3::EdgeEdge);
            };
            // Largest balls at inside points.
            for c in inside_points(m, &mut rng, 30) {
                for x in &m.tree().exact_contacts(c, &reach).unwrap().contacts {
                    check(x, "the largest ball");
                }
            }
            // Maximal* balls grown from surface points.
            for _ in 0..30 {
                let k = rng.gen_range(0..m.triangles().len());
                let corners = m.triangles()[k].map(|i| m.positions()[i as usize]);
                let (u, w) = (rng.gen_range(0.05..0.45), rng.gen_range(0.05..0.45));
                let vertex = rng.gen_range(0..ball.vertices().len());
                let grown = m.tree().maximal_ball_exact_on(corners, (u, w), vertex, &reach);
                // Only balls in the material are inscribed: a cone pointing
                // out grows the ball in a cavity or outside.
                if let Some(grown) = grown.filter(|g| g.radius.is_finite() && m.inside(g.centre) == Some(true)) {
                    for x in &grown.opposite {
                        check(x, "a maximal* ball");
                    }
                }
            }
        }
    }
    eprintln!("{checked} contacts checked, {edge_edge} EE");
    assert!(checked >= 500 && edge_edge >= 10, "{checked} contacts checked, {edge_edge} EE");
}

#[test]
fn vertex_face_classes_are_the_farthest_ball_vertices() {
    for (solid, soup) in integer_meshes().into_iter().chain([("L prism", l_prism(1.0, 0.0))]) {
        let m = mesh(&soup);
        for (name, ball) in balls() {
            let classes = contact_classes(&m, &ball);
            for (t, tri) in m.triangles().iter().enumerate() {
                let [a, b, c] = tri.map(|i| m.positions()[i as usize]);
                let n = (b - a).cross(c - a);
                let along: Vec<f64> = ball.vertices().iter().map(|w| n.dot(*w)).collect();
                let top = along.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                let mut want: Vec<usize> =
                    (0..along.len()).filter(|&k| along[k] >= top - 1e-9 * top.abs().max(1.0)).collect();
                want.sort_unstable();
                let got: Vec<usize> = classes
                    .vertex_face
                    .iter()
                    .filter(|x| x.surface == SurfacePart::Face(t as u32))
                    .map(|x| match x.ball {
                        Feature3::Vertex(v) => v,
                        other => panic!("a VF class with ball feature {other:?}"),
                    })
                    .collect();
                assert_eq!(got, want, "{solid}, {name}, triangle {t}");
                let ties = classes.vertex_face.iter().filter(|x| x.surface == SurfacePart::Face(t as u32) && x.tie);
                assert_eq!(ties.count(), if want.len() > 1 { want.len() } else { 0 }, "{solid}, {name}, triangle {t}");
            }
        }
    }
}

#[test]
fn a_box_has_no_reflex_edge_and_under_the_cube_every_face_ties() {
    let m = mesh(&cuboid([0.0; 3], [3.0, 2.0, 1.0]));
    let classes = contact_classes(&m, &Ball3::cube());
    assert!(classes.reflex_edges.is_empty() && classes.edge_edge.is_empty());
    // Each face's normal is an axis: the cube's facet across it is
    // parallel, its four vertices tie.
    assert_eq!(classes.vertex_face.len(), 4 * m.triangles().len());
    assert!(classes.vertex_face.iter().all(|x| x.tie));
    let turned = contact_classes(&m, &Ball3::cube().rotated([0.3, -0.5, 0.2]).unwrap());
    assert_eq!(turned.vertex_face.len(), m.triangles().len());
    assert!(turned.vertex_face.iter().all(|x| !x.tie));
}

/// The L prism's one reflex edge: under the axis-aligned cube the cube's
/// vertical edge at (+1, +1) has the very fan of normals (+x to +y) of
/// that edge: a tie; under the other balls, the ball edges whose fans of
/// facet normals cross the quarter from +x to +y in the plane z = 0, by
/// the closed form (where the fan crosses z = 0, both coordinates
/// positive), away from near-ties.
#[test]
fn the_l_prism_has_one_reflex_edge_and_its_edge_classes() {
    let m = mesh(&l_prism(1.0, 0.0));
    let cube = Ball3::cube();
    let classes = contact_classes(&m, &cube);
    let at = |q: [f64; 3]| m.positions().iter().position(|p| p.to_array() == q).unwrap() as u32;
    let (low, high) = (at([1.0, 1.0, 0.0]), at([1.0, 1.0, 1.0]));
    assert_eq!(classes.reflex_edges, vec![[low.min(high), low.max(high)]]);
    // Every cube edge one of whose facets is parallel to a face at the
    // notch (normal +x or +y) ties: the vertical edge at (+1, +1) with
    // the very fan, two more vertical ones and four horizontal ones
    // sharing an end of it (their facet lies on the face, the edge along
    // it, crossing the reflex edge: flat contacts).
    assert_eq!(classes.edge_edge.len(), 7, "{:?}", classes.edge_edge);
    assert!(classes.edge_edge.iter().all(|x| x.tie));
    let ends = |x: &ContactClass| {
        let Feature3::Edge(k) = x.ball else { panic!("{x:?}") };
        cube.edges()[k].vertices.map(|i| cube.vertices()[i])
    };
    assert!(classes.edge_edge.iter().any(|x| ends(x).iter().all(|w| w.x == 1.0 && w.y == 1.0)));
    assert!(classes.edge_edge.iter().all(|x| ends(x).iter().all(|w| w.x == 1.0 || w.y == 1.0)));
    let mut crossings = 0;
    for (name, ball) in balls().into_iter().filter(|(n, _)| *n != "cube") {
        let classes = contact_classes(&m, &ball);
        for (k, edge) in ball.edges().iter().enumerate() {
            let [a, b] = edge.facets.map(|f| ball.facets()[f].normal);
            let listed = classes.edge_edge.iter().find(|x| x.ball == Feature3::Edge(k));
            let tiny = 1e-9;
            if a.z.abs() < tiny || b.z.abs() < tiny {
                continue;
            }
            let crossing = if (a.z > 0.0) == (b.z > 0.0) {
                false
            } else {
                let s = a.z / (a.z - b.z);
                let nu = a * (1.0 - s) + b * s;
                if nu.x.abs() < tiny * nu.norm() || nu.y.abs() < tiny * nu.norm() {
                    continue;
                }
                nu.x > 0.0 && nu.y > 0.0
            };
            assert_eq!(listed.is_some(), crossing, "{name}, ball edge {k}: {listed:?}");
            assert!(listed.is_none_or(|x| !x.tie), "{name}, ball edge {k}: a tie");
            crossings += usize::from(crossing);
        }
    }
    assert!(crossings >= 4, "only {crossings} crossings");
}

/// A slab with an L-shaped pocket (concave corners at the pocket's floor,
/// a saddle at its inner corner, lowered into a valley: a convex edge up
/// and reflex ones along the floor) and a box with a turned cavity (concave corners), under
/// turned balls: a ball facet rests on vertex `v` (an FV class) iff a tiny
/// ball `c + ε·B` with the facet's centroid on `v` lies inside the solid:
/// `c` is inside (winding number) and its least gauge distance to the
/// triangles (brute force) is `ε`, for every vertex and facet.
#[test]
fn face_vertex_classes_are_the_facets_a_tiny_ball_rests_on() {
    use common::maximal_oracle::{inside, least_gauge, planes};
    use medax::shape::mesh_samples::union;
    let outer = cuboid([-6.0, -6.0, -6.0], [6.0, 6.0, 6.0]);
    let inner = cuboid([-2.0, -2.5, -3.0], [3.0, 2.0, 1.5]);
    let (s, c) = (0.4f64.sin(), 0.4f64.cos());
    let turned: Vec<[f64; 3]> = inner.0.iter().map(|&[x, y, z]| [c * x - s * z, y, s * x + c * z]).collect();
    let cavity = union(&[outer, (turned, inner.1.iter().map(|t| [t[0], t[2], t[1]]).collect())]);
    let turned_balls = [
        ("turned tetrahedron", Ball3::tetrahedron().rotated([0.2, 0.4, -0.3]).unwrap()),
        ("turned octahedron", Ball3::octahedron().rotated([-0.4, 0.1, 0.6]).unwrap()),
        ("turned icosahedron", Ball3::icosahedron().rotated([0.5, 0.3, 0.1]).unwrap()),
    ];
    let (mut classes_seen, mut saddles) = (0, 0);
    let pocket = common::solids::pocket_with_valley();
    for (solid, soup) in [("L pocket", pocket), ("turned cavity", cavity)] {
        let m = mesh(&soup);
        let tris: Vec<[Point3; 3]> = m.triangles().iter().map(|t| t.map(|i| m.positions()[i as usize])).collect();
        let eps = 1e-4 * m.bbox().diagonal();
        for (name, ball) in &turned_balls {
            let classes = contact_classes(&m, ball);
            let pl = planes(ball);
            for (v, &x) in m.positions().iter().enumerate() {
                for (f, facet) in ball.facets().iter().enumerate() {
                    let k = facet.vertices.len() as f64;
                    let g = facet.vertices.iter().fold(Point3::new(0.0, 0.0, 0.0), |a, &i| a + ball.vertices()[i])
                        * (1.0 / k);
                    let c = x - g * eps;
                    let r = tris.iter().map(|&t| least_gauge(ball, &pl, c, t)).fold(f64::INFINITY, f64::min);
                    let below = r >= eps * (1.0 - 1e-7) && inside(&m, c);
                    let got = classes
                        .face_vertex
                        .iter()
                        .find(|c| c.surface == SurfacePart::Vertex(v as u32) && c.ball == Feature3::Facet(f));
                    assert_eq!(
                        got.is_some(),
                        below,
                        "{solid}, {name}: vertex {v} at {x:?}, facet {f} (gauge {} of ε)",
                        r / eps
                    );
                    if let Some(c) = got {
                        assert!(!c.tie && c.kind == ContactKind3::FaceVertex, "{c:?}");
                        classes_seen += 1;
                        saddles += usize::from(solid == "L pocket" && (x.x == 2.0 && x.y == 2.0 && x.z == 0.4));
                    }
                }
            }
        }
    }
    eprintln!("{classes_seen} FV classes, {saddles} at the saddle");
    assert!(classes_seen >= 20 && saddles >= 1, "{classes_seen} FV classes, {saddles} at the saddle");
}
