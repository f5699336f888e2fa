//! Validation of loops into a shape: the checks and their order.
//!
//! Each check assumes the earlier ones passed: finiteness before geometry,
//! element sanity before intersections, no intersections before the
//! containment tests of holes (which then need only one point per hole).
//! All positions and indices in errors refer to the loops as given.

pub(crate) mod containment;
pub(crate) mod intersect;
pub(crate) mod sweep;
pub(crate) mod sweep_status;

use crate::kernel::element::Element;
use crate::kernel::{BBox, Point};
use crate::shape::index::element_index::ElementIndex;
use crate::shape::model::bulge_loop::{Loop, LoopKind};
use crate::shape::model::error::{Degeneracy, ElementRef, ShapeError};
use crate::shape::model::joints::{classify, turning_angle, JointKind};
use crate::shape::model::options::ShapeOptions;
use crate::shape::model::per_element;
use crate::shape::validate::containment::check_holes;
use crate::shape::validate::intersect::element_pair_approach;
use crate::shape::validate::sweep::{sweep_intersections, SweepOutcome};
use crate::shape::{MAX_COORDINATE, MIN_EXTENT, MIN_RELATIVE_TOLERANCE};
use std::ops::ControlFlow;

/// The result of validation: normalised loops and what was learned on the way.
pub(crate) struct Validated {
    pub loops: Vec<Loop>,
    pub reversed: Vec<bool>,
    pub joints: Vec<Vec<JointKind>>,
    pub flattened: usize,
    pub tolerance: f64,
    pub bbox: BBox,
}

fn at(loop_index: usize, element: usize) -> ElementRef {
    ElementRef { loop_index, element }
}

pub(crate) fn validate(mut loops: Vec<Loop>, opts: &ShapeOptions) -> Result<Validated, ShapeError> {
    opts.check()?;
    if loops.is_empty() {
        return Err(ShapeError::Empty);
    }
    check_numbers(&loops)?;
    let mut vbox = BBox::EMPTY;
    for l in &loops {
        for v in &l.vertices {
            vbox.add_point(v.p);
        }
    }
    if vbox.diagonal() < MIN_EXTENT {
        return Err(ShapeError::OutOfRange { at: at(0, 0), value: vbox.diagonal() });
    }
    // Below a few hundred ulps of the largest coordinate, rounding in the
    // constructions would decide crossings; such a tolerance is raised.
    let scale = vbox.min.x.abs().max(vbox.min.y.abs()).max(vbox.max.x.abs()).max(vbox.max.y.abs()).max(vbox.diagonal());
    let tol = opts.tolerance_for(vbox.diagonal()).max(MIN_RELATIVE_TOLERANCE * scale);
    let flatten = Flatten {
        sagitta: opts.flatten_sagitta.unwrap_or(tol),
        radius: opts.max_radius_ratio * vbox.diagonal(),
        // Two neighbouring flattened arcs add their half-sweeps at the joint.
        half_sweep: 0.5 * opts.angle_tolerance,
    };
    let offsets = per_element::offsets(&loops);
    let flattened = check_elements(&mut loops, &offsets, tol, &flatten)?;
    let boxes = per_element::map_elements(&loops, &offsets, |l, i| loops[l].element(i).bbox());
    let bbox = boxes.iter().fold(BBox::EMPTY, |b, e| b.union(e));
    if bbox.min.x.min(bbox.min.y) < -MAX_COORDINATE || bbox.max.x.max(bbox.max.y) > MAX_COORDINATE {
        let (gid, value) = boxes
            .iter()
            .enumerate()
            .find_map(|(g, b)| {
                [b.min.x, b.min.y, b.max.x, b.max.y].into_iter().find(|v| v.abs() > MAX_COORDINATE).map(|v| (g, v))
            })
            .expect("some box is out of range");
        let (l, i) = locate(&offsets, gid);
        return Err(ShapeError::OutOfRange { at: at(l, i), value });
    }
    // Turning angles once: the cusp check needs them now, the joint classes later.
    // A curve site's two ends are cusps by construction: the walk turns
    // right round them (turning angle −π, a reflex fan of π), whatever
    // the rounded tangents say.
    let mut turns = per_element::map_elements(&loops, &offsets, |l, i| {
        if loops[l].kind() == LoopKind::Point {
            -std::f64::consts::TAU
        } else if loops[l].is_curve_end(i) {
            -std::f64::consts::PI
        } else {
            turning_angle(&loops[l], i)
        }
    });
    if let Some(gid) = turns.iter().enumerate().position(|(g, t)| {
        let (l, i) = locate(&offsets, g);
        loops[l].kind() != LoopKind::Point
            && !loops[l].is_curve_end(i)
            && t.abs() > std::f64::consts::PI - opts.angle_tolerance
    }) {
        let (l, i) = locate(&offsets, gid);
        return Err(ShapeError::Degenerate { at: at(l, i), kind: Degeneracy::Cusp, position: loops[l].vertices[i].p });
    }
    let index = ElementIndex::with_boxes(boxes, offsets);
    check_intersections(&loops, &index, tol)?;
    // After the intersection check, so that a symmetric bow-tie is reported
    // as the crossing it is rather than as "no area".
    let areas: Vec<f64> = loops.iter().map(Loop::signed_area).collect();
    for (li, l) in loops.iter().enumerate() {
        if l.kind() == LoopKind::Region && areas[li].abs() <= tol * l.perimeter() {
            return Err(ShapeError::Degenerate {
                at: at(li, 0),
                kind: Degeneracy::ZeroArea,
                position: l.vertices[0].p,
            });
        }
    }
    check_holes(&loops, &index, &areas)?;

    let mut reversed = Vec::with_capacity(loops.len());
    for (li, l) in loops.iter_mut().enumerate() {
        let want_ccw = li == 0;
        // A curve loop has its interior on both sides: never turned round.
        let flip = l.kind() == LoopKind::Region && (areas[li] > 0.0) != want_ccw;
        if flip {
            *l = l.reversed();
            // Vertex k of the reversed loop is vertex n − 1 − k, where the
            // same two elements meet traversed backwards: the turn flips sign.
            let t = &mut turns[index.offsets[li]..index.offsets[li + 1]];
            t.reverse();
            t.iter_mut().for_each(|a| *a = -*a);
        }
        reversed.push(flip);
    }
    let joints = loops
        .iter()
        .enumerate()
        .map(|(li, _)| {
            turns[index.offsets[li]..index.offsets[li + 1]].iter().map(|&t| classify(t, opts.angle_tolerance)).collect()
        })
        .collect();
    Ok(Validated { loops, reversed, joints, flattened, tolerance: tol, bbox })
}

