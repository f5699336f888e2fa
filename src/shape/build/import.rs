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

/// Where a curve of a drawing comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Origin {
    /// 1-based line (DXF) or byte offset (SVG) of its entity.
    pub source: usize,
    /// Its layer, an index into [`RawDrawing::layers`].
    pub layer: u32,
    /// Its DXF handle (or its block reference's); 0 where there is none.
    pub handle: u64,
}

/// A loop and where its elements come from: one origin per element, or
/// one for all.
pub(crate) struct Traced {
    pub l: Loop,
    pub from: Vec<Origin>,
}

impl Traced {
    /// The origin of element `e`.
    pub fn origin(&self, e: usize) -> Origin {
        self.from.get(e).or(self.from.first()).copied().unwrap_or_default()
    }
}

/// A parsed drawing's curves: closed polylines and circles as loops,
/// everything else as loose elements to chain, each with its origin.
pub(crate) struct DrawingParts {
    /// Loops and the origin of their entity.
    pub loops: Vec<(Loop, Origin)>,
    /// Elements to chain.
    pub loose: Vec<LooseElement>,
    /// The origin of each loose element's entity.
    pub origins: Vec<Origin>,
    /// The diagonal of the extent of the curves taken (model units).
    pub diagonal: f64,
}

/// Splits a parsed drawing into loops and loose elements, taking the
/// curves that `take` accepts by layer and colour.
pub(crate) fn drawing_parts(d: &RawDrawing, take: impl Fn(u32, i16) -> bool) -> DrawingParts {
    let mut loops = Vec::new();
    let mut loose = Vec::new();
    let mut origins = Vec::new();
    for p in d.polylines.iter().filter(|p| take(p.layer, p.colour)) {
        let elems = polyline_elements(p);
        let origin = Origin { source: p.source, layer: p.layer, handle: p.handle };
        if p.closed {
            loops.push((Loop::new(elems.iter().map(|e| Vertex { p: e.a, bulge: e.bulge }).collect()), origin));
        } else {
            origins.extend(std::iter::repeat_n(origin, elems.len()));
            loose.extend(elems);
        }
    }
    for l in d.lines.iter().filter(|l| take(l.layer, l.colour)) {
        loose.push(LooseElement { a: pt(l.a), b: pt(l.b), bulge: 0.0 });
        origins.push(Origin { source: l.source, layer: l.layer, handle: l.handle });
    }
    for a in d.arcs.iter().filter(|a| take(a.layer, a.colour)) {
        let origin = Origin { source: a.source, layer: a.layer, handle: a.handle };
        let c = pt(a.center);
        let (s, e) = (a.start_deg.to_radians(), a.end_deg.to_radians());
        let mut sweep = (e - s).rem_euclid(TAU);
        if sweep == 0.0 {
            sweep = TAU;
        }
        let start = c + Point::new(s.cos(), s.sin()) * a.radius;
        if sweep >= TAU * (1.0 - 1e-15) {
            loops.push((circle_loop(c, a.radius), origin));
        } else {
            let end = c + Point::new(e.cos(), e.sin()) * a.radius;
            loose.push(LooseElement { a: start, b: end, bulge: (sweep / 4.0).tan() });
            origins.push(origin);
        }
    }
    for c in d.circles.iter().filter(|c| take(c.layer, c.colour)) {
        let origin = Origin { source: c.source, layer: c.layer, handle: c.handle };
        loops.push((circle_loop(pt(c.center), c.radius), origin));
    }
    let diagonal = scale_of(
        loops.iter().flat_map(|(l, _)| l.vertices.iter().map(|v| v.p)).chain(loose.iter().flat_map(|e| [e.a, e.b])),
    );
    DrawingParts { loops, loose, origins, diagonal }
}

/// Loops from a parsed drawing: closed polylines and circles as they are,
/// everything else chained. The largest loop becomes the outer boundary.
fn drawing_loops(d: &RawDrawing, opts: &ShapeOptions) -> Result<Vec<Loop>, ShapeError> {
    let parts = drawing_parts(d, |_, _| true);
    let mut loops: Vec<Loop> = parts.loops.into_iter().map(|(l, _)| l).collect();
    loops.extend(chain_loops(&parts.loose, opts.chain_tolerance_for(parts.diagonal))?);
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

/// An SVG document's subpaths as a drawing of polylines.
pub(crate) fn svg_drawing(paths: &[SvgSubpath]) -> Result<RawDrawing, ShapeError> {
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
        drawing.polylines.push(RawPolyline {
            vertices: verts,
            closed: sp.closed,
            source: sp.source,
            layer: 0,
            colour: 0,
            handle: 0,
        });
    }
    Ok(drawing)
}

fn svg_loops(paths: &[SvgSubpath], opts: &ShapeOptions) -> Result<Vec<Loop>, ShapeError> {
    drawing_loops(&svg_drawing(paths)?, opts)
}

impl Shape2d {
    /// Reads medax shape JSON (`{"loops": [[[x, y, bulge], ...], ...]}`; first loop outer).
    pub fn from_json_str(text: &str, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        Shape2d::from_raw_json(json::read_loops(text)?, opts)
    }

    pub(crate) fn from_raw_json(raw: Vec<RawPolyline>, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
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
        let bytes = read_bytes(path)?;
        let hint = Format::from_path(path);
        if hint == Some(Format::Json) || (hint.is_none() && looks_json(&bytes)) {
            if let Some(raw) = json::read_loops_fast(&bytes) {
                return Shape2d::from_raw_json(raw, opts);
            }
        }
        let (text, format) = decode(&bytes, hint);
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

/// A file's bytes, or the I/O error naming it.
pub(crate) fn read_bytes(path: &std::path::Path) -> Result<Vec<u8>, ShapeError> {
    std::fs::read(path).map_err(|e| ShapeError::Io { path: path.display().to_string(), message: e.to_string() })
}

/// True when the first non-blank byte opens a JSON object.
pub(crate) fn looks_json(bytes: &[u8]) -> bool {
    bytes.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'{')
}

/// A file's text and format (`hint` from the extension, else sniffed).
/// Strict decoding first: it is several times faster than the lossy one,
/// which is kept for files with stray bytes in comments.
pub(crate) fn decode(bytes: &[u8], hint: Option<Format>) -> (std::borrow::Cow<'_, str>, Format) {
    let text = match std::str::from_utf8(bytes) {
        Ok(t) => std::borrow::Cow::Borrowed(t),
        Err(_) => String::from_utf8_lossy(bytes),
    };
    let format = hint.unwrap_or_else(|| sniff(&text));
    (text, format)
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
