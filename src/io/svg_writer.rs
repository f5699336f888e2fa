//! A small SVG document writer: paths with line and circular-arc commands,
//! circles, polylines and text, in model coordinates.
//!
//! The document maps model coordinates (y up) to the SVG canvas (y down) with
//! one transform on the drawing group, so every number in the file is a model
//! coordinate and arcs stay exact `A` commands rather than flattened polylines.

use std::fmt::Write as _;

/// One path command in model coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathCmd {
    /// Start a subpath at the point.
    MoveTo([f64; 2]),
    /// Straight line to the point.
    LineTo([f64; 2]),
    /// Circular arc of the given radius to the point; `large` when the sweep
    /// exceeds 180 degrees, `ccw` when it runs counter-clockwise in model
    /// coordinates (y up).
    ArcTo {
        /// Radius, model units.
        radius: f64,
        /// True when the sweep exceeds 180 degrees.
        large: bool,
        /// True when counter-clockwise in model coordinates.
        ccw: bool,
        /// End point.
        to: [f64; 2],
    },
    /// Close the subpath.
    Close,
}

/// Stroke and fill of a drawn item.
#[derive(Debug, Clone, PartialEq)]
pub struct Style {
    /// SVG colour of the stroke, e.g. `"#1f3b73"`, or `"none"`.
    pub stroke: String,
    /// SVG colour of the fill, or `"none"`.
    pub fill: String,
    /// Stroke width in screen pixels (not scaled with the model).
    pub width_px: f64,
    /// Fill opacity in [0, 1].
    pub fill_opacity: f64,
}

impl Style {
    /// A stroke-only style.
    pub fn stroke(colour: &str, width_px: f64) -> Style {
        Style { stroke: colour.into(), fill: "none".into(), width_px, fill_opacity: 1.0 }
    }

    /// A filled style with an outline.
    pub fn filled(stroke: &str, fill: &str, width_px: f64, fill_opacity: f64) -> Style {
        Style { stroke: stroke.into(), fill: fill.into(), width_px, fill_opacity }
    }

    /// Attributes with the stroke width converted to model units (`scale`
    /// model units per pixel): not every renderer honours
    /// `vector-effect="non-scaling-stroke"`.
    fn attrs(&self, scale: f64) -> String {
        format!(
            "stroke=\"{}\" fill=\"{}\" fill-opacity=\"{}\" stroke-width=\"{}\" fill-rule=\"evenodd\"",
            self.stroke,
            self.fill,
            self.fill_opacity,
            num(self.width_px * scale)
        )
    }
}

/// An SVG document under construction. `view` is the model-space box to show
/// (min x, min y, max x, max y); `width_px` the picture width in pixels.
pub struct SvgDocument {
    view: [f64; 4],
    width_px: f64,
    body: String,
}

fn num(v: f64) -> String {
    // Shortest round-trip form keeps files exact and small.
    let s = format!("{v:?}");
    s.strip_suffix(".0").map(str::to_string).unwrap_or(s)
}

impl SvgDocument {
    /// A new document showing the model box `view` = [xmin, ymin, xmax, ymax],
    /// padded by 3 % on each side.
    pub fn new(view: [f64; 4], width_px: f64) -> SvgDocument {
        let (w, h) = ((view[2] - view[0]).max(1e-300), (view[3] - view[1]).max(1e-300));
        let pad = 0.03 * w.max(h);
        SvgDocument {
            view: [view[0] - pad, view[1] - pad, view[2] + pad, view[3] + pad],
            width_px,
            body: String::new(),
        }
    }

    /// Adds a path.
    pub fn path(&mut self, cmds: &[PathCmd], style: &Style) {
        let mut d = String::new();
        for c in cmds {
            match *c {
                PathCmd::MoveTo(p) => {
                    let _ = write!(d, "M{} {} ", num(p[0]), num(p[1]));
                }
                PathCmd::LineTo(p) => {
                    let _ = write!(d, "L{} {} ", num(p[0]), num(p[1]));
                }
                PathCmd::ArcTo { radius, large, ccw, to } => {
                    // The group flips y, and SVG's sweep flag 1 means the
                    // positive-angle direction of the (flipped) user space,
                    // which is counter-clockwise in model space.
                    let _ = write!(
                        d,
                        "A{r} {r} 0 {} {} {} {} ",
                        large as u8,
                        ccw as u8,
                        num(to[0]),
                        num(to[1]),
                        r = num(radius)
                    );
                }
                PathCmd::Close => d.push_str("Z "),
            }
        }
        let _ = writeln!(self.body, "<path d=\"{}\" {}/>", d.trim_end(), style.attrs(self.model_per_px()));
    }

    /// Adds a circle.
    pub fn circle(&mut self, center: [f64; 2], radius: f64, style: &Style) {
        let _ = writeln!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" {}/>",
            num(center[0]),
            num(center[1]),
            num(radius),
            style.attrs(self.model_per_px())
        );
    }

    /// Adds a dot of a fixed screen size at a model point.
    pub fn dot(&mut self, at: [f64; 2], radius_px: f64, colour: &str) {
        let r = radius_px * self.model_per_px();
        let _ = writeln!(
            self.body,
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"none\"/>",
            num(at[0]),
            num(at[1]),
            num(r),
            colour
        );
    }

    fn model_per_px(&self) -> f64 {
        (self.view[2] - self.view[0]) / self.width_px
    }

    /// Adds a caption line in screen space at the top-left corner.
    pub fn caption(&mut self, line: usize, text: &str) {
        let esc = text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
        let _ = writeln!(
            self.body,
            "<text x=\"8\" y=\"{}\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"13\" fill=\"#333\" data-screen=\"1\">{}</text>",
            18 + 16 * line,
            esc
        );
    }

    /// The finished document.
    pub fn finish(self) -> String {
        let [x0, y0, x1, y1] = self.view;
        let (w, h) = (x1 - x0, y1 - y0);
        let height_px = (self.width_px * h / w).clamp(50.0, 20.0 * self.width_px);
        let mut model = String::new();
        let mut screen = String::new();
        for line in self.body.lines() {
            if line.contains("data-screen=\"1\"") {
                screen.push_str(line);
                screen.push('\n');
            } else {
                model.push_str(line);
                model.push('\n');
            }
        }
        // Model group: scale to pixels, flip y so that model y points up.
        let s = self.width_px / w;
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{wp}\" height=\"{hp}\" viewBox=\"0 0 {wp} {hp}\">\n\
             <rect width=\"{wp}\" height=\"{hp}\" fill=\"white\"/>\n\
             <g transform=\"matrix({s} 0 0 {ns} {tx} {ty})\">\n{model}</g>\n{screen}</svg>\n",
            wp = num(self.width_px),
            hp = num(height_px.round()),
            s = num(s),
            ns = num(-s),
            tx = num(-x0 * s),
            ty = num(y1 * s),
        )
    }
}
