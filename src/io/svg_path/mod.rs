//! SVG reader: path data and the basic shape elements, as subpaths of straight
//! segments and elliptical arcs.
//!
//! Coordinates are SVG user units exactly as written (y pointing down, the SVG
//! convention); flipping or scaling is the caller's business. Documents are
//! read with a small linear-time scanner, not an XML parser: it finds `path`,
//! `polygon`, `polyline`, `rect`, `circle`, `ellipse` and `line` elements in
//! document order. It does not apply `transform` attributes, the root
//! element's `viewBox`, `width` or `height`, or CSS, and it does not follow
//! `<use>` references; the content of elements that are never rendered
//! directly (`defs`, `symbol`, `clipPath`, `mask`, `pattern`, `marker`) is
//! skipped. Lengths must be plain numbers (user units) or carry `px`; other
//! units and percentages are errors, since resolving them needs the viewport.
//! Entity references such as `&#10;` are not expanded.
//!
//! Errors are [`ParseError`]s with `line` 0 and the byte offset in `column`.
//! Numbers that overflow to infinity are passed through for the shape layer to
//! reject.

mod document;
mod path_data;
mod scan;
mod subpath;

pub use crate::io::svg_path::subpath::{PathSeg, SvgSubpath};

use crate::io::svg_path::document::read_document;
use crate::io::svg_path::path_data::parse_path_at;
use crate::io::ParseError;

/// Parses SVG path data (the `d` attribute) into subpaths with absolute
/// coordinates. Supports M, L, H, V, A, Z in both cases with implicit command
/// repetition (extra pairs after M are L). A drawing command after `Z` starts a
/// new subpath at the closed subpath's start, as the SVG specification says.
///
/// # Errors
///
/// Curve commands (C, S, Q, T: Bézier curves are not supported yet), data not
/// starting with a moveto, unknown characters, and missing or malformed
/// numbers or arc flags; the position is the byte offset in `d`.
pub fn parse_path_data(d: &str) -> Result<Vec<SvgSubpath>, ParseError> {
    parse_path_at(d, 0)
}

