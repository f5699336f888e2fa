//! The vertices of the linear program "least `r` with a point of triangle
//! `T` in `c + r·B`" (see `touch_exact.rs`), written once over a
//! [`Ring`]: each vertex's radius `num / den`, point `at / den` and the
//! least features holding it, or "not a vertex", or "the ring cannot
//! tell" (`Err`).

use super::ball3::{Ball3, Feature3};
use crate::kernel::exact_line::Units;
use crate::kernel::exact_space::{cmp_ratios, Ring, V3};
use crate::kernel::Point3;
use std::cell::OnceCell;
use std::cmp::Ordering;

/// The least feature of a triangle holding a point: corner `k`, side `k`
/// (from corner `k` to corner `k + 1 mod 3`), or its interior.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum TrianglePart {
    /// A corner, 0, 1 or 2.
    Corner(u8),
    /// The open side from corner `k` to corner `k + 1 mod 3`.
    Side(u8),
    /// The open interior.
    Face,
}

/// Where a question's ball is centred (or grown from).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Centre {
    /// A point, exactly as given.
    At(Point3),
    /// The point `t0 + a·(t1 − t0) + b·(t2 − t0)` of a triangle's plane,
    /// exactly: on the plane, where an `f64` point seldom is.
    On([Point3; 3], f64, f64),
    /// The point `base + a·(u₁ − u₀) + b·(w₁ − w₀)` of the plane through
    /// `base` spanned by two differences of given points, exactly: a
    /// contact plane of an edge (its line and a ball edge's direction),
    /// whose direction is a difference of ball vertices.
    Span(Point3, [Point3; 2], [Point3; 2], f64, f64),
}

impl Centre {
    /// Every input value (for units).
    pub fn values(&self) -> Vec<f64> {
        match *self {
            Centre::At(c) => c.to_array().to_vec(),
            Centre::On(t, a, b) => t.iter().flat_map(|p| p.to_array()).chain([a, b, 1.0]).collect(),
            Centre::Span(o, u, w, a, b) => {
                [o, u[0], u[1], w[0], w[1]].iter().flat_map(|p| p.to_array()).chain([a, b, 1.0]).collect()
            }
        }
    }

    /// The point, rounded.
    pub fn approx(&self) -> Point3 {
        match *self {
            Centre::At(c) => c,
            Centre::On([t0, t1, t2], a, b) => t0 + (t1 - t0) * a + (t2 - t0) * b,
            Centre::Span(o, [u0, u1], [w0, w1], a, b) => o + (u1 - u0) * a + (w1 - w0) * b,
        }
    }
}

/// The centre `o + a·(u₁ − u₀) + b·(w₁ − w₀)` times the denominator `D`
/// of `a` and `b` (`a = A / D`), that `D`, and the triangles moved so
/// that the centre is the origin, times `D`.
#[allow(clippy::type_complexity)]
fn spanned<R: Ring>(
    o: Point3,
    [u0, u1]: [Point3; 2],
    [w0, w1]: [Point3; 2],
    a: f64,
    b: f64,
    units: Units,
    ts: &[[Point3; 3]],
) -> (V3<R>, Option<R>, Vec<[V3<R>; 3]>) {
    let d = R::of(1.0, units);
    let (e1, e2) = (V3::<R>::diff(u1, u0, units), V3::<R>::diff(w1, w0, units));
    let off = e1.scale(&R::of(a, units)).add(&e2.scale(&R::of(b, units)));
    let moved = ts.iter().map(|t| t.map(|p| V3::diff(p, o, units).scale(&d).sub(&off))).collect();
    (V3::of(o, units).scale(&d).add(&off), Some(d), moved)
}

/// "The ring cannot tell": ask again on exact integers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Unsure;

fn sure(o: Option<Ordering>) -> Result<Ordering, Unsure> {
    o.ok_or(Unsure)
}

/// The three kinds of vertex of the program, by the features that meet.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Which {
    /// Corner `k` on the plane of facet `f`, a facet the corner's gauge
    /// is largest on.
    Fv { corner: usize, facet: usize },
    /// Ball edge `e` meeting side `k` (from corner `k` to `k + 1 mod 3`).
    Ee { edge: usize, side: usize },
    /// Ball vertex `v` on the triangle's plane.
    Vf { vertex: usize },
}

