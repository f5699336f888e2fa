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
//! small linear system with a rational answer (Lemma 8). The vertices
//! that can be least (`touch_lp.rs`: the corners, the ball edges where a
//! side's gauge turns, the ball vertices farthest toward the plane) are
//! compared, first on the floating filter [`Fb`] and, when a sign is
//! unsure there (a tie, a degenerate contact), again on exact integers.
//! The winner's radius and point are always recomputed on the integers,
//! so the `f64`s reported are the exact values rounded.
//!
//! The work per triangle is `O(F + E)` sign tests and a few small
//! systems: fine for the few triangles near a contact, not meant for a
//! whole search (the walk of `reach3.rs` finds those triangles first).

use super::ball3::{Ball3, Feature3};
pub(crate) use super::touch_lp::Centre;
pub use super::touch_lp::TrianglePart;
use super::touch_lp::{Candidate, Setting, Source, Unsure};
use crate::kernel::bigint::BigInt;
use crate::kernel::exact_line::Units;
use crate::kernel::exact_space::{cmp_ratios, Fb, Ring, V3};
use crate::kernel::Point3;
use std::cmp::Ordering;

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

/// The least candidates over every triangle (all tied).
fn least<R: Ring>(s: &Setting<'_, R>) -> Result<Vec<Candidate<R>>, Unsure> {
    let mut best: Vec<Candidate<R>> = Vec::new();
    for ti in 0..s.ts.len() {
        for which in s.plausible(ti) {
            let Some(cand) = s.candidate(ti, which)? else { continue };
            let order = match best.first() {
                None => Ordering::Less,
                Some(b) if b.source == cand.source && cand.source != Source::Own => Ordering::Equal,
                Some(b) => cmp_ratios(&cand.num, &cand.den, &b.num, &b.den).ok_or(Unsure)?,
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
    solve(ball, None, Centre::At(c), ts).map(|s| (s.radius, s.points))
}

/// The exact answer of a question, rounded.
pub(crate) struct Solved {
    /// The least radius.
    pub radius: f64,
    /// Where it is reached, with the triangle's index in the question.
    pub points: Vec<(usize, TouchPoint)>,
    /// The ball's centre: the point asked, or for a ball grown from a
    /// vertex `p − radius·ṽ`.
    pub centre: Point3,
}

/// The ball `p + s·(B − ṽ)` grown about `p` from ball vertex `apex`
/// (maximal* balls, thesis 3.3.2.2): the exact least `s` at which it
/// touches one of `ts`, where, and its centre `p − s·ṽ`. Triangles
/// through `p` answer 0; the caller leaves them out. `None` as for
/// [`touch_exact_many`], or when no triangle meets the vertex's cone.
pub(crate) fn grow_exact_many(ball: &Ball3, apex: usize, p: Centre, ts: &[[Point3; 3]]) -> Option<Solved> {
    solve(ball, Some(apex), p, ts)
}

/// Whether triangle `t` meets the open cone of the balls grown about `p`
/// from ball vertex `apex` (see `Setting::enters_cone`): only such a
/// triangle can stop a maximal* ball. Filter first, integers behind.
pub(crate) fn enters_cone(ball: &Ball3, apex: usize, p: Centre, t: [Point3; 3]) -> bool {
    let ts = [t];
    let units = units_of(ball, &p, &ts);
    let filtered: Setting<'_, Fb> = Setting::new(ball, Some(apex), units, p, &ts);
    match filtered.enters_cone(0) {
        Ok(answer) => answer,
        Err(Unsure) => {
            let exact: Setting<'_, BigInt> = Setting::new(ball, Some(apex), units, p, &ts);
            exact.enters_cone(0).unwrap_or(true)
        }
    }
}

/// Whether the open cone of the balls grown from ball vertex `apex` about
/// a point of the plane through `t` crosses that plane (meets both open
/// sides): then a triangle of the plane holding the apex in its interior
/// stops the growth at once (radius 0). The cone is spanned by the
/// directions `w − ṽ` to the other ball vertices, and it crosses the plane
/// unless `ṽ` is the farthest or the nearest vertex along its normal `n`;
/// on a convex polytope that shows at `ṽ`'s neighbours: the cone crosses
/// iff one neighbour `w` has `n·(w − ṽ) > 0` and one `< 0`. Signs of
/// `det(t1 − t0, t2 − t0, w − ṽ)`: filter first, integers behind.
pub(crate) fn cone_crosses_plane(ball: &Ball3, apex: usize, t: [Point3; 3]) -> bool {
    let w = ball.vertices();
    let around: Vec<usize> = ball
        .edges()
        .iter()
        .filter_map(|e| match e.vertices {
            [a, b] if a == apex => Some(b),
            [a, b] if b == apex => Some(a),
            _ => None,
        })
        .collect();
    let values = t.iter().chain(w.iter()).flat_map(|p| p.to_array());
    let units = Units::covering(values);
    fn signs<R: Ring>(t: [Point3; 3], w: &[Point3], apex: usize, around: &[usize], units: Units) -> Option<[bool; 2]> {
        let (e1, e2) = (V3::<R>::diff(t[1], t[0], units), V3::<R>::diff(t[2], t[0], units));
        let mut seen = [false; 2];
        for &k in around {
            match e1.det(&e2, &V3::diff(w[k], w[apex], units)).sign()? {
                Ordering::Greater => seen[0] = true,
                Ordering::Less => seen[1] = true,
                Ordering::Equal => {}
            }
        }
        Some(seen)
    }
    let seen = signs::<Fb>(t, w, apex, &around, units)
        .unwrap_or_else(|| signs::<BigInt>(t, w, apex, &around, units).unwrap_or([false; 2]));
    seen == [true, true]
}

/// Integers in units common to the ball, the centre and the triangles.
fn units_of(ball: &Ball3, c: &Centre, ts: &[[Point3; 3]]) -> Units {
    let values = ball.vertices().iter().chain(ts.iter().flatten()).flat_map(|p| p.to_array());
    Units::covering(values.chain(c.values()))
}

fn solve(ball: &Ball3, apex: Option<usize>, c: Centre, ts: &[[Point3; 3]]) -> Option<Solved> {
    let finite = |p: &Point3| p.to_array().iter().all(|v| v.is_finite());
    if ts.is_empty() || !c.values().iter().all(|v| v.is_finite()) || !ts.iter().flatten().all(finite) {
        return None;
    }
    let units = units_of(ball, &c, ts);
    let exact: Setting<'_, BigInt> = Setting::new(ball, apex, units, c, ts);
    // A sure, single winner of the filter has its features decided; its
    // numbers come again from the integers. Otherwise everything does.
    let filtered: Setting<'_, Fb> = Setting::new(ball, apex, units, c, ts);
    let winners: Vec<Candidate<BigInt>> = match least(&filtered) {
        // One point (maybe reached from several triangles sharing it).
        Ok(best)
            if !best.is_empty()
                && best.iter().all(|w| w.source == best[0].source)
                && (best.len() == 1 || best[0].source != Source::Own) =>
        {
            best.iter()
                .map(|w| {
                    let mut cand = exact.candidate(w.triangle_index, w.which).ok()??;
                    (cand.ball, cand.triangle) = (w.ball, w.triangle);
                    Some(cand)
                })
                .collect::<Option<_>>()?
        }
        _ => least(&exact).ok()?,
    };
    let first = winners.first()?;
    // Lengths carry the centre's scale `D`: r = num / (den·D).
    let scaled = |den: &BigInt| exact.scale.as_ref().map_or(den.clone(), |d| den * d);
    let radius = Ring::ratio(&first.num, &scaled(&first.den), 0);
    // The centre: the point asked, less `s·ṽ` for a grown ball.
    let mut centre = exact.at_centre.scale(&first.den);
    if let Some(a) = apex {
        centre = centre.sub(&exact.vertex_as_given(a).scale(&first.num));
    }
    let centre = centre.approx_over(&scaled(&first.den), exact.shift());
    let mut points: Vec<(usize, TouchPoint)> = winners
        .iter()
        .map(|cand| {
            let point = cand.at.add(&exact.at_centre.scale(&cand.den)).approx_over(&scaled(&cand.den), exact.shift());
            (cand.triangle_index, TouchPoint { point, ball: cand.ball, triangle: cand.triangle })
        })
        .collect();
    points.sort_by_key(|(ti, p)| (*ti, p.triangle, p.ball));
    points.dedup_by_key(|(ti, p)| (*ti, p.triangle, p.ball));
    Some(Solved { radius, points, centre })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against every vertex (not only the neighbours) in `f64`, on random
    /// balls and planes where no sign is near 0.
    #[test]
    fn the_cone_crosses_a_plane_iff_the_apex_is_neither_top_nor_bottom() {
        let mut seed = 5u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let (mut crossing, mut not) = (0, 0);
        for _ in 0..200 {
            let pts: Vec<Point3> = (0..12).map(|_| Point3::new(next(), next(), next()) * 2.0).collect();
            let Ok(ball) = Ball3::from_points(&pts.iter().map(|&p| p + Point3::new(0.1, 0.0, 0.0)).collect::<Vec<_>>())
            else {
                continue;
            };
            for _ in 0..10 {
                let t = [0, 1, 2].map(|_| Point3::new(next(), next(), next()) * 3.0);
                let n = (t[1] - t[0]).cross(t[2] - t[0]);
                let w = ball.vertices();
                let apex = ((next() + 1.0) * 0.5 * w.len() as f64) as usize % w.len();
                let along: Vec<f64> = w.iter().map(|&x| n.dot(x - w[apex])).collect();
                if along.iter().enumerate().any(|(k, &a)| k != apex && a.abs() < 1e-9) {
                    continue;
                }
                let want = along.iter().any(|&a| a > 0.0) && along.iter().any(|&a| a < 0.0);
                assert_eq!(cone_crosses_plane(&ball, apex, t), want, "apex {apex}, plane {t:?}");
                if want {
                    crossing += 1;
                } else {
                    not += 1;
                }
            }
        }
        assert!(crossing > 100 && not > 100, "{crossing} crossing, {not} not");
    }

    /// Exact ties: the cube's vertex (1, 1, 1) with planes through its
    /// edges or facets (a neighbour on the plane) counts those as sides
    /// the cone does not cross.
    #[test]
    fn a_plane_along_a_cone_wall_is_not_crossed() {
        let cube = Ball3::cube();
        let apex = cube.vertices().iter().position(|&w| w == Point3::new(1.0, 1.0, 1.0)).unwrap();
        let o = Point3::new(0.0, 0.0, 0.0);
        let plane = |n: Point3| {
            let u = if n.x.abs() < 0.5 { Point3::new(1.0, 0.0, 0.0) } else { Point3::new(0.0, 1.0, 0.0) };
            let a = n.cross(u);
            [o, a, n.cross(a)]
        };
        assert!(!cone_crosses_plane(&cube, apex, plane(Point3::new(0.0, 0.0, 1.0))), "a facet's plane");
        assert!(!cone_crosses_plane(&cube, apex, plane(Point3::new(1.0, 1.0, 0.0))), "along an edge");
        assert!(cone_crosses_plane(&cube, apex, plane(Point3::new(1.0, -1.0, 0.0))), "through the cone");
        assert!(!cone_crosses_plane(&cube, apex, plane(Point3::new(1.0, 1.0, 1.0))), "the vertex's own");
    }
}
