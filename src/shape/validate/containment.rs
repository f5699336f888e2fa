//! Which loop directly contains each hole, in O(log n) per hole.
//!
//! Once no two elements touch, a hole's container follows from one ray. Cast
//! it rightwards from the hole's rightmost point p and take the first
//! element of another loop L it crosses. If the crossing leaves L (p is on
//! L's inner side), L contains the hole. If it enters L, the hole lies in
//! the same face as L's outside, so it has L's container. An entered L has
//! a point right of p, hence a rightmost point right of p: resolving holes
//! in decreasing order of their rightmost x never meets a cycle.
//!
//! The ray is y = p.y moved up by an infinitesimal ε (the half-open rule
//! below): an element counts when its lower end is at or below p.y and its
//! upper end above. Two elements crossing at the same x can only meet at a
//! vertex of one loop; the perturbed ray meets the one leaning further left
//! (smaller dx/dy going up) first, which is the tie-break.

use crate::kernel::element::Element;
use crate::kernel::{BBox, Point};
use crate::shape::index::box_tree::BoxTree;
use crate::shape::index::element_index::ElementIndex;
use crate::shape::model::bulge_loop::{Loop, LoopKind};
use crate::shape::model::error::ShapeError;
use rayon::prelude::*;
use std::ops::ControlFlow;

/// dx/dy of `u`, a direction pointing into an element from the crossing
/// (upwards, or horizontal at a lowest point): the order in which an
/// infinitesimally raised horizontal ray meets elements that leave one
/// point. A horizontal direction leans fully left or right.
fn lean(u: Point) -> f64 {
    if u.y > 0.0 {
        u.x / u.y
    } else if u.x > 0.0 {
        f64::INFINITY
    } else {
        f64::NEG_INFINITY
    }
}

/// First crossing of the raised ray from `p` with element `e`:
/// (x, lean, crossing goes upwards).
fn crossing(e: &Element, p: Point) -> Option<(f64, f64, bool)> {
    let spans = |lo: f64, hi: f64| lo <= p.y && p.y < hi;
    match e {
        Element::Segment(s) => {
            let up = s.b.y > s.a.y;
            let (lo, hi) = if up { (s.a, s.b) } else { (s.b, s.a) };
            if !spans(lo.y, hi.y) {
                return None;
            }
            let x = if p.y == lo.y { lo.x } else { lo.x + (p.y - lo.y) * (hi.x - lo.x) / (hi.y - lo.y) };
            (x > p.x).then_some((x, lean(hi - lo), up))
        }
        Element::Arc(arc) => {
            // Cut at the circle's top and bottom into y-monotone pieces and
            // keep the nearest crossing.
            let (c, r, ccw) = (arc.center, arc.radius, arc.is_ccw());
            let mut best: Option<(f64, f64, bool)> = None;
            for (start, end, mid) in arc.monotone_pieces(Point::new(0.0, 1.0)) {
                let up = end.y > start.y;
                let (lo, hi) = if up { (start, end) } else { (end, start) };
                if !spans(lo.y, hi.y) {
                    continue;
                }
                // The half of the circle from the piece's middle angle: a
                // piece from top to bottom has both ends at x = c.x.
                let right_half = mid.cos() >= 0.0;
                let x = if p.y == lo.y {
                    lo.x
                } else {
                    let h = ((r - (p.y - c.y).abs()) * (r + (p.y - c.y).abs())).max(0.0).sqrt();
                    if right_half {
                        c.x + h
                    } else {
                        c.x - h
                    }
                };
                let q = Point::new(x, p.y);
                // Travel tangent at q, then turned to point along the piece
                // away from its lower end.
                let travel = if ccw { (q - c).perp() } else { -(q - c).perp() };
                let into = if up { travel } else { -travel };
                let l = lean(into);
                // Two pieces of one arc can meet the ray at the same point
                // (its lowest); the lean decides as between elements.
                if x > p.x && best.is_none_or(|b| x < b.0 || (x == b.0 && l < b.1)) {
                    best = Some((x, l, up));
                }
            }
            best
        }
    }
}

/// The rightmost point of a loop.
fn rightmost(l: &Loop) -> Point {
    let mut best = l.vertices()[0].p;
    for e in l.elements() {
        let cand = match e {
            Element::Arc(a) if a.spans_direction(a.center + Point::new(1.0, 0.0)) => {
                a.center + Point::new(a.radius, 0.0)
            }
            _ => {
                if e.end().x > e.start().x {
                    e.end()
                } else {
                    e.start()
                }
            }
        };
        if cand.x > best.x {
            best = cand;
        }
    }
    best
}

