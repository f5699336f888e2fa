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
use std::fmt;

#[derive(Deserialize)]
struct ShapeFile {
    loops: Vec<Vec<JsonVertex>>,
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
    let file: ShapeFile = serde_json::from_str(text).map_err(|e| ParseError {
        format: Format::Json,
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
        unsupported: false,
    })?;
    Ok(file
        .loops
        .into_iter()
        .enumerate()
        .map(|(li, lp)| RawPolyline { vertices: lp.into_iter().map(|v| v.0).collect(), closed: true, source: li })
        .collect())
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
    fn reports_position_of_syntax_errors() {
        let e = read_loops("{\"loops\": [[[0, 0],\n [1, x]]]}").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.column > 1);
        let e = read_loops("{\"loops\": [[[0, 0],\n  [0, 0, 1, 2]]]}").unwrap_err();
        assert!(e.message.contains("expected [x, y] or [x, y, bulge]"), "{}", e.message);
        assert_eq!(e.line, 2);
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
