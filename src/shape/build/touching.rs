//! Shapes of a drawing that touch: two parts sharing an edge, an island
//! touching the hole it lies in. Each shape validates on its own, so only
//! pairs of shapes are searched, and of each only the loops near the other.

use crate::kernel::Point;
use crate::shape::build::import::Traced;
use crate::shape::index::box_tree::BoxTree;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::ElementRef;
use crate::shape::shape2d::Shape2d;
use crate::shape::validate::first_meeting;
use crate::shape::validate::intersect::element_pair_approach;
use std::ops::ControlFlow;

/// Two shapes of a drawing that touch or cross, and the two entities that
/// meet.
#[derive(Debug, Clone, PartialEq)]
pub struct Touching {
    /// The two shapes, indices into
    /// [`Drawing2d::shapes`](crate::shape::Drawing2d::shapes), smaller first.
    pub shapes: [usize; 2],
    /// A point where they meet or come within the validation tolerance
    /// (model units).
    pub position: Point,
    /// The 1-based lines (DXF) or byte offsets (SVG) of the two entities.
    pub sources: [usize; 2],
    /// Their DXF handles (group 5), or those of the block references that
    /// placed them; 0 where the file gives none.
    pub handles: [u64; 2],
}

/// One report per pair of shapes that meet (within the smaller of their
/// validation tolerances), naming the two entities found to meet.
/// `traced[i]` are the loops of `shapes[i]` as given to validation, with
/// their origins.
pub(crate) fn touching_shapes(shapes: &[Shape2d], traced: &[Vec<Traced>]) -> Vec<Touching> {
    let tol = |i: usize| shapes[i].tolerance();
    let tree = BoxTree::new(shapes.iter().enumerate().map(|(i, s)| s.bbox().inflate(tol(i))).collect());
    let mut out = Vec::new();
    for (i, s) in shapes.iter().enumerate() {
        let mut near = Vec::new();
        tree.visit_overlapping(&s.bbox().inflate(tol(i)), |j| {
            if j > i {
                near.push(j);
            }
            ControlFlow::<()>::Continue(())
        });
        near.sort_unstable();
        for j in near {
            let t = tol(i).min(tol(j));
            // Loops of each shape that come near the other's box.
            let (bi, bj) = (s.bbox().inflate(t), shapes[j].bbox().inflate(t));
            let of_i: Vec<&Traced> = traced[i].iter().filter(|l| l.l.bbox().overlaps(&bj)).collect();
            let of_j: Vec<&Traced> = traced[j].iter().filter(|l| l.l.bbox().overlaps(&bi)).collect();
            if of_i.is_empty() || of_j.is_empty() {
                continue;
            }
            let loops: Vec<Loop> = of_i.iter().chain(&of_j).map(|l| l.l.clone()).collect();
            let Some((a, b, position)) = meeting(&loops, of_i.len(), t) else {
                continue;
            };
            // Within one shape nothing meets: one element is of each.
            let (a, b) = if a.loop_index < b.loop_index { (a, b) } else { (b, a) };
            if a.loop_index >= of_i.len() || b.loop_index < of_i.len() {
                continue;
            }
            let (oa, ob) = (of_i[a.loop_index].origin(a.element), of_j[b.loop_index - of_i.len()].origin(b.element));
            out.push(Touching {
                shapes: [i, j],
                position,
                sources: [oa.source, ob.source],
                handles: [oa.handle, ob.handle],
            });
        }
    }
    out
}

/// Below this many element pairs, every pair is tested: a sweep costs
/// more to set up than it saves (most drawings hold small parts).
const PAIRS_TESTED_ONE_BY_ONE: usize = 4096;

/// Where an element of `loops[..split]` meets one of `loops[split..]`
/// (within `tol`), or where any two elements meet, as validation finds it.
fn meeting(loops: &[Loop], split: usize, tol: f64) -> Option<(ElementRef, ElementRef, Point)> {
    let count = |ls: &[Loop]| ls.iter().map(Loop::len).sum::<usize>();
    if count(&loops[..split]).saturating_mul(count(&loops[split..])) > PAIRS_TESTED_ONE_BY_ONE {
        return first_meeting(loops, tol);
    }
    let refs = |from: usize, to: usize| {
        (from..to).flat_map(|l| (0..loops[l].len()).map(move |element| ElementRef { loop_index: l, element }))
    };
    let bbox = |r: ElementRef| loops[r.loop_index].element(r.element).bbox().inflate(tol);
    refs(0, split).find_map(|a| {
        let ba = bbox(a);
        refs(split, loops.len())
            .filter(|&b| ba.overlaps(&bbox(b)))
            .find_map(|b| element_pair_approach(loops, a, b, tol).map(|p| (a, b, p)))
    })
}
