//! The medax shape JSON format: `{"loops": [[[x, y, bulge], ...], ...]}`.
//!
//! The first loop is the outer boundary, the others are holes. A vertex is
//! `[x, y, bulge]` or `[x, y]` (bulge 0). Each loop is closed implicitly: the
//! element of the last vertex runs back to the first. This is a public
//! contract (see README); unknown top-level keys are ignored so that files can
//! carry metadata.

use super::{Format, ParseError, RawPolyline, RawVertex};
use serde::de::{Deserializer, Error as _, SeqAccess, Visitor};
use serde::Deserialize;
use serde_json::Value;
use std::fmt;

#[derive(Deserialize)]
struct ShapeFile {
    loops: Vec<Vec<JsonVertex>>,
}

/// A shape file or a drawing file (`{"shapes": [{"loops": ...}, ...]}`,
/// what `medax info --json` writes).
#[derive(Deserialize)]
struct AnyFile {
    loops: Option<Vec<Vec<JsonVertex>>>,
    shapes: Option<Vec<ShapeFile>>,
}

fn polylines(loops: Vec<Vec<JsonVertex>>) -> Vec<RawPolyline> {
    loops
        .into_iter()
        .enumerate()
        .map(|(li, lp)| RawPolyline {
            vertices: lp.into_iter().map(|v| v.0).collect(),
            closed: true,
            source: li,
            ..RawPolyline::default()
        })
        .collect()
}

/// A JSON document of medax: one shape or a drawing of several.
#[derive(Debug, Clone, PartialEq)]
pub enum JsonDoc {
    /// `{"loops": ...}`: the loops of one shape.
    Shape(Vec<RawPolyline>),
    /// `{"shapes": [{"loops": ...}, ...]}`: the loops of each shape.
    Drawing(Vec<Vec<RawPolyline>>),
}

/// Reads shape JSON or drawing JSON (`loops` wins where both are given).
pub fn read_doc(text: &str) -> Result<JsonDoc, ParseError> {
    if let Some(loops) = read_loops_fast(text.as_bytes()) {
        return Ok(JsonDoc::Shape(loops));
    }
    let file: AnyFile = serde_json::from_str(text).map_err(parse_error)?;
    match (file.loops, file.shapes) {
        (Some(loops), _) => Ok(JsonDoc::Shape(polylines(loops))),
        (None, Some(shapes)) => Ok(JsonDoc::Drawing(shapes.into_iter().map(|s| polylines(s.loops)).collect())),
        (None, None) => Err(ParseError {
            format: Format::Json,
            line: 1,
            column: 1,
            message: "neither `loops` (a shape) nor `shapes` (a drawing) is given".into(),
            unsupported: false,
        }),
    }
}

/// `[x, y]` or `[x, y, bulge]`, read without allocating (files hold
/// millions of vertices).
struct JsonVertex(RawVertex);

impl<'de> Deserialize<'de> for JsonVertex {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = JsonVertex;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a vertex [x, y] or [x, y, bulge]")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<JsonVertex, A::Error> {
                let wrong =
                    |n: usize| A::Error::custom(format!("expected [x, y] or [x, y, bulge], found {n} number(s)"));
                let x: f64 = seq.next_element()?.ok_or_else(|| wrong(0))?;
                let y: f64 = seq.next_element()?.ok_or_else(|| wrong(1))?;
                let bulge: f64 = seq.next_element()?.unwrap_or(0.0);
                if seq.next_element::<f64>()?.is_some() {
                    return Err(wrong(4));
                }
                Ok(JsonVertex(RawVertex { x, y, bulge }))
            }
        }
        d.deserialize_seq(V)
    }
}

/// Reads shape JSON into closed polylines (loop order preserved).
pub fn read_loops(text: &str) -> Result<Vec<RawPolyline>, ParseError> {
    match read_loops_fast(text.as_bytes()) {
        Some(loops) => Ok(loops),
        None => read_loops_generic(text),
    }
}

/// The fast path of [`read_loops`] on raw bytes: `Some` exactly when the
/// bytes are a plain `{"loops": ...}` document (then equal to what
/// [`read_loops`] returns for them); `None` means "decode and use
/// [`read_loops`]", which reports errors with positions.
pub fn read_loops_fast(bytes: &[u8]) -> Option<Vec<RawPolyline>> {
    super::json_scan::scan_loops(bytes, PIECE_BYTES)
}

/// Documents are read in parallel pieces of about this many bytes.
const PIECE_BYTES: usize = 4 << 20;

/// [`read_loops_fast`] with a given piece size, so that tests and fuzzing
/// exercise the splitting on small inputs.
#[doc(hidden)]
pub fn read_loops_fast_in_pieces(bytes: &[u8], piece_bytes: usize) -> Option<Vec<RawPolyline>> {
    super::json_scan::scan_loops(bytes, piece_bytes)
}