/// Loop and element index of a global element id.
fn locate(offsets: &[usize], gid: usize) -> (usize, usize) {
    let l = offsets.partition_point(|&o| o <= gid) - 1;
    (l, gid - offsets[l])
}

fn check_numbers(loops: &[Loop]) -> Result<(), ShapeError> {
    for (li, l) in loops.iter().enumerate() {
        let n = l.len();
        let few = match l.kind() {
            LoopKind::Point => n != 1,
            LoopKind::Curve => n < 2,
            LoopKind::Region => n < 2 || (n == 2 && l.vertices.iter().all(|v| v.bulge == 0.0)),
        };
        if few {
            return Err(ShapeError::TooFewElements { loop_index: li, count: n });
        }
        for (i, v) in l.vertices.iter().enumerate() {
            if !(v.p.is_finite() && v.bulge.is_finite()) {
                return Err(ShapeError::NonFinite { at: at(li, i) });
            }
            for c in [v.p.x, v.p.y] {
                if c.abs() > MAX_COORDINATE {
                    return Err(ShapeError::OutOfRange { at: at(li, i), value: c });
                }
            }
        }
    }
    Ok(())
}

/// When an arc counts as straight: sagitta at most `sagitta`, or radius above `radius`.
/// The sagitta test alone would turn short arcs of smooth biarc curves into
/// segments and so create corners; the half-sweep bound keeps every joint's
/// class (a chord's tangent differs from the arc's by half the sweep).
struct Flatten {
    sagitta: f64,
    radius: f64,
    half_sweep: f64,
}

/// What [`check_elements`] found for one element.
#[derive(Clone, Copy, PartialEq)]
enum ElementCheck {
    Keep,
    Flatten,
    ZeroLength,
    RadiusOverflow,
}

