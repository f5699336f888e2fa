//! Shapes of a drawing that touch: two parts sharing an edge, an island
//! touching the hole it lies in. Each shape validates on its own, so only
//! elements of two different shapes are paired, and of each shape only the
//! loops near the other: loops and elements are found through box trees,
//! so a plate of 10^5 holes with an island in each stays near-linear.

use crate::kernel::Point;
use crate::shape::build::import::Traced;
use crate::shape::index::box_tree::BoxTree;
use crate::shape::model::bulge_loop::Loop;
use crate::shape::model::error::ElementRef;
use crate::shape::shape2d::Shape2d;
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

/// Shapes with more loops than this get a box tree over their loops.
const LOOPS_SCANNED: usize = 16;

/// One report per pair of shapes that meet (within the smaller of their
/// validation tolerances), naming the two entities found to meet.
/// `traced[i]` are the loops of `shapes[i]` as given to validation, with
/// their origins.
pub(crate) fn touching_shapes(shapes: &[Shape2d], traced: &[Vec<Traced>]) -> Vec<Touching> {
    let tol = |i: usize| shapes[i].tolerance();
    let tree = BoxTree::new(shapes.iter().enumerate().map(|(i, s)| s.bbox().inflate(tol(i))).collect());
    let loop_trees: Vec<Option<BoxTree>> = traced
        .iter()
        .map(|t| (t.len() > LOOPS_SCANNED).then(|| BoxTree::new(t.iter().map(|l| l.l.bbox()).collect())))
        .collect();
    // The loops of shape `i` whose boxes meet `b`.
    let near = |i: usize, b: &crate::kernel::BBox| -> Vec<usize> {
        match &loop_trees[i] {
            Some(t) => {
                let mut out = Vec::new();
                t.visit_overlapping(b, |k| {
                    out.push(k);
                    ControlFlow::<()>::Continue(())
                });
                out.sort_unstable();
                out
            }
            None => (0..traced[i].len()).filter(|&k| traced[i][k].l.bbox().overlaps(b)).collect(),
        }
    };
    let mut out = Vec::new();
    for (i, s) in shapes.iter().enumerate() {
        let mut others = Vec::new();
        tree.visit_overlapping(&s.bbox().inflate(tol(i)), |j| {
            if j > i {
                others.push(j);
            }
            ControlFlow::<()>::Continue(())
        });
        others.sort_unstable();
        for j in others {
            let t = tol(i).min(tol(j));
            let (of_i, of_j) = (near(i, &shapes[j].bbox().inflate(t)), near(j, &s.bbox().inflate(t)));
            if of_i.is_empty() || of_j.is_empty() {
                continue;
            }
            let loops: Vec<Loop> = of_i
                .iter()
                .map(|&k| traced[i][k].l.clone())
                .chain(of_j.iter().map(|&k| traced[j][k].l.clone()))
                .collect();
            let Some((a, b, position)) = meeting(&loops, of_i.len(), t) else {
                continue;
            };
            let oa = traced[i][of_i[a.loop_index]].origin(a.element);
            let ob = traced[j][of_j[b.loop_index - of_i.len()]].origin(b.element);
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

/// Where an element of `loops[..split]` meets one of `loops[split..]`
/// (within `tol`): the pairs whose boxes overlap, found through a box tree
/// over the second group's elements, tested as validation tests them.
fn meeting(loops: &[Loop], split: usize, tol: f64) -> Option<(ElementRef, ElementRef, Point)> {
    let refs = |from: usize, to: usize| {
        (from..to).flat_map(|l| (0..loops[l].len()).map(move |element| ElementRef { loop_index: l, element }))
    };
    let bbox = |r: ElementRef| loops[r.loop_index].element(r.element).bbox().inflate(tol);
    let second: Vec<ElementRef> = refs(split, loops.len()).collect();
    let tree = BoxTree::new(second.iter().map(|&r| bbox(r)).collect());
    refs(0, split).find_map(|a| {
        let mut found = None;
        tree.visit_overlapping(&bbox(a), |k| match element_pair_approach(loops, a, second[k], tol) {
            Some(p) => {
                found = Some((a, second[k], p));
                ControlFlow::Break(())
            }
            None => ControlFlow::Continue(()),
        });
        found
    })
}
