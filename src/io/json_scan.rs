//! A fast path for the common shape file: a top-level object whose only key
//! is `"loops"`, holding arrays of vertex arrays of plain JSON numbers.
//!
//! Shape files hold millions of numbers, and a generic JSON deserializer
//! spends most of its time on per-value dispatch. This scanner accepts a
//! strict subset of JSON and answers `None` on anything else (other keys,
//! escapes, syntax errors, numbers that overflow), in which case the caller
//! runs the full deserializer, which then produces the same values or the
//! positioned error. So the fast path never decides whether input is valid;
//! it only reads input that is.

use super::{RawPolyline, RawVertex};

/// JSON's whitespace: narrower than ASCII's (no form feed).
trait JsonWs {
    fn is_json_ws(&self) -> bool;
}

impl JsonWs for u8 {
    fn is_json_ws(&self) -> bool {
        matches!(self, b' ' | b'\n' | b'\r' | b'\t')
    }
}

struct Scanner<'a> {
    s: &'a [u8],
    i: usize,
}

impl<'a> Scanner<'a> {
    fn skip_ws(&mut self) {
        while let Some(b' ' | b'\n' | b'\r' | b'\t') = self.s.get(self.i) {
            self.i += 1;
        }
    }

    /// Skips whitespace, then consumes `c` if it comes next.
    fn eat(&mut self, c: u8) -> bool {
        self.skip_ws();
        if self.s.get(self.i) == Some(&c) {
            self.i += 1;
            true
        } else {
            false
        }
    }

    /// A JSON number (RFC 8259 grammar), converted with correct rounding.
    fn number(&mut self) -> Option<f64> {
        self.skip_ws();
        let start = self.i;
        let digits = |sc: &mut Scanner| {
            let from = sc.i;
            while sc.s.get(sc.i).is_some_and(u8::is_ascii_digit) {
                sc.i += 1;
            }
            sc.i - from
        };
        if self.s.get(self.i) == Some(&b'-') {
            self.i += 1;
        }
        let int_start = self.i;
        let n = digits(self);
        if n == 0 || (n > 1 && self.s[int_start] == b'0') {
            return None;
        }
        if self.s.get(self.i) == Some(&b'.') {
            self.i += 1;
            if digits(self) == 0 {
                return None;
            }
        }
        if let Some(b'e' | b'E') = self.s.get(self.i) {
            self.i += 1;
            if let Some(b'+' | b'-') = self.s.get(self.i) {
                self.i += 1;
            }
            if digits(self) == 0 {
                return None;
            }
        }
        // The slice is ASCII by construction.
        let text = std::str::from_utf8(&self.s[start..self.i]).ok()?;
        let v: f64 = text.parse().ok()?;
        // The full reader rejects overflow with a message; leave that to it.
        v.is_finite().then_some(v)
    }

    fn vertex(&mut self) -> Option<RawVertex> {
        if !self.eat(b'[') {
            return None;
        }
        let x = self.number()?;
        if !self.eat(b',') {
            return None;
        }
        let y = self.number()?;
        let bulge = if self.eat(b',') { self.number()? } else { 0.0 };
        self.eat(b']').then_some(RawVertex { x, y, bulge })
    }
}

