//! Maximal* balls decided exactly (`TriangleTree::maximal_ball_exact`)
//! against an oracle that shares nothing with the library: for every
//! triangle not through `p`, the linear program "least `s` with a point
//! `x = t0 + a·e1 + b·e2` of the triangle in `p + s·(B − ṽ)`" solved by
//! brute force over every triple of its constraints in `i128` rationals
//! (a generic vertex enumeration, where the library enumerates typed
//! contacts), the least over all triangles that meet the open cone the
//! balls fill (others slide along its walls), and each reported contact's
//! features checked on the oracle's exact point.

mod common;

use common::rational::{check_features, dot, exact_planes, integer_meshes, sub, v_of, Q, V};
use medax::kernel::Point3;
use medax::shape::{Ball3, ContactKind3, ExactMaximalBall, Mesh3d, MeshOptions};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use std::collections::BTreeMap;

/// A constraint `ca·a + cb·b + cs·s + c0 ≤ 0`.
type Row = [Q; 4];

/// The rows of `x = t0 + a·e1 + b·e2` in the triangle, and of the
/// fourth variable at most 0 (`sign` −1: `s ≥ 0`) or at most 1 (`sign`
/// +1: `τ ≤ 1`).
fn triangle_rows(sign: i128) -> Vec<Row> {
    let zero = Q::int(0);
    vec![
        [Q::int(-1), zero, zero, zero],
        [zero, Q::int(-1), zero, zero],
        [Q::int(1), Q::int(1), zero, Q::int(-1)],
        [zero, zero, Q::int(sign), if sign > 0 { Q::int(-1) } else { zero }],
    ]
}

/// Solves three tight rows for `(a, b, s)` by Cramer's rule.
fn meet(r: [&Row; 3]) -> Option<[Q; 3]> {
    let det3 = |m: [[Q; 3]; 3]| {
        m[0][0]
            .mul(m[1][1].mul(m[2][2]).sub(m[1][2].mul(m[2][1])))
            .sub(m[0][1].mul(m[1][0].mul(m[2][2]).sub(m[1][2].mul(m[2][0]))))
            .add(m[0][2].mul(m[1][0].mul(m[2][1]).sub(m[1][1].mul(m[2][0]))))
    };
    let a = r.map(|x| [x[0], x[1], x[2]]);
    let rhs = r.map(|x| Q(-x[3].0, x[3].1));
    let d = det3(a);
    if d.sign().is_eq() {
        return None;
    }
    let col = |k: usize| {
        let mut m = a;
        (0..3).for_each(|i| m[i][k] = rhs[i]);
        det3(m).div(d)
    };
    Some([col(0), col(1), col(2)])
}

/// The least `s` for triangle `t` and the points reaching it (`None`
/// when the cone misses the triangle).
fn least_on(planes: &[(V, Q)], v: V, p: V, t: [V; 3]) -> Option<(Q, Vec<V>)> {
    let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
    let mut rows = triangle_rows(-1);
    for &(n, h) in planes {
        let hv = h.sub(dot(n, v));
        rows.push([dot(n, e1), dot(n, e2), Q(-hv.0, hv.1), dot(n, sub(t[0], p))]);
    }
    let mut best: Option<(Q, Vec<V>)> = None;
    let k = rows.len();
    for i in 0..k {
        for j in i + 1..k {
            for l in j + 1..k {
                let Some([a, b, s]) = meet([&rows[i], &rows[j], &rows[l]]) else { continue };
                let feasible =
                    rows.iter().all(|r| r[0].mul(a).add(r[1].mul(b)).add(r[2].mul(s)).add(r[3]).sign().is_le());
                if !feasible {
                    continue;
                }
                let x = [0, 1, 2].map(|c| t[0][c].add(e1[c].mul(a)).add(e2[c].mul(b)));
                match best.as_mut() {
                    Some((bs, pts)) if s.cmp(*bs).is_eq() => pts.push(x),
                    Some((bs, _)) if s.cmp(*bs).is_gt() => {}
                    _ => best = Some((s, vec![x])),
                }
            }
        }
    }
    best
}

