//! A brute-force oracle for maximal* balls anchored on a face, sharing
//! nothing with the library: the maximal* radius at a point `p` of a
//! face is the largest `s` for which no other triangle comes closer to
//! the centre `p − s·ṽ` than `s` in the ball's gauge (the least gauge over
//! a triangle by enumerating the linear program's candidate points in
//! `f64`), found by bisection. With the solids and balls the 3D
//! arrangement tests run on.

use super::solids::{l_prism, Soup};
use medax::kernel::Point3;
use medax::shape::mesh_samples::{cuboid, sphere, torus, union};
use medax::shape::{Ball3, Mesh3d, MeshOptions};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

pub fn solids() -> Vec<(&'static str, Mesh3d)> {
    let mut cavity = cuboid([-6.0, -6.0, -6.0], [6.0, 6.0, 6.0]);
    let inner = cuboid([-2.0, -2.5, -3.0], [3.0, 2.0, 1.5]);
    cavity = union(&[cavity, (inner.0, inner.1.iter().map(|t| [t[0], t[2], t[1]]).collect())]);
    let soups: Vec<(&str, Soup)> = vec![
        ("L prism", l_prism(1.3, 1.0)),
        ("torus", torus(3.0, 1.3, 14, 9)),
        ("sphere", sphere([0.2, -0.1, 0.3], 2.0, 9, 7)),
        ("box with cavity", cavity),
    ];
    soups.into_iter().map(|(n, (v, t))| (n, Mesh3d::from_triangles(&v, &t, &MeshOptions::default()).unwrap())).collect()
}

pub fn balls() -> Vec<(&'static str, Ball3)> {
    let mut rng = SmallRng::seed_from_u64(20);
    let cloud: Vec<Point3> = (0..24)
        .map(|_| {
            let v = Point3::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
            v * (1.0 / v.norm()) + Point3::new(0.2, -0.1, 0.15)
        })
        .collect();
    vec![
        ("turned tetrahedron", Ball3::tetrahedron().rotated([0.2, 0.4, -0.3]).unwrap()),
        ("turned cube", Ball3::cube().rotated([0.3, -0.5, 0.2]).unwrap()),
        ("turned octahedron", Ball3::octahedron().rotated([-0.4, 0.1, 0.6]).unwrap()),
        ("off-centre hull of 24 points", Ball3::from_points(&cloud).unwrap()),
    ]
}

/// The ball's facet planes `n·x ≤ h` from its corners.
pub fn planes(ball: &Ball3) -> Vec<(Point3, f64)> {
    ball.facets()
        .iter()
        .map(|f| {
            let [a, b, c] = [0, 1, 2].map(|k| ball.vertices()[f.vertices[k]]);
            let n = (b - a).cross(c - a);
            (n, n.dot(a))
        })
        .collect()
}

pub fn gauge(planes: &[(Point3, f64)], x: Point3) -> f64 {
    planes.iter().map(|&(n, h)| n.dot(x) / h).fold(0.0, f64::max)
}

/// The least gauge of `y − c` over triangle `t`, over the candidate points
/// of the linear program: corners, side points on the planes through `c`
/// and a ball edge, rays from `c` through a ball vertex meeting `t`.
pub fn least_gauge(ball: &Ball3, planes: &[(Point3, f64)], c: Point3, t: [Point3; 3]) -> f64 {
    let mut best = f64::INFINITY;
    let mut offer = |y: Point3| best = best.min(gauge(planes, y - c));
    t.iter().for_each(|&p| offer(p));
    let w = ball.vertices();
    for e in ball.edges() {
        let m = w[e.vertices[0]].cross(w[e.vertices[1]]);
        for (p, q) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            let den = m.dot(q - p);
            if den != 0.0 {
                let u = m.dot(c - p) / den;
                if (0.0..=1.0).contains(&u) {
                    offer(p + (q - p) * u);
                }
            }
        }
    }
    let n = (t[1] - t[0]).cross(t[2] - t[0]);
    for &wv in w {
        let den = n.dot(wv);
        if den == 0.0 {
            continue;
        }
        let s = n.dot(t[0] - c) / den;
        if s < 0.0 {
            continue;
        }
        let y = c + wv * s;
        if (0..3).all(|k| (t[(k + 1) % 3] - t[k]).cross(y - t[k]).dot(n) >= -1e-12 * n.norm2()) {
            offer(y);
        }
    }
    best
}

