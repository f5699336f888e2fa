//! Building shapes from files: JSON, DXF and SVG.

use crate::io::svg_path::{PathSeg, SvgSubpath};
use crate::io::{dxf, json, svg_path, Format, RawDrawing, RawPolyline};
use crate::kernel::{BBox, Point};
use crate::shape::build::chain::{chain_loops, outer_first};
use crate::shape::model::bulge_loop::{Loop, Vertex};
use crate::shape::model::error::ShapeError;
use crate::shape::model::loose::LooseElement;
use crate::shape::model::options::ShapeOptions;
use crate::shape::shape2d::Shape2d;
use std::f64::consts::TAU;

fn pt(p: [f64; 2]) -> Point {
    Point::new(p[0], p[1])
}

fn polyline_elements(p: &RawPolyline) -> Vec<LooseElement> {
    let n = p.vertices.len();
    let count = if p.closed { n } else { n.saturating_sub(1) };
    (0..count)
        .map(|i| {
            let (v, w) = (p.vertices[i], p.vertices[(i + 1) % n]);
            LooseElement { a: Point::new(v.x, v.y), b: Point::new(w.x, w.y), bulge: v.bulge }
        })
        .collect()
}

fn circle_loop(center: Point, r: f64) -> Loop {
    let a = center + Point::new(r, 0.0);
    let b = center - Point::new(r, 0.0);
    Loop::new(vec![Vertex { p: a, bulge: 1.0 }, Vertex { p: b, bulge: 1.0 }])
}

fn scale_of(points: impl Iterator<Item = Point>) -> f64 {
    let mut bb = BBox::EMPTY;
    for p in points.filter(|p| p.is_finite()) {
        bb.add_point(p);
    }
    bb.diagonal()
}

/// Loops from a parsed drawing: closed polylines and circles as they are,
/// everything else chained. The largest loop becomes the outer boundary.
fn drawing_loops(d: &RawDrawing, opts: &ShapeOptions) -> Result<Vec<Loop>, ShapeError> {
    let mut loops = Vec::new();
    let mut loose = Vec::new();
    for p in &d.polylines {
        let elems = polyline_elements(p);
        if p.closed {
            loops.push(Loop::new(elems.iter().map(|e| Vertex { p: e.a, bulge: e.bulge }).collect()));
        } else {
            loose.extend(elems);
        }
    }
    for l in &d.lines {
        loose.push(LooseElement { a: pt(l.a), b: pt(l.b), bulge: 0.0 });
    }
    for a in &d.arcs {
        let c = pt(a.center);
        let (s, e) = (a.start_deg.to_radians(), a.end_deg.to_radians());
        let mut sweep = (e - s).rem_euclid(TAU);
        if sweep == 0.0 {
            sweep = TAU;
        }
        let start = c + Point::new(s.cos(), s.sin()) * a.radius;
        if sweep >= TAU * (1.0 - 1e-15) {
            loops.push(circle_loop(c, a.radius));
        } else {
            let end = c + Point::new(e.cos(), e.sin()) * a.radius;
            loose.push(LooseElement { a: start, b: end, bulge: (sweep / 4.0).tan() });
        }
    }
    for c in &d.circles {
        loops.push(circle_loop(pt(c.center), c.radius));
    }
    let diag = scale_of(
        loops.iter().flat_map(|l| l.vertices.iter().map(|v| v.p)).chain(loose.iter().flat_map(|e| [e.a, e.b])),
    );
    let chained = chain_loops(&loose, opts.chain_tolerance_for(diag))?;
    loops.extend(chained);
    Ok(outer_first(loops))
}

/// Converts an SVG arc command to a bulge: the SVG sweep flag 1 means the
/// positive-angle direction of the coordinates as written.
fn svg_arc_bulge(from: Point, seg: &PathSeg, source: usize) -> Result<f64, ShapeError> {
    let PathSeg::Arc { rx, ry, large_arc, sweep, to, .. } = *seg else {
        return Ok(0.0);
    };
    let (rx, ry) = (rx.abs(), ry.abs());
    if rx == 0.0 || ry == 0.0 {
        return Ok(0.0); // SVG: a zero radius draws a straight line.
    }
    if (rx - ry).abs() > 1e-9 * rx.max(ry) {
        return Err(ShapeError::Unsupported {
            what: format!("elliptical arc (rx {rx} ≠ ry {ry}) in the subpath at byte {source}; only circular arcs"),
        });
    }
    let c = from.dist(pt(to));
    // SVG scales a too-small radius up until the arc fits.
    let r = rx.max(0.5 * c);
    let small = 2.0 * (0.5 * c / r).clamp(-1.0, 1.0).asin();
    let theta = if large_arc { TAU - small } else { small };
    Ok((theta / 4.0).tan() * if sweep { 1.0 } else { -1.0 })
}

