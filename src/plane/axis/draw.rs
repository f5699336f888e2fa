//! Pictures of medial axes: the shape, the axis coloured by radius, nodes
//! by kind and, on request, a sample of maximal disks.

use crate::io::svg_writer::{PathCmd, Style, SvgDocument};
use crate::plane::axis::{MedialAxis2d, NodeKind};
use crate::shape::{draw_joints, shape_document, Shape2d};

/// What to draw besides the shape and the axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisPicture {
    /// Picture width in pixels.
    pub width_px: f64,
    /// Chordal tolerance of the drawn edges, model units.
    pub tolerance: f64,
    /// Draw the maximal disk at every node.
    pub disks: bool,
}

/// Blue (small radius) through green to red (the largest radius).
fn ramp(s: f64) -> String {
    let s = s.clamp(0.0, 1.0);
    let (r, g, b) = if s < 0.5 {
        let k = s / 0.5;
        (0.0, 90.0 + 100.0 * k, 200.0 * (1.0 - k))
    } else {
        let k = (s - 0.5) / 0.5;
        (220.0 * k, 190.0 * (1.0 - k) + 40.0, 0.0)
    };
    format!("#{:02x}{:02x}{:02x}", r as u8, g as u8, b as u8)
}

impl MedialAxis2d {
    /// An SVG picture of `shape` with this axis.
    pub fn to_svg(&self, shape: &Shape2d, pic: &AxisPicture) -> String {
        let mut doc = shape_document(shape, 0.0, pic.width_px);
        draw_joints(&mut doc, shape);
        self.draw_axis(&mut doc, shape, pic);
        doc.caption(0, &self.picture_caption());
        doc.finish()
    }

    /// Draws the axis coloured by radius, its nodes by kind and (on
    /// request) the disks at branch points into `doc`, over whatever is
    /// there (the shape, rings): pictures that show more than the axis
    /// compose with this.
    pub fn draw_axis(&self, doc: &mut SvgDocument, shape: &Shape2d, pic: &AxisPicture) {
        let r_max = self.largest_radius();
        if pic.disks {
            for n in self.nodes.iter().filter(|n| n.kind == NodeKind::Branch) {
                doc.circle([n.point.x, n.point.y], n.radius, &Style::filled("#9aa5b1", "none", 0.6, 0.0));
            }
        }
        for pl in self.sampled(shape, pic.tolerance) {
            // Spans whose radius changes a lot (straight edges have two
            // samples) are split, interpolating, so the colour can follow.
            let pl: Vec<(crate::kernel::Point, f64)> = pl.into_iter().map(crate::kernel::Disk::parts).collect();
            let mut fine = vec![pl[0]];
            for w in pl.windows(2) {
                let k = (((w[1].1 - w[0].1).abs() / r_max) / 0.04).ceil().clamp(1.0, 50.0) as usize;
                for j in 1..=k {
                    let f = j as f64 / k as f64;
                    fine.push((w[0].0 + (w[1].0 - w[0].0) * f, w[0].1 + (w[1].1 - w[0].1) * f));
                }
            }
            let pl = fine;
            // One stroke per stretch of similar radius, so colour follows r.
            let mut k = 0;
            while k + 1 < pl.len() {
                let s = pl[k].1 / r_max;
                let mut j = k + 1;
                while j + 1 < pl.len() && (pl[j].1 / r_max - s).abs() < 0.05 {
                    j += 1;
                }
                let mut cmds = vec![PathCmd::MoveTo([pl[k].0.x, pl[k].0.y])];
                cmds.extend(pl[k + 1..=j].iter().map(|p| PathCmd::LineTo([p.0.x, p.0.y])));
                doc.path(&cmds, &Style::stroke(&ramp(s), 1.6));
                k = j;
            }
        }
        for n in &self.nodes {
            let colour = match n.kind {
                NodeKind::Branch => "#111111",
                NodeKind::Leaf => "#8e44ad",
                NodeKind::Joint => "#f39c12",
                NodeKind::Corner => continue,
            };
            doc.dot([n.point.x, n.point.y], 2.2, colour);
        }
    }

    fn largest_radius(&self) -> f64 {
        self.nodes.iter().map(|n| n.radius).fold(0.0, f64::max).max(f64::MIN_POSITIVE)
    }

    /// The caption of [`MedialAxis2d::to_svg`]: counts and the colour scale.
    pub fn picture_caption(&self) -> String {
        let branches = self.nodes.iter().filter(|n| n.kind == NodeKind::Branch).count();
        format!(
            "medial axis: {} nodes ({branches} branch), {} edges; colour = disk radius (blue small, red {:.4})",
            self.nodes.len(),
            self.edges.len(),
            self.largest_radius()
        )
    }
}
