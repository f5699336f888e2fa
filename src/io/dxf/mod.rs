//! ASCII DXF reader: LWPOLYLINE, POLYLINE/VERTEX/SEQEND, LINE, ARC and CIRCLE
//! entities of the ENTITIES section with their layers, and the blocks its
//! INSERTs place, as raw plain data.
//!
//! A DXF file is a sequence of group code/value line pairs. The ENTITIES
//! section is read (a bare entity list with no SECTION structure is accepted
//! too), the BLOCKS section for the blocks that INSERT and MINSERT records
//! place (`blocks.rs`), and `$INSUNITS` from the HEADER; TABLES, OBJECTS and
//! the rest are skipped. Other entities (text, dimensions, hatches…) are
//! kept by type, layer and point for the caller to report; unknown group
//! codes are ignored, because real files carry many. Z values are ignored:
//! everything is read in the XY plane, in the drawing's model units.
//!
//! Mirrored entities: CAD programs often write 2D entities with the extrusion
//! direction (groups 210/220/230) set to (0, 0, -1). ARC, CIRCLE, LWPOLYLINE
//! and 2D POLYLINE coordinates are in the entity's object coordinate system,
//! whose x axis is then the world's -x. When group 230 is negative the reader
//! maps them to world coordinates: x is negated, arc angles `a` become
//! `180° - a` with start and end swapped (so arcs stay counter-clockwise), and
//! bulges change sign (the mirror reverses the turning direction). LINE
//! endpoints are world coordinates in DXF, so LINE is never mirrored. Other
//! (tilted) extrusion directions are read as if they were +Z.
//!
//! Every error is a [`ParseError`] with the 1-based line of the offending group
//! code or value and column 1. Numbers are parsed with Rust's `f64` parser
//! after trimming; "inf" and "nan" are passed through for the shape layer to
//! reject.

mod blocks;
mod entities;
mod pairs;

use crate::io::dxf::entities::Reader;
use crate::io::dxf::pairs::{error, Pair, Pairs};
use crate::io::{ParseError, RawDrawing};