/// Whether triangle `t` has a point strictly inside every wall of the
/// cone at `p` (the ball's facets through `ṽ`): the largest `τ ≤ 1` with
/// a point at least `τ` inside each wall, by the same enumeration.
fn meets_open_cone(planes: &[(V, Q)], v: V, p: V, t: [V; 3]) -> bool {
    let (e1, e2) = (sub(t[1], t[0]), sub(t[2], t[0]));
    let mut rows = triangle_rows(1);
    for &(n, h) in planes {
        if h.sub(dot(n, v)).sign().is_eq() {
            rows.push([dot(n, e1), dot(n, e2), Q::int(1), dot(n, sub(t[0], p))]);
        }
    }
    let mut best: Option<Q> = None;
    let k = rows.len();
    for i in 0..k {
        for j in i + 1..k {
            for l in j + 1..k {
                let Some([a, b, tau]) = meet([&rows[i], &rows[j], &rows[l]]) else { continue };
                if rows.iter().all(|r| r[0].mul(a).add(r[1].mul(b)).add(r[2].mul(tau)).add(r[3]).sign().is_le())
                    && best.is_none_or(|b| tau.cmp(b).is_gt())
                {
                    best = Some(tau);
                }
            }
        }
    }
    best.is_some_and(|b| b.sign().is_gt())
}

fn f64_of(v: V) -> Point3 {
    Point3::new(v[0].f64(), v[1].f64(), v[2].f64())
}

/// What an exact maximal* ball came to, counted over a test.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Outcome {
    /// Stopped by a contact of this kind.
    Stopped(ContactKind3),
    /// Radius 0: the vertex's cone straddles the surface.
    Zero,
    /// Radius infinity: nothing stops the ball.
    Unbounded,
}

/// Checks one exact maximal* ball against the oracle; counts its kinds.
#[allow(clippy::too_many_arguments)]
fn check(
    m: &Mesh3d,
    ball: &Ball3,
    vertex: usize,
    p: Point3,
    got: &ExactMaximalBall,
    what: &str,
    seen: &mut BTreeMap<Outcome, usize>,
) {
    let planes = exact_planes(ball);
    let (pq, v) = (v_of(p), v_of(ball.vertices()[vertex]));
    let pos = |i: u32| v_of(m.positions()[i as usize]);
    let reach_bound = ball.vertices().iter().map(|w| (*w - ball.vertices()[vertex]).norm()).fold(0.0, f64::max);
    let mut best: Option<(Q, Vec<V>)> = None;
    for t in m.triangles() {
        let tq = t.map(pos);
        // Far triangles cannot stop a ball of radius ≈ got.radius.
        let tf = t.map(|i| m.positions()[i as usize]);
        let lo = (0..3).map(|k| tf.iter().map(|q| q.coord(k)).fold(f64::INFINITY, f64::min)).collect::<Vec<_>>();
        let hi = (0..3).map(|k| tf.iter().map(|q| q.coord(k)).fold(f64::NEG_INFINITY, f64::max)).collect::<Vec<_>>();
        let gap = (0..3).map(|k| (lo[k] - p.coord(k)).max(p.coord(k) - hi[k]).max(0.0).powi(2)).sum::<f64>().sqrt();
        if got.radius.is_finite() && gap > 2.0 * got.radius * reach_bound + 1.0 {
            continue;
        }
        // A triangle meeting only the cone's walls or its apex never
        // stops the growth; one meeting the open cone through p stops it
        // at 0.
        if !meets_open_cone(&planes, v, pq, tq) {
            continue;
        }
        let Some((s, pts)) = least_on(&planes, v, pq, tq) else { continue };
        match best.as_mut() {
            Some((bs, all)) if s.cmp(*bs).is_eq() => all.extend(pts),
            Some((bs, _)) if s.cmp(*bs).is_gt() => {}
            _ => best = Some((s, pts)),
        }
    }
    // Nothing stops the ball: it grows without bound (outside the solid).
    let Some((s, points)) = best else {
        assert_eq!(got.radius, f64::INFINITY, "{what}: the oracle finds nothing stopping the ball");
        *seen.entry(Outcome::Unbounded).or_default() += 1;
        return;
    };
    assert_eq!(got.radius, s.f64(), "{what}: radius");
    // A cone straddling the surface at p: radius 0, no contacts reported.
    if s.sign().is_eq() {
        assert_eq!(got.centre, p, "{what}: centre of a ball of radius 0");
        *seen.entry(Outcome::Zero).or_default() += 1;
        return;
    }
    let centre = [0, 1, 2].map(|k| pq[k].sub(v[k].mul(s)));
    assert!((got.centre - f64_of(centre)).norm() <= 1e-12 * (1.0 + got.centre.norm()), "{what}: centre");
    let near = |a: Point3, b: Point3| (a - b).norm() <= 1e-12 * (1.0 + a.norm());
    assert!(!got.opposite.is_empty(), "{what}: no contacts");
    for x in &got.opposite {
        let y = *points
            .iter()
            .find(|&&y| near(f64_of(y), x.point))
            .unwrap_or_else(|| panic!("{what}: contact {x:?} is not a least point of the oracle"));
        check_features(m, ball, &planes, y, (centre, s), x, what);
        *seen.entry(Outcome::Stopped(x.kind)).or_default() += 1;
    }
    if !got.flat {
        for y in &points {
            assert!(got.opposite.iter().any(|x| near(f64_of(*y), x.point)), "{what}: least point {y:?} missing");
        }
    }
}

