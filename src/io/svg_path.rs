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

use super::{Format, ParseError};
use std::fmt;

/// One drawing segment of a subpath, from the current point to `to`, in
/// absolute SVG user coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathSeg {
    /// Straight segment.
    Line {
        /// End point, user units.
        to: [f64; 2],
    },
    /// Elliptical arc in SVG's endpoint form (the `A` command). The radii are
    /// as written: SVG's corrections for negative, zero or too small radii are
    /// left to the caller.
    Arc {
        /// x radius, user units.
        rx: f64,
        /// y radius, user units.
        ry: f64,
        /// Rotation of the ellipse's x axis, degrees.
        x_rotation_deg: f64,
        /// SVG large-arc flag: take the arc of more than 180 degrees.
        large_arc: bool,
        /// SVG sweep flag: run in the positive-angle direction (clockwise on
        /// screen, where y points down).
        sweep: bool,
        /// End point, user units.
        to: [f64; 2],
    },
}

/// A subpath: a start point and the segments drawn from it.
#[derive(Debug, Clone, PartialEq)]
pub struct SvgSubpath {
    /// Start point, user units.
    pub start: [f64; 2],
    /// Segments in drawing order; may be empty (e.g. a lone `M`).
    pub segs: Vec<PathSeg>,
    /// True when the subpath is closed (`Z`, `<polygon>`, `<rect>`, ...): a
    /// straight segment back to `start` is implied when the last segment does
    /// not already end there.
    pub closed: bool,
    /// Byte offset in the input of the command that started the subpath (`M`,
    /// or the first command after a `Z`), or of the element's `<`.
    pub source: usize,
}

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

fn error(at: usize, message: String) -> ParseError {
    ParseError { format: Format::Svg, line: 0, column: at, message, unsupported: false }
}

/// A subpath with its segments.
fn subpath(start: [f64; 2], segs: Vec<PathSeg>, closed: bool, source: usize) -> SvgSubpath {
    SvgSubpath { start, segs, closed, source }
}

/// An unrotated elliptical arc in the positive-angle direction of at most
/// 180 degrees: the pieces of circles, ellipses and rounded corners.
fn arc_to(rx: f64, ry: f64, to: [f64; 2]) -> PathSeg {
    PathSeg::Arc { rx, ry, x_rotation_deg: 0.0, large_arc: false, sweep: true, to }
}

/// At most the first 40 characters of a name, so that garbage input cannot
/// make a huge message.
fn clip(s: &str) -> &str {
    s.char_indices().nth(40).and_then(|(i, _)| s.get(..i)).unwrap_or(s)
}

fn is_wsp(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b'\x0c')
}

/// What is being parsed, for messages.
#[derive(Clone, Copy)]
enum Ctx<'a> {
    Command(char),
    Attribute(&'a str),
}

impl fmt::Display for Ctx<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ctx::Command(c) => write!(f, "the '{c}' command"),
            Ctx::Attribute(a) => write!(f, "attribute '{a}'"),
        }
    }
}

/// A position in a piece of the input that starts at byte `base` of it.
struct Cursor<'a> {
    text: &'a str,
    pos: usize,
    base: usize,
    ctx: Ctx<'a>,
}

impl<'a> Cursor<'a> {
    fn new(text: &'a str, base: usize, ctx: Ctx<'a>) -> Cursor<'a> {
        Cursor { text, pos: 0, base, ctx }
    }

    fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.pos).copied()
    }

    /// The character at the cursor, quoted, for messages.
    fn found(&self) -> String {
        match self.text.get(self.pos..).and_then(|s| s.chars().next()) {
            Some(c) => format!("{c:?}"),
            None => "the end".into(),
        }
    }

    fn error_here(&self, message: String) -> ParseError {
        error(self.base + self.pos, message)
    }

    fn skip_wsp(&mut self) {
        while self.peek().is_some_and(is_wsp) {
            self.pos += 1;
        }
    }

    fn skip_comma_wsp(&mut self) {
        self.skip_wsp();
        if self.peek() == Some(b',') {
            self.pos += 1;
            self.skip_wsp();
        }
    }

    fn digits(&mut self) -> usize {
        let start = self.pos;
        while self.peek().is_some_and(|b| b.is_ascii_digit()) {
            self.pos += 1;
        }
        self.pos - start
    }

    /// Skips separators and says whether another argument follows, which
    /// makes the previous command repeat.
    fn more_args(&mut self) -> bool {
        self.skip_comma_wsp();
        matches!(self.peek(), Some(b'0'..=b'9' | b'+' | b'-' | b'.'))
    }

    /// An SVG number: sign, digits with an optional fraction, optional
    /// exponent. It ends where the grammar does, so "-1-2" and ".5.5" are two
    /// numbers each.
    fn number(&mut self) -> Result<f64, ParseError> {
        let start = self.pos;
        if matches!(self.peek(), Some(b'+' | b'-')) {
            self.pos += 1;
        }
        let mut n = self.digits();
        if self.peek() == Some(b'.') {
            self.pos += 1;
            n += self.digits();
        }
        if n == 0 {
            self.pos = start;
            return Err(self.error_here(format!("expected a number for {}, found {}", self.ctx, self.found())));
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            // Only an exponent with digits belongs to the number.
            let mark = self.pos;
            self.pos += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            if self.digits() == 0 {
                self.pos = mark;
            }
        }
        let s = self.text.get(start..self.pos).unwrap_or("");
        s.parse::<f64>().map_err(|_| error(self.base + start, format!("invalid number {:?} for {}", clip(s), self.ctx)))
    }

    fn pair(&mut self) -> Result<[f64; 2], ParseError> {
        let x = self.number()?;
        self.skip_comma_wsp();
        Ok([x, self.number()?])
    }

    /// An arc flag: a single `0` or `1`, which needs no separator after it.
    fn flag(&mut self) -> Result<bool, ParseError> {
        let v = match self.peek() {
            Some(b'0') => false,
            Some(b'1') => true,
            _ => {
                return Err(self.error_here(format!(
                    "expected an arc flag (0 or 1) for {}, found {}",
                    self.ctx,
                    self.found()
                )))
            }
        };
        self.pos += 1;
        self.skip_comma_wsp();
        Ok(v)
    }
}

