//! Disks tangent to three sites: the Apollonius problem, which gives the
//! branch points of the medial axis (thesis 2.2.3 "Branching points", 2.5.4).
//!
//! A site is what an element looks like to a disk touching it: a point (a
//! vertex), a line with the side the disk is on, or a circle with the kind
//! of tangency. Each tangency condition is linear in (x, y, r, u) with
//! u = x² + y² − r²:
//!
//! * point q:                 u − 2q·c + |q|² = 0
//! * circle (o, R), σ = ±1:   u − 2o·c − 2σR·r + |o|² − R² = 0  (|c − o| = r + σR)
//! * line (a, n), disk on n:  n·c − r − n·a = 0
//!
//! Three sites give three linear equations in four unknowns: a line of
//! solutions, cut by the quadric u = x² + y² − r² in at most two points.
//! So there are at most two disks for each choice of sides and tangency
//! kinds; choosing the choice and the disk (touching the right portions of
//! the elements) is the caller's job. Plain `f64`; the residuals are a few
//! ulps of the input magnitudes for well-separated sites, and the problem
//! is ill-conditioned when the sites nearly admit a family of solutions.

use super::Point;

/// What an element looks like to a disk that touches it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Site {
    /// A point (a vertex).
    Point(Point),
    /// The line through `a` with unit normal `n`; the disk lies on the side
    /// `n` points to.
    Line {
        /// A point of the line.
        a: Point,
        /// Unit normal towards the disk.
        n: Point,
    },
    /// The circle (`o`, `r`): `outside` when the disk touches it from
    /// outside (|c − o| = ρ + r for a disk of radius ρ), otherwise the disk
    /// and the circle are nested (|c − o| = |ρ − r|).
    Circle {
        /// Centre.
        o: Point,
        /// Radius, > 0.
        r: f64,
        /// External tangency.
        outside: bool,
    },
}

impl Site {
    /// The tangency condition as coefficients of (x, y, r, u) and a constant.
    fn equation(&self) -> ([f64; 4], f64) {
        match *self {
            Site::Point(q) => ([-2.0 * q.x, -2.0 * q.y, 0.0, 1.0], q.norm2()),
            Site::Circle { o, r, outside } => {
                let s = if outside { 1.0 } else { -1.0 };
                ([-2.0 * o.x, -2.0 * o.y, -2.0 * s * r, 1.0], (o.norm() - r) * (o.norm() + r))
            }
            Site::Line { a, n } => ([n.x, n.y, -1.0, 0.0], -n.dot(a)),
        }
    }

    /// Signed tangency defect of the disk (`c`, `rho`): 0 when it touches
    /// the site as the site's kind says (distance units).
    pub fn defect(&self, c: Point, rho: f64) -> f64 {
        match *self {
            Site::Point(q) => c.dist(q) - rho,
            Site::Line { a, n } => n.dot(c - a) - rho,
            Site::Circle { o, r, outside } => {
                if outside {
                    c.dist(o) - (rho + r)
                } else {
                    c.dist(o) - (rho - r).abs()
                }
            }
        }
    }

    /// Where the disk (`c`, `rho`) touches the site.
    pub fn contact(&self, c: Point, rho: f64) -> Point {
        match *self {
            Site::Point(q) => q,
            Site::Line { n, .. } => c - n * rho,
            Site::Circle { o, r, outside } => {
                let v = c - o;
                let l = v.norm();
                if l == 0.0 {
                    return o + Point::new(r, 0.0);
                }
                // Towards the disk's centre unless the circle is inside the disk.
                if outside || rho < r {
                    o + v * (r / l)
                } else {
                    o - v * (r / l)
                }
            }
        }
    }
}

fn det3(m: [[f64; 3]; 3]) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// Every disk (centre, radius > 0) tangent to all three sites as their
/// kinds say: zero, one or two, smallest radius first.
pub fn tangent_disks(sites: [Site; 3]) -> Vec<(Point, f64)> {
    // Solve around the sites' own origin: the equations carry |q|², whose
    // rounding would swamp a small configuration far from (0, 0).
    let origin = working_origin(&sites);
    tangent_disks_at_origin(sites.map(|s| s.shifted(-origin))).into_iter().map(|(c, r)| (c + origin, r)).collect()
}

