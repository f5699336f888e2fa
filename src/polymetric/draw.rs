//! Pictures of the axis under a polygon ball, drawn as the thesis's
//! figures are (3.5–3.10): regular edges solid, jump edges dashed (their
//! balls are maximal* but not maximal inscribed), and the ball itself at
//! a few of the largest branch points so the metric can be seen.

use super::graph::{BallAxis, BallNodeKind};
use super::offset::BallOffsetLayer;
use crate::io::svg_writer::{PathCmd, Style};
use crate::kernel::Point;
use crate::shape::{draw_joints, shape_document, Shape2d};

/// How many balls the picture draws (at the branch points of largest
/// radius): enough to show the metric, few enough not to hide the axis.
const BALLS_DRAWN: usize = 4;

/// Dashes per unit of the picture's larger side.
const DASHES: f64 = 160.0;

impl BallAxis {
    /// An SVG picture of `shape` with this axis, `width_px` wide.
    pub fn to_svg(&self, shape: &Shape2d, width_px: f64) -> String {
        let mut doc = shape_document(shape, 0.0, width_px);
        draw_joints(&mut doc, shape);
        let bb = shape.bbox();
        let dash = (bb.max.x - bb.min.x).max(bb.max.y - bb.min.y) / DASHES;
        let mut big: Vec<usize> =
            (0..self.nodes.len()).filter(|&i| self.nodes[i].kind == BallNodeKind::Branch).collect();
        big.sort_by(|&a, &b| self.nodes[b].r.total_cmp(&self.nodes[a].r));
        for &i in big.iter().take(BALLS_DRAWN) {
            let n = &self.nodes[i];
            doc.path(&ball_path(&self.ball, n.at, n.r), &Style::filled("#7f8c8d", "#bdc3c7", 0.8, 0.35));
        }
        let solid = Style::stroke("#1f5fbf", 1.6);
        let dashed = Style::stroke("#c0392b", 1.2);
        for e in &self.edges {
            let (a, b) = (self.nodes[e.from].at, self.nodes[e.to].at);
            if e.jump {
                doc.path(&dashes(a, b, dash), &dashed);
            } else {
                doc.path(&[PathCmd::MoveTo([a.x, a.y]), PathCmd::LineTo([b.x, b.y])], &solid);
            }
        }
        for n in &self.nodes {
            let colour = match n.kind {
                BallNodeKind::Branch => "#111111",
                BallNodeKind::PseudoBranch => "#8e44ad",
                BallNodeKind::Joint => "#f39c12",
                BallNodeKind::Leaf => "#16a085",
                BallNodeKind::Corner => continue,
            };
            doc.dot([n.at.x, n.at.y], 2.2, colour);
        }
        let [branch, pseudo, _, joint, _] = self.kind_counts();
        doc.caption(
            0,
            &format!(
                "axis under a {}-gon ball: {} nodes ({branch} branch, {pseudo} pseudo-branch, {joint} joint), {} edges, {} jump edges (dashed)",
                self.ball.len(),
                self.nodes.len(),
                self.edges.len(),
                self.jump_count()
            ),
        );
        doc.finish()
    }
}

/// The outline of the ball `at + r·B`, closed.
pub(super) fn ball_path(ball: &crate::shape::Ball2, at: Point, r: f64) -> Vec<PathCmd> {
    let ring = ball.placed(at, r);
    let mut cmds: Vec<PathCmd> = ring.iter().map(|p| PathCmd::LineTo([p.x, p.y])).collect();
    cmds[0] = PathCmd::MoveTo([ring[0].x, ring[0].y]);
    cmds.push(PathCmd::Close);
    cmds
}

/// Colours of successive offset layers.
const LAYER_COLOURS: [&str; 6] = ["#c0392b", "#27ae60", "#8e44ad", "#d35400", "#2980b9", "#16a085"];

impl BallAxis {
    /// An SVG picture of `shape`, this axis thin and grey (jump edges
    /// dashed) and the offset `layers` computed from it, a colour each.
    pub fn offsets_svg(&self, shape: &Shape2d, layers: &[BallOffsetLayer], width_px: f64) -> String {
        let mut doc = shape_document(shape, 0.0, width_px);
        let bb = shape.bbox();
        let dash = (bb.max.x - bb.min.x).max(bb.max.y - bb.min.y) / DASHES;
        let grey = Style::stroke("#9aa5b1", 0.8);
        for e in &self.edges {
            let (a, b) = (self.nodes[e.from].at, self.nodes[e.to].at);
            let cmds = if e.jump {
                dashes(a, b, dash)
            } else {
                vec![PathCmd::MoveTo([a.x, a.y]), PathCmd::LineTo([b.x, b.y])]
            };
            doc.path(&cmds, &grey);
        }
        let mut count = 0;
        for (k, layer) in layers.iter().enumerate() {
            let style = Style::stroke(LAYER_COLOURS[k % LAYER_COLOURS.len()], 1.4);
            for lp in &layer.loops {
                let mut cmds: Vec<PathCmd> = lp.points.iter().map(|p| PathCmd::LineTo([p.x, p.y])).collect();
                cmds[0] = PathCmd::MoveTo([lp.points[0].x, lp.points[0].y]);
                cmds.push(PathCmd::Close);
                doc.path(&cmds, &style);
                count += 1;
            }
        }
        doc.caption(
            0,
            &format!(
                "offsets under a {}-gon ball: {} distance(s), {count} loop(s); axis in grey, jump edges dashed",
                self.ball.len(),
                layers.len()
            ),
        );
        doc.finish()
    }
}

/// The segment `a`–`b` as dashes of about `len`, gaps as long.
fn dashes(a: Point, b: Point, len: f64) -> Vec<PathCmd> {
    let k = ((a.dist(b) / len).ceil() as usize).clamp(1, 10_000);
    let at = |t: f64| {
        let p = a + (b - a) * t;
        [p.x, p.y]
    };
    let mut cmds = Vec::new();
    for j in (0..k).step_by(2) {
        cmds.push(PathCmd::MoveTo(at(j as f64 / k as f64)));
        cmds.push(PathCmd::LineTo(at(((j + 1) as f64 / k as f64).min(1.0))));
    }
    cmds
}
