//! Documents: a linear scan for the shape elements (`path`, `polygon`,
//! `polyline`, `rect`, `circle`, `ellipse`, `line`) and their attributes,
//! each converted to subpaths by the SVG equivalent paths.

use crate::io::svg_path::path_data::parse_path_at;
use crate::io::svg_path::scan::{clip, error, is_wsp, Ctx, Cursor};
use crate::io::svg_path::subpath::{arc_to, subpath, PathSeg, SvgSubpath};
use crate::io::ParseError;

/// An attribute of the tag being read; `at` is the byte offset of its value.
struct Attr<'a> {
    name: &'a str,
    value: &'a str,
    at: usize,
}

fn find_byte(bytes: &[u8], from: usize, needle: u8) -> Option<usize> {
    bytes.get(from..)?.iter().position(|&b| b == needle).map(|i| from + i)
}

/// The offset just past the first `end` at or after `from`.
fn skip_past(bytes: &[u8], from: usize, end: &[u8], start: usize, what: &str) -> Result<usize, ParseError> {
    let found = bytes.get(from..).and_then(|rest| rest.windows(end.len()).position(|w| w == end));
    found.map(|i| from + i + end.len()).ok_or_else(|| error(start, format!("unterminated {what}")))
}

/// Reads a start tag at `lt` into its name and `attrs`; returns the name,
/// whether the tag is self-closing, and the offset after its `>`.
fn scan_tag<'a>(text: &'a str, lt: usize, attrs: &mut Vec<Attr<'a>>) -> Result<(&'a str, bool, usize), ParseError> {
    let bytes = text.as_bytes();
    let name_end = |mut j: usize, stop: &[u8]| {
        while bytes.get(j).is_some_and(|&b| !is_wsp(b) && !stop.contains(&b)) {
            j += 1;
        }
        j
    };
    let skip_wsp = |mut j: usize| {
        while bytes.get(j).is_some_and(|&b| is_wsp(b)) {
            j += 1;
        }
        j
    };
    let mut j = name_end(lt + 1, b"/><");
    let name = text.get(lt + 1..j).unwrap_or("");
    if name.is_empty() {
        return Err(error(lt, "expected an element name after '<'".into()));
    }
    attrs.clear();
    loop {
        j = skip_wsp(j);
        match bytes.get(j) {
            None => return Err(error(lt, format!("unterminated <{}> tag", clip(name)))),
            Some(b'>') => return Ok((name, false, j + 1)),
            Some(b'/') if bytes.get(j + 1) == Some(&b'>') => return Ok((name, true, j + 2)),
            Some(_) => {}
        }
        let attr_start = j;
        j = name_end(j, b"=/><");
        let attr = text.get(attr_start..j).unwrap_or("");
        j = skip_wsp(j);
        if attr.is_empty() || bytes.get(j) != Some(&b'=') {
            return Err(error(j, format!("expected an attribute name followed by '=' in <{}> tag", clip(name))));
        }
        j = skip_wsp(j + 1);
        let quote = match bytes.get(j) {
            Some(&q @ (b'"' | b'\'')) => q,
            _ => {
                return Err(error(
                    j,
                    format!("expected a quoted value for attribute '{}' of <{}>", clip(attr), clip(name)),
                ))
            }
        };
        let close = find_byte(bytes, j + 1, quote)
            .ok_or_else(|| error(j, format!("unterminated value of '{}'", clip(attr))))?;
        attrs.push(Attr { name: attr, value: text.get(j + 1..close).unwrap_or(""), at: j + 1 });
        j = close + 1;
    }
}

