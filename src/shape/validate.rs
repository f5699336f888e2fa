//! Validation of loops into a shape: the checks and their order.
//!
//! Each check assumes the earlier ones passed: finiteness before geometry,
//! element sanity before intersections, no intersections before the
//! containment tests of holes (which then need only one point per hole).
//! All positions and indices in errors refer to the loops as given.

use super::box_tree::BoxTree;
use super::bulge_loop::{winding_contribution, Loop};
use super::error::{Degeneracy, ElementRef, ShapeError};
use super::intersect::approach_point;
use super::joints::{classify, turning_angle, JointKind};
use super::options::ShapeOptions;
use super::MAX_COORDINATE;
use crate::kernel::{BBox, FilteredKernel, Point};
use rayon::prelude::*;
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
    let tol = opts.tolerance_for(vbox.diagonal());
    let flatten = opts.flatten_sagitta.unwrap_or(tol);
    let mut flattened = 0;
    for (li, l) in loops.iter_mut().enumerate() {
        flattened += check_elements(li, l, tol, flatten)?;
    }
    let bbox = loops.iter().fold(BBox::EMPTY, |b, l| b.union(&l.bbox()));
    for (li, l) in loops.iter().enumerate() {
        for (i, e) in l.elements().enumerate() {
            let bb = e.bbox();
            for v in [bb.min.x, bb.min.y, bb.max.x, bb.max.y] {
                if v.abs() > MAX_COORDINATE {
                    return Err(ShapeError::OutOfRange {
                        at: at(li, i),
                        value: v,
                    });
                }
            }
        }
        for i in 0..l.len() {
            if turning_angle(l, i).abs() > std::f64::consts::PI - opts.angle_tolerance {
                return Err(ShapeError::Degenerate {
                    at: at(li, i),
                    kind: Degeneracy::Cusp,
                    position: l.vertices[i].p,
                });
            }
        }
        if l.signed_area().abs() <= tol * l.perimeter() {
            return Err(ShapeError::Degenerate {
                at: at(li, 0),
                kind: Degeneracy::ZeroArea,
                position: l.vertices[0].p,
            });
        }
    }
    let index = ElementIndex::new(&loops);
    check_intersections(&loops, &index, tol)?;
    check_holes(&loops, &index)?;

    let mut reversed = Vec::with_capacity(loops.len());
    for (li, l) in loops.iter_mut().enumerate() {
        let want_ccw = li == 0;
        let flip = (l.signed_area() > 0.0) != want_ccw;
        if flip {
            *l = l.reversed();
        }
        reversed.push(flip);
    }
    let joints = loops
        .iter()
        .map(|l| {
            (0..l.len())
                .map(|i| classify(turning_angle(l, i), opts.angle_tolerance))
                .collect()
        })
        .collect();
    Ok(Validated {
        loops,
        reversed,
        joints,
        flattened,
        tolerance: tol,
        bbox,
    })
}

fn check_numbers(loops: &[Loop]) -> Result<(), ShapeError> {
    for (li, l) in loops.iter().enumerate() {
        let n = l.len();
        if n < 2 || (n == 2 && l.vertices.iter().all(|v| v.bulge == 0.0)) {
            return Err(ShapeError::TooFewElements {
                loop_index: li,
                count: n,
            });
        }
        for (i, v) in l.vertices.iter().enumerate() {
            if !(v.p.is_finite() && v.bulge.is_finite()) {
                return Err(ShapeError::NonFinite { at: at(li, i) });
            }
            for c in [v.p.x, v.p.y] {
                if c.abs() > MAX_COORDINATE {
                    return Err(ShapeError::OutOfRange {
                        at: at(li, i),
                        value: c,
                    });
                }
            }
        }
    }
    Ok(())
}

/// Rejects zero-length elements and turns arcs flatter than `flatten` into
/// segments; returns how many were flattened.
fn check_elements(li: usize, l: &mut Loop, tol: f64, flatten: f64) -> Result<usize, ShapeError> {
    let n = l.len();
    let mut flattened = 0;
    for i in 0..n {
        let (a, b) = (l.vertices[i].p, l.vertices[(i + 1) % n].p);
        if a.dist(b) <= tol {
            return Err(ShapeError::Degenerate {
                at: at(li, i),
                kind: Degeneracy::ZeroLength,
                position: a,
            });
        }
        if l.vertices[i].bulge != 0.0 && l.element(i).sagitta() <= flatten {
            l.vertices[i].bulge = 0.0;
            flattened += 1;
        }
    }
    Ok(flattened)
}