/// [`read_loops`] through the general deserializer only, without the fast
/// path; the two must agree on every input the fast path accepts (tests and
/// the fuzz target compare them).
#[doc(hidden)]
pub fn read_loops_generic(text: &str) -> Result<Vec<RawPolyline>, ParseError> {
    let file: ShapeFile = serde_json::from_str(text).map_err(|e| {
        let mut err = parse_error(e);
        // A drawing where one shape is expected: say so, not "missing loops".
        if let Ok(AnyFile { loops: None, shapes: Some(shapes) }) = serde_json::from_str::<AnyFile>(text) {
            err.message = format!(
                "a drawing of {} shape(s) (`shapes`), not one shape (`loops`): read it as a drawing \
                 (Drawing2d, mx_drawing, or the command line's --shape K)",
                shapes.len()
            );
        }
        err
    })?;
    Ok(polylines(file.loops))
}

/// A serde error as a [`ParseError`] at its line and column.
fn parse_error(e: serde_json::Error) -> ParseError {
    ParseError { format: Format::Json, line: e.line(), column: e.column(), message: e.to_string(), unsupported: false }
}

/// Voronoi sites as read from a sites file (`medax voronoi`):
/// `{"points": [[x, y], ...], "curves": [[[x, y, bulge], ...], ...],
/// "regions": [[[x, y, bulge], ...], ...], "boundary": [[x, y, bulge], ...]}`,
/// every key optional. Plain numbers: validation happens when the sites
/// are used.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RawSites {
    /// Point sites `[x, y]`.
    pub points: Vec<[f64; 2]>,
    /// Open curves, vertex chains (the last vertex's bulge is ignored).
    pub curves: Vec<Vec<RawVertex>>,
    /// Closed regions, bulge loops.
    pub regions: Vec<Vec<RawVertex>>,
    /// The caller's outer boundary, when given.
    pub boundary: Option<Vec<RawVertex>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SitesFile {
    #[serde(default)]
    points: Vec<[f64; 2]>,
    #[serde(default)]
    curves: Vec<Vec<JsonVertex>>,
    #[serde(default)]
    regions: Vec<Vec<JsonVertex>>,
    #[serde(default)]
    boundary: Option<Vec<JsonVertex>>,
}

/// Reads a sites file; errors carry the line and column.
pub fn read_sites(text: &str) -> Result<RawSites, ParseError> {
    let file: SitesFile = serde_json::from_str(text).map_err(parse_error)?;
    let plain = |l: Vec<JsonVertex>| l.into_iter().map(|v| v.0).collect::<Vec<_>>();
    Ok(RawSites {
        points: file.points,
        curves: file.curves.into_iter().map(plain).collect(),
        regions: file.regions.into_iter().map(plain).collect(),
        boundary: file.boundary.map(plain),
    })
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BallFile {
    vertices: Vec<[f64; 2]>,
}

/// Reads a unit ball file, `{"vertices": [[x, y], ...]}` (either
/// orientation; unitless): the vertices as given, not yet validated.
pub fn read_ball(text: &str) -> Result<Vec<[f64; 2]>, ParseError> {
    let file: BallFile = serde_json::from_str(text).map_err(parse_error)?;
    Ok(file.vertices)
}

/// Writes loops as shape JSON, one loop per line, with shortest round-trip
/// number formatting (reading the output back gives bit-identical values).
pub fn write_loops(loops: &[Vec<RawVertex>]) -> String {
    let mut s = String::from("{\"loops\": [\n");
    for (i, lp) in loops.iter().enumerate() {
        s.push_str("  [");
        for (j, v) in lp.iter().enumerate() {
            if j > 0 {
                s.push_str(", ");
            }
            s.push_str(&format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.bulge));
        }
        s.push(']');
        if i + 1 < loops.len() {
            s.push(',');
        }
        s.push('\n');
    }
    s.push_str("]}\n");
    s
}

/// Closed bulge loops as the JSON value `[[[x, y, bulge], ..], ..]`, the
/// loops of `write_loops` (numbers in shortest round-trip form once
/// written).
pub fn loops_json<V: Copy + Into<RawVertex>>(loops: impl IntoIterator<Item = impl AsRef<[V]>>) -> Value {
    let triple = |v: V| {
        let v: RawVertex = v.into();
        [v.x, v.y, v.bulge]
    };
    loops.into_iter().map(|l| l.as_ref().iter().map(|&v| triple(v)).collect::<Vec<_>>()).collect()
}

/// What `write` writes, as a string: the `to_json` of a streaming JSON
/// writer (writing to a vector cannot fail, and serde_json writes UTF-8).
pub(crate) fn written(write: impl FnOnce(&mut Vec<u8>) -> std::io::Result<()>) -> String {
    let mut out = Vec::new();
    let _ = write(&mut out);
    String::from_utf8(out).unwrap_or_default()
}