/// What a candidate was computed from, when two triangles can share it:
/// a corner (its coordinates' bits) on a facet, or a side (its ends'
/// bits, in order) on a ball edge. Equal sources give equal numbers, so
/// the tie of a vertex or edge shared by two triangles needs no sign.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Source {
    Corner([u64; 3], usize),
    Side([[u64; 3]; 2], usize),
    /// A ball vertex on one triangle's plane.
    Own,
}

/// A vertex of the program: `r = num / den` (`den > 0`), the point
/// `at / den`, and its least features.
#[derive(Debug, Clone)]
pub(super) struct Candidate<R> {
    /// Which triangle of the question.
    pub triangle_index: usize,
    pub which: Which,
    pub source: Source,
    pub num: R,
    pub den: R,
    pub at: V3<R>,
    pub ball: Feature3,
    pub triangle: TrianglePart,
}

/// One question's numbers in ring `R`, moved so that the centre is the
/// origin (the filter's bounds then scale with the question, not with
/// its distance from the origin): the triangles, and the ball's vertices
/// and facet planes `n·x ≤ h` (`h > 0`: the origin is inside), converted
/// when first needed (on integers most are never).
pub(super) struct Setting<'a, R> {
    ball: &'a Ball3,
    units: Units,
    /// For a ball grown about a point from one of its vertices (a
    /// maximal* ball): that vertex, the origin of the ball `B − ṽ` (its
    /// facets through `ṽ` have `h = 0`: the walls of the cone the balls
    /// fill).
    apex: Option<usize>,
    /// The triangles as given, for [`Source`]s.
    given: &'a [[Point3; 3]],
    /// The centre where it was, times `scale`, for the points reported.
    pub at_centre: V3<R>,
    /// For a centre on a triangle, every length is multiplied by the
    /// denominator `D` of its parameters (`a = A / D`); `None` for 1.
    pub scale: Option<R>,
    /// The origin: the centre moved.
    c: V3<R>,
    /// The triangles moved with it.
    pub ts: Vec<[V3<R>; 3]>,
    vertices: Vec<OnceCell<V3<R>>>,
    planes: Vec<OnceCell<(V3<R>, R)>>,
}