#[test]
fn exact_maximal_balls_match_the_vertex_enumeration_oracle() {
    let mut rng = SmallRng::seed_from_u64(57);
    let balls = [Ball3::tetrahedron(), Ball3::cube(), Ball3::octahedron()];
    let mut seen = BTreeMap::new();
    let mut grown = 0;
    for (mesh_name, (v, t)) in integer_meshes() {
        let m = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
        for (bi, ball) in balls.iter().enumerate() {
            let reach = ball.reach();
            for _ in 0..16 {
                let k = rng.gen_range(0..m.triangles().len());
                let [a, b, c] = m.triangles()[k].map(|i| m.positions()[i as usize]);
                // Dyadic points: inside the triangle, or an edge midpoint.
                let (u, w) = if rng.gen_bool(0.7) { (0.25, 0.25) } else { (0.5, 0.0) };
                let p = a + (b - a) * u + (c - a) * w;
                let vertex = rng.gen_range(0..ball.vertices().len());
                let what = format!("{mesh_name}, ball {bi}, vertex {vertex} at {p:?}");
                let got = m.tree().maximal_ball_exact(p, vertex, &reach);
                let got = got.unwrap_or_else(|| {
                    panic!("{what}: no exact ball ({:?})", m.tree().maximal_ball_with(p, vertex, &reach))
                });
                check(&m, ball, vertex, p, &got, &what, &mut seen);
                // The same point given by its triangle (exact there too;
                // radius 0 there by the cone crossing the plane).
                let on = m.tree().maximal_ball_exact_on([a, b, c], (u, w), vertex, &reach).unwrap();
                assert_eq!(on, got, "{what}: on the triangle");
                if !(got.radius > 0.0 && got.radius.is_finite()) {
                    continue;
                }
                let f = m.tree().maximal_ball_with(p, vertex, &reach).unwrap();
                assert!(
                    (f.radius - got.radius).abs() <= 1e-9 * got.radius,
                    "{what}: f64 {} vs exact {}",
                    f.radius,
                    got.radius
                );
                grown += 1;
            }
        }
    }
    eprintln!("grown {grown}, outcomes {seen:?}");
    assert!(grown >= 40, "only {grown} balls grew");
    let kinds = seen.keys().filter(|o| matches!(o, Outcome::Stopped(_))).count();
    assert!(kinds >= 4, "too few contact types: {seen:?}");
    assert!(seen.get(&Outcome::Zero).is_some_and(|&n| n >= 3), "too few cones straddling: {seen:?}");
    assert!(seen.get(&Outcome::Unbounded).is_some_and(|&n| n >= 3), "too few balls unbounded: {seen:?}");
}

/// A plate thinner than the `f64` construction's slack: the ball grown
/// from the top face down into the plate is lost in rounding there (the
/// first ray starts below the plate, and the huge ball's gauges agree to
/// 10^-12: unbounded), the exact construction finds the bottom face at
/// half the thickness (the cube ball's vertex (1, 1, 1) at p: the balls
/// are p + s·[−2, 0]³).
#[test]
fn a_plate_thinner_than_rounding_stops_the_ball_at_half_its_thickness() {
    let h = 2f64.powi(-45);
    let (v, t) = medax::shape::mesh_samples::cuboid([0.0; 3], [1.0, 1.0, h]);
    let m = Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap();
    let ball = Ball3::cube();
    let vertex = ball.vertices().iter().position(|w| *w == Point3::new(1.0, 1.0, 1.0)).unwrap();
    let reach = ball.reach();
    let p = Point3::new(0.25, 0.5, h);
    let f = m.tree().maximal_ball_with(p, vertex, &reach).unwrap();
    assert!(f.radius == 0.0 || f.radius.is_infinite(), "the f64 construction finds this now ({f:?}): thinner plate");
    let got = m.tree().maximal_ball_exact(p, vertex, &reach).unwrap();
    assert_eq!(got.radius, h / 2.0);
    assert_eq!(got.centre, Point3::new(0.25 - h / 2.0, 0.5 - h / 2.0, h / 2.0));
    assert!(!got.opposite.is_empty() && got.opposite.iter().all(|c| c.point.z == 0.0), "{:?}", got.opposite);
}