/// All elements of all loops in one box tree, with global ids.
pub(crate) struct ElementIndex {
    pub tree: BoxTree,
    /// `offsets[l]` = global id of element 0 of loop `l`; one extra entry at the end.
    pub offsets: Vec<usize>,
}

impl ElementIndex {
    pub fn new(loops: &[Loop]) -> ElementIndex {
        let mut offsets = Vec::with_capacity(loops.len() + 1);
        let mut total = 0;
        for l in loops {
            offsets.push(total);
            total += l.len();
        }
        offsets.push(total);
        let boxes: Vec<BBox> = loops
            .par_iter()
            .flat_map_iter(|l| l.elements().map(|e| e.bbox()))
            .collect();
        ElementIndex {
            tree: BoxTree::new(boxes),
            offsets,
        }
    }

    pub fn locate(&self, id: usize) -> ElementRef {
        let l = self.offsets.partition_point(|&o| o <= id) - 1;
        at(l, id - self.offsets[l])
    }
}

fn check_intersections(loops: &[Loop], index: &ElementIndex, tol: f64) -> Result<(), ShapeError> {
    let total = *index.offsets.last().unwrap_or(&0);
    let exclude_radius = 64.0 * tol;
    let first = (0..total).into_par_iter().find_map_first(|gid| {
        let r = index.locate(gid);
        let l = &loops[r.loop_index];
        let n = l.len();
        let e = l.element(r.element);
        let query = index.tree.item_box(gid).inflate(tol);
        let mut worst: Option<(usize, Point)> = None;
        index.tree.visit_overlapping::<()>(&query, |other| {
            if other <= gid || worst.is_some_and(|(w, _)| w < other) {
                return ControlFlow::Continue(());
            }
            let o = index.locate(other);
            let f = loops[o.loop_index].element(o.element);
            let mut shared: [Point; 2] = [Point::default(); 2];
            let mut k = 0;
            if o.loop_index == r.loop_index {
                if (r.element + 1) % n == o.element {
                    shared[k] = e.end();
                    k += 1;
                }
                if (o.element + 1) % n == r.element {
                    shared[k] = e.start();
                    k += 1;
                }
            }
            if let Some(p) = approach_point(&e, &f, tol, &shared[..k], exclude_radius) {
                worst = Some((other, p));
            }
            ControlFlow::Continue(())
        });
        worst.map(|(other, p)| (r, index.locate(other), p))
    });
    match first {
        Some((first, second, position)) => Err(ShapeError::Intersection {
            first,
            second,
            position,
        }),
        None => Ok(()),
    }
}

/// With no intersections, a hole is inside the outer loop iff one of its
/// points is; nesting between holes likewise. One ray query per hole.
fn check_holes(loops: &[Loop], index: &ElementIndex) -> Result<(), ShapeError> {
    let k = FilteredKernel;
    let xmax = index.tree.bounds().max.x;
    let err = (1..loops.len()).into_par_iter().find_map_first(|h| {
        let p = loops[h].vertices[0].p;
        let ray = BBox {
            min: p,
            max: Point::new(xmax.max(p.x), p.y),
        };
        let mut winding = vec![0i32; loops.len()];
        index.tree.visit_overlapping::<()>(&ray, |gid| {
            let r = index.locate(gid);
            if r.loop_index != h {
                let e = loops[r.loop_index].element(r.element);
                winding[r.loop_index] += winding_contribution(&k, &e, p);
            }
            ControlFlow::Continue(())
        });
        if winding[0] == 0 {
            return Some(ShapeError::HoleOutside { hole: h, position: p });
        }
        (1..loops.len())
            .find(|&c| c != h && winding[c] != 0)
            .map(|c| ShapeError::HoleInsideHole {
                hole: h,
                container: c,
                position: p,
            })
    });
    err.map_or(Ok(()), Err)
}
