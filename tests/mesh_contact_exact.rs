//! The largest ball at a centre with exact contacts
//! (`TriangleTree::exact_contacts`), against an oracle that shares nothing
//! with the library: every vertex of every triangle's linear program in
//! `i128` rationals, the least gauge over all, the points that reach it,
//! and each reported feature checked on the oracle's exact point (a
//! surface vertex is that vertex, an edge point lies strictly inside the
//! edge, a ball edge point has exactly that edge's two facets tight…).
//!
//! Centres are built to make the non-regular contacts happen: a ball
//! vertex or edge midpoint placed on a mesh vertex or edge midpoint, plus
//! random lattice centres. Every contact type must occur, and flat
//! contacts (a ball facet on a face) too. Metamorphic checks: an integer
//! translation and the corners of every triangle rotated leave the
//! contacts unchanged; doubling everything doubles the radius.

mod common;

use common::rational::{
    check_features, exact_planes, gauge, inside_points, integer_meshes, lp_points, sub, v_of, Q, V,
};
use medax::kernel::Point3;
use medax::shape::mesh_samples::torus;
use medax::shape::{Ball3, ContactKind3, ExactContacts, Feature3, Mesh3d, MeshOptions, SurfacePart, TriangleTree};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::collections::BTreeMap;

fn integer_balls() -> Vec<(String, Ball3)> {
    let mut out = vec![
        ("tetrahedron".to_string(), Ball3::tetrahedron()),
        ("cube".to_string(), Ball3::cube()),
        ("octahedron".to_string(), Ball3::octahedron()),
    ];
    let mut rng = SmallRng::seed_from_u64(23);
    while out.len() < 6 {
        let pts: Vec<Point3> = (0..10)
            .map(|_| {
                Point3::new(rng.gen_range(-4..=4) as f64, rng.gen_range(-4..=4) as f64, rng.gen_range(-4..=4) as f64)
            })
            .map(|p| p + Point3::new(1.0, -1.0, 0.0))
            .collect();
        if let Ok(b) = Ball3::from_points(&pts) {
            out.push((format!("random integer hull {}", out.len() - 3), b));
        }
    }
    out
}

/// Centres where a ball vertex or edge midpoint, scaled by a small
/// radius, lands on a mesh vertex or edge midpoint; and lattice centres.
fn centres(m: &Mesh3d, ball: &Ball3, rng: &mut SmallRng, n: usize) -> Vec<Point3> {
    let mut out = Vec::new();
    let b = m.bbox();
    let mut tries = 0;
    while out.len() < n && tries < 100 * n {
        tries += 1;
        let t = m.triangles()[rng.gen_range(0..m.triangles().len())];
        let (a, bb) = (m.positions()[t[0] as usize], m.positions()[t[1] as usize]);
        let target = if rng.gen_bool(0.5) { a } else { (a + bb) * 0.5 };
        let e = ball.edges()[rng.gen_range(0..ball.edges().len())];
        let (u, w) = (ball.vertices()[e.vertices[0]], ball.vertices()[e.vertices[1]]);
        let feature = if rng.gen_bool(0.5) { u } else { (u + w) * 0.5 };
        let r = rng.gen_range(1..=6) as f64 * 0.25;
        let c = match rng.gen_range(0..3) {
            0 => {
                let pick = |lo: f64, hi: f64, rng: &mut SmallRng| (rng.gen_range(lo..hi) * 2.0).round() / 2.0;
                Point3::new(pick(b.min.x, b.max.x, rng), pick(b.min.y, b.max.y, rng), pick(b.min.z, b.max.z, rng))
            }
            _ => target - feature * r,
        };
        if m.inside(c) == Some(true) {
            out.push(c);
        }
    }
    out
}

