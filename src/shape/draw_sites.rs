//! Pictures of Voronoi sites, shared by the Euclidean diagrams and those
//! under a polygon ball: the sites drawn over a view that leaves the
//! library's frame out, and edges clipped to that view.

use crate::io::svg_writer::{PathCmd, Style, SvgDocument};
use crate::kernel::Point;
use crate::shape::{shape_path, LoopKind, Shape2d};

/// A picture of the sites of a Voronoi diagram (`shape`: the frame, then
/// the sites as loops), `width_px` wide, and its view box: round the sites
/// with a margin when the library chose the frame (which is not drawn),
/// the caller's boundary otherwise.
pub(crate) fn sites_document(shape: &Shape2d, auto_frame: bool, width_px: f64) -> (SvgDocument, [f64; 4]) {
    let loops = shape.loops();
    let view = if auto_frame {
        let b = loops[1..].iter().fold(crate::kernel::BBox::EMPTY, |b, l| b.union(&l.bbox()));
        let m = 0.25 * b.diagonal().max(f64::MIN_POSITIVE);
        [b.min.x - m, b.min.y - m, b.max.x + m, b.max.y + m]
    } else {
        let b = shape.bbox();
        [b.min.x, b.min.y, b.max.x, b.max.y]
    };
    let mut doc = SvgDocument::new(view, width_px);
    let mut cmds = shape_path(shape);
    // The frame is the first loop: its commands run up to its Close.
    let frame_end = cmds.iter().position(|c| *c == PathCmd::Close).map_or(0, |i| i + 1);
    if !auto_frame {
        doc.path(&cmds[..frame_end], &Style::stroke("#1f3b73", 1.5));
    }
    cmds.drain(..frame_end);
    doc.path(&cmds, &Style::filled("#1f3b73", "#dfe8f6", 1.2, 1.0));
    // A point site's loop draws nothing: a dot instead.
    for l in loops.iter().filter(|l| l.kind() == LoopKind::Point) {
        let p = l.vertices()[0].p;
        doc.dot([p.x, p.y], 3.0, "#1f3b73");
    }
    (doc, view)
}

/// Path commands for the parts of `pts` inside the box `view` (min x, min
/// y, max x, max y): edges run on to a frame far outside the picture, and
/// renderers draw strokes reaching that far with artefacts.
pub(crate) fn clipped(pts: &[Point], view: &[f64; 4]) -> Vec<PathCmd> {
    let mut out = Vec::new();
    let mut open = false;
    for w in pts.windows(2) {
        let Some((a, b, whole_end)) = clip_segment(w[0], w[1], view) else {
            open = false;
            continue;
        };
        if !open {
            out.push(PathCmd::MoveTo([a.x, a.y]));
        }
        out.push(PathCmd::LineTo([b.x, b.y]));
        open = whole_end;
    }
    out
}

/// The part of segment `p`–`q` inside the box (Liang–Barsky), and whether
/// it reaches `q` (so the next segment continues the same stroke).
fn clip_segment(p: Point, q: Point, view: &[f64; 4]) -> Option<(Point, Point, bool)> {
    let d = q - p;
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (den, num) in [(-d.x, p.x - view[0]), (d.x, view[2] - p.x), (-d.y, p.y - view[1]), (d.y, view[3] - p.y)] {
        if den == 0.0 {
            if num < 0.0 {
                return None;
            }
        } else {
            let t = num / den;
            if den < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then(|| (p + d * t0, p + d * t1, t1 == 1.0))
}