/// Reads an SVG document, or bare path data when the text (after an optional
/// byte-order mark and whitespace) does not start with `<`. Subpaths come in
/// document order; see the module documentation for what is and is not read.
///
/// # Errors
///
/// Malformed markup (unterminated tags, comments or attribute values,
/// unquoted values), errors in path data or `points`, lengths with units
/// other than px, negative sizes, and rounded `<rect>` corners that are not
/// circular; the position is the byte offset in `text`.
pub fn read_svg(text: &str) -> Result<Vec<SvgSubpath>, ParseError> {
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let base = text.len() - body.len();
    if body.trim_start().starts_with('<') {
        read_document(text, base)
    } else {
        parse_path_at(body, base)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::Format;

    fn line(x: f64, y: f64) -> PathSeg {
        PathSeg::Line { to: [x, y] }
    }

    #[test]
    fn resolves_relative_commands_and_h_v() {
        let p = parse_path_data("M10 20 l5 0 L 30,40 h-5 V0 v 10 H 1").unwrap();
        assert_eq!(p.len(), 1);
        assert_eq!((p[0].start, p[0].closed, p[0].source), ([10.0, 20.0], false, 0));
        assert_eq!(
            p[0].segs,
            vec![
                line(15.0, 20.0),
                line(30.0, 40.0),
                line(25.0, 40.0),
                line(25.0, 0.0),
                line(25.0, 10.0),
                line(1.0, 10.0)
            ]
        );
    }

    #[test]
    fn repeats_commands_implicitly_and_reads_compact_numbers() {
        let p = parse_path_data("m1 1 2 2 3 3").unwrap();
        assert_eq!(p[0].start, [1.0, 1.0]);
        assert_eq!(p[0].segs, vec![line(3.0, 3.0), line(6.0, 6.0)]);
        let p = parse_path_data("M.5.5-1-2L1e-3,2E+1 4.  -.25e1").unwrap();
        assert_eq!(p[0].start, [0.5, 0.5]);
        assert_eq!(p[0].segs, vec![line(-1.0, -2.0), line(1e-3, 20.0), line(4.0, -2.5)]);
    }

    #[test]
    fn reads_arcs_with_compact_flags() {
        let p = parse_path_data("M0 0a1 1 0 00 1 1A2,3 45 1,1 5-5a1 1 0 0110 10").unwrap();
        let arc = |rx, ry, x_rotation_deg, large_arc, sweep, to| PathSeg::Arc {
            rx,
            ry,
            x_rotation_deg,
            large_arc,
            sweep,
            to,
        };
        assert_eq!(
            p[0].segs,
            vec![
                arc(1.0, 1.0, 0.0, false, false, [1.0, 1.0]),
                arc(2.0, 3.0, 45.0, true, true, [5.0, -5.0]),
                arc(1.0, 1.0, 0.0, false, true, [15.0, 5.0]),
            ]
        );
        let e = parse_path_data("M0 0 A1 1 0 2 0 3 3").unwrap_err();
        assert_eq!((e.line, e.column), (0, 12));
        assert!(e.message.contains("arc flag"), "{}", e.message);
    }

    #[test]
    fn continues_after_z_from_the_closed_start() {
        let d = "M1 0 L2 0 L2 1 Z L 5 5 z z m 1 1 l 1 0";
        let p = parse_path_data(d).unwrap();
        assert_eq!(p.len(), 3);
        assert!(p[0].closed && p[1].closed && !p[2].closed);
        assert_eq!((p[1].start, p[1].segs.clone(), p[1].source), ([1.0, 0.0], vec![line(5.0, 5.0)], 17));
        assert_eq!((p[2].start, p[2].segs.clone()), ([2.0, 1.0], vec![line(3.0, 1.0)]));
    }

    #[test]
    fn reports_unsupported_and_malformed_data_with_offsets() {
        let e = parse_path_data("M0 0 L1 1 C 1 2 3 4 5 6").unwrap_err();
        assert_eq!((e.format, e.line, e.column), (Format::Svg, 0, 10));
        assert!(e.message.contains("Bézier curves are not supported yet"), "{}", e.message);
        let cases = [("L1 1", 0, "moveto"), ("  z", 2, "moveto"), ("M1", 2, "number"), ("M1 2 x", 5, "path command")];
        for (d, at, word) in cases {
            let e = parse_path_data(d).unwrap_err();
            assert_eq!(e.column, at, "{d}");
            assert!(e.message.contains(word), "{d}: {}", e.message);
        }
        assert!(parse_path_data("M1 2 Z 3").is_err());
        assert!(parse_path_data("M1 2 L3 4e").is_err());
        assert!(parse_path_data("M1 2 L- 4").is_err());
        assert!(parse_path_data(" \n").unwrap().is_empty());
    }

    #[test]
    fn reads_shape_elements_from_a_document() {
        let doc = r#"<?xml version="1.0"?>
<!DOCTYPE svg [ <!ENTITY x "<>"> ]>
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <!-- <path d="M 9 9 L 8 8"/> -->
  <defs><path d="M 7 7 L 6 6"/><g><rect width="1" height="1"/></g></defs>
  <style><![CDATA[ path > g { } ]]></style>
  <g transform="scale(2)">
    <polygon points="0,0 10,0 10 10"/>
    <polyline points=" 1 2, 3 4 "></polyline>
    <svg:rect x='1' y="2" width="4px" height="3" />
    <circle cx="5" cy="6" r="2"/>
    <line x2="3" y2="4"/>
    <path id="p" d="M 1 1 H 2"/>
  </g>
</svg>"#;
        let p = read_svg(doc).unwrap();
        assert_eq!(p.len(), 6);
        assert!(p[0].closed && !p[1].closed && p[2].closed && p[3].closed && !p[4].closed);
        assert_eq!((p[0].start, p[0].segs.clone()), ([0.0, 0.0], vec![line(10.0, 0.0), line(10.0, 10.0)]));
        assert_eq!(p[0].source, doc.find("<polygon").unwrap());
        assert_eq!(p[1].segs, vec![line(3.0, 4.0)]);
        assert_eq!((p[2].start, p[2].segs.clone()), ([1.0, 2.0], vec![line(5.0, 2.0), line(5.0, 5.0), line(1.0, 5.0)]));
        let half = |to| PathSeg::Arc { rx: 2.0, ry: 2.0, x_rotation_deg: 0.0, large_arc: false, sweep: true, to };
        assert_eq!((p[3].start, p[3].segs.clone()), ([7.0, 6.0], vec![half([3.0, 6.0]), half([7.0, 6.0])]));
        assert_eq!((p[4].start, p[4].segs.clone()), ([0.0, 0.0], vec![line(3.0, 4.0)]));
        assert_eq!(p[5].source, doc.find("M 1 1").unwrap());
    }

    #[test]
    fn rounds_rect_corners_only_when_circular() {
        let p = read_svg(r#"<rect width="10" height="4" rx="2"/>"#).unwrap();
        assert_eq!(p[0].start, [2.0, 0.0]);
        assert_eq!(p[0].segs.len(), 6, "the vertical sides vanish when the corners meet");
        assert_eq!(p[0].segs[0], line(8.0, 0.0));
        let corner =
            PathSeg::Arc { rx: 2.0, ry: 2.0, x_rotation_deg: 0.0, large_arc: false, sweep: true, to: [2.0, 0.0] };
        assert_eq!(p[0].segs[5], corner);
        let e = read_svg(r#"<rect width="10" height="4" rx="1" ry="1.5"/>"#).unwrap_err();
        assert!(e.message.contains("circular"), "{}", e.message);
        assert_eq!(read_svg(r#"<rect width="10" height="4" rx="0" ry="3"/>"#).unwrap()[0].segs.len(), 3);
    }

    #[test]
    fn reports_document_errors_with_offsets() {
        let e = read_svg(r#"<rect width="100%" height="1"/>"#).unwrap_err();
        assert_eq!(e.column, 16);
        assert!(e.message.contains("'width'"), "{}", e.message);
        let e = read_svg(r#"<svg><path d="M0 0 Q 1 1 2 2"/></svg>"#).unwrap_err();
        assert_eq!(e.column, 19);
        assert_eq!(read_svg("<svg><path d=M0/>").unwrap_err().column, 13);
        assert_eq!(read_svg("<svg><!-- open").unwrap_err().column, 5);
        assert_eq!(read_svg("<svg><line x1=\"1\"").unwrap_err().column, 5);
        assert!(read_svg("<circle r=\"-1\"/>").is_err());
        assert!(read_svg("<polygon points=\"1 2 3\"/>").unwrap_err().message.contains("odd"));
        assert_eq!(read_svg("\u{feff}  M1 2 L 3").unwrap_err().column, 13);
    }

    /// Deterministic pseudo-random inputs built from syntax-heavy pieces: the
    /// readers must return, not panic, and finish quickly on deep or long input.
    #[test]
    fn never_panics_on_garbage() {
        let pieces = [
            "<",
            ">",
            "/",
            "=",
            "\"",
            "'",
            "<!--",
            "-->",
            "<![CDATA[",
            "]]>",
            "<?",
            "<!",
            "[",
            "]",
            "<path d=\"",
            "<rect ",
            "<circle r='",
            "<defs>",
            "</defs>",
            "<style>",
            "M",
            "m",
            "a",
            "Z",
            "L",
            "h",
            "1",
            "0",
            "-",
            ".",
            "e",
            ",",
            " ",
            "é",
            "\u{feff}",
            "points=\"",
            "rx=\"",
            "px",
            "%",
        ];
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        for _ in 0..20_000 {
            let mut s = String::new();
            for _ in 0..(seed % 24) {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                s.push_str(pieces[(seed % pieces.len() as u64) as usize]);
            }
            let _ = read_svg(&s);
            let _ = parse_path_data(&s);
        }
        let deep = "<g>".repeat(100_000) + "<line x2='1'/>";
        assert_eq!(read_svg(&deep).unwrap().len(), 1);
        let long = "M0 0".to_string() + &" l1 1".repeat(100_000);
        assert_eq!(parse_path_data(&long).unwrap()[0].segs.len(), 100_000);
    }
}
