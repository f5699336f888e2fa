//! The contact arrangement of a contact domain (thesis 3.3.2.4,
//! Algorithm 7 `arrang`): a convex region of it split into cells on each
//! of which the maximal* balls anchored there touch one opposite class.
//! A VF class's domain is its face ([`face_arrangement`]); an EE class's
//! is cut into trapezoids first (`edge_domain`).
//!
//! A stack of convex subdomains starts with the region. For a subdomain,
//! each edge moved a hair inside (the thesis's `e^D`, so that no sample
//! lies on the projection line the edge came from) is walked by
//! [`opposite_along_in`]; the first change found gives a projection line
//! (where the two radius functions tie, or where a contact stops
//! holding), and the subdomain is cut by it into two convex ones. A
//! subdomain whose edges are all crossing-free is one cell: for a solid
//! without cavities, crossing-free edges enclose no projection line
//! (Property 3). With cavities an island of another class could hide
//! inside a cell; the sample at each cell's centroid is checked too.
//!
//! Points are the domain plane's coordinates `(a, b)` (for a face its own
//! parameters: `corner0 + a·(corner1 − corner0) + b·(corner2 − corner0)`).
//! The cells are `f64` polygons; their classes are decided exactly at
//! samples.

use super::along::{opposite_along_in, vf_plane, AlongError, ChangeKind, Opposite};
use super::domain::{DomainPlane, Line2};
use super::radius::{radius_fn, Affine3, RadiusFn};
use crate::shape::ball::Reach;
use crate::shape::Mesh3d;

/// How far inside the face its domain starts, and each walked edge lies
/// inside its subdomain: a fraction of the way to the centroid.
const INSET: f64 = 1e-6;

/// Cuts before the arrangement is given up (a runaway would mean lines
/// that do not separate what they were found between).
const MAX_CUTS: usize = 4096;

/// A polygon in a face's parameters.
type Polygon2 = Vec<(f64, f64)>;

/// A cell of a contact arrangement.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// Its corners, counter-clockwise in the face's parameters `(a, b)`.
    pub polygon: Vec<(f64, f64)>,
    /// The opposite class of the maximal* balls anchored in it.
    pub opposite: Opposite,
    /// Their radius there.
    pub radius: RadiusFn,
}

/// The contact arrangement of one VF class.
#[derive(Debug, Clone, PartialEq)]
pub struct FaceArrangement {
    /// The face.
    pub face: u32,
    /// The ball vertex of the class.
    pub anchor: usize,
    /// The cells; together they cover the face (less a rim of
    /// 10^-6 of the way to its centroid).
    pub cells: Vec<Cell>,
}

/// The contact arrangement of the VF class `(anchor, face)`.
///
/// # Errors
///
/// As [`opposite_along_in`]; [`AlongError::Unresolved`] when the cutting
/// runs away or a subdomain's edges disagree with no line to cut by.
pub fn face_arrangement(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    face: u32,
    anchor: usize,
) -> Result<FaceArrangement, AlongError> {
    let plane = vf_plane(mesh, reach, face, anchor)?;
    let cells = domain_arrangement(mesh, reach, &plane, anchor, &inset(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]))?;
    Ok(FaceArrangement { face, anchor, cells })
}

/// The cells of a convex region `start` (counter-clockwise, in `plane`'s
/// coordinates) of a contact domain whose balls are anchored at ball
/// vertex `anchor`: the region cut by projection lines until each part
/// has one opposite class.
///
/// # Errors
///
/// As [`face_arrangement`].
pub fn domain_arrangement(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    plane: &DomainPlane,
    anchor: usize,
    start: &[(f64, f64)],
) -> Result<Vec<Cell>, AlongError> {
    let mut stack = vec![start.to_vec()];
    let mut cells = Vec::new();
    let mut cuts = 0;
    while let Some(d) = stack.pop() {
        match cut_of(mesh, reach, plane, anchor, &d)? {
            Cut::Line(line) => {
                cuts += 1;
                if cuts > MAX_CUTS {
                    return Err(AlongError::Unresolved { at: 0.0 });
                }
                let (left, right) = split(&d, &line);
                stack.push(left);
                stack.push(right);
            }
            Cut::Cell(opposite) => {
                let radius = radius_fn(mesh, reach.ball(), anchor, opposite.ball, opposite.surface)
                    .ok_or(AlongError::NotGeneral { at: 0.0 })?;
                cells.push(Cell { polygon: d, opposite, radius });
            }
        }
    }
    Ok(cells)
}