pub(crate) fn read_document(text: &str, from: usize) -> Result<Vec<SvgSubpath>, ParseError> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut attrs = Vec::new();
    let mut i = from;
    // Element depth inside content that is not rendered (defs, ...); counting
    // instead of recursing keeps deep nesting cheap and safe.
    let mut hidden = 0usize;
    while let Some(lt) = find_byte(bytes, i, b'<') {
        let rest = &bytes[lt..];
        if rest.starts_with(b"<!--") {
            i = skip_past(bytes, lt + 4, b"-->", lt, "comment")?;
        } else if rest.starts_with(b"<![CDATA[") {
            i = skip_past(bytes, lt + 9, b"]]>", lt, "CDATA section")?;
        } else if rest.starts_with(b"<?") {
            i = skip_past(bytes, lt + 2, b"?>", lt, "processing instruction")?;
        } else if rest.starts_with(b"<!") {
            i = skip_declaration(bytes, lt)?;
        } else if rest.starts_with(b"</") {
            i = skip_past(bytes, lt + 2, b">", lt, "end tag")?;
            hidden = hidden.saturating_sub(1);
        } else {
            let (name, self_closing, end) = scan_tag(text, lt, &mut attrs)?;
            i = end;
            if hidden > 0 {
                hidden += usize::from(!self_closing);
                continue;
            }
            let local = name.rsplit_once(':').map_or(name, |(_, l)| l);
            match local {
                "defs" | "symbol" | "clipPath" | "mask" | "pattern" | "marker" => hidden = usize::from(!self_closing),
                // Their text may hold '<' that is not markup.
                "script" | "style" if !self_closing => {
                    i = (end..bytes.len()).find(|&k| bytes[k..].starts_with(b"</")).unwrap_or(bytes.len());
                }
                _ => element(local, lt, &attrs, &mut out)?,
            }
        }
    }
    Ok(out)
}

/// Skips `<!DOCTYPE ...>`, including an internal subset in brackets.
fn skip_declaration(bytes: &[u8], lt: usize) -> Result<usize, ParseError> {
    let mut depth = 0usize;
    for (k, &b) in bytes.iter().enumerate().skip(lt + 2) {
        match b {
            b'[' => depth += 1,
            b']' => depth = depth.saturating_sub(1),
            b'>' if depth == 0 => return Ok(k + 1),
            _ => {}
        }
    }
    Err(error(lt, "unterminated <! declaration".into()))
}

/// A length attribute in user units; absent means 0, as in SVG.
fn length(attrs: &[Attr], name: &str) -> Result<f64, ParseError> {
    let Some(a) = attrs.iter().find(|a| a.name == name) else {
        return Ok(0.0);
    };
    let mut c = Cursor::new(a.value, a.at, Ctx::Attribute(name));
    c.skip_wsp();
    let v = c.number()?;
    if a.value.get(c.pos..).is_some_and(|s| s.starts_with("px")) {
        c.pos += 2;
    }
    c.skip_wsp();
    if c.peek().is_some() {
        return Err(c.error_here(format!(
            "unexpected {} in attribute '{name}': only plain numbers (user units) or px lengths are supported",
            c.found()
        )));
    }
    Ok(v)
}

fn points(a: &Attr) -> Result<Vec<[f64; 2]>, ParseError> {
    let mut c = Cursor::new(a.value, a.at, Ctx::Attribute("points"));
    let mut pts = Vec::new();
    c.skip_wsp();
    while c.peek().is_some() {
        let x = c.number()?;
        c.skip_comma_wsp();
        if c.peek().is_none() {
            return Err(c.error_here("odd number of coordinates in attribute 'points'".into()));
        }
        pts.push([x, c.number()?]);
        c.skip_comma_wsp();
    }
    Ok(pts)
}

