//! Pictures of shapes as SVG.

use crate::io::svg_writer::{PathCmd, Style, SvgDocument};
use crate::kernel::element::Element;
use crate::shape::model::bulge_loop::Vertex;
use crate::shape::model::joints::JointKind;
use crate::shape::shape2d::Shape2d;

/// SVG path commands for all loops of a shape (draw with the even-odd rule
/// to show holes).
pub fn shape_path(shape: &Shape2d) -> Vec<PathCmd> {
    let mut cmds = Vec::with_capacity(shape.element_count() + 2 * shape.loops().len());
    for l in shape.loops() {
        push_loop_path(&mut cmds, l.vertices());
    }
    cmds
}

/// Appends the SVG path commands of one closed bulge loop (arcs as exact
/// `A` commands) to `cmds`; nothing for an empty loop.
pub fn push_loop_path(cmds: &mut Vec<PathCmd>, vertices: &[Vertex]) {
    let Some(first) = vertices.first() else { return };
    cmds.push(PathCmd::MoveTo([first.p.x, first.p.y]));
    for (i, v) in vertices.iter().enumerate() {
        let next = vertices[(i + 1) % vertices.len()].p;
        let to = [next.x, next.y];
        cmds.push(match Element::from_bulge(v.p, next, v.bulge) {
            Element::Segment(_) => PathCmd::LineTo(to),
            Element::Arc(a) => PathCmd::ArcTo { radius: a.radius, large: a.bulge.abs() > 1.0, ccw: a.is_ccw(), to },
        });
    }
    cmds.push(PathCmd::Close);
}

/// A document showing `shape` grown by `margin` (model units) on every
/// side (room for outer offsets), with the shape filled and outlined: the
/// ground of every picture of a shape and what was computed from it.
pub fn shape_document(shape: &Shape2d, margin: f64, width_px: f64) -> SvgDocument {
    let bb = shape.bbox();
    let m = margin.max(0.0);
    let mut doc = SvgDocument::new([bb.min.x - m, bb.min.y - m, bb.max.x + m, bb.max.y + m], width_px);
    doc.path(&shape_path(shape), &Style::filled("#1f3b73", "#dfe8f6", 1.5, 1.0));
    doc
}

/// Marks the shape's corners in a document (convex red, reflex blue,
/// smooth grey); nothing for shapes of more than 20,000 elements.
pub fn draw_joints(doc: &mut SvgDocument, shape: &Shape2d) {
    if shape.element_count() <= 20_000 {
        for (li, l) in shape.loops().iter().enumerate() {
            for (i, v) in l.vertices().iter().enumerate() {
                let colour = match shape.joint(li, i) {
                    JointKind::Convex => "#c0392b",
                    JointKind::Reflex => "#2e86c1",
                    JointKind::Smooth => "#7f8c8d",
                };
                doc.dot([v.p.x, v.p.y], 2.5, colour);
            }
        }
    }
}

impl Shape2d {
    /// A picture of the shape, `width_px` wide, with a caption.
    pub fn to_svg(&self, width_px: f64) -> String {
        let mut doc = shape_document(self, 0.0, width_px);
        draw_joints(&mut doc, self);
        let (segs, arcs) = self.element_counts();
        let [smooth, convex, reflex] = self.joint_counts();
        doc.caption(
            0,
            &format!(
                "{} loop(s), {segs} segments, {arcs} arcs; joints: {convex} convex (red), {reflex} reflex (blue), {smooth} smooth",
                self.loops().len()
            ),
        );
        doc.finish()
    }
}
