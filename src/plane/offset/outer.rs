//! Outer offsets as inner offsets of the complement (thesis 2.4.1): the
//! shape becomes a hole in a circle far enough away that the circle's own
//! offset never meets the shape's, and each hole becomes a region of its
//! own. The grown shape Ω ⊕ B_ρ is connected (Ω is), so its outer loop is
//! the one loop round the shape in the framed part, and every other loop
//! (pockets closed off by the growth, shrunken holes) is a hole of it.

use crate::kernel::Point;
use crate::plane::medial::conquer::{medial_axis, AxisOptions};
use crate::plane::offset::layer::{OffsetError, OffsetLayer, OffsetLoop, OffsetRegion};
use crate::plane::offset::trim::Trimmer;
use crate::shape::{Loop, Shape2d, ShapeOptions, Vertex};
use rayon::prelude::*;

/// The frame's radius: the shape's circumradius (half its diagonal), plus
/// twice the reach, so that the frame's offset and the shape's stay apart,
/// plus another half diagonal, so that the frame is never close for a tiny
/// reach.
fn frame_radius(shape: &Shape2d, reach: f64) -> f64 {
    shape.bbox().diagonal() + 2.0 * reach
}

/// The trimmers of the complement's parts: the framed shape first, then
/// each hole's inside.
pub(crate) fn complement_trimmers(
    shape: &Shape2d,
    axis_opts: &AxisOptions,
    reach: f64,
) -> Result<Vec<Trimmer>, OffsetError> {
    if !reach.is_finite() || reach < 0.0 {
        return Err(OffsetError::BadReach(reach));
    }
    let c = shape.bbox().center();
    let r = frame_radius(shape, reach);
    // Two half circles, counter-clockwise.
    let frame =
        vec![Vertex { p: c + Point::new(r, 0.0), bulge: 1.0 }, Vertex { p: c - Point::new(r, 0.0), bulge: 1.0 }];
    let shape_opts = ShapeOptions { tolerance: Some(shape.tolerance()), ..ShapeOptions::default() };
    let mut parts: Vec<Vec<Vec<Vertex>>> = vec![vec![frame, shape.outer().reversed().vertices().to_vec()]];
    parts.extend(shape.holes().iter().map(|h| vec![h.reversed().vertices().to_vec()]));
    parts
        .into_par_iter()
        .map(|loops| {
            let part = Shape2d::from_bulge_loops(loops, &shape_opts).map_err(|_| OffsetError::Topology {
                distance: -reach,
                what: "the shape's complement is no valid shape",
            })?;
            let axis = medial_axis(&part, axis_opts)?;
            let t = Trimmer::new(&part, &axis);
            t.check().map_err(|what| OffsetError::Topology { distance: -reach, what })?;
            Ok(t)
        })
        .collect()
}

/// The outer offset at `distance` > 0 from the complement's parts
/// (`parts` as [`complement_trimmers`] made them; `tol` the shape's
/// touching tolerance).
pub(crate) fn outer_layer(parts: &[Trimmer], tol: f64, distance: f64) -> Result<OffsetLayer, OffsetError> {
    let (framed, sources) = parts[0].layer_sources(distance, tol)?;
    let mut outer: Option<OffsetLoop> = None;
    let mut holes: Vec<OffsetLoop> = Vec::new();
    let frame_region = sources.iter().position(|&s| s == 0).map(|i| framed.loops[i].region);
    for (lp, &source) in framed.loops.iter().zip(&sources) {
        if source == 0 {
            continue;
        }
        let flipped = flip(lp);
        if Some(lp.region) == frame_region {
            if outer.replace(flipped).is_some() {
                return Err(OffsetError::Topology { distance: -distance, what: "the grown shape has two outer loops" });
            }
        } else {
            holes.push(flipped);
        }
    }
    let Some(outer) = outer else {
        return Err(OffsetError::Topology { distance: -distance, what: "the grown shape has no outer loop" });
    };
    for part in &parts[1..] {
        holes.extend(part.layer(distance, tol)?.loops.iter().map(flip));
    }
    let mut loops = vec![outer];
    loops.extend(holes);
    let regions = vec![OffsetRegion { outer: 0, holes: (1..loops.len()).collect() }];
    Ok(OffsetLayer { distance: -distance, loops, regions, anchors: vec![usize::MAX], piece_region: Vec::new() })
}

/// The loop the other way round, in region 0.
fn flip(lp: &OffsetLoop) -> OffsetLoop {
    let vertices = Loop::new(lp.vertices.clone()).reversed().vertices().to_vec();
    OffsetLoop { vertices, area: -lp.area, region: 0 }
}
