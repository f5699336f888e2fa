//! Pictures of offsets: the shape, its medial axis in thin grey and the
//! offset loops on top, arcs as exact SVG arcs. The pieces are public so
//! that the CAM pictures (pocket rings, V-carve paths) draw the same way.

use crate::io::svg_writer::{PathCmd, Style, SvgDocument};
use crate::plane::axis::MedialAxis2d;
use crate::plane::offset::layer::OffsetLayer;
use crate::shape::{push_loop_path, shape_document, Shape2d, Vertex};

/// Colours of successive offset layers: dark enough on the shape's light
/// fill, and far apart so neighbouring layers are told apart.
const LAYER_COLOURS: [&str; 6] = ["#c0392b", "#16a085", "#8e44ad", "#d35400", "#2c3e50", "#27ae60"];

/// The colour of layer `k` in pictures with several layers.
pub fn layer_colour(k: usize) -> &'static str {
    LAYER_COLOURS[k % LAYER_COLOURS.len()]
}

/// Draws the medial axis as thin grey polylines sampled to chordal
/// tolerance `tol` (model units): context for the loops drawn on top.
pub fn draw_axis_thin(doc: &mut SvgDocument, shape: &Shape2d, axis: &MedialAxis2d, tol: f64) {
    for pl in axis.sampled(shape, tol) {
        let mut cmds: Vec<PathCmd> = Vec::with_capacity(pl.len());
        for (k, p) in pl.iter().map(|d| d.center).enumerate() {
            cmds.push(if k == 0 { PathCmd::MoveTo([p.x, p.y]) } else { PathCmd::LineTo([p.x, p.y]) });
        }
        doc.path(&cmds, &Style::stroke("#9aa5b1", 0.7));
    }
}

/// Draws closed bulge loops as one path (even-odd fill, so holes show).
pub fn draw_loops(doc: &mut SvgDocument, loops: impl IntoIterator<Item = impl AsRef<[Vertex]>>, style: &Style) {
    let mut cmds = Vec::new();
    for l in loops {
        push_loop_path(&mut cmds, l.as_ref());
    }
    if !cmds.is_empty() {
        doc.path(&cmds, style);
    }
}

/// How far the loops of `layers` reach beyond the shape's box: an outer
/// offset at distance −d lies within d of the shape, so the margin to give
/// [`shape_document`] is the largest outer distance (0 for inner ones).
fn margin(layers: &[OffsetLayer]) -> f64 {
    layers.iter().map(|l| -l.distance).fold(0.0, f64::max)
}

/// An SVG picture `width_px` wide of `shape`, its axis (thin grey, sampled
/// to chordal tolerance `tol`, model units) and the loops of every layer,
/// one colour per layer, with a caption.
pub fn offsets_to_svg(shape: &Shape2d, axis: &MedialAxis2d, layers: &[OffsetLayer], width_px: f64, tol: f64) -> String {
    let mut doc = shape_document(shape, margin(layers), width_px);
    draw_axis_thin(&mut doc, shape, axis, tol);
    for (k, layer) in layers.iter().enumerate() {
        draw_loops(&mut doc, &layer.loops, &Style::stroke(layer_colour(k), 1.4));
    }
    let loops: usize = layers.iter().map(|l| l.loops.len()).sum();
    doc.caption(0, &format!("offsets: {} distance(s), {loops} loop(s); medial axis in grey", layers.len()));
    doc.finish()
}