/// The maximal* radius at `p` on triangle `own` with ball vertex `anchor`
/// at `p`, by bisection on the brute-force gauge (nested balls: once a
/// triangle enters, it stays in).
pub fn oracle_radius(m: &Mesh3d, ball: &Ball3, planes: &[(Point3, f64)], own: usize, anchor: usize, p: Point3) -> f64 {
    try_oracle_radius(m, ball, planes, own, anchor, p)
        .unwrap_or_else(|| panic!("the oracle's ball grows without bound at {p:?}"))
}

/// [`oracle_radius`], `None` when the ball grows without bound (the
/// vertex's cone points out of the solid).
pub fn try_oracle_radius(
    m: &Mesh3d,
    ball: &Ball3,
    planes: &[(Point3, f64)],
    own: usize,
    anchor: usize,
    p: Point3,
) -> Option<f64> {
    let v = ball.vertices()[anchor];
    let tris: Vec<[Point3; 3]> = m
        .triangles()
        .iter()
        .enumerate()
        .filter(|&(k, _)| k != own)
        .map(|(_, t)| t.map(|i| m.positions()[i as usize]))
        .collect();
    let empty = |s: f64| tris.iter().all(|&t| least_gauge(ball, planes, p - v * s, t) >= s * (1.0 - 1e-13));
    let (mut lo, mut hi) = (0.0, 1.0);
    while empty(hi) {
        lo = hi;
        hi *= 2.0;
        if hi > 1e6 {
            return None;
        }
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if empty(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// The ball vertex farthest along the face's outward normal (its VF
/// class's anchor).
pub fn vf_anchor(m: &Mesh3d, ball: &Ball3, face: usize) -> usize {
    let [a, b, c] = m.triangles()[face].map(|i| m.positions()[i as usize]);
    let n = (b - a).cross(c - a);
    let along: Vec<f64> = ball.vertices().iter().map(|w| n.dot(*w)).collect();
    (0..along.len()).max_by(|&i, &j| along[i].total_cmp(&along[j])).unwrap()
}

/// The result, or `None` counted in `refused` for input outside general
/// position or changes too close to separate; any other error fails.
pub fn accepted<T>(got: Result<T, medax::space::AlongError>, what: &str, refused: &mut usize) -> Option<T> {
    use medax::space::AlongError;
    match got {
        Ok(g) => Some(g),
        Err(e @ (AlongError::NotGeneral { .. } | AlongError::Unresolved { .. })) => {
            eprintln!("{what}: {e}");
            *refused += 1;
            None
        }
        Err(e) => panic!("{what}: {e}"),
    }
}

/// Distance from `p` to triangle `t`.
pub fn to_triangle(p: Point3, [a, b, c]: [Point3; 3]) -> f64 {
    let n = (b - a).cross(c - a);
    let h = n.dot(p - a) / n.norm2();
    let q = p - n * h;
    if (0..3).all(|k| {
        let (s, e) = ([a, b, c][k], [a, b, c][(k + 1) % 3]);
        (e - s).cross(q - s).dot(n) >= 0.0
    }) {
        return (p - q).norm();
    }
    let seg = |s: Point3, e: Point3| {
        let u = ((p - s).dot(e - s) / (e - s).norm2()).clamp(0.0, 1.0);
        (p - (s + (e - s) * u)).norm()
    };
    seg(a, b).min(seg(b, c)).min(seg(c, a))
}

/// Whether `p` lies inside the closed surface: the solid angles its
/// triangles subtend (Van Oosterom and Strackee) sum to 4π inside, 0
/// outside.
pub fn inside(m: &Mesh3d, p: Point3) -> bool {
    let mut total = 0.0;
    for t in m.triangles() {
        let [a, b, c] = t.map(|i| m.positions()[i as usize] - p);
        let (la, lb, lc) = (a.norm(), b.norm(), c.norm());
        let num = a.dot(b.cross(c));
        let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
        total += 2.0 * num.atan2(den);
    }
    total > 2.0 * std::f64::consts::PI
}