/// Collects subpaths while path data is read.
#[derive(Default)]
struct Builder {
    out: Vec<SvgSubpath>,
    open: Option<SvgSubpath>,
    cur: [f64; 2],
}

impl Builder {
    fn move_to(&mut self, p: [f64; 2], source: usize) {
        self.out.extend(self.open.take());
        self.open = Some(subpath(p, Vec::new(), false, source));
        self.cur = p;
    }

    fn push(&mut self, seg: PathSeg, to: [f64; 2], source: usize) {
        // Only after a Z is there no open subpath (a leading non-M is rejected
        // earlier); SVG then starts the next one where the closed one started,
        // which is the current point.
        let cur = self.cur;
        let sub = self.open.get_or_insert_with(|| subpath(cur, Vec::new(), false, source));
        sub.segs.push(seg);
        self.cur = to;
    }

    fn close(&mut self) {
        // A second Z in a row has nothing left to close.
        if let Some(mut sub) = self.open.take() {
            sub.closed = true;
            self.cur = sub.start;
            self.out.push(sub);
        }
    }
}

fn parse_path_at(d: &str, base: usize) -> Result<Vec<SvgSubpath>, ParseError> {
    let mut c = Cursor::new(d, base, Ctx::Command('M'));
    let mut b = Builder::default();
    loop {
        c.skip_wsp();
        let Some(letter) = c.peek() else { break };
        let at = base + c.pos;
        match letter {
            b'M' | b'm' | b'L' | b'l' | b'H' | b'h' | b'V' | b'v' | b'A' | b'a' | b'Z' | b'z' => {}
            b'C' | b'c' | b'S' | b's' | b'Q' | b'q' | b'T' | b't' => {
                let msg = format!(
                    "Bézier curves are not supported yet (found the '{}' command); convert curves to lines and arcs first",
                    letter as char
                );
                return Err(ParseError { unsupported: true, ..error(at, msg) });
            }
            _ => return Err(error(at, format!("expected a path command (M, L, H, V, A or Z), found {}", c.found()))),
        }
        if b.out.is_empty() && b.open.is_none() && !matches!(letter, b'M' | b'm') {
            return Err(error(at, format!("path data must begin with a moveto (M or m), found '{}'", letter as char)));
        }
        c.pos += 1;
        c.ctx = Ctx::Command(letter as char);
        c.skip_wsp();
        let relative = letter.is_ascii_lowercase();
        // Relative coordinates are offsets from the current point at each repetition.
        let abs = |b: &Builder, p: [f64; 2]| {
            if relative {
                [b.cur[0] + p[0], b.cur[1] + p[1]]
            } else {
                p
            }
        };
        match letter.to_ascii_uppercase() {
            b'M' => {
                let p = abs(&b, c.pair()?);
                b.move_to(p, at);
                // Further pairs are implicit linetos (relative after `m`).
                while c.more_args() {
                    let to = abs(&b, c.pair()?);
                    b.push(PathSeg::Line { to }, to, at);
                }
            }
            b'L' => loop {
                let to = abs(&b, c.pair()?);
                b.push(PathSeg::Line { to }, to, at);
                if !c.more_args() {
                    break;
                }
            },
            b'H' | b'V' => loop {
                let v = c.number()?;
                let mut to = b.cur;
                let axis = usize::from(letter.eq_ignore_ascii_case(&b'V'));
                to[axis] = if relative { to[axis] + v } else { v };
                b.push(PathSeg::Line { to }, to, at);
                if !c.more_args() {
                    break;
                }
            },
            b'A' => loop {
                let rx = c.number()?;
                c.skip_comma_wsp();
                let ry = c.number()?;
                c.skip_comma_wsp();
                let x_rotation_deg = c.number()?;
                c.skip_comma_wsp();
                let large_arc = c.flag()?;
                let sweep = c.flag()?;
                let to = abs(&b, c.pair()?);
                b.push(PathSeg::Arc { rx, ry, x_rotation_deg, large_arc, sweep, to }, to, at);
                if !c.more_args() {
                    break;
                }
            },
            _ => b.close(),
        }
    }
    b.out.extend(b.open.take());
    Ok(b.out)
}

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

fn read_document(text: &str, from: usize) -> Result<Vec<SvgSubpath>, ParseError> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