/// Rejects zero-length elements and turns arcs that are straight by
/// `flatten` into segments; returns how many were flattened. The first
/// offending element in loop order is reported.
fn check_elements(loops: &mut [Loop], offsets: &[usize], tol: f64, flatten: &Flatten) -> Result<usize, ShapeError> {
    let checks = per_element::map_elements(loops, offsets, |l, i| {
        let lp = &loops[l];
        // A point site's element is the point itself.
        if lp.kind() == LoopKind::Point {
            return ElementCheck::Keep;
        }
        let (a, b) = (lp.vertices[i].p, lp.vertices[(i + 1) % lp.len()].p);
        if a.dist(b) <= tol {
            return ElementCheck::ZeroLength;
        }
        let Element::Arc(arc) = lp.element(i) else { return ElementCheck::Keep };
        // Only arcs of at most a half turn are nearly straight when their
        // radius is huge; a huge nearly full circle is out of range instead.
        let straight = (arc.bulge.abs() <= 1.0 && arc.radius > flatten.radius)
            || (Element::Arc(arc).sagitta() <= flatten.sagitta && arc.sweep().abs() / 2.0 <= flatten.half_sweep);
        if straight {
            ElementCheck::Flatten
        } else if !(arc.center.is_finite() && arc.radius.is_finite()) {
            // A nearly full circle on a tiny chord (huge bulge) can have a
            // radius that overflows; large but finite radii of flat arcs are
            // fine (their sagitta exceeds the tolerance, so the radius stays
            // below diagonal² / (8·tolerance)).
            ElementCheck::RadiusOverflow
        } else {
            ElementCheck::Keep
        }
    });
    let mut flattened = 0;
    let lens: Vec<usize> = loops.iter().map(Loop::len).collect();
    let all = lens.iter().enumerate().flat_map(|(l, &n)| (0..n).map(move |i| (l, i)));
    for ((l, i), c) in all.zip(checks) {
        match c {
            ElementCheck::Keep => {}
            ElementCheck::Flatten => {
                loops[l].vertices[i].bulge = 0.0;
                flattened += 1;
            }
            ElementCheck::ZeroLength => {
                let position = loops[l].vertices[i].p;
                return Err(ShapeError::Degenerate { at: at(l, i), kind: Degeneracy::ZeroLength, position });
            }
            ElementCheck::RadiusOverflow => {
                let value = match loops[l].element(i) {
                    Element::Arc(arc) => arc.radius,
                    Element::Segment(_) => f64::INFINITY,
                };
                return Err(ShapeError::OutOfRange { at: at(l, i), value });
            }
        }
    }
    Ok(flattened)
}

/// Mean candidate pairs per element the box tree may test before the sweep
/// takes over: the tree is fast and parallel on ordinary boundaries, the
/// sweep is O(n log n) on every boundary (dense spokes, combs) where element
/// boxes overlap a lot.
const TREE_BUDGET_PER_ELEMENT: usize = 64;

/// Mean candidates per element, estimated from a sample, above which the
/// sweep is used straight away.
const TREE_MEAN_CANDIDATES: usize = 32;

fn check_intersections(loops: &[Loop], index: &ElementIndex, tol: f64) -> Result<(), ShapeError> {
    let tree_result = if tree_looks_cheap(index, tol) {
        tree_intersections(loops, index, tol, Some(TREE_BUDGET_PER_ELEMENT))
    } else {
        None
    };
    let found = match tree_result {
        Some(found) => found,
        None => match sweep_intersections(loops, &index.offsets, tol) {
            SweepOutcome::Clear => None,
            SweepOutcome::Found(a, b, p) => Some((a, b, p)),
            // The height order broke down, which only happens next to a
            // crossing the sweep has not isolated yet: search exhaustively.
            SweepOutcome::Inconsistent => tree_intersections(loops, index, tol, None).flatten(),
        },
    };
    match found {
        Some((first, second, position)) => Err(ShapeError::Intersection { first, second, position }),
        None => Ok(()),
    }
}

type Pair = (ElementRef, ElementRef, Point);