/// Converts one shape element to subpaths, per the SVG equivalent paths.
fn element(name: &str, at: usize, attrs: &[Attr], out: &mut Vec<SvgSubpath>) -> Result<(), ParseError> {
    let get = |n: &str| attrs.iter().find(|a| a.name == n);
    let len = |n: &str| length(attrs, n);
    let line = |to| PathSeg::Line { to };
    let closed = |start, segs| subpath(start, segs, true, at);
    let negative = |what: &str| error(at, format!("<{name}> has a negative {what}"));
    // Two half ellipses, starting at the rightmost point as SVG specifies.
    let ellipse = |c: [f64; 2], rx: f64, ry: f64| {
        let (left, right) = ([c[0] - rx, c[1]], [c[0] + rx, c[1]]);
        closed(right, vec![arc_to(rx, ry, left), arc_to(rx, ry, right)])
    };
    match name {
        "path" => {
            if let Some(d) = get("d") {
                out.extend(parse_path_at(d.value, d.at)?);
            }
        }
        "polygon" | "polyline" => {
            let pts = match get("points") {
                Some(a) => points(a)?,
                None => Vec::new(),
            };
            if let Some((&start, rest)) = pts.split_first() {
                let segs = rest.iter().map(|&p| line(p)).collect();
                out.push(subpath(start, segs, name == "polygon", at));
            }
        }
        "line" => {
            let (a, b) = ([len("x1")?, len("y1")?], [len("x2")?, len("y2")?]);
            out.push(subpath(a, vec![line(b)], false, at));
        }
        "circle" => {
            let r = len("r")?;
            if r < 0.0 {
                return Err(negative("radius"));
            }
            // A zero radius disables rendering.
            if r != 0.0 {
                out.push(ellipse([len("cx")?, len("cy")?], r, r));
            }
        }
        "ellipse" => {
            let (rx, ry) = (len("rx")?, len("ry")?);
            if rx < 0.0 || ry < 0.0 {
                return Err(negative("radius"));
            }
            if rx != 0.0 && ry != 0.0 {
                out.push(ellipse([len("cx")?, len("cy")?], rx, ry));
            }
        }
        "rect" => {
            let (x, y, w, h) = (len("x")?, len("y")?, len("width")?, len("height")?);
            if w < 0.0 || h < 0.0 {
                return Err(negative("width or height"));
            }
            if w == 0.0 || h == 0.0 {
                return Ok(());
            }
            // A missing radius takes the other's value; both clamp to half the side.
            let (rx, ry) = match (get("rx"), get("ry")) {
                (None, None) => (0.0, 0.0),
                (Some(_), None) => (len("rx")?, len("rx")?),
                (None, Some(_)) => (len("ry")?, len("ry")?),
                (Some(_), Some(_)) => (len("rx")?, len("ry")?),
            };
            if rx < 0.0 || ry < 0.0 {
                return Err(negative("corner radius"));
            }
            let (rx, ry) = (rx.min(w / 2.0), ry.min(h / 2.0));
            let (x1, y1) = (x + w, y + h);
            if rx == 0.0 || ry == 0.0 {
                out.push(closed([x, y], vec![line([x1, y]), line([x1, y1]), line([x, y1])]));
                return Ok(());
            }
            if rx != ry {
                let msg = format!(
                    "<rect> corners must be circular (rx == ry after clamping to half the width and height), found rx = {rx}, ry = {ry}"
                );
                return Err(error(at, msg));
            }
            let r = rx;
            let arc = |to| arc_to(r, r, to);
            // Straight sides vanish when the corners meet; leave them out
            // rather than emit zero-length segments.
            let (sides_w, sides_h) = (2.0 * r < w, 2.0 * r < h);
            let mut segs = Vec::with_capacity(8);
            segs.extend(sides_w.then(|| line([x1 - r, y])));
            segs.push(arc([x1, y + r]));
            segs.extend(sides_h.then(|| line([x1, y1 - r])));
            segs.push(arc([x1 - r, y1]));
            segs.extend(sides_w.then(|| line([x + r, y1])));
            segs.push(arc([x, y1 - r]));
            segs.extend(sides_h.then(|| line([x, y + r])));
            segs.push(arc([x + r, y]));
            out.push(closed([x + r, y], segs));
        }
        _ => {}
    }
    Ok(())
}
