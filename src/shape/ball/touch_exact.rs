//! Where a space ball grown from a centre first touches a triangle,
//! decided exactly: the least `r` with `(c + r·B) ∩ T ≠ ∅`, and every
//! point where that ball touches `T` with the least feature of the ball
//! and of the triangle holding it (thesis 3.1.2: the contact types VF,
//! EE, FV and the non-regular VE, EV, VV).
//!
//! The least `r` is a linear program in `(point of T, r)`, so it is
//! reached at a vertex of its feasible polyhedron, and every vertex is
//! one of three kinds (three independent tight constraints): a corner of
//! `T` on a facet plane of `r·B` (FV), a side of `T` meeting an edge of
//! `r·B` (EE), a vertex of `r·B` on the plane of `T` (VF). Each is a
//! small linear system with a rational answer (Lemma 8); all are
//! enumerated and compared, first on the floating filter [`Fx`] and, when
//! a sign is unsure there (a tie, a degenerate contact), again on exact
//! integers. The winner's radius and point are always recomputed on the
//! integers, so the `f64`s reported are the exact values rounded.
//!
//! Enumeration is `3 + V + 3E` small systems per triangle: fine for the
//! few triangles near a contact, not meant for a whole search (the walk
//! of `reach3.rs` finds the candidates first).

use super::ball3::{Ball3, Feature3};
use crate::kernel::bigint::BigInt;
use crate::kernel::exact_line::Units;
use crate::kernel::exact_space::{cmp_ratios, Ring, V3};
use crate::kernel::Point3;
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

/// One point where the ball touches the triangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TouchPoint {
    /// The point (exact value rounded).
    pub point: Point3,
    /// The least feature of the ball (scaled and placed) holding it.
    pub ball: Feature3,
    /// The least feature of the triangle holding it.
    pub triangle: TrianglePart,
}

/// The exact least gauge over a triangle and where it is reached.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactTouch {
    /// The least `r` (exact value rounded to `f64`).
    pub radius: f64,
    /// The points of contact: one in general position; the corners of the
    /// contact segment or polygon when a ball edge or facet lies flat on
    /// the triangle. Each once, ordered by their features.
    pub points: Vec<TouchPoint>,
}

/// The three kinds of vertex of the linear program, by the features that
/// meet there.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Which {
    /// Corner `k` on the plane of facet `f`, the facet the gauge of the
    /// corner is largest on.
    Fv { corner: usize, facet: usize },
    /// Ball edge `e` meeting side `k`.
    Ee { edge: usize, side: usize },
    /// Ball vertex `v` on the triangle's plane.
    Vf { vertex: usize },
}

/// A vertex of the program: `r = num / den` (`den > 0`), the point
/// `at / den`, and its features.
#[derive(Debug, Clone)]
struct Candidate<R> {
    /// Which triangle of the question.
    triangle_index: usize,
    which: Which,
    num: R,
    den: R,
    at: V3<R>,
    ball: Feature3,
    triangle: TrianglePart,
}

/// One question's numbers in ring `R`: the centre, the ball's vertices
/// and facet planes `n·x ≤ h` (`h > 0`: the origin is inside).
struct Setting<R> {
    /// Values are integers times `2^shift` (0 for the filter).
    shift: i64,
    c: V3<R>,
    /// The triangles asked about.
    ts: Vec<[V3<R>; 3]>,
    vertices: Vec<V3<R>>,
    planes: Vec<(V3<R>, R)>,
}

fn plane<R: Ring>(ball: &Ball3, vertices: &[V3<R>], f: usize) -> (V3<R>, R) {
    // The first three corners are not collinear (the hull keeps no three
    // consecutive corners collinear), so they span the facet's plane.
    let k = &ball.facets()[f].vertices;
    let (a, b, c) = (&vertices[k[0]], &vertices[k[1]], &vertices[k[2]]);
    let n = b.sub(a).cross(&c.sub(a));
    let h = n.dot(a);
    (n, h)
}

impl<R: Ring> Setting<R> {
    fn new(ball: &Ball3, shift: i64, c: V3<R>, ts: Vec<[V3<R>; 3]>, vertices: Vec<V3<R>>) -> Setting<R> {
        let planes = (0..ball.facets().len()).map(|f| plane(ball, &vertices, f)).collect();
        Setting { shift, c, ts, vertices, planes }
    }
}

/// The sign of `x` when the ring is sure.
fn sign<R: Ring>(x: &R) -> Option<Ordering> {
    x.sign()
}