impl<'a, R: Ring> Setting<'a, R> {
    /// The question in `units` (integers: common to every value of the
    /// question, so each equation is homogeneous and `r` unitless).
    pub fn new(
        ball: &'a Ball3,
        apex: Option<usize>,
        units: Units,
        centre: Centre,
        ts: &'a [[Point3; 3]],
    ) -> Setting<'a, R> {
        // Triangles moved so that the centre is the origin: differences of
        // inputs (one rounding in the filter), and for a centre on a
        // triangle its offset `A·e1 + B·e2` from the triangle's corner.
        let (at_centre, scale, moved): (V3<R>, Option<R>, Vec<[V3<R>; 3]>) = match centre {
            Centre::At(c) => (V3::of(c, units), None, ts.iter().map(|t| t.map(|p| V3::diff(p, c, units))).collect()),
            Centre::On([t0, t1, t2], a, b) => spanned(t0, [t0, t1], [t0, t2], a, b, units, ts),
            Centre::Span(o, u, w, a, b) => spanned(o, u, w, a, b, units, ts),
        };
        Setting {
            ball,
            units,
            apex,
            given: ts,
            at_centre,
            scale,
            c: V3::of(Point3::new(0.0, 0.0, 0.0), units),
            ts: moved,
            vertices: (0..ball.vertices().len()).map(|_| OnceCell::new()).collect(),
            planes: (0..ball.facets().len()).map(|_| OnceCell::new()).collect(),
        }
    }

    /// Values are integers times `2^shift`.
    pub fn shift(&self) -> i64 {
        self.units.exponent() as i64
    }

    fn vertex(&self, v: usize) -> &V3<R> {
        let w = self.ball.vertices();
        self.vertices[v].get_or_init(|| match self.apex {
            Some(a) => V3::diff(w[v], w[a], self.units),
            None => V3::of(w[v], self.units),
        })
    }

    /// The ball's vertex `v` where the ball was given (not moved to an
    /// apex), for centres reported.
    pub fn vertex_as_given(&self, v: usize) -> V3<R> {
        V3::of(self.ball.vertices()[v], self.units)
    }

    fn plane(&self, f: usize) -> &(V3<R>, R) {
        self.planes[f].get_or_init(|| {
            // The first three corners are not collinear (the hull keeps no
            // three consecutive corners collinear): they span the plane.
            let k = &self.ball.facets()[f].vertices;
            let (a, b, c) = (self.vertex(k[0]), self.vertex(k[1]), self.vertex(k[2]));
            let n = b.sub(a).cross(&c.sub(a));
            let h = n.dot(a);
            (n, h)
        })
    }

    /// For a ball grown from the apex: whether triangle `ti` meets the
    /// open cone the balls fill (some point strictly inside every wall).
    /// A triangle that meets only the closed cone touches the balls on
    /// their walls at most and never enters one, so it stops no growth; one
    /// that meets the open cone enters the ball right after its least
    /// touching radius (the closure of its part in the open cone is its
    /// part in the closed cone). Decided by the linear program "largest
    /// `t ≤ 1` with a point of the triangle at least `t` inside every
    /// wall", every vertex of it enumerated (a handful of walls).
    pub fn enters_cone(&self, ti: usize) -> Result<bool, Unsure> {
        let Some(apex) = self.apex else { return Ok(true) };
        let t = &self.ts[ti];
        let (e1, e2) = (t[1].sub(&t[0]), t[2].sub(&t[0]));
        let zero = R::of(0.0, self.units);
        let one = R::of(1.0, self.units);
        let minus = one.neg();
        // Rows `[ca, cb, ct, c0]` of `ca·a + cb·b + ct·t + c0 ≤ 0`.
        let mut rows = vec![
            [minus.clone(), zero.clone(), zero.clone(), zero.clone()],
            [zero.clone(), minus.clone(), zero.clone(), zero.clone()],
            [one.clone(), one.clone(), zero.clone(), minus.clone()],
            [zero.clone(), zero.clone(), one.clone(), minus.clone()],
        ];
        for &w in self.ball.facets_around(apex) {
            let (n, _) = self.plane(w);
            rows.push([n.dot(&e1), n.dot(&e2), one.clone(), n.dot(&t[0])]);
        }
        let mut best: Option<(R, R)> = None;
        let k = rows.len();
        for i in 0..k {
            for j in i + 1..k {
                for l in j + 1..k {
                    let m = [&rows[i], &rows[j], &rows[l]];
                    let col = |c: usize| V3 { x: m[0][c].clone(), y: m[1][c].clone(), z: m[2][c].clone() };
                    let c0 = col(3);
                    let rhs = V3 { x: c0.x.neg(), y: c0.y.neg(), z: c0.z.neg() };
                    let (ca, cb, ct) = (col(0), col(1), col(2));
                    let mut d = ca.det(&cb, &ct);
                    let (mut da, mut db, mut dt) = (rhs.det(&cb, &ct), ca.det(&rhs, &ct), ca.det(&cb, &rhs));
                    match sure(d.sign())? {
                        Ordering::Equal => continue,
                        Ordering::Less => (d, da, db, dt) = (d.neg(), da.neg(), db.neg(), dt.neg()),
                        Ordering::Greater => {}
                    }
                    // The three chosen rows are tight by construction (their
                    // value is 0, which the filter cannot certify).
                    let mut feasible = true;
                    for (q, r) in rows.iter().enumerate() {
                        if q == i || q == j || q == l {
                            continue;
                        }
                        let v = r[0].mul(&da).add(&r[1].mul(&db)).add(&r[2].mul(&dt)).add(&r[3].mul(&d));
                        if sure(v.sign())? == Ordering::Greater {
                            feasible = false;
                            break;
                        }
                    }
                    if feasible {
                        let better = match &best {
                            None => true,
                            Some((bt, bd)) => sure(cmp_ratios(&dt, &d, bt, bd))? == Ordering::Greater,
                        };
                        if better {
                            best = Some((dt, d));
                        }
                    }
                }
            }
        }
        Ok(match best {
            Some((dt, _)) => sure(dt.sign())? == Ordering::Greater,
            None => false,
        })
    }

    /// The program's vertices of triangle `ti` that can be least: the
    /// three corners; a ball edge on a side only where the side's gauge
    /// turns from falling to rising (its two facets' planes do not both
    /// rise or both fall along the side: elsewhere the point is not least
    /// even on the side); a ball vertex only when no neighbour lies
    /// farther toward the plane (else the point is not least even on the
    /// plane, or it lies on a side or corner, found there).
    pub fn plausible(&self, ti: usize) -> Vec<Which> {
        let ball = self.ball;
        let t = &self.ts[ti];
        let mut out: Vec<Which> = (0..3).map(|corner| Which::Fv { corner, facet: usize::MAX }).collect();
        for side in 0..3 {
            let d = t[(side + 1) % 3].sub(&t[side]);
            let slope: Vec<Option<Ordering>> =
                (0..ball.facets().len()).map(|f| self.plane(f).0.dot(&d).sign()).collect();
            for (edge, e) in ball.edges().iter().enumerate() {
                let [a, b] = e.facets.map(|f| slope[f]);
                let monotone = a == b && matches!(a, Some(Ordering::Greater | Ordering::Less));
                if !monotone {
                    out.push(Which::Ee { edge, side });
                }
            }
        }
        let n = t[1].sub(&t[0]).cross(&t[2].sub(&t[0]));
        let mut dominated = vec![false; ball.vertices().len()];
        if let Some(toward @ (Ordering::Greater | Ordering::Less)) = n.dot(&t[0].sub(&self.c)).sign() {
            for e in ball.edges() {
                let [a, b] = e.vertices;
                match n.dot(&self.vertex(b).sub(self.vertex(a))).sign().map(|o| {
                    if toward.is_lt() {
                        o.reverse()
                    } else {
                        o
                    }
                }) {
                    Some(Ordering::Greater) => dominated[a] = true,
                    Some(Ordering::Less) => dominated[b] = true,
                    _ => {}
                }
            }
        }
        out.extend((0..ball.vertices().len()).filter(|&v| !dominated[v]).map(|vertex| Which::Vf { vertex }));
        out
    }

    /// Vertex `which` of triangle `ti`, `Ok(None)` when it is not a
    /// feasible vertex. For a corner (`facet` `usize::MAX`) the facets are
    /// scanned for the largest gauge and its ties; with a facet given,
    /// the winner is known and only its numbers are computed.
    pub fn candidate(&self, ti: usize, which: Which) -> Result<Option<Candidate<R>>, Unsure> {
        let t = &self.ts[ti];
        let bits = |k: usize| self.given[ti][k % 3].to_array().map(f64::to_bits);
        let found = |which, num, den, at, ball_feature, part| {
            let source = match which {
                Which::Fv { corner, facet } => Source::Corner(bits(corner), facet),
                Which::Ee { edge, side } => {
                    let (a, b) = (bits(side), bits(side + 1));
                    Source::Side(if a <= b { [a, b] } else { [b, a] }, edge)
                }
                Which::Vf { .. } => Source::Own,
            };
            Ok(Some(Candidate { triangle_index: ti, which, source, num, den, at, ball: ball_feature, triangle: part }))
        };
        match which {
            Which::Fv { corner, facet } => {
                let d = t[corner].sub(&self.c);
                let part = TrianglePart::Corner(corner as u8);
                if facet != usize::MAX {
                    let (n, h) = self.plane(facet);
                    return found(which, n.dot(&d), h.clone(), t[corner].scale(h), Feature3::Facet(facet), part);
                }
                // The facet the corner's gauge is largest on, and its ties.
                // A wall of the apex's cone (h = 0) bounds no radius: the
                // corner is outside every ball when beyond it, on the wall
                // when on it.
                let mut best: Option<(usize, R, R)> = None;
                let (mut tight, mut walls) = (Vec::new(), Vec::new());
                for g in 0..self.ball.facets().len() {
                    let (n, h) = self.plane(g);
                    let ng = n.dot(&d);
                    if sure(h.sign())? == Ordering::Equal {
                        match sure(ng.sign())? {
                            Ordering::Greater => return Ok(None),
                            Ordering::Equal => walls.push(g),
                            Ordering::Less => {}
                        }
                        continue;
                    }
                    let order = match &best {
                        None => Ordering::Greater,
                        Some((_, num, den)) => sure(cmp_ratios(&ng, h, num, den))?,
                    };
                    match order {
                        Ordering::Greater => (best, tight) = (Some((g, ng, h.clone())), vec![g]),
                        Ordering::Equal => tight.push(g),
                        Ordering::Less => {}
                    }
                }
                let Some((best, num, den)) = best else { return Ok(None) };
                tight.extend(walls);
                tight.sort_unstable();
                let at = t[corner].scale(&den);
                found(Which::Fv { corner, facet: best }, num, den, at, ball_part(self.ball, &tight), part)
            }
            Which::Vf { vertex } => {
                let n = t[1].sub(&t[0]).cross(&t[2].sub(&t[0]));
                let w = self.vertex(vertex);
                let (mut num, mut den) = (n.dot(&t[0].sub(&self.c)), n.dot(w));
                match sure(den.sign())? {
                    Ordering::Equal => return Ok(None),
                    Ordering::Less => (num, den) = (num.neg(), den.neg()),
                    Ordering::Greater => {}
                }
                if sure(num.sign())? == Ordering::Less {
                    return Ok(None);
                }
                let at = self.c.scale(&den).add(&w.scale(&num));
                match triangle_part(t, &at, &den)? {
                    Some(part) => found(which, num, den, at, Feature3::Vertex(vertex), part),
                    None => Ok(None),
                }
            }
            Which::Ee { edge, side } => {
                let [a, b] = self.ball.edges()[edge].vertices;
                let va = self.vertex(a);
                let ev = self.vertex(b).sub(va);
                let tk = &t[side];
                let back = tk.sub(&t[(side + 1) % 3]); // −(the side's direction)
                let g = tk.sub(&self.c);
                // r·va + w·ev − u·side = tk − c, by Cramer's rule.
                let mut den = va.det(&ev, &back);
                let (mut r, mut w, mut u) = (g.det(&ev, &back), va.det(&g, &back), va.det(&ev, &g));
                match sure(den.sign())? {
                    Ordering::Equal => return Ok(None),
                    Ordering::Less => (den, r, w, u) = (den.neg(), r.neg(), w.neg(), u.neg()),
                    Ordering::Greater => {}
                }
                let (w_lo, w_hi) = (sure(w.sign())?, sure(r.sub(&w).sign())?);
                let (u_lo, u_hi) = (sure(u.sign())?, sure(den.sub(&u).sign())?);
                if sure(r.sign())?.is_lt() || [w_lo, w_hi, u_lo, u_hi].iter().any(|o| o.is_lt()) {
                    return Ok(None);
                }
                let ball_feature = match (w_lo, w_hi) {
                    (Ordering::Equal, _) => Feature3::Vertex(a),
                    (_, Ordering::Equal) => Feature3::Vertex(b),
                    _ => Feature3::Edge(edge),
                };
                let part = match (u_lo, u_hi) {
                    (Ordering::Equal, _) => TrianglePart::Corner(side as u8),
                    (_, Ordering::Equal) => TrianglePart::Corner(((side + 1) % 3) as u8),
                    _ => TrianglePart::Side(side as u8),
                };
                let at = tk.scale(&den).sub(&back.scale(&u));
                found(which, r, den, at, ball_feature, part)
            }
        }
    }
}