/// A JSON document on one line, ending with a newline.
pub fn to_line(doc: &Value) -> String {
    let mut out = serde_json::to_string(doc).unwrap_or_default();
    out.push('\n');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_bulges_and_defaults_missing_bulge_to_zero() {
        let loops = read_loops(r#"{"loops": [[[0,0,0.5],[1,0],[1,1,-1]]], "name": "x"}"#).unwrap();
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0].vertices[0], RawVertex { x: 0.0, y: 0.0, bulge: 0.5 });
        assert_eq!(loops[0].vertices[1].bulge, 0.0);
        assert_eq!(loops[0].vertices[2].bulge, -1.0);
    }

    #[test]
    fn reads_sites_with_every_key_optional() {
        let s = read_sites(r#"{"points": [[1, 2]], "regions": [[[0,0],[1,0,0.5],[1,1]]]}"#).unwrap();
        assert_eq!(s.points, vec![[1.0, 2.0]]);
        assert_eq!(s.regions[0][1], RawVertex { x: 1.0, y: 0.0, bulge: 0.5 });
        assert!(s.curves.is_empty() && s.boundary.is_none());
        assert_eq!(read_sites("{}").unwrap(), RawSites::default());
        let e = read_sites("{\"regions\": [],\n \"pionts\": []}").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.message.contains("pionts"), "{}", e.message);
    }

    #[test]
    fn reports_position_of_syntax_errors() {
        let e = read_loops("{\"loops\": [[[0, 0],\n [1, x]]]}").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.column > 1);
        let e = read_loops("{\"loops\": [[[0, 0],\n  [0, 0, 1, 2]]]}").unwrap_err();
        assert!(e.message.contains("expected [x, y] or [x, y, bulge]"), "{}", e.message);
        assert_eq!(e.line, 2);
    }

    #[test]
    fn fast_path_agrees_with_the_general_reader() {
        let cases = [
            r#"{"loops": [[[0,0,0.5],[1,0],[1,1,-1]]]}"#,
            " {\n\"loops\" :[ [ [ -0.0 , 1e3 , 2.5E-3 ] ,[1,2] ] , [] ] } \n",
            r#"{"loops": []}"#,
            r#"{"loops": [[[0.1, 0.2, 0.30000000000000004], [123456789012345678901234567890, -1e-320]]]}"#,
            r#"{"loops": [[[0, 0], [1, 0] , [1, 1]], [], [[2, 2, 0.5] ,[ -3, 3]],[[4,4]]]}"#,
            r#"{"loops": [[[0, 0], [1, 0]], [[1, 1]] [[2, 2]]]}"#,
            r#"{"loops": [[[0, 0], [1, 0]], [[1, 1], ]]}"#,
            // Everything below leaves the fast path; the result must not change.
            r#"{"loops": [[[0,0]]], "name": "x"}"#,
            r#"{"loops": [[[01, 0]]]}"#,
            r#"{"loops": [[[1., 0]]]}"#,
            r#"{"loops": [[[.5, 0]]]}"#,
            r#"{"loops": [[[1e, 0]]]}"#,
            r#"{"loops": [[[+1, 0]]]}"#,
            r#"{"loops": [[[1e999, 0]]]}"#,
            r#"{"loops": [[[1, 0, 0, 0]]]}"#,
            r#"{"loops": [[[1]]]}"#,
            r#"{"loops": [[[1, 0],]]}"#,
            r#"{"loops": [[[1, 0]]]} x"#,
            r#"{"lo\u006fps": [[[1, 0]]]}"#,
            // fuzz/json: a trailing form feed is ASCII whitespace, not JSON's.
            "{\"loops\": [[[1, 0]]]}\u{c}",
            "{\"loops\": [[[1, 0], \u{c}[2, 0]]]}",
        ];
        for c in cases {
            let fast = read_loops_fast(c.as_bytes());
            let full = read_loops_generic(c);
            match fast.clone() {
                Some(v) => assert_eq!(Ok(v), full, "{c}"),
                None => assert!(full.is_err() || c.contains("name") || c.contains("\\u"), "{c}: {full:?}"),
            }
            assert_eq!(read_loops(c), full, "{c}");
            for piece in 1..c.len() {
                assert_eq!(read_loops_fast_in_pieces(c.as_bytes(), piece), fast, "{c} in pieces of {piece}");
            }
        }
        assert!(read_loops_fast(cases[3].as_bytes()).is_some());
    }

    #[test]
    fn writing_then_reading_is_bit_exact() {
        let lp = vec![
            RawVertex { x: 0.1, y: 1e-300, bulge: 0.3333333333333333 },
            RawVertex { x: -7.0, y: 2.5e17, bulge: 0.0 },
        ];
        let back = read_loops(&write_loops(std::slice::from_ref(&lp))).unwrap();
        assert_eq!(back[0].vertices, lp);
    }
}