/// The oracle's exact answer: the least gauge and the distinct points
/// reaching it (over all triangles).
fn oracle(m: &Mesh3d, ball: &Ball3, planes: &[(V, Q)], c: Point3) -> (Q, Vec<V>) {
    let cq = v_of(c);
    let mut best: Option<Q> = None;
    let mut points: Vec<V> = Vec::new();
    for t in m.triangles() {
        let tq = t.map(|i| v_of(m.positions()[i as usize]));
        for (y, g) in lp_points(ball, planes, cq, tq) {
            match best.map(|b| g.cmp(b)) {
                None | Some(std::cmp::Ordering::Less) => {
                    best = Some(g);
                    points = vec![y];
                }
                Some(std::cmp::Ordering::Equal) => points.push(y),
                _ => {}
            }
        }
    }
    let same = |a: &V, b: &V| (0..3).all(|k| a[k].cmp(b[k]).is_eq());
    let mut distinct: Vec<V> = Vec::new();
    for p in points {
        if !distinct.iter().any(|d| same(d, &p)) {
            distinct.push(p);
        }
    }
    (best.unwrap(), distinct)
}

fn f64_of(v: V) -> Point3 {
    Point3::new(v[0].f64(), v[1].f64(), v[2].f64())
}

/// Checks one answer against the oracle; returns the kinds seen.
fn check(m: &Mesh3d, ball: &Ball3, planes: &[(V, Q)], c: Point3, got: &ExactContacts, what: &str) {
    let (r, points) = oracle(m, ball, planes, c);
    assert_eq!(got.radius, r.f64(), "{what}: radius");
    let near = |a: Point3, b: Point3| (a - b).norm() <= 1e-12 * (1.0 + a.norm());
    let cq = v_of(c);
    for x in &got.contacts {
        let y = *points
            .iter()
            .find(|&&y| near(f64_of(y), x.point))
            .unwrap_or_else(|| panic!("{what}: contact {x:?} is not a least point of the oracle {points:?}"));
        check_features(m, ball, planes, y, (cq, r), x, what);
        let d = sub(y, cq);
        assert!(gauge(planes, d).cmp(r).is_eq());
        let kind = match (x.ball, x.surface) {
            (Feature3::Vertex(_), SurfacePart::Face(_)) => ContactKind3::VertexFace,
            (Feature3::Vertex(_), SurfacePart::Edge(_)) => ContactKind3::VertexEdge,
            (Feature3::Vertex(_), SurfacePart::Vertex(_)) => ContactKind3::VertexVertex,
            (Feature3::Edge(_), SurfacePart::Edge(_)) => ContactKind3::EdgeEdge,
            (Feature3::Edge(_), SurfacePart::Vertex(_)) => ContactKind3::EdgeVertex,
            (Feature3::Facet(_), SurfacePart::Vertex(_)) => ContactKind3::FaceVertex,
            other => panic!("{what}: impossible feature pair {other:?}"),
        };
        assert_eq!(x.kind, kind, "{what}");
    }
    if !got.flat {
        // In general position every least point is reported.
        for y in &points {
            assert!(got.contacts.iter().any(|x| near(f64_of(*y), x.point)), "{what}: least point {y:?} missing");
        }
    }
}

#[test]
fn exact_contacts_match_the_rational_oracle_in_every_contact_type() {
    let mut rng = SmallRng::seed_from_u64(54);
    let mut seen: BTreeMap<ContactKind3, usize> = BTreeMap::new();
    let mut flats = 0;
    for (mesh_name, (v, t)) in integer_meshes() {
        let m = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
        for (ball_name, ball) in integer_balls() {
            let planes = exact_planes(&ball);
            let reach = ball.reach();
            for c in centres(&m, &ball, &mut rng, 24) {
                let what = format!("{mesh_name}, {ball_name}, centre {c:?}");
                let got = m.tree().exact_contacts(c, &reach).unwrap();
                check(&m, &ball, &planes, c, &got, &what);
                let f = m.ball_radius(c, &ball).radius;
                assert!((got.radius - f).abs() <= 1e-13 * (f + 1.0), "{what}: f64 radius {f}, exact {}", got.radius);
                for x in &got.contacts {
                    *seen.entry(x.kind).or_default() += 1;
                }
                flats += got.flat as usize;
            }
        }
    }
    let kinds = [
        ContactKind3::VertexFace,
        ContactKind3::EdgeEdge,
        ContactKind3::FaceVertex,
        ContactKind3::VertexEdge,
        ContactKind3::EdgeVertex,
        ContactKind3::VertexVertex,
    ];
    eprintln!("contact types seen: {seen:?}, {flats} flat");
    assert!(kinds.iter().all(|k| seen.get(k).copied().unwrap_or(0) >= 3) && flats >= 3, "{seen:?}, {flats} flat");
}

