//! Outer offsets under a polygon ball, as inner offsets of the complement
//! (thesis 2.4.1 for disks; the same reading here): the shape grown by d
//! is where the centre of a tool d·B may go without entering the shape,
//! so its boundary is the inner offset of the space around the shape, cut
//! off by a frame far enough not to matter, and of each hole taken as a
//! region of its own.

use super::build::medial_axis_with_ball;
use super::offset::{layer_of, BallOffsetLayer};
use super::BallAxisError;
use crate::kernel::Point;
use crate::shape::{Ball2, Shape2d, ShapeOptions, Vertex};

/// The shape grown by `d` > 0 under `ball` (model units): loops where the
/// centre of the tool `c + d·B` touches the shape from outside; outer
/// loops counter-clockwise, the holes left of the shape's holes clockwise.
/// Computes the axis of the complement (a frame round the shape, and each
/// hole) under the ball.
pub fn outer_offset(shape: &Shape2d, ball: &Ball2, d: f64) -> Result<BallOffsetLayer, BallAxisError> {
    let bb = shape.bbox();
    let reach = ball.vertices().iter().map(|v| v.norm()).fold(0.0, f64::max);
    // The frame's own offset ring stays a full tool size clear of the
    // grown shape: the margin exceeds twice the tool's reach.
    let margin = 2.0 * d * reach + 0.05 * bb.diagonal();
    let (x0, y0, x1, y1) = (bb.min.x - margin, bb.min.y - margin, bb.max.x + margin, bb.max.y + margin);
    let frame: Vec<Vertex> =
        [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(|(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 }).to_vec();
    let polygon = |l: usize| -> Vec<Vertex> { shape.loops()[l].vertices().to_vec() };
    let complement = |loops: Vec<Vec<Vertex>>| {
        Shape2d::from_bulge_loops(loops, &ShapeOptions::default()).map_err(|_| BallAxisError::Inconsistent {
            at: bb.min,
            what: "the space round the shape is not a valid shape",
        })
    };
    let mut rings: Vec<Vec<Point>> = Vec::new();
    // Round the outer loop: the holes of the framed space's offset.
    let around = complement(vec![frame, polygon(0)])?;
    let layer = medial_axis_with_ball(&around, ball)?.offset(&around, d)?;
    for lp in layer.loops.iter().filter(|l| l.area < 0.0) {
        // Turned counter-clockwise: the grown shape's outer boundary.
        rings.push(lp.points.iter().rev().copied().collect());
    }
    // Inside each hole: its inner offset, turned clockwise, bounds a hole
    // of the grown shape.
    for l in 1..shape.loops().len() {
        let hole = complement(vec![polygon(l)])?;
        let layer = medial_axis_with_ball(&hole, ball)?.offset(&hole, d)?;
        for lp in layer.loops.iter().filter(|l| l.area > 0.0) {
            rings.push(lp.points.iter().rev().copied().collect());
        }
    }
    Ok(layer_of(-d, rings, shape.tolerance()))
}
