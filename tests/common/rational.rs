//! Exact rationals of `i128` for test oracles in space: small enough
//! inputs (multiples of 1/64 below 10^9, a few products deep) keep every
//! value in range, and an overflow panics instead of lying. Shares nothing
//! with the library's exact arithmetic.

use medax::kernel::Point3;
use medax::shape::mesh_samples::{cuboid, sphere, torus, union};
use medax::shape::{Ball3, ExactContact, Feature3, Mesh3d, SurfacePart};
use std::cmp::Ordering;

/// A rational `n / d` with `d > 0`, reduced.
#[derive(Clone, Copy, Debug)]
pub struct Q(pub i128, pub i128);

pub fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

impl Q {
    pub fn new(n: i128, d: i128) -> Q {
        assert!(d != 0);
        let g = gcd(n, d) * d.signum();
        Q(n / g, d / g)
    }
    pub fn int(n: i128) -> Q {
        Q(n, 1)
    }
    pub fn add(self, o: Q) -> Q {
        Q::new(self.0.checked_mul(o.1).unwrap() + o.0.checked_mul(self.1).unwrap(), self.1.checked_mul(o.1).unwrap())
    }
    pub fn sub(self, o: Q) -> Q {
        self.add(Q(-o.0, o.1))
    }
    pub fn mul(self, o: Q) -> Q {
        Q::new(self.0.checked_mul(o.0).unwrap(), self.1.checked_mul(o.1).unwrap())
    }
    pub fn div(self, o: Q) -> Q {
        Q::new(self.0.checked_mul(o.1).unwrap(), self.1.checked_mul(o.0).unwrap())
    }
    pub fn cmp(self, o: Q) -> Ordering {
        self.0.checked_mul(o.1).unwrap().cmp(&o.0.checked_mul(self.1).unwrap())
    }
    pub fn sign(self) -> Ordering {
        self.0.cmp(&0)
    }
    pub fn f64(self) -> f64 {
        self.0 as f64 / self.1 as f64
    }
}

pub type V = [Q; 3];

pub fn sub(a: V, b: V) -> V {
    [a[0].sub(b[0]), a[1].sub(b[1]), a[2].sub(b[2])]
}
pub fn dot(a: V, b: V) -> Q {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}
pub fn cross(a: V, b: V) -> V {
    [a[1].mul(b[2]).sub(a[2].mul(b[1])), a[2].mul(b[0]).sub(a[0].mul(b[2])), a[0].mul(b[1]).sub(a[1].mul(b[0]))]
}
pub fn along(p: V, d: V, t: Q) -> V {
    [p[0].add(d[0].mul(t)), p[1].add(d[1].mul(t)), p[2].add(d[2].mul(t))]
}
/// Exact value of an `f64` that is a multiple of 1/64 (asserted).
pub fn q_of(x: f64) -> Q {
    assert!((64.0 * x).fract() == 0.0 && x.abs() < 1e9, "{x} is not a multiple of 1/64");
    Q::new((64.0 * x) as i128, 64)
}
pub fn v_of(p: Point3) -> V {
    [q_of(p.x), q_of(p.y), q_of(p.z)]
}

/// The ball's facet planes from its own corners: (n, h) with x ∈ B iff
/// n·x ≤ h for all, h > 0.
pub fn exact_planes(ball: &Ball3) -> Vec<(V, Q)> {
    ball.facets()
        .iter()
        .map(|f| {
            let [a, b, c] = [0, 1, 2].map(|k| v_of(ball.vertices()[f.vertices[k]]));
            let n = cross(sub(b, a), sub(c, a));
            let h = dot(n, a);
            assert_eq!(h.sign(), Ordering::Greater, "origin inside, facets outward");
            (n, h)
        })
        .collect()
}

pub fn gauge(planes: &[(V, Q)], x: V) -> Q {
    planes.iter().map(|&(n, h)| dot(n, x).div(h)).fold(Q::int(0), |m, g| if g.cmp(m).is_gt() { g } else { m })
}

/// Every vertex of the linear program min r s.t. y ∈ T, y − c ∈ r·B
/// (and some more feasible points) with its gauge: the corners of T; the
/// points of a side on the plane through `c` and a ball edge; the ray
/// from `c` through a ball vertex meeting T.
pub fn lp_points(ball: &Ball3, planes: &[(V, Q)], c: V, t: [V; 3]) -> Vec<(V, Q)> {
    let mut out = Vec::new();
    let mut offer = |y: V| out.push((y, gauge(planes, sub(y, c))));
    t.iter().for_each(|&p| offer(p));
    let w: Vec<V> = ball.vertices().iter().map(|&p| v_of(p)).collect();
    for e in ball.edges() {
        let m = cross(w[e.vertices[0]], w[e.vertices[1]]);
        for (p, q) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            let den = dot(m, sub(q, p));
            if den.sign().is_ne() {
                let u = dot(m, sub(c, p)).div(den);
                if u.sign().is_ge() && u.cmp(Q::int(1)).is_le() {
                    offer(along(p, sub(q, p), u));
                }
            }
        }
    }
    let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    for &wv in &w {
        let den = dot(n, wv);
        if den.sign().is_eq() {
            continue;
        }
        let s = dot(n, sub(t[0], c)).div(den);
        if s.sign().is_lt() {
            continue;
        }
        let y = along(c, wv, s);
        let inside = (0..3).all(|k| dot(cross(sub(t[(k + 1) % 3], t[k]), sub(y, t[k])), n).sign().is_ge());
        if inside {
            offer(y);
        }
    }
    out
}