/// Estimates the box tree's work from a sample of about 1000 evenly spaced
/// elements (box overlaps only, no geometry), so that boundaries where boxes
/// overlap heavily go straight to the sweep.
fn tree_looks_cheap(index: &ElementIndex, tol: f64) -> bool {
    let total = index.tree.len();
    let step = (total / 1024).max(1);
    let mut overlaps = 0usize;
    let samples = total.div_ceil(step);
    let allowed = samples * TREE_MEAN_CANDIDATES;
    for gid in (0..total).step_by(step) {
        let query = index.tree.item_box(gid).inflate(tol);
        let over = index.tree.visit_overlapping(&query, |_| {
            overlaps += 1;
            if overlaps > allowed {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        });
        if over.is_some() {
            return false;
        }
    }
    true
}

/// Tests every pair of elements whose boxes come within `tol`, in
/// parallel; the smallest offending pair wins. `None` when the budget (mean
/// candidate pairs per element) ran out before an answer.
fn tree_intersections(loops: &[Loop], index: &ElementIndex, tol: f64, budget: Option<usize>) -> Option<Option<Pair>> {
    let budget = budget.map(|b| b.saturating_mul(index.tree.len()));
    let found = index
        .tree
        .min_overlapping_pair(tol, budget, |i, j| element_pair_approach(loops, index.locate(i), index.locate(j), tol));
    found.ok().map(|f| f.map(|(i, j, p)| (index.locate(i), index.locate(j), p)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::samples;
    use crate::shape::validate::sweep::sweep_in_slabs;
    use crate::shape::Vertex;

    /// The sweep and the exhaustive box-tree search must agree on whether a
    /// boundary has a crossing or near-touch, on random polygons and arc
    /// chains with and without crossings.
    #[test]
    fn sweep_agrees_with_exhaustive_tree_search() {
        let mut seen = [0usize; 2];
        for seed in 0..300u64 {
            let n = 6 + (seed % 50) as usize;
            let mut l: Vec<Vertex> = samples::star_polygon(n, seed).remove(0);
            let mut mix = crate::util::mix::Mix(seed);
            let mut rnd = || mix.next();
            for v in l.iter_mut() {
                if rnd() < 0.4 {
                    v.bulge = (rnd() - 0.5) * 1.5;
                }
            }
            if seed % 3 == 0 {
                let (i, j) = ((rnd() * n as f64) as usize % n, (rnd() * n as f64) as usize % n);
                l.swap(i, j);
            }
            let loops = vec![Loop::new(l)];
            let index = ElementIndex::new(&loops);
            let tol = 1e-9;
            let tree = tree_intersections(&loops, &index, tol, None).unwrap();
            for slabs in [1, 2, 5] {
                let sweep = sweep_in_slabs(&loops, &index.offsets, tol, slabs);
                let sweep_found = match sweep {
                    SweepOutcome::Clear => false,
                    SweepOutcome::Found(..) => true,
                    SweepOutcome::Inconsistent => continue,
                };
                assert_eq!(tree.is_some(), sweep_found, "seed {seed}, {slabs} slabs: tree {tree:?}");
                seen[sweep_found as usize] += 1;
            }
        }
        assert!(seen[0] > 50 && seen[1] > 50, "{seen:?}");
    }

    #[test]
    fn joint_classes_of_reversed_loops_match_a_fresh_classification() {
        let mut checked = 0;
        for seed in 0..40u64 {
            let mut l: Vec<Vertex> = samples::star_polygon(8 + seed as usize, seed).remove(0);
            for (k, v) in l.iter_mut().enumerate() {
                v.bulge = [0.0, 0.2, -0.1][(k + seed as usize) % 3];
            }
            // Clockwise outer loop: validation must reverse it.
            let loops = vec![Loop::new(l).reversed()];
            let opts = ShapeOptions::default();
            let Ok(v) = validate(loops, &opts) else { continue };
            assert!(v.reversed[0]);
            let l = &v.loops[0];
            let fresh: Vec<JointKind> =
                (0..l.len()).map(|i| classify(turning_angle(l, i), opts.angle_tolerance)).collect();
            assert_eq!(v.joints[0], fresh, "seed {seed}");
            checked += 1;
        }
        assert!(checked >= 20, "{checked}");
    }

    #[test]
    fn dense_spokes_fall_back_to_the_sweep() {
        // 20k spokes: the tree alone would visit ~10^8 candidates.
        let loops: Vec<Loop> = samples::star_polygon(20_000, 3).into_iter().map(Loop::new).collect();
        let index = ElementIndex::new(&loops);
        assert!(tree_intersections(&loops, &index, 1e-9, Some(TREE_BUDGET_PER_ELEMENT)).is_none());
        assert!(check_intersections(&loops, &index, 1e-9).is_ok());
    }

    fn lp(pts: &[(f64, f64)]) -> Loop {
        Loop::new(pts.iter().map(|&(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 }).collect())
    }

    /// Runs the exhaustive tree search and the sweep with 1, 2 and 5 slabs;
    /// all must agree. Returns whether they found a pair.
    fn all_paths(loops: &[Loop], tol: f64) -> bool {
        let index = ElementIndex::new(loops);
        let tree = tree_intersections(loops, &index, tol, None).unwrap().is_some();
        for slabs in [1, 2, 5] {
            match sweep_in_slabs(loops, &index.offsets, tol, slabs) {
                SweepOutcome::Clear => assert!(!tree, "{slabs} slabs missed what the tree found"),
                SweepOutcome::Found(..) => assert!(tree, "{slabs} slabs found what the tree did not"),
                SweepOutcome::Inconsistent => panic!("inconsistent order on a small input"),
            }
        }
        tree
    }

    #[test]
    fn touches_where_one_element_ends_and_another_starts() {
        // Review findings: pieces meeting only at event points were never
        // both in the sweep's set.
        let outer = lp(&[(-3.0, -3.0), (3.0, -3.0), (3.0, 3.0), (-3.0, 3.0)]);
        let a = lp(&[(0.0, 0.0), (-1.0, 1.0), (-2.0, 0.0), (-1.0, -1.0)]);
        let b = lp(&[(0.0, 0.0), (1.0, -1.0), (2.0, 0.0), (1.0, 1.0)]);
        assert!(all_paths(&[outer.clone(), a.clone(), b], 1e-9));
        let tip = lp(&[(1e-10, 5.0), (1.0, 4.0), (2.0, 5.0), (1.0, 6.0)]);
        let square = lp(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]);
        assert!(all_paths(&[square.clone(), tip], 1e-9));
        let apart = lp(&[(1e-3, 5.0), (1.0, 4.0), (2.0, 5.0), (1.0, 6.0)]);
        assert!(!all_paths(&[square.clone(), apart], 1e-9));
        // A circle hole whose leftmost point nearly touches the wall.
        let ring = Loop::new(vec![
            Vertex { p: Point::new(2.0, 5.0), bulge: 1.0 },
            Vertex { p: Point::new(1e-10, 5.0), bulge: 1.0 },
        ]);
        assert!(all_paths(&[square, ring], 1e-9));
    }

    #[test]
    fn random_holes_with_touches_agree_on_every_path() {
        let mut mix = crate::util::mix::Mix(0x2545_f491_4f6c_dd1d);
        let mut rnd = || mix.next();
        let mut seen = [0usize; 2];
        for _ in 0..300 {
            let mut loops = vec![lp(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)])];
            for _ in 0..5 {
                // Squares and diamonds on a coarse grid, so that exact
                // touches and shared vertices are common.
                let (cx, cy) = (1.0 + (rnd() * 16.0).floor() * 0.5, 1.0 + (rnd() * 16.0).floor() * 0.5);
                let h = 0.25 * (1.0 + (rnd() * 2.0).floor());
                let mut l = if rnd() < 0.5 {
                    lp(&[(cx - h, cy - h), (cx + h, cy - h), (cx + h, cy + h), (cx - h, cy + h)])
                } else {
                    lp(&[(cx, cy - h), (cx + h, cy), (cx, cy + h), (cx - h, cy)])
                };
                if rnd() < 0.3 {
                    l.vertices[0].bulge = 0.4;
                }
                loops.push(l);
            }
            seen[all_paths(&loops, 1e-9) as usize] += 1;
        }
        assert!(seen[0] > 50 && seen[1] > 50, "{seen:?}");
    }

    #[test]
    fn zero_tolerance_is_raised_and_still_finds_crossings() {
        // Review finding: at tolerance 0 rounding hid most bow-tie crossings.
        let mut x = 7u64;
        for _ in 0..150 {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let t = (x >> 11) as f64 / (1u64 << 53) as f64;
            let bow = lp(&[(0.0, 0.0), (3.0, 1.0 + t), (3.0, 0.0), (0.0, 1.1 + t)]);
            let opts = ShapeOptions { tolerance: Some(0.0), ..ShapeOptions::default() };
            assert!(matches!(validate(vec![bow], &opts), Err(ShapeError::Intersection { .. })));
        }
    }

    #[test]
    fn a_crossing_just_beside_a_shared_vertex_is_found() {
        // Review finding: the arc leaves (0,0) almost along the incoming
        // segment and crosses it about 7·tol away, then sweeps below it.
        let l = Loop::new(vec![
            Vertex { p: Point::new(-1.0, 0.0), bulge: 0.0 },
            Vertex { p: Point::new(0.0, 0.0), bulge: 2.414222097932759 },
            Vertex { p: Point::new(0.001999990000025, -0.002), bulge: 0.0 },
            Vertex { p: Point::new(1.0, -1.0), bulge: 0.0 },
            Vertex { p: Point::new(-1.0, -1.0), bulge: 0.0 },
        ]);
        assert!(validate(vec![l], &ShapeOptions::default()).is_err());
    }
}