/// Reads an ASCII DXF drawing into raw polylines, lines, arcs and circles in
/// model units, in file order; `source` fields are the 1-based line of each
/// entity's `0` group code. See the module documentation for what is read and
/// how mirrored (extrusion 0, 0, -1) entities are handled.
///
/// # Errors
///
/// Binary DXF; a group code that is not an integer; a number or flag value
/// that does not parse; a file ending between a group code and its value; an
/// entity missing a required group (e.g. a LINE without 11).
pub fn read_dxf(text: &str) -> Result<RawDrawing, ParseError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    if text.starts_with("AutoCAD Binary DXF") {
        let e = error(1, "binary DXF is not supported; save the drawing as ASCII DXF".into());
        return Err(ParseError { unsupported: true, ..e });
    }
    let mut pairs = Pairs::new(text);
    let mut reader = Reader::default();
    // A record is a `0 NAME` pair and the non-zero groups after it; it can only
    // be interpreted once the next `0` pair (or the end) shows it is complete.
    let mut head: Option<Pair> = None;
    let mut groups: Vec<Pair> = Vec::new();
    loop {
        let next = pairs.next_pair()?;
        if let Some(p) = next {
            if p.code != 0 {
                // Groups before the first `0` (e.g. 999 comments) belong to nothing.
                if head.is_some() {
                    groups.push(p);
                }
                continue;
            }
        }
        if let Some(h) = head.take() {
            reader.record(&h, &groups)?;
        }
        groups.clear();
        match next {
            // Anything after EOF is not part of the drawing.
            Some(p) if p.value.trim().eq_ignore_ascii_case("EOF") => break,
            Some(p) => head = Some(p),
            None => break,
        }
    }
    Ok(reader.finish())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::RawVertex;

    /// Builds DXF text from (code, value) pairs with the given line ending.
    fn dxf(pairs: &[(i32, &str)], eol: &str) -> String {
        pairs.iter().map(|(c, v)| format!("{c:>3}{eol}{v}{eol}")).collect()
    }

    /// Wraps entity pairs in a file with HEADER, BLOCKS and ENTITIES sections.
    fn entities<'a>(body: &[(i32, &'a str)]) -> Vec<(i32, &'a str)> {
        let mut all = vec![(0, "SECTION"), (2, "HEADER"), (9, "$ACADVER"), (1, "AC1015"), (0, "ENDSEC")];
        all.extend([(0, "SECTION"), (2, "BLOCKS"), (0, "BLOCK"), (0, "LINE")]);
        all.extend([(10, "0"), (20, "0"), (11, "1"), (21, "1"), (0, "ENDBLK"), (0, "ENDSEC")]);
        all.extend([(0, "SECTION"), (2, "ENTITIES")]);
        all.extend_from_slice(body);
        all.extend([(0, "ENDSEC"), (0, "EOF")]);
        all
    }

    #[test]
    fn reads_all_entity_kinds_with_crlf_and_bom() {
        let body = [
            (0, "LWPOLYLINE"),
            (5, "2F"),
            (100, "AcDbPolyline"),
            (90, "3"),
            (70, "1"),
            (10, "0.0"),
            (20, "0.0"),
            (10, "10"),
            (20, "0"),
            (42, "0.5"),
            (10, " 10 "),
            (20, "5e0"),
            (0, "LINE"),
            (10, "1"),
            (20, "2"),
            (30, "0"),
            (11, "3"),
            (21, "4"),
            (0, "ARC"),
            (10, "5"),
            (20, "6"),
            (40, "2"),
            (50, "0"),
            (51, "90"),
            (0, "CIRCLE"),
            (10, "-1"),
            (20, "-2"),
            (40, "0.25"),
            (0, "POLYLINE"),
            (66, "1"),
            (70, "1"),
            (0, "VERTEX"),
            (10, "0"),
            (20, "0"),
            (42, "-1"),
            (0, "VERTEX"),
            (70, "16"),
            (10, "99"),
            (20, "99"),
            (0, "VERTEX"),
            (10, "2"),
            (20, "0"),
            (0, "SEQEND"),
            (0, "HATCH"),
            (10, "oops, not read"),
        ];
        let text = format!("\u{feff}{}", dxf(&entities(&body), "\r\n"));
        let d = read_dxf(&text).unwrap();
        // The LINE inside BLOCKS is not read.
        assert_eq!(d.lines.len(), 1);
        assert_eq!(d.lines[0].a, [1.0, 2.0]);
        assert_eq!(d.lines[0].b, [3.0, 4.0]);
        assert_eq!(d.polylines.len(), 2);
        let lw = &d.polylines[0];
        assert!(lw.closed);
        assert_eq!(
            lw.vertices,
            vec![
                RawVertex { x: 0.0, y: 0.0, bulge: 0.0 },
                RawVertex { x: 10.0, y: 0.0, bulge: 0.5 },
                RawVertex { x: 10.0, y: 5.0, bulge: 0.0 },
            ]
        );
        // 15 HEADER and BLOCKS pairs, then SECTION and ENTITIES, come before it.
        assert_eq!(lw.source, 2 * 17 + 1);
        let arc = d.arcs[0];
        assert_eq!((arc.center, arc.radius, arc.start_deg, arc.end_deg), ([5.0, 6.0], 2.0, 0.0, 90.0));
        assert_eq!((d.circles[0].center, d.circles[0].radius), ([-1.0, -2.0], 0.25));
        let pl = &d.polylines[1];
        assert!(pl.closed);
        assert_eq!(pl.vertices.len(), 2, "the spline frame vertex is skipped");
        assert_eq!(pl.vertices[0].bulge, -1.0);
        assert_eq!((pl.vertices[1].x, pl.vertices[1].bulge), (2.0, 0.0));
    }

    #[test]
    fn reads_a_bare_entity_list_and_skips_3d_polylines() {
        let text = dxf(
            &[
                (0, "POLYLINE"),
                (70, "8"),
                (0, "VERTEX"),
                (10, "junk is not parsed"),
                (0, "SEQEND"),
                (0, "CIRCLE"),
                (10, "1"),
                (20, "1"),
                (40, "1"),
            ],
            "\n",
        );
        let d = read_dxf(&format!("{text}\n\n")).unwrap();
        assert!(d.polylines.is_empty());
        assert_eq!(d.circles.len(), 1);
        assert_eq!(d.circles[0].source, 11);
    }

    #[test]
    fn mirrors_entities_with_negative_extrusion() {
        let body = [
            (0, "ARC"),
            (10, "3"),
            (20, "1"),
            (40, "1"),
            (50, "10"),
            (51, "100"),
            (210, "0"),
            (220, "0"),
            (230, "-1"),
            (0, "CIRCLE"),
            (10, "3"),
            (20, "1"),
            (40, "1"),
            (230, "-1.0"),
            (0, "LWPOLYLINE"),
            (10, "1"),
            (20, "2"),
            (42, "0.5"),
            (10, "4"),
            (20, "2"),
            (230, "-1"),
            (0, "LINE"),
            (10, "1"),
            (20, "2"),
            (11, "3"),
            (21, "4"),
            (230, "-1"),
        ];
        let d = read_dxf(&dxf(&body, "\n")).unwrap();
        let arc = d.arcs[0];
        assert_eq!((arc.center, arc.start_deg, arc.end_deg), ([-3.0, 1.0], 80.0, 170.0));
        assert_eq!(d.circles[0].center, [-3.0, 1.0]);
        let v = &d.polylines[0].vertices;
        assert_eq!((v[0].x, v[0].y, v[0].bulge, v[1].x), (-1.0, 2.0, -0.5, -4.0));
        assert_eq!((d.lines[0].a, d.lines[0].b), ([1.0, 2.0], [3.0, 4.0]));
    }

    #[test]
    fn reports_errors_with_line_numbers() {
        let e = read_dxf("0\nLINE\n10\n1\n20\n2\n11\n3\n").unwrap_err();
        assert_eq!((e.line, e.column), (1, 1));
        assert!(e.message.contains("LINE") && e.message.contains("group 21"), "{}", e.message);

        let e = read_dxf("0\nLINE\n10\n1\nx20\n2\n").unwrap_err();
        assert_eq!(e.line, 5);
        assert!(e.message.contains("integer group code"), "{}", e.message);

        let e = read_dxf("0\nCIRCLE\n10\n1\n20\n2\n40\n1,5\n").unwrap_err();
        assert_eq!(e.line, 8);
        assert!(e.message.contains("CIRCLE at line 1") && e.message.contains("\"1,5\""), "{}", e.message);

        let e = read_dxf("0\r\nCIRCLE\r\n10\r\n1\r\n20").unwrap_err();
        assert_eq!(e.line, 5);
        assert!(e.message.contains("middle"), "{}", e.message);

        let e = read_dxf("0\nLWPOLYLINE\n10\n1\n10\n2\n20\n3\n").unwrap_err();
        assert_eq!(e.line, 3);

        let e = read_dxf("0\nPOLYLINE\n0\nVERTEX\n20\n1\n").unwrap_err();
        assert_eq!(e.line, 3);
        assert!(e.message.contains("VERTEX") && e.message.contains("group 10"), "{}", e.message);

        let e = read_dxf("AutoCAD Binary DXF\r\n\u{1a}\0").unwrap_err();
        assert!(e.message.contains("binary DXF"), "{}", e.message);
    }

    #[test]
    fn passes_non_finite_numbers_through_and_ignores_text_after_eof() {
        let d = read_dxf("0\nCIRCLE\n10\ninf\n20\nNaN\n40\n1\n0\nEOF\ngarbage").unwrap();
        assert!(d.circles[0].center[0].is_infinite() && d.circles[0].center[1].is_nan());
    }

    #[test]
    fn never_panics_on_garbage() {
        let samples =
            ["", "\n", "0", "0\n", " 0 \n\r\n", "\u{feff}", "0\nSECTION\n", "0\nVERTEX\n10\n1\n", "é\nü", "\r\r\r"];
        for s in samples {
            let _ = read_dxf(s);
        }
        let long = "0\nLINE\n".repeat(10_000) + "999\ncomment";
        assert!(read_dxf(&long).is_err());
    }
}
