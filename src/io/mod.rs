//! File formats, read into and written from plain data.
//!
//! This is the bottom layer: it knows numbers and syntax, not geometry. Readers
//! return raw entities (vertex lists, lines, arcs, path commands) with their
//! source positions; the shape layer chains, validates and builds shapes from
//! them. Every reader is total: any byte string gives `Ok` or a [`ParseError`]
//! with a position, never a panic.

pub mod dxf;
pub mod dxf_writer;
pub mod json;
mod json_scan;
pub mod mesh;
pub mod svg_path;
pub mod svg_writer;

use std::fmt;

/// The file formats medax reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// `{"loops": [[[x, y, bulge], ...], ...]}`; see README.
    Json,
    /// ASCII DXF: LWPOLYLINE, POLYLINE/VERTEX, LINE, ARC, CIRCLE entities.
    Dxf,
    /// SVG documents or bare path data.
    Svg,
}

impl Format {
    /// Guesses the format from a file name's extension (case-insensitive).
    pub fn from_path(path: &std::path::Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "json" => Some(Format::Json),
            "dxf" => Some(Format::Dxf),
            "svg" => Some(Format::Svg),
            _ => None,
        }
    }

    /// Lower-case name, as used in messages.
    pub fn name(self) -> &'static str {
        match self {
            Format::Json => "JSON",
            Format::Dxf => "DXF",
            Format::Svg => "SVG",
        }
    }
}

/// A syntax error with its position: 1-based line and column where the format
/// has lines (JSON, DXF), otherwise line 0 and the byte offset in `column`.
#[derive(Debug, Clone, PartialEq)]
pub struct ParseError {
    /// Which format was being read.
    pub format: Format,
    /// 1-based line, or 0 when the position is a byte offset.
    pub line: usize,
    /// 1-based column, or the byte offset when `line == 0`.
    pub column: usize,
    /// What was wrong, for a person.
    pub message: String,
    /// True when the input is well-formed but uses something medax does not
    /// read (yet): Bézier curves in SVG, binary DXF.
    pub unsupported: bool,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{} parse error at byte {}: {}", self.format.name(), self.column, self.message)
        } else {
            write!(
                f,
                "{} parse error at line {}, column {}: {}",
                self.format.name(),
                self.line,
                self.column,
                self.message
            )
        }
    }
}

impl std::error::Error for ParseError {}

/// One vertex of a bulge loop: position and the bulge of the element that
/// starts here (`tan(sweep/4)`, positive = counter-clockwise, 0 = segment).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RawVertex {
    /// x coordinate, model units.
    pub x: f64,
    /// y coordinate, model units.
    pub y: f64,
    /// Bulge of the element from this vertex to the next.
    pub bulge: f64,
}

/// A polyline with bulges as read from a file.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RawPolyline {
    /// The vertices in file order.
    pub vertices: Vec<RawVertex>,
    /// True when the file marks it closed (the last vertex connects to the first).
    pub closed: bool,
    /// 1-based source line (DXF) or byte offset (SVG) where it starts.
    pub source: usize,
    /// Its layer: an index into [`RawDrawing::layers`] (0 in formats
    /// without layers).
    pub layer: u32,
    /// Its colour as an AutoCAD colour index 1–255 (DXF group 62), with
    /// "by layer" and "by block" resolved (7, white/black, where nothing
    /// says; 0 in formats without colours).
    pub colour: i16,
    /// Its DXF handle (group 5, hexadecimal), or that of the block
    /// reference that placed it; 0 where there is none.
    pub handle: u64,
}

/// A circular arc as read from a file: centre, radius and angles in degrees,
/// running counter-clockwise from `start_deg` to `end_deg` (the DXF convention).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawArc {
    /// Centre, model units.
    pub center: [f64; 2],
    /// Radius, model units.
    pub radius: f64,
    /// Start angle, degrees.
    pub start_deg: f64,
    /// End angle, degrees (counter-clockwise from the start).
    pub end_deg: f64,
    /// 1-based source line.
    pub source: usize,
    /// Its layer: an index into [`RawDrawing::layers`].
    pub layer: u32,
    /// Its colour as an AutoCAD colour index 1–255 (DXF group 62), with
    /// "by layer" and "by block" resolved (7, white/black, where nothing
    /// says; 0 in formats without colours).
    pub colour: i16,
    /// Its DXF handle (group 5, hexadecimal), or that of the block
    /// reference that placed it; 0 where there is none.
    pub handle: u64,
}

/// A line segment as read from a file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawLine {
    /// Start point.
    pub a: [f64; 2],
    /// End point.
    pub b: [f64; 2],
    /// 1-based source line.
    pub source: usize,
    /// Its layer: an index into [`RawDrawing::layers`].
    pub layer: u32,
    /// Its colour as an AutoCAD colour index 1–255 (DXF group 62), with
    /// "by layer" and "by block" resolved (7, white/black, where nothing
    /// says; 0 in formats without colours).
    pub colour: i16,
    /// Its DXF handle (group 5, hexadecimal), or that of the block
    /// reference that placed it; 0 where there is none.
    pub handle: u64,
}

/// A full circle as read from a file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawCircle {
    /// Centre, model units.
    pub center: [f64; 2],
    /// Radius, model units.
    pub radius: f64,
    /// 1-based source line (DXF) or byte offset (SVG).
    pub source: usize,
    /// Its layer: an index into [`RawDrawing::layers`].
    pub layer: u32,
    /// Its colour as an AutoCAD colour index 1–255 (DXF group 62), with
    /// "by layer" and "by block" resolved (7, white/black, where nothing
    /// says; 0 in formats without colours).
    pub colour: i16,
    /// Its DXF handle (group 5, hexadecimal), or that of the block
    /// reference that placed it; 0 where there is none.
    pub handle: u64,
}

/// Everything geometric a drawing file held, before chaining into loops.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RawDrawing {
    /// Polylines with bulges (closed ones are loops already).
    pub polylines: Vec<RawPolyline>,
    /// Loose line segments, to be chained.
    pub lines: Vec<RawLine>,
    /// Loose arcs, to be chained.
    pub arcs: Vec<RawArc>,
    /// Full circles (each is a loop).
    pub circles: Vec<RawCircle>,
    /// Layer names, indexed by the entities' `layer`; empty in formats
    /// without layers.
    pub layers: Vec<String>,
    /// Entities that are not curves medax reads (text, dimensions,
    /// hatches, points, splines, ellipses…, and block references that
    /// could not be placed), in file order.
    pub skipped: Vec<RawSkipped>,
    /// The drawing's unit as DXF's `$INSUNITS` code (0 unitless, 1 inch,
    /// 2 foot, 4 millimetre, 5 centimetre, 6 metre…), where it says.
    pub units: Option<i64>,
}

/// An entity of a drawing that is not a curve medax reads.
#[derive(Debug, Clone, PartialEq)]
pub struct RawSkipped {
    /// Its type as the file names it (`TEXT`, `HATCH`, `INSERT`…).
    pub entity: String,
    /// Its layer: an index into [`RawDrawing::layers`].
    pub layer: u32,
    /// Its colour as an AutoCAD colour index 1–255 (DXF group 62), with
    /// "by layer" and "by block" resolved (7, white/black, where nothing
    /// says; 0 in formats without colours).
    pub colour: i16,
    /// Its DXF handle (group 5, hexadecimal), or that of the block
    /// reference that placed it; 0 where there is none.
    pub handle: u64,
    /// Its insertion or first point (groups 10 and 20) where it has one.
    pub position: Option<[f64; 2]>,
    /// 1-based source line.
    pub source: usize,
}