/// The first crossing of a hole's ray: position, tie-break, direction and loop.
#[derive(Clone, Copy, Debug)]
struct Hit {
    x: f64,
    lean: f64,
    up: bool,
    loop_index: usize,
}

impl Hit {
    fn before(&self, o: &Hit) -> bool {
        self.x < o.x || (self.x == o.x && self.lean < o.lean)
    }
}

/// The first crossing of hole `h`'s ray from `p`, however far.
fn full_ray(loops: &[Loop], index: &ElementIndex, h: usize, p: Point) -> Option<Hit> {
    let crossing_of = |gid: usize| {
        let r = index.locate(gid);
        (r.loop_index != h).then(|| crossing(&loops[r.loop_index].element(r.element), p)).flatten().map(|c| (r, c))
    };
    let (gid, _) = index.tree.first_hit_right(p, |gid| crossing_of(gid).map(|(_, (x, lean, _))| (x, lean)))?;
    let (r, (x, lean, up)) = crossing_of(gid)?;
    Some(Hit { x, lean, up, loop_index: r.loop_index })
}

/// First hits of the rays of all holes (index 0 unused) within a short
/// reach: the hole's own width plus height. Rays of holes that lie close
/// together are batched (one tree descent per 8 holes), which is what makes
/// plates with 10^5 holes fast. `None` where nothing lies within reach.
fn short_rays(loops: &[Loop], index: &ElementIndex, probes: &[Point]) -> Vec<Option<Hit>> {
    let segments: Vec<BBox> = (1..loops.len())
        .into_par_iter()
        .map(|h| {
            let own =
                (index.offsets[h]..index.offsets[h + 1]).fold(BBox::EMPTY, |b, gid| b.union(index.tree.item_box(gid)));
            let p = probes[h];
            BBox { min: p, max: Point::new(p.x + own.width() + own.height(), p.y) }
        })
        .collect();
    let rays = BoxTree::new(segments);
    let leaves: Vec<(&BBox, &[u32])> = rays.leaves().collect();
    let found: Vec<(usize, Hit)> = leaves
        .par_iter()
        .flat_map_iter(|&(group, members)| {
            let mut best: [Option<Hit>; 8] = [None; 8];
            index.tree.visit_overlapping::<()>(group, |gid| {
                let r = index.locate(gid);
                let eb = index.tree.item_box(gid);
                let mut element = None;
                for (k, &m) in members.iter().enumerate() {
                    let h = m as usize + 1;
                    let segment = rays.item_box(m as usize);
                    if r.loop_index == h || !eb.overlaps(segment) {
                        continue;
                    }
                    let e = element.get_or_insert_with(|| loops[r.loop_index].element(r.element));
                    let Some((x, lean, up)) = crossing(e, probes[h]) else { continue };
                    let hit = Hit { x, lean, up, loop_index: r.loop_index };
                    if x <= segment.max.x && best[k].is_none_or(|b| hit.before(&b)) {
                        best[k] = Some(hit);
                    }
                }
                ControlFlow::Continue(())
            });
            members.iter().zip(best).filter_map(|(&m, b)| b.map(|b| (m as usize + 1, b)))
        })
        .collect();
    let mut hits = vec![None; loops.len()];
    for (h, hit) in found {
        hits[h] = Some(hit);
    }
    hits
}

/// [`check_holes`] for shapes with point sites. A point is never hit by
/// a ray (a zero-length element crosses nothing) and contains nothing, so
/// the other loops are checked among themselves, and each point's ray is
/// cast against them only: a cloud of points would otherwise send every
/// ray through the boxes of all the others.
fn check_with_points(loops: &[Loop], areas: &[f64]) -> Result<(), ShapeError> {
    let keep: Vec<usize> = (0..loops.len()).filter(|&l| loops[l].kind() != LoopKind::Point).collect();
    let sub: Vec<Loop> = keep.iter().map(|&l| loops[l].clone()).collect();
    let sub_areas: Vec<f64> = keep.iter().map(|&l| areas[l]).collect();
    let sub_index = ElementIndex::new(&sub);
    check_holes(&sub, &sub_index, &sub_areas).map_err(|e| match e {
        ShapeError::HoleOutside { hole, position } => ShapeError::HoleOutside { hole: keep[hole], position },
        ShapeError::HoleInsideHole { hole, container, position } => {
            ShapeError::HoleInsideHole { hole: keep[hole], container: keep[container], position }
        }
        other => other,
    })?;
    // Every other loop lies directly inside loop 0 now: a point's ray that
    // first crosses loop 0 or a region leaving it is inside that loop, one
    // that enters a region or meets a curve is beside it, in loop 0.
    let bad = (0..loops.len()).into_par_iter().filter(|&h| loops[h].kind() == LoopKind::Point).find_map_first(|h| {
        let p = loops[h].vertices()[0].p;
        match full_ray(&sub, &sub_index, usize::MAX, p) {
            None => Some(ShapeError::HoleOutside { hole: h, position: p }),
            Some(hit) => {
                let l = hit.loop_index;
                let leaves = sub[l].kind() == LoopKind::Region && hit.up == (sub_areas[l] > 0.0);
                match (l, leaves) {
                    (0, false) => Some(ShapeError::HoleOutside { hole: h, position: p }),
                    (0, true) | (_, false) => None,
                    (c, true) => Some(ShapeError::HoleInsideHole { hole: h, container: keep[c], position: p }),
                }
            }
        }
    });
    bad.map_or(Ok(()), Err)
}