fn svg_loops(paths: &[SvgSubpath], opts: &ShapeOptions) -> Result<Vec<Loop>, ShapeError> {
    let mut drawing = RawDrawing::default();
    for sp in paths {
        let mut verts = Vec::with_capacity(sp.segs.len() + 1);
        let mut cur = pt(sp.start);
        for seg in &sp.segs {
            let to = match seg {
                PathSeg::Line { to } | PathSeg::Arc { to, .. } => *to,
            };
            let bulge = svg_arc_bulge(cur, seg, sp.source)?;
            verts.push(crate::io::RawVertex { x: cur.x, y: cur.y, bulge });
            cur = pt(to);
        }
        if sp.closed && cur.dist(pt(sp.start)) > 0.0 {
            // Z draws the closing line itself.
            verts.push(crate::io::RawVertex { x: cur.x, y: cur.y, bulge: 0.0 });
        } else if !sp.closed {
            verts.push(crate::io::RawVertex { x: cur.x, y: cur.y, bulge: 0.0 });
        }
        drawing.polylines.push(RawPolyline { vertices: verts, closed: sp.closed, source: sp.source });
    }
    drawing_loops(&drawing, opts)
}

impl Shape2d {
    /// Reads medax shape JSON (`{"loops": [[[x, y, bulge], ...], ...]}`; first loop outer).
    pub fn from_json_str(text: &str, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        Shape2d::from_raw_json(json::read_loops(text)?, opts)
    }

    fn from_raw_json(raw: Vec<RawPolyline>, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        let loops = raw.into_iter().map(|p| p.vertices.into_iter().map(Vertex::from).collect()).collect();
        Shape2d::from_bulge_loops(loops, opts)
    }

    /// Reads an ASCII DXF drawing: LWPOLYLINE/POLYLINE (with bulges), LINE,
    /// ARC and CIRCLE entities, chained into loops within the chaining
    /// tolerance; the loop enclosing the largest area is the outer boundary.
    pub fn from_dxf_str(text: &str, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        let d = dxf::read_dxf(text)?;
        Shape2d::from_loops(drawing_loops(&d, opts)?, opts)
    }

    /// Reads an SVG document or bare path data (M/L/H/V/A/Z, circular arcs
    /// only; `transform` attributes are not applied and y is taken as
    /// written). Subpaths are chained into loops like DXF entities.
    pub fn from_svg_str(text: &str, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        let paths = svg_path::read_svg(text)?;
        Shape2d::from_loops(svg_loops(&paths, opts)?, opts)
    }

    /// Reads a shape file; the format comes from the extension (`.json`,
    /// `.dxf`, `.svg`) or, failing that, from the first non-blank character.
    pub fn from_file(path: impl AsRef<std::path::Path>, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        let path = path.as_ref();
        let io_err = |e: std::io::Error| ShapeError::Io { path: path.display().to_string(), message: e.to_string() };
        let bytes = std::fs::read(path).map_err(io_err)?;
        let hint = Format::from_path(path);
        let looks_json = || bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{');
        if hint == Some(Format::Json) || (hint.is_none() && looks_json()) {
            if let Some(raw) = json::read_loops_fast(&bytes) {
                return Shape2d::from_raw_json(raw, opts);
            }
        }
        // Strict decoding first: it is several times faster than the lossy
        // one, which is kept for files with stray bytes in comments.
        let text = match std::str::from_utf8(&bytes) {
            Ok(t) => std::borrow::Cow::Borrowed(t),
            Err(_) => String::from_utf8_lossy(&bytes),
        };
        let format = hint.unwrap_or_else(|| sniff(&text));
        Shape2d::from_str_as(&text, format, opts)
    }

    /// Reads text in the given format.
    pub fn from_str_as(text: &str, format: Format, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        match format {
            Format::Json => Shape2d::from_json_str(text, opts),
            Format::Dxf => Shape2d::from_dxf_str(text, opts),
            Format::Svg => Shape2d::from_svg_str(text, opts),
        }
    }
}

/// Guesses a format from content: `{` JSON, `<` SVG, otherwise DXF.
pub fn sniff(text: &str) -> Format {
    match text.trim_start_matches('\u{feff}').trim_start().chars().next() {
        Some('{') => Format::Json,
        Some('<') => Format::Svg,
        Some('M') | Some('m') => Format::Svg,
        _ => Format::Dxf,
    }
}