/// What a subdomain needs: a cut, or nothing (a cell of this class).
enum Cut {
    Line(Line2),
    Cell(Opposite),
}

/// The first projection line crossing an edge of `d` (moved inside)
/// that separates `d`'s corners, or the class of `d` when there is none.
fn cut_of(
    mesh: &Mesh3d,
    reach: &Reach<'_>,
    plane: &DomainPlane,
    anchor: usize,
    d: &[(f64, f64)],
) -> Result<Cut, AlongError> {
    let inner = inset(d);
    let size = d.iter().map(|&(a, b)| a.abs() + b.abs()).fold(0.0, f64::max).max(1.0);
    let mut class: Option<Opposite> = None;
    let mut disagree = false;
    // Changes whose every candidate line misses `d` or only grazes it
    // (cuts off a needle narrower than the tolerance), and whether any
    // missed it altogether.
    let (mut needles, mut unexplained) = (0, 0);
    let mut unresolved: Option<AlongError> = None;
    for k in 0..inner.len() {
        let (from, to) = (inner[k], inner[(k + 1) % inner.len()]);
        // An edge passing a hair from a junction's projection may hold
        // changes too close to separate: the other edges may still give
        // a cut, after which that edge is gone.
        let along = match opposite_along_in(mesh, reach, plane, anchor, from, to) {
            Ok(a) => a,
            Err(e @ AlongError::Unresolved { .. }) => {
                unresolved = Some(e);
                continue;
            }
            Err(e) => return Err(e),
        };
        for (i, change) in along.changes.iter().enumerate() {
            let (left, right) = (&along.pieces[i], &along.pieces[i + 1]);
            let p = change.point;
            let tie = Affine3 {
                grad: left.radius.radius.grad - right.radius.radius.grad,
                at0: left.radius.radius.at0 - right.radius.radius.at0,
            };
            // Where the radius functions meet (a tie), or the condition of
            // the contact that ends or starts there: one that holds inside
            // its own piece and fails inside the other, crossing 0 nearest
            // the change. The condition least in magnitude there can be
            // another line through a nearby corner along which the walk
            // runs a hair inside; then the two radii also meet at the
            // change, and their tie is the line.
            let mut candidates = Vec::with_capacity(4);
            if change.kind == ChangeKind::Tie {
                candidates.push(tie);
            } else {
                let at = |t: f64| plane.point((from.0 + t * (to.0 - from.0), from.1 + t * (to.1 - from.1)));
                let (t_in, t_out) = (0.5 * (left.from + left.to), 0.5 * (right.from + right.to));
                let (p_in, p_out) = (at(t_in), at(t_out));
                let crossing = |g: &Affine3, own_first: bool| {
                    let (a, b) = (g.at(p_in), g.at(p_out));
                    let (mine, other) = if own_first { (a, b) } else { (b, a) };
                    (mine >= 0.0 && other < 0.0)
                        .then(|| ((t_in + (t_out - t_in) * (a / (a - b)) - change.at).abs(), *g))
                };
                let mut crossings: Vec<(f64, Affine3)> = left
                    .radius
                    .holds
                    .iter()
                    .filter_map(|g| crossing(g, true))
                    .chain(right.radius.holds.iter().filter_map(|g| crossing(g, false)))
                    .collect();
                crossings.sort_by(|x, y| x.0.total_cmp(&y.0));
                candidates.extend(crossings.into_iter().map(|x| x.1));
                candidates.push(tie);
                let ending = if left.radius.margin(p).abs() <= right.radius.margin(p).abs() {
                    &left.radius
                } else {
                    &right.radius
                };
                candidates.extend(ending.holds.iter().min_by(|g, h| g.at(p).abs().total_cmp(&h.at(p).abs())));
            }
            let mut grazed = false;
            for f in candidates {
                let line = plane.line(&f);
                let values: Vec<f64> = d.iter().map(|&q| line.at(q)).collect();
                let scale = (line.ca.abs() + line.cb.abs()) * size * 1e-9;
                let (lo, hi) =
                    values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &v| (l.min(v), h.max(v)));
                if hi > scale && lo < -scale {
                    return Ok(Cut::Line(line));
                }
                grazed |= lo <= scale && hi >= -scale;
            }
            if grazed {
                needles += 1;
            } else {
                unexplained += 1;
            }
        }
        for piece in &along.pieces {
            disagree |= class.is_some_and(|c| c != piece.opposite);
            class = Some(piece.opposite);
        }
    }
    if let Some(e) = unresolved {
        return Err(e);
    }
    // Every edge crossing-free: one class all round, and (with cavities
    // an island could hide inside) at the centroid too.
    let g = centroid(d);
    let there = plane.maximal_ball(mesh, g, anchor, reach);
    let at_centre = there.as_ref().and_then(|b| match b.opposite.as_slice() {
        [c] => Some(Opposite { ball: c.ball, surface: c.surface, kind: c.kind }),
        _ => None,
    });
    match (class, disagree) {
        (Some(c), false) if at_centre.is_none_or(|x| x == c) => Ok(Cut::Cell(c)),
        // The edges disagree only beside lines that cut off a needle of
        // `d` narrower than 10^-9 of its size (two projection lines
        // meeting at a junction at a hair's angle): the needle's piece of
        // sheet is below the weld tolerance, and `d` is one cell of the
        // class at its centroid.
        (Some(_), true) if unexplained == 0 && needles > 0 => {
            at_centre.map(Cut::Cell).ok_or(AlongError::Unresolved { at: 0.0 })
        }
        _ => Err(AlongError::Unresolved { at: 0.0 }),
    }
}