#[derive(Clone, Copy, PartialEq)]
enum Container {
    Outside,
    Loop(usize),
}

/// Checks that every hole lies directly inside loop 0: no hole outside it,
/// none inside another hole. Loops are in input orientation, `areas` are
/// their signed areas.
pub(crate) fn check_holes(loops: &[Loop], index: &ElementIndex, areas: &[f64]) -> Result<(), ShapeError> {
    if loops.len() < 2 {
        return Ok(());
    }
    if loops.iter().any(|l| l.kind() == LoopKind::Point) {
        return check_with_points(loops, areas);
    }
    let ccw: Vec<bool> = areas.iter().map(|&a| a > 0.0).collect();
    let probes: Vec<Point> = (0..loops.len())
        .into_par_iter()
        .map(|h| if h == 0 { Point::default() } else { rightmost(&loops[h]) })
        .collect();
    let short = short_rays(loops, index, &probes);
    // For each hole: its test point and (loop hit, leaving it?). Moving
    // right across an upward element leaves its left side: the inside of a
    // counter-clockwise loop. The few rays that met nothing nearby go the
    // whole way.
    let probes: Vec<(Point, Option<(usize, bool)>)> = (0..loops.len())
        .into_par_iter()
        .map(|h| {
            let hit = if h == 0 { None } else { short[h].or_else(|| full_ray(loops, index, h, probes[h])) };
            // Nothing lies inside a curve site: its ray always enters it.
            let leaves = |hit: &Hit| loops[hit.loop_index].kind() == LoopKind::Region && hit.up == ccw[hit.loop_index];
            (probes[h], hit.map(|hit| (hit.loop_index, leaves(&hit))))
        })
        .collect();
    let mut order: Vec<usize> = (1..loops.len()).collect();
    order.sort_by(|&a, &b| probes[b].0.x.total_cmp(&probes[a].0.x));
    let mut container = vec![Container::Outside; loops.len()];
    for &h in &order {
        container[h] = match probes[h].1 {
            None => Container::Outside,
            Some((l, true)) => Container::Loop(l),
            Some((0, false)) => Container::Outside,
            Some((l, false)) => container[l],
        };
    }
    for h in 1..loops.len() {
        let position = probes[h].0;
        match container[h] {
            Container::Loop(0) => {}
            Container::Outside => return Err(ShapeError::HoleOutside { hole: h, position }),
            Container::Loop(c) => return Err(ShapeError::HoleInsideHole { hole: h, container: c, position }),
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::FilteredKernel;
    use crate::shape::Vertex;

    fn square(cx: f64, cy: f64, h: f64, bulge: f64) -> Loop {
        let v = |x: f64, y: f64| Vertex { p: Point::new(x, y), bulge };
        Loop::new(vec![v(cx - h, cy - h), v(cx + h, cy - h), v(cx + h, cy + h), v(cx - h, cy + h)])
    }

    fn areas(loops: &[Loop]) -> Vec<f64> {
        loops.iter().map(Loop::signed_area).collect()
    }

    fn circle(cx: f64, cy: f64, r: f64) -> Loop {
        Loop::new(vec![
            Vertex { p: Point::new(cx + r, cy), bulge: 1.0 },
            Vertex { p: Point::new(cx - r, cy), bulge: 1.0 },
        ])
    }

    /// The answer by winding numbers over every loop (independent code).
    fn oracle(loops: &[Loop]) -> Result<(), (usize, Option<usize>)> {
        let k = FilteredKernel;
        for h in 1..loops.len() {
            let p = loops[h].vertices()[0].p;
            if loops[0].winding_number(&k, p) == 0 {
                return Err((h, None));
            }
            if let Some(c) = (1..loops.len()).find(|&c| c != h && loops[c].winding_number(&k, p) != 0) {
                return Err((h, Some(c)));
            }
        }
        Ok(())
    }

    #[test]
    fn crossing_of_a_half_circle_piece_from_top_to_bottom() {
        // fuzz/json: the left half of a large arc, from its top to its bottom
        // point, was taken for the right half.
        let e = Element::from_bulge(Point::new(0.0, 3.0), Point::new(2.0, 2.0), 5.0);
        let (x, _, up) = crossing(&e, Point::new(2.0, 1.0)).unwrap();
        assert!((x - 2.5640549922170512).abs() < 1e-12);
        assert!(up);
        let (x, _, up) = crossing(&e, Point::new(-4.0, 1.0)).unwrap();
        assert!(x < -2.9 && !up);
    }

    #[test]
    fn ray_tangent_to_the_bottom_of_a_circle_meets_its_left_side_first() {
        // fuzz/svg: a square hole's corner (5, 4) level with the bottom of a
        // circular hole at (6, 4); both circle pieces start there with a
        // horizontal tangent. The raised ray enters the circle, then leaves.
        let k = FilteredKernel;
        let outer = square(5.0, 5.0, 5.0, 0.0);
        let sq = square(4.0, 3.0, 1.0, 0.0);
        let circ = |b: f64| {
            Loop::new(vec![Vertex { p: Point::new(5.0, 5.0), bulge: b }, Vertex { p: Point::new(7.0, 5.0), bulge: b }])
        };
        // Exactly −1 puts the lowest point at a vertex; one ulp less puts it
        // inside an arc, which is then cut there into two pieces.
        for c in [circ(-1.0), circ(-1.0).reversed(), circ(-0.9999999999999999), circ(-0.9999999999999999).reversed()] {
            let loops = vec![outer.clone(), sq.clone(), c];
            let index = ElementIndex::new(&loops);
            assert_eq!(check_holes(&loops, &index, &areas(&loops)), Ok(()));
            assert_eq!(loops[2].winding_number(&k, Point::new(4.0, 3.0)), 0);
        }
    }

    #[test]
    fn agrees_with_winding_numbers_on_aligned_grids() {
        let mut mix = crate::util::mix::Mix(99);
        let mut rnd = || mix.next();
        let mut seen = [0usize; 3];
        for _ in 0..400 {
            let outer = match (rnd() * 3.0) as u32 {
                0 => square(5.0, 5.0, 5.0, 0.0),
                1 => circle(5.0, 5.0, 6.0),
                // A big arc and its chord around the grid.
                _ => Loop::new(vec![
                    Vertex { p: Point::new(11.0, 11.0), bulge: 5.0 },
                    Vertex { p: Point::new(8.0, 12.0), bulge: 0.0 },
                ]),
            };
            let mut loops = vec![outer];
            // Cells on a 2-unit grid: every row shares y values, so rays run
            // exactly through other holes' vertices and arc extremes.
            for i in 0..4 {
                for j in 0..4 {
                    let (cx, cy) = (2.0 + 2.0 * i as f64, 2.0 + 2.0 * j as f64);
                    match (rnd() * 7.0) as u32 {
                        0 => loops.push(square(cx, cy, 0.5, 0.0)),
                        1 => loops.push(circle(cx, cy, 0.5)),
                        2 => loops.push(square(cx, cy, 0.5, 0.2)),
                        3 if rnd() < 0.1 => {
                            loops.push(square(cx, cy, 0.7, 0.0));
                            loops.push(circle(cx, cy, 0.3));
                        }
                        4 if rnd() < 0.1 => loops.push(circle(cx + 20.0, cy, 0.5)),
                        // A 286° arc closed by a chord: pieces from the
                        // circle's top to its bottom.
                        5 => loops.push(Loop::new(vec![
                            Vertex { p: Point::new(cx + 0.4, cy), bulge: 3.0 },
                            Vertex { p: Point::new(cx, cy + 0.4), bulge: 0.0 },
                        ])),
                        _ => {}
                    }
                }
            }
            if rnd() < 0.5 {
                for l in loops.iter_mut().skip(1) {
                    *l = l.reversed();
                }
            }
            let index = ElementIndex::new(&loops);
            let got = check_holes(&loops, &index, &areas(&loops));
            match (oracle(&loops), &got) {
                (Ok(()), Ok(())) => seen[0] += 1,
                (Err((h, None)), Err(ShapeError::HoleOutside { hole, .. })) if *hole == h => seen[1] += 1,
                (Err((h, Some(_))), Err(ShapeError::HoleInsideHole { hole, .. })) if *hole == h => seen[2] += 1,
                // Nesting has two valid descriptions: the inner hole inside
                // the outer one, or (for the lowest index) either of them.
                (Err(_), Err(ShapeError::HoleInsideHole { .. })) => seen[2] += 1,
                (want, _) => panic!("oracle {want:?}, containment {got:?}"),
            }
        }
        assert!(seen.iter().all(|&c| c > 20), "{seen:?}");
    }
}