/// The same question asked of a translated, a scaled and a re-cornered
/// copy gives the same contacts (the radius doubled when scaled).
#[test]
fn exact_contacts_are_invariant_under_translation_scaling_and_corner_order() {
    let mut rng = SmallRng::seed_from_u64(55);
    for (mesh_name, (v, t)) in integer_meshes() {
        let m = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
        let pos: Vec<[f64; 3]> = m.positions().iter().map(|p| p.to_array()).collect();
        let shift = [3.0, -5.0, 7.0];
        let moved: Vec<[f64; 3]> = pos.iter().map(|p| [p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]]).collect();
        let doubled: Vec<[f64; 3]> = pos.iter().map(|p| p.map(|x| 2.0 * x)).collect();
        let turned: Vec<[u32; 3]> =
            m.triangles().iter().enumerate().map(|(k, t)| [t[k % 3], t[(k + 1) % 3], t[(k + 2) % 3]]).collect();
        let trees = [
            TriangleTree::from_arrays(&pos, m.triangles()),
            TriangleTree::from_arrays(&moved, m.triangles()),
            TriangleTree::from_arrays(&doubled, m.triangles()),
            TriangleTree::from_arrays(&pos, &turned),
        ];
        for (ball_name, ball) in integer_balls() {
            let reach = ball.reach();
            for c in centres(&m, &ball, &mut rng, 12) {
                let what = format!("{mesh_name}, {ball_name}, centre {c:?}");
                let key =
                    |x: &ExactContacts| x.contacts.iter().map(|k| (k.ball, k.surface, k.kind)).collect::<Vec<_>>();
                let base = trees[0].exact_contacts(c, &reach).unwrap();
                let moved = trees[1].exact_contacts(c + Point3::new(shift[0], shift[1], shift[2]), &reach).unwrap();
                let doubled = trees[2].exact_contacts(c * 2.0, &reach).unwrap();
                let turned = trees[3].exact_contacts(c, &reach).unwrap();
                assert_eq!((key(&moved), moved.radius), (key(&base), base.radius), "{what}: translated");
                assert_eq!((key(&doubled), doubled.radius), (key(&base), 2.0 * base.radius), "{what}: doubled");
                assert_eq!((key(&turned), turned.radius), (key(&base), base.radius), "{what}: corners turned");
            }
        }
    }
}

/// Balls no small integer gives: the exact radius agrees with the `f64`
/// search and every contact lies on the ball at that radius.
#[test]
fn exact_contacts_of_irrational_balls_lie_on_the_ball() {
    let mut rng = SmallRng::seed_from_u64(56);
    let balls = [
        ("icosahedron", Ball3::icosahedron()),
        ("geodesic 80", Ball3::geodesic(80).unwrap()),
        ("turned tetrahedron", Ball3::tetrahedron().rotated([0.4, 1.1, -0.7]).unwrap()),
    ];
    let (v, t) = torus(3.0, 1.0, 30, 16);
    let m = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
    for (ball_name, ball) in &balls {
        let reach = ball.reach();
        for c in inside_points(&m, &mut rng, 30) {
            let got = m.tree().exact_contacts(c, &reach).unwrap();
            let f = m.ball_radius(c, ball);
            assert!((got.radius - f.radius).abs() <= 1e-12 * f.radius, "{ball_name} at {c:?}: {got:?} vs {f:?}");
            assert!(!got.contacts.is_empty());
            for x in &got.contacts {
                assert!((ball.gauge(x.point - c) - got.radius).abs() <= 1e-12 * got.radius, "{ball_name}: {x:?}");
            }
        }
    }
}