/// A point near all three sites, where the equations are solved: the
/// least-squares point of the distances to the sites' anchors, a line's
/// measured across it only (its anchor may lie far along it, as on a long
/// straight edge, and the mean of anchors with it). A circle counts by
/// its centre: the equations carry |o|² − R², exact around the centre,
/// and a frame's circle reaches far beyond the disks touching it.
/// Parallel lines leave a direction free: it is pinned weakly to the
/// anchors' mean.
fn working_origin(sites: &[Site; 3]) -> Point {
    let mean = sites.iter().map(Site::anchor).fold(Point::default(), |a, b| a + b) * (1.0 / 3.0);
    // Σ Mᵢ·x = Σ Mᵢ·pᵢ around the mean, Mᵢ = I for points, n·nᵀ for lines.
    let (mut m, mut rhs) = ([0.0f64; 3], Point::default());
    for s in sites {
        let (w, p) = match *s {
            Site::Point(q) => ([1.0, 0.0, 1.0], q - mean),
            Site::Line { a, n } => ([n.x * n.x, n.x * n.y, n.y * n.y], n * n.dot(a - mean)),
            Site::Circle { o, .. } => ([1.0, 0.0, 1.0], o - mean),
        };
        m = [m[0] + w[0], m[1] + w[1], m[2] + w[2]];
        rhs = rhs + p;
    }
    let pin = 1e-6 * (m[0] + m[2]);
    let (a, b, c) = (m[0] + pin, m[1], m[2] + pin);
    let det = a * c - b * b;
    if det.is_nan() || det <= 0.0 || !rhs.is_finite() {
        return mean;
    }
    mean + Point::new((c * rhs.x - b * rhs.y) / det, (a * rhs.y - b * rhs.x) / det)
}

impl Site {
    /// A point that fixes where the site is.
    fn anchor(&self) -> Point {
        match *self {
            Site::Point(q) => q,
            Site::Line { a, .. } => a,
            Site::Circle { o, .. } => o,
        }
    }

    /// The site moved by `d`.
    fn shifted(&self, d: Point) -> Site {
        match *self {
            Site::Point(q) => Site::Point(q + d),
            Site::Line { a, n } => Site::Line { a: a + d, n },
            Site::Circle { o, r, outside } => Site::Circle { o: o + d, r, outside },
        }
    }
}