/// The exact least gauge of `y − c` over triangle `t`.
pub fn exact_on_triangle(ball: &Ball3, planes: &[(V, Q)], c: V, t: [V; 3]) -> Q {
    lp_points(ball, planes, c, t).into_iter().map(|(_, g)| g).min_by(|a, b| a.cmp(*b)).unwrap()
}

pub type Soup = (Vec<[f64; 3]>, Vec<[u32; 3]>);

/// Integer meshes: a box with a box-shaped cavity, a coarse sphere and a
/// torus scaled by 8 and rounded to the integer grid.
pub fn integer_meshes() -> Vec<(&'static str, Soup)> {
    let round = |(v, t): Soup, k: f64| -> Soup { (v.iter().map(|p| p.map(|x| (x * k).round())).collect(), t) };
    let mut cavity = cuboid([-6.0, -6.0, -6.0], [6.0, 6.0, 6.0]);
    let inner = cuboid([-2.0, -2.0, -3.0], [3.0, 2.0, 2.0]);
    cavity = union(&[cavity, (inner.0, inner.1.iter().map(|t| [t[0], t[2], t[1]]).collect())]);
    vec![
        ("box with cavity", cavity),
        ("sphere", round(sphere([0.0, 0.0, 0.0], 1.0, 8, 6), 8.0)),
        ("torus", round(torus(3.0, 1.3, 12, 8), 8.0)),
    ]
}

/// Checks a contact's features on the oracle's exact point `y` of a ball
/// of centre `centre` and radius `r`: the surface part holds `y` (a
/// vertex is `y`, an edge has it strictly inside, a face too), and the
/// ball part is the least one (`y − centre` is `r` times that vertex, or
/// exactly that edge's two facets or that facet are tight).
pub fn check_features(
    m: &Mesh3d,
    ball: &Ball3,
    planes: &[(V, Q)],
    y: V,
    (centre, r): (V, Q),
    x: &ExactContact,
    what: &str,
) {
    let pos = |i: u32| v_of(m.positions()[i as usize]);
    let same = |a: V, b: V| (0..3).all(|k| a[k].cmp(b[k]).is_eq());
    match x.surface {
        SurfacePart::Vertex(i) => assert!(same(y, pos(i)), "{what}: {x:?} not at that vertex"),
        SurfacePart::Edge([a, b]) => {
            let along = sub(pos(b), pos(a));
            let on = cross(along, sub(y, pos(a))).iter().all(|q| q.sign().is_eq());
            let t = dot(sub(y, pos(a)), along);
            assert!(on && t.sign().is_gt() && t.cmp(dot(along, along)).is_lt(), "{what}: {x:?} off its edge");
        }
        SurfacePart::Face(t) => {
            let tq = m.triangles()[t as usize].map(pos);
            let n = cross(sub(tq[1], tq[0]), sub(tq[2], tq[0]));
            let inside = (0..3).all(|k| dot(cross(sub(tq[(k + 1) % 3], tq[k]), sub(y, tq[k])), n).sign().is_gt());
            assert!(inside && dot(n, sub(y, tq[0])).sign().is_eq(), "{what}: {x:?} not inside its face");
        }
    }
    let d = sub(y, centre);
    let tight: Vec<usize> =
        planes.iter().enumerate().filter(|(_, (n, h))| dot(*n, d).cmp(h.mul(r)).is_eq()).map(|(f, _)| f).collect();
    match x.ball {
        Feature3::Vertex(u) => {
            let w = v_of(ball.vertices()[u]);
            assert!((0..3).all(|k| d[k].cmp(w[k].mul(r)).is_eq()), "{what}: {x:?} not at that ball vertex");
        }
        Feature3::Edge(e) => {
            let mut want = ball.edges()[e].facets.to_vec();
            want.sort_unstable();
            assert_eq!(tight, want, "{what}: {x:?} not inside that ball edge");
        }
        Feature3::Facet(f) => assert_eq!(tight, vec![f], "{what}: {x:?} not inside that ball facet"),
    }
}

/// `n` points drawn uniformly from the mesh's box that lie inside it.
pub fn inside_points(m: &Mesh3d, rng: &mut rand::rngs::SmallRng, n: usize) -> Vec<Point3> {
    use rand::Rng;
    let b = m.bbox();
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let c = Point3::new(
            rng.gen_range(b.min.x..b.max.x),
            rng.gen_range(b.min.y..b.max.y),
            rng.gen_range(b.min.z..b.max.z),
        );
        if m.inside(c) == Some(true) {
            out.push(c);
        }
    }
    out
}