/// The least feature of the triangle holding the point `at / den` of its
/// plane (`den > 0`), `None` when unsure, `Some(None)` when outside.
fn triangle_part<R: Ring>(t: &[V3<R>; 3], at: &V3<R>, den: &R) -> Option<Option<TrianglePart>> {
    let n = t[1].sub(&t[0]).cross(&t[2].sub(&t[0]));
    let mut zero = [false; 3];
    for k in 0..3 {
        let side = t[(k + 1) % 3].sub(&t[k]);
        let rel = at.sub(&t[k].scale(den));
        match sign(&n.dot(&side.cross(&rel)))? {
            Ordering::Less => return Some(None),
            o => zero[k] = o == Ordering::Equal,
        }
    }
    Some(Some(match zero {
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

/// The ball feature of a point on the ball's boundary where exactly the
/// facets `tight` are tight: one a facet, two an edge, more a vertex.
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

/// Candidate `which`, or `Ok(None)` when it is not a feasible vertex of
/// the program; `Err(())` when the ring cannot tell.
fn candidate<R: Ring>(ball: &Ball3, s: &Setting<R>, ti: usize, which: Which) -> Result<Option<Candidate<R>>, ()> {
    let sure = |o: Option<Ordering>| o.ok_or(());
    let t = &s.ts[ti];
    let found = |num, den, at, ball_feature, part| {
        Ok(Some(Candidate { triangle_index: ti, which, num, den, at, ball: ball_feature, triangle: part }))
    };
    match which {
        Which::Fv { corner, facet } => {
            let d = t[corner].sub(&s.c);
            let (n, h) = &s.planes[facet];
            let num = n.dot(&d);
            let mut tight = vec![facet];
            for (g, (m, hg)) in s.planes.iter().enumerate() {
                if g == facet {
                    continue;
                }
                match sure(cmp_ratios(&m.dot(&d), hg, &num, h))? {
                    Ordering::Greater => return Ok(None),
                    Ordering::Equal => tight.push(g),
                    Ordering::Less => {}
                }
            }
            tight.sort_unstable();
            let at = t[corner].scale(h);
            found(num, h.clone(), at, ball_part(ball, &tight), TrianglePart::Corner(corner as u8))
        }
        Which::Vf { vertex } => {
            let n = t[1].sub(&t[0]).cross(&t[2].sub(&t[0]));
            let (mut num, mut den) = (n.dot(&t[0].sub(&s.c)), n.dot(&s.vertices[vertex]));
            match sure(sign(&den))? {
                Ordering::Equal => return Ok(None),
                Ordering::Less => (num, den) = (num.neg(), den.neg()),
                Ordering::Greater => {}
            }
            if sure(sign(&num))? == Ordering::Less {
                return Ok(None);
            }
            let at = s.c.scale(&den).add(&s.vertices[vertex].scale(&num));
            let Some(part) = triangle_part(t, &at, &den).ok_or(())? else {
                return Ok(None);
            };
            found(num, den, at, Feature3::Vertex(vertex), part)
        }
        Which::Ee { edge, side } => {
            let [a, b] = ball.edges()[edge].vertices;
            let va = &s.vertices[a];
            let ev = s.vertices[b].sub(va);
            let (tk, tl) = (&t[side], &t[(side + 1) % 3]);
            let ms = tk.sub(tl); // −(side direction)
            let g = tk.sub(&s.c);
            // r·va + w·ev − u·side = tk − c, by Cramer's rule.
            let mut den = va.det(&ev, &ms);
            let (mut r, mut w, mut u) = (g.det(&ev, &ms), va.det(&g, &ms), va.det(&ev, &g));
            match sure(sign(&den))? {
                Ordering::Equal => return Ok(None),
                Ordering::Less => (den, r, w, u) = (den.neg(), r.neg(), w.neg(), u.neg()),
                Ordering::Greater => {}
            }
            let (w_lo, w_hi) = (sure(sign(&w))?, sure(sign(&r.sub(&w)))?);
            let (u_lo, u_hi) = (sure(sign(&u))?, sure(sign(&den.sub(&u)))?);
            if sure(sign(&r))?.is_lt() || w_lo.is_lt() || w_hi.is_lt() || u_lo.is_lt() || u_hi.is_lt() {
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
            let at = tk.scale(&den).sub(&ms.scale(&u));
            found(r, den, at, ball_feature, part)
        }
    }
}

/// Every vertex of the program in a fixed order.
fn all_candidates(ball: &Ball3) -> impl Iterator<Item = Which> + '_ {
    let fv = (0..3).flat_map(move |corner| (0..ball.facets().len()).map(move |facet| Which::Fv { corner, facet }));
    let ee = (0..ball.edges().len()).flat_map(|edge| (0..3).map(move |side| Which::Ee { edge, side }));
    let vf = (0..ball.vertices().len()).map(|vertex| Which::Vf { vertex });
    fv.chain(ee).chain(vf)
}

/// The least candidates over every triangle (all tied), or `Err(())`
/// when unsure.
fn least<R: Ring>(ball: &Ball3, s: &Setting<R>) -> Result<Vec<Candidate<R>>, ()> {
    let mut best: Vec<Candidate<R>> = Vec::new();
    for ti in 0..s.ts.len() {
        for which in all_candidates(ball) {
            let Some(cand) = candidate(ball, s, ti, which)? else { continue };
            let order = match best.first() {
                None => Ordering::Less,
                Some(b) => cmp_ratios(&cand.num, &cand.den, &b.num, &b.den).ok_or(())?,
            };
            match order {
                Ordering::Less => best = vec![cand],
                Ordering::Equal => best.push(cand),
                Ordering::Greater => {}
            }
        }
    }
    Ok(best)
}

/// The exact least gauge of `x − c` over triangle `t` under `ball`, and
/// where it is reached (`None` only when a coordinate is not finite).
pub fn touch_exact(ball: &Ball3, c: Point3, t: [Point3; 3]) -> Option<ExactTouch> {
    let (radius, points) = touch_exact_many(ball, c, &[t])?;
    Some(ExactTouch { radius, points: points.into_iter().map(|(_, p)| p).collect() })
}

/// [`touch_exact`] over several triangles at once: the exact least gauge
/// over all of them, and each point where it is reached with the index
/// of its triangle in `ts` (sorted by triangle, then features; each
/// point once per triangle). `None` when a coordinate is not finite or
/// `ts` is empty.
pub(crate) fn touch_exact_many(ball: &Ball3, c: Point3, ts: &[[Point3; 3]]) -> Option<(f64, Vec<(usize, TouchPoint)>)> {
    let finite = |p: &Point3| p.to_array().iter().all(|v| v.is_finite());
    if ts.is_empty() || !finite(&c) || !ts.iter().flatten().all(finite) {
        return None;
    }
    let vertices = ball.vertices().iter().map(|&v| V3::fx(v)).collect();
    let filtered = Setting::new(ball, 0, V3::fx(c), ts.iter().map(|t| t.map(V3::fx)).collect(), vertices);
    let exact = exact_setting(ball, c, ts);
    let chosen: Vec<(usize, Which)> = match least(ball, &filtered) {
        Ok(best) if best.len() == 1 => vec![(best[0].triangle_index, best[0].which)],
        _ => least(ball, &exact).ok()?.iter().map(|cand| (cand.triangle_index, cand.which)).collect(),
    };
    // The winners again on integers: exact values to round, features
    // decided with every tie seen.
    let mut points = Vec::new();
    let mut radius = f64::NAN;
    for (ti, which) in chosen {
        let cand = candidate(ball, &exact, ti, which).ok()??;
        radius = Ring::ratio(&cand.num, &cand.den, 0);
        let point = cand.at.approx_over(&cand.den, exact.shift);
        points.push((ti, TouchPoint { point, ball: cand.ball, triangle: cand.triangle }));
    }
    points.sort_by_key(|(ti, p)| (*ti, p.triangle, p.ball));
    points.dedup_by_key(|(ti, p)| (*ti, p.triangle, p.ball));
    Some((radius, points))
}

/// The question on integers in units common to the ball, the centre and
/// the triangles: every equation is homogeneous, so `r` is unitless.
fn exact_setting(ball: &Ball3, c: Point3, ts: &[[Point3; 3]]) -> Setting<BigInt> {
    let values = ball.vertices().iter().chain(ts.iter().flatten()).chain([&c]).flat_map(|p| p.to_array());
    let units = Units::covering(values);
    let vertices = ball.vertices().iter().map(|&v| V3::int(units, v)).collect();
    let ts = ts.iter().map(|t| t.map(|p| V3::int(units, p))).collect();
    Setting::new(ball, units.exponent() as i64, V3::int(units, c), ts, vertices)
}
