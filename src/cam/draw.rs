//! Pictures of pockets and V-carves: the shape, its medial axis in thin
//! grey, and the rings or paths on top (arcs as exact SVG arcs).

use super::pocket::Pocket;
use super::vcarve::VCarve;
use crate::io::svg_writer::{PathCmd, Style, SvgDocument};
use crate::plane::offset::draw::{draw_axis_thin, draw_loops, layer_colour};
use crate::plane::MedialAxis2d;
use crate::shape::{shape_document, Shape2d};

/// The fill of material left uncut: a warning colour that stands out on
/// the shape's light blue.
const UNCUT_FILL: &str = "#ff7f0e";

/// Draws the pocket's uncut regions (filled in orange) and rings into
/// `doc`: in `ring_colour`, or one colour per level when `None`.
pub fn draw_pocket(doc: &mut SvgDocument, pocket: &Pocket, ring_colour: Option<&str>) {
    for u in &pocket.uncut {
        draw_loops(doc, &u.loops, &Style::filled(UNCUT_FILL, UNCUT_FILL, 0.5, 0.75));
    }
    for r in &pocket.rings {
        let style = Style::stroke(ring_colour.unwrap_or(layer_colour(r.level)), 1.2);
        draw_loops(doc, &r.loops, &style);
    }
}

impl Pocket {
    /// An SVG picture `width_px` wide of `shape`, its axis (sampled to
    /// chordal tolerance `tol`, model units), the rings (one colour per
    /// level) and the uncut regions filled in orange.
    pub fn to_svg(&self, shape: &Shape2d, axis: &MedialAxis2d, width_px: f64, tol: f64) -> String {
        let mut doc = shape_document(shape, 0.0, width_px);
        draw_axis_thin(&mut doc, shape, axis, tol);
        draw_pocket(&mut doc, self, None);
        let levels = self.level_count();
        let uncut = self.uncut_area();
        doc.caption(
            0,
            &format!(
                "pocket: {} rings in {levels} levels{}; uncut (orange): {} regions, area {uncut:.4}",
                self.rings.len(),
                if self.truncated { " (cut short at the level limit)" } else { "" },
                self.uncut.len()
            ),
        );
        doc.finish()
    }
}

/// Light (shallow) to dark (deep) red.
fn depth_colour(s: f64) -> String {
    let s = s.clamp(0.0, 1.0);
    let c = |light: f64, dark: f64| (light + (dark - light) * s) as u8;
    format!("#{:02x}{:02x}{:02x}", c(250.0, 120.0), c(170.0, 0.0), c(150.0, 20.0))
}

impl VCarve {
    /// An SVG picture `width_px` wide of `shape`, its axis (sampled to
    /// chordal tolerance `tol`, model units), the flat bottom filled in grey
    /// with its rings, and the paths coloured by depth (light shallow, dark
    /// deep).
    pub fn to_svg(&self, shape: &Shape2d, axis: &MedialAxis2d, width_px: f64, tol: f64) -> String {
        // The flat bottom under the axis, so that the axis shows through.
        let mut doc = shape_document(shape, 0.0, width_px);
        draw_loops(&mut doc, &self.flat.loops, &Style::filled("#34495e", "#b0bec5", 1.0, 0.8));
        draw_axis_thin(&mut doc, shape, axis, tol);
        let deepest = self.deepest().max(f64::MIN_POSITIVE);
        // Runs of segments in one tenth of the depth range share a stroke.
        let bin = |d: f64| ((d / deepest) * 10.0).floor().min(9.0);
        for p in &self.paths {
            let mut k = 0;
            while k + 1 < p.points.len() {
                let b = bin(0.5 * (p.points[k][2] + p.points[k + 1][2]));
                let mut cmds = vec![PathCmd::MoveTo([p.points[k][0], p.points[k][1]])];
                while k + 1 < p.points.len() && bin(0.5 * (p.points[k][2] + p.points[k + 1][2])) == b {
                    k += 1;
                    cmds.push(PathCmd::LineTo([p.points[k][0], p.points[k][1]]));
                }
                doc.path(&cmds, &Style::stroke(&depth_colour((b + 0.5) / 10.0), 1.6));
            }
        }
        doc.caption(
            0,
            &format!(
                "v-carve: {} paths (dark = deep, deepest {deepest:.4}), {} flat rings at radius {:.4}",
                self.paths.len(),
                self.flat.loops.len(),
                self.flat_radius()
            ),
        );
        doc.finish()
    }
}