fn tangent_disks_at_origin(sites: [Site; 3]) -> Vec<(Point, f64)> {
    let eqs = sites.map(|s| s.equation());
    // Rows [A | −k]: A·x = −k with x = (x, y, r, u).
    let a: [[f64; 4]; 3] = eqs.map(|e| e.0);
    let b: [f64; 3] = eqs.map(|e| -e.1);
    // The null vector of A: signed 3×3 minors (a generalised cross product).
    // The three columns other than `skip` (arrays, not vectors: this runs
    // for every candidate branch point of every base case).
    let others = |skip: usize| [0, 1, 2].map(|k| if k < skip { k } else { k + 1 });
    let minor = |skip: usize| {
        let cols = others(skip);
        det3([0, 1, 2].map(|i| [a[i][cols[0]], a[i][cols[1]], a[i][cols[2]]]))
    };
    let v = [minor(0), -minor(1), minor(2), -minor(3)];
    let vv: f64 = v.iter().map(|x| x * x).sum();
    if vv == 0.0 || !vv.is_finite() {
        // Dependent conditions: infinitely many disks or none; not a branch point.
        return Vec::new();
    }
    // A particular solution: the one orthogonal to v, from the 3×3 system
    // in the three coordinates where v is smallest (Cramer's rule).
    let big = (0..4).max_by(|&i, &j| v[i].abs().total_cmp(&v[j].abs())).unwrap_or(0);
    let cols = others(big);
    let m = [0, 1, 2].map(|i| [a[i][cols[0]], a[i][cols[1]], a[i][cols[2]]]);
    let d = det3(m);
    let mut x0 = [0.0; 4];
    for (k, &col) in cols.iter().enumerate() {
        let mut mk = m;
        for i in 0..3 {
            mk[i][k] = b[i];
        }
        x0[col] = det3(mk) / d;
    }
    // x = x0 + λ·v on the quadric x² + y² − r² − u = 0.
    let q = |p: [f64; 4], w: [f64; 4]| p[0] * w[0] + p[1] * w[1] - p[2] * w[2];
    let qa = q(v, v);
    let qb = 2.0 * q(x0, v) - v[3];
    let qc = q(x0, x0) - x0[3];
    let mut lambdas: [Option<f64>; 2] = [None; 2];
    let mut push = |l: f64| {
        let slot = usize::from(lambdas[0].is_some());
        lambdas[slot] = Some(l);
    };
    // Linear only when the quadratic term moves the near root by less than
    // rounding: its relative effect there is qa·qc / qb². (Comparing qa
    // with the other coefficients alone dropped it for a point and two
    // nearly parallel lines, where the pencil runs close to the quadric's
    // cone, and placed the disk 2 % of its radius off the point.)
    if qa == 0.0 || (qa * qc).abs() <= 1e-17 * qb * qb {
        if qb != 0.0 {
            push(-qc / qb);
        }
    } else {
        let disc = qb * qb - 4.0 * qa * qc;
        if disc >= 0.0 {
            // Stable roots: no cancellation between −b and ±√disc.
            let s = -0.5 * (qb + qb.signum() * disc.sqrt());
            if s != 0.0 {
                push(qc / s);
            }
            push(s / qa);
        }
    }
    let mut out: Vec<(Point, f64)> = Vec::with_capacity(2);
    out.extend(
        lambdas
            .into_iter()
            .flatten()
            .map(|l| (Point::new(x0[0] + l * v[0], x0[1] + l * v[1]), x0[2] + l * v[2]))
            .filter(|(c, r)| c.is_finite() && r.is_finite() && *r > 0.0),
    );
    out.sort_by(|a, b| a.1.total_cmp(&b.1));
    out.dedup_by(|a, b| (a.1 - b.1).abs() <= 1e-12 * b.1 && a.0.dist(b.0) <= 1e-12 * (1.0 + b.1));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    /// A site touching the disk (c, r) at angle `t`, of kind `kind`.
    fn site_at(c: Point, r: f64, t: f64, kind: u32, rng: &mut impl Rng) -> Site {
        let u = Point::new(t.cos(), t.sin());
        let q = c + u * r;
        match kind % 4 {
            0 => Site::Point(q),
            1 => Site::Line { a: q + u.perp() * rng.gen_range(-3.0..3.0), n: -u },
            // External: the circle lies beyond q.
            2 => {
                let big = rng.gen_range(0.1..5.0);
                Site::Circle { o: q + u * big, r: big, outside: true }
            }
            // Nested: the circle's centre lies on the segment through q and c
            // (circle around the disk when big > r, inside it otherwise).
            _ => {
                let big = rng.gen_range(0.1..2.0 * r);
                Site::Circle { o: q - u * big, r: big, outside: false }
            }
        }
    }

    #[test]
    fn a_point_and_two_nearly_parallel_lines() {
        // The disk beside a nearly flat convex corner (two lines meeting at
        // an angle of π − 2.8e-3, the disk on the same side of both),
        // through a point: the pencil of the two lines runs close to the
        // quadric's cone, so the quadratic's leading coefficient is tiny
        // and must not be dropped. Far from the origin, as in a real shape.
        let x = Point::new(16.66, -163.84);
        for (k, eps) in [1.4e-3f64, 1e-4, 1e-5].into_iter().enumerate() {
            let n1 = Point::new(-eps.cos(), eps.sin());
            let n2 = Point::new(-eps.cos(), -eps.sin());
            let q = x + Point::new(-4.1, -0.5 + 0.1 * k as f64);
            let sites = [Site::Point(q), Site::Line { a: x, n: n1 }, Site::Line { a: x, n: n2 }];
            let disks = tangent_disks(sites);
            let (c, r) = disks[0];
            assert!(r > 1.0 && r < 10.0, "{eps}: {disks:?}");
            for s in &sites {
                assert!(s.defect(c, r).abs() < 1e-9, "{eps}: {s:?} misses {c:?} {r} by {}", s.defect(c, r));
            }
        }
    }

    #[test]
    fn long_lines_anchored_far_from_the_disk() {
        // The foot of a channel of a long slanted comb: the base line y = -1
        // anchored at x = 0, a wall x - y = 53 404 anchored at its far end
        // (90 904, 37 500), and the vertex (53 405, 0). The disk touching
        // all three has radius r with 5.828r² − 11.657r + 5 = 0 (the
        // smaller root), wherever the lines are anchored.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let sites = [
            Site::Line { a: Point::new(0.0, -1.0), n: Point::new(0.0, 1.0) },
            Site::Line { a: Point::new(90_904.0, 37_500.0), n: Point::new(h, -h) },
            Site::Point(Point::new(53_405.0, 0.0)),
        ];
        let (a, b, c) = (3.0 + 2.0 * 2f64.sqrt(), -(6.0 + 4.0 * 2f64.sqrt()), 5.0);
        let want = (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
        let (centre, r) = tangent_disks(sites)[0];
        assert!((r - want).abs() < 1e-9, "radius {r}, want {want}");
        for s in &sites {
            assert!(s.defect(centre, r).abs() < 1e-9, "{s:?} misses by {}", s.defect(centre, r));
        }
    }

    #[test]
    fn recovers_a_disk_built_from_its_contacts() {
        let mut rng = rand::rngs::SmallRng::seed_from_u64(3);
        let mut found = 0;
        let mut kinds_seen = [0usize; 4];
        for trial in 0..5000 {
            let c = Point::new(rng.gen_range(-10.0..10.0), rng.gen_range(-10.0..10.0));
            let r = rng.gen_range(0.2..5.0);
            let ts = [rng.gen_range(0.0..2.1), rng.gen_range(2.1..4.2), rng.gen_range(4.2..6.2)];
            let kinds = [rng.gen_range(0..4), rng.gen_range(0..4), rng.gen_range(0..4)];
            let sites = [0, 1, 2].map(|i| site_at(c, r, ts[i], kinds[i], &mut rng));
            let disks = tangent_disks(sites);
            // Every answer is tangent to all three sites.
            for &(dc, dr) in &disks {
                for s in &sites {
                    assert!(s.defect(dc, dr).abs() < 1e-8 * (1.0 + dr + dc.norm()), "trial {trial}: {s:?} {dc:?} {dr}");
                }
            }
            // And the disk the sites were built from is among them.
            let hit = disks.iter().any(|&(dc, dr)| dc.dist(c) < 1e-7 * (1.0 + r) && (dr - r).abs() < 1e-7 * (1.0 + r));
            assert!(hit, "trial {trial}: kinds {kinds:?}, want {c:?} {r}, got {disks:?}");
            found += 1;
            for k in kinds {
                kinds_seen[k as usize] += 1;
            }
            // Contact points lie on the disk's circle.
            for (i, s) in sites.iter().enumerate() {
                let p = s.contact(c, r);
                let want = c + Point::new(ts[i].cos(), ts[i].sin()) * r;
                assert!(p.dist(want) < 1e-9 * (1.0 + r + c.norm()), "trial {trial}: {s:?}");
            }
        }
        assert_eq!(found, 5000);
        assert!(kinds_seen.iter().all(|&k| k > 2000), "{kinds_seen:?}");
    }

    #[test]
    fn incircle_circumcircle_and_no_solution() {
        // Triangle (0,0), (4,0), (0,3): inradius 1 at (1,1), circumcircle
        // centre (2, 1.5) radius 2.5.
        let line = |a: Point, b: Point| Site::Line { a, n: (b - a).unit().perp() };
        let (p, q, s) = (Point::new(0.0, 0.0), Point::new(4.0, 0.0), Point::new(0.0, 3.0));
        let d = tangent_disks([line(p, q), line(q, s), line(s, p)]);
        assert_eq!(d.len(), 1);
        assert!(d[0].0.dist(Point::new(1.0, 1.0)) < 1e-12 && (d[0].1 - 1.0).abs() < 1e-12);
        let d = tangent_disks([Site::Point(p), Site::Point(q), Site::Point(s)]);
        assert_eq!(d.len(), 1);
        assert!(d[0].0.dist(Point::new(2.0, 1.5)) < 1e-12 && (d[0].1 - 2.5).abs() < 1e-12);
        // Three parallel lines: no disk.
        let h =
            |y: f64, up: bool| Site::Line { a: Point::new(0.0, y), n: Point::new(0.0, if up { 1.0 } else { -1.0 }) };
        assert!(tangent_disks([h(0.0, true), h(2.0, false), h(5.0, false)]).is_empty());
    }
}