/// Reads `{"loops": [...]}` when the text is exactly that shape of JSON;
/// `None` means "use the full reader".
///
/// Works on bytes: everything it accepts is ASCII, so callers holding a
/// file's bytes can skip UTF-8 decoding. Large documents are read in
/// parallel pieces of about `piece_bytes`.
pub(super) fn scan_loops(bytes: &[u8], piece_bytes: usize) -> Option<Vec<RawPolyline>> {
    let mut sc = Scanner { s: bytes, i: 0 };
    if !sc.eat(b'{') {
        return None;
    }
    sc.skip_ws();
    if !sc.s[sc.i..].starts_with(b"\"loops\"") {
        return None;
    }
    sc.i += b"\"loops\"".len();
    if !(sc.eat(b':') && sc.eat(b'[')) {
        return None;
    }
    // The document must end with `] }`; what lies between is the list of loops.
    let mut end = bytes.len();
    for want in [b'}', b']'] {
        while end > sc.i && bytes[end - 1].is_json_ws() {
            end -= 1;
        }
        if end <= sc.i || bytes[end - 1] != want {
            return None;
        }
        end -= 1;
    }
    let cuts = split_points(bytes, sc.i, end, piece_bytes);
    let pieces: Vec<Option<Vec<Vec<RawVertex>>>> = {
        use rayon::prelude::*;
        cuts.par_windows(2).map(|w| read_piece(bytes, w[0], w[1], w[0] != sc.i, w[1] != end)).collect()
    };
    // Piece k > 0 starts inside the last loop of piece k − 1.
    let mut loops: Vec<Vec<RawVertex>> = Vec::new();
    for (k, piece) in pieces.into_iter().enumerate() {
        let mut frags = piece?.into_iter();
        if k > 0 {
            let first = frags.next()?;
            loops.last_mut()?.extend(first);
        }
        loops.extend(frags);
    }
    Some(
        loops
            .into_iter()
            .enumerate()
            .map(|(source, vertices)| RawPolyline { vertices, closed: true, source, layer: 0, colour: 0, handle: 0 })
            .collect(),
    )
}

/// Piece boundaries in `[start, end)`: `start`, then positions of a vertex's
/// `[` that follows `],` and precedes a number (inside a loop, in any
/// document the scanner accepts), about `piece_bytes` apart, then `end`.
/// A wrong guess cannot slip through: each piece must end exactly in the
/// state the next one starts in.
fn split_points(s: &[u8], start: usize, end: usize, piece_bytes: usize) -> Vec<usize> {
    let mut cuts = vec![start];
    let mut at = start + piece_bytes.max(1);
    'next: while at < end {
        let mut i = at;
        while i < end {
            if s[i] == b']' {
                let mut j = i + 1;
                let ws = |j: &mut usize| {
                    while *j < end && s[*j].is_json_ws() {
                        *j += 1;
                    }
                };
                ws(&mut j);
                if j < end && s[j] == b',' {
                    j += 1;
                    ws(&mut j);
                    if j < end && s[j] == b'[' {
                        let mut k = j + 1;
                        ws(&mut k);
                        if k < end && (s[k] == b'-' || s[k].is_ascii_digit()) {
                            cuts.push(j);
                            at = j + piece_bytes.max(1);
                            continue 'next;
                        }
                    }
                }
            }
            i += 1;
        }
        break;
    }
    cuts.push(end);
    cuts
}

/// Reads loops from `s[start..end]`. `open_start`: the piece starts at a
/// vertex inside a loop begun by the previous piece (its vertices come
/// first in the result). `open_end`: the piece must end just after a `,`
/// between two vertices, and its last loop continues in the next piece.
fn read_piece(s: &[u8], start: usize, end: usize, open_start: bool, open_end: bool) -> Option<Vec<Vec<RawVertex>>> {
    let mut sc = Scanner { s: &s[..end], i: start };
    let mut loops = Vec::new();
    let mut cur = Vec::new();
    let mut in_loop = open_start;
    if !in_loop {
        sc.skip_ws();
        if sc.i == end {
            // `[]`: no loops at all (only possible when unsplit).
            return (!open_end).then_some(loops);
        }
    }
    loop {
        if !in_loop {
            if !sc.eat(b'[') {
                return None;
            }
            in_loop = true;
            if sc.eat(b']') {
                // An empty loop (rejected later, with its index, by validation).
                loops.push(std::mem::take(&mut cur));
                in_loop = false;
            }
        }
        if in_loop {
            cur.push(sc.vertex()?);
            if sc.eat(b',') {
                sc.skip_ws();
                if sc.i == end {
                    if !open_end {
                        return None;
                    }
                    loops.push(cur);
                    return Some(loops);
                }
                continue;
            }
            if !sc.eat(b']') {
                return None;
            }
            loops.push(std::mem::take(&mut cur));
            in_loop = false;
        }
        // Between loops: another one, or the end of the list.
        if sc.eat(b',') {
            continue;
        }
        sc.skip_ws();
        return (sc.i == end && !open_end).then_some(loops);
    }
}