/// The polygon moved toward its centroid by [`INSET`] of the way.
pub(crate) fn inset(d: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let g = centroid(d);
    d.iter().map(|&(a, b)| (a + (g.0 - a) * INSET, b + (g.1 - b) * INSET)).collect()
}

/// The centroid of a convex polygon's corners.
fn centroid(d: &[(f64, f64)]) -> (f64, f64) {
    let n = d.len() as f64;
    let (sa, sb) = d.iter().fold((0.0, 0.0), |(x, y), &(a, b)| (x + a, y + b));
    (sa / n, sb / n)
}

/// A convex polygon cut by a line into the parts where it is `≥ 0` and
/// `≤ 0`, each counter-clockwise. Corners within 10^-12 of the line (in
/// the parameters) count as on it, so a cut through a corner makes no
/// sliver; corners closer than that to the one before are dropped.
fn split(d: &[(f64, f64)], line: &Line2) -> (Polygon2, Polygon2) {
    let tol = 1e-12 * (line.ca.abs() + line.cb.abs());
    let f = |p: (f64, f64)| {
        let v = line.at(p);
        if v.abs() <= tol {
            0.0
        } else {
            v
        }
    };
    let (mut pos, mut neg) = (Vec::new(), Vec::new());
    for k in 0..d.len() {
        let (p, q) = (d[k], d[(k + 1) % d.len()]);
        let (fp, fq) = (f(p), f(q));
        if fp >= 0.0 {
            pos.push(p);
        }
        if fp <= 0.0 {
            neg.push(p);
        }
        if (fp > 0.0 && fq < 0.0) || (fp < 0.0 && fq > 0.0) {
            let s = fp / (fp - fq);
            let x = (p.0 + (q.0 - p.0) * s, p.1 + (q.1 - p.1) * s);
            pos.push(x);
            neg.push(x);
        }
    }
    (without_repeats(pos), without_repeats(neg))
}

/// The polygon without corners within 10^-12 of the one before.
fn without_repeats(mut d: Polygon2) -> Polygon2 {
    let near = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs() + (p.1 - q.1).abs() <= 1e-12;
    d.dedup_by(|q, p| near(*p, *q));
    while d.len() > 1 && near(d[0], d[d.len() - 1]) {
        d.pop();
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_splits_a_square_into_two_counter_clockwise_parts() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let line = Line2 { ca: 1.0, cb: 0.0, c0: -0.25 };
        let (pos, neg) = split(&square, &line);
        let area = |d: &[(f64, f64)]| {
            (0..d.len()).map(|k| d[k].0 * d[(k + 1) % d.len()].1 - d[(k + 1) % d.len()].0 * d[k].1).sum::<f64>() / 2.0
        };
        assert!((area(&pos) - 0.75).abs() < 1e-15 && (area(&neg) - 0.25).abs() < 1e-15);
        assert!(pos.iter().all(|&p| line.at(p) >= 0.0) && neg.iter().all(|&p| line.at(p) <= 0.0));
    }
}