/// The least feature of the triangle holding the point `at / den` of its
/// plane (`den > 0`); `None` when outside.
fn triangle_part<R: Ring>(t: &[V3<R>; 3], at: &V3<R>, den: &R) -> Result<Option<TrianglePart>, Unsure> {
    let n = t[1].sub(&t[0]).cross(&t[2].sub(&t[0]));
    let mut zero = [false; 3];
    for k in 0..3 {
        let side = t[(k + 1) % 3].sub(&t[k]);
        let rel = at.sub(&t[k].scale(den));
        match sure(n.dot(&side.cross(&rel)).sign())? {
            Ordering::Less => return Ok(None),
            o => zero[k] = o == Ordering::Equal,
        }
    }
    Ok(Some(match zero {
        [false, false, false] => TrianglePart::Face,
        [true, false, false] => TrianglePart::Side(0),
        [false, true, false] => TrianglePart::Side(1),
        [false, false, true] => TrianglePart::Side(2),
        // Sides k and k + 1 meet at corner k + 1.
        [true, true, _] => TrianglePart::Corner(1),
        [false, true, true] => TrianglePart::Corner(2),
        [true, false, true] => TrianglePart::Corner(0),
    }))
}

/// The ball feature of a boundary point where exactly the facets `tight`
/// are tight: one a facet, two an edge, more a vertex.
fn ball_part(ball: &Ball3, tight: &[usize]) -> Feature3 {
    match tight {
        [f] => Feature3::Facet(*f),
        [f, g] => match ball.edges().iter().position(|e| e.facets.contains(f) && e.facets.contains(g)) {
            Some(e) => Feature3::Edge(e),
            None => common_vertex(ball, tight),
        },
        _ => common_vertex(ball, tight),
    }
}

fn common_vertex(ball: &Ball3, tight: &[usize]) -> Feature3 {
    let first = &ball.facets()[tight[0]].vertices;
    let v = first
        .iter()
        .copied()
        .find(|v| tight.iter().all(|&f| ball.facets()[f].vertices.contains(v)))
        .unwrap_or(first[0]);
    Feature3::Vertex(v)
}
