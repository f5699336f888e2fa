//! Byte-level scanning shared by the text formats: lines, whitespace
//! separated words with their lines, and numbers. Bytes rather than `str`
//! because a mesh file is not promised to be UTF-8 (a comment in Latin-1
//! must not stop the read), and only the words that matter are decoded.

/// One line: its 1-based number, the byte offset of its start, and its
/// content without the `\n` or `\r\n` that ends it.
#[derive(Clone, Copy)]
pub(super) struct Line<'a> {
    pub number: usize,
    pub start: usize,
    pub text: &'a [u8],
}

/// The lines of `bytes` (a final line without a line break included; the
/// empty piece after a final `\n` not).
pub(super) fn lines(bytes: &[u8]) -> impl Iterator<Item = Line<'_>> {
    let mut start = 0;
    let mut number = 0;
    std::iter::from_fn(move || {
        if start >= bytes.len() {
            return None;
        }
        let rest = &bytes[start..];
        let len = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        let mut text = &rest[..len];
        if let Some(t) = text.strip_suffix(b"\r") {
            text = t;
        }
        number += 1;
        let line = Line { number, start, text };
        start += len + 1;
        Some(line)
    })
}

/// The whitespace-separated words of a line.
pub(super) fn words(text: &[u8]) -> impl Iterator<Item = &[u8]> {
    text.split(|b| is_space(*b)).filter(|w| !w.is_empty())
}

fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n' | 0x0b | 0x0c)
}

/// A word of a token stream, with where it starts.
#[derive(Clone, Copy)]
pub(super) struct Token<'a> {
    pub text: &'a [u8],
    pub line: usize,
    /// Byte offset of the start of `line`.
    pub line_start: usize,
}

/// Whitespace-separated words across lines (STL and PLY ASCII, whose
/// records need not follow lines), each with its line.
pub(super) struct Tokens<'a> {
    bytes: &'a [u8],
    pos: usize,
    line: usize,
    line_start: usize,
}

impl<'a> Tokens<'a> {
    /// Words of `bytes` from `pos`, which is on 1-based line `line` starting at
    /// byte `line_start`.
    pub fn new(bytes: &'a [u8], pos: usize, line: usize, line_start: usize) -> Self {
        Tokens { bytes, pos, line, line_start }
    }

    /// The line the scan is on (after the last word read), and its start.
    pub fn here(&self) -> (usize, usize) {
        (self.line, self.line_start)
    }

    /// Skips the rest of the current line (a name after `solid`).
    pub fn skip_line(&mut self) {
        while let Some(&b) = self.bytes.get(self.pos) {
            if b == b'\n' {
                return;
            }
            self.pos += 1;
        }
    }
}

impl<'a> Iterator for Tokens<'a> {
    type Item = Token<'a>;

    fn next(&mut self) -> Option<Token<'a>> {
        while let Some(&b) = self.bytes.get(self.pos) {
            if !is_space(b) {
                break;
            }
            self.pos += 1;
            if b == b'\n' {
                self.line += 1;
                self.line_start = self.pos;
            }
        }
        let start = self.pos;
        while self.bytes.get(self.pos).is_some_and(|&b| !is_space(b)) {
            self.pos += 1;
        }
        let text = self.bytes.get(start..self.pos).filter(|t| !t.is_empty())?;
        Some(Token { text, line: self.line, line_start: self.line_start })
    }
}

/// A decimal number as Rust reads it (`1`, `-2.5e-3`, `inf`, `NaN`).
pub(super) fn parse_f64(word: &[u8]) -> Option<f64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

/// A non-negative integer (a count or an index).
pub(super) fn parse_u64(word: &[u8]) -> Option<u64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

/// A signed integer.
pub(super) fn parse_i64(word: &[u8]) -> Option<i64> {
    std::str::from_utf8(word).ok()?.parse().ok()
}

/// A word for a message: lossy UTF-8, cut at 40 characters so that a
/// megabyte of garbage without spaces does not become the message.
pub(super) fn shown(word: &[u8]) -> String {
    let s = String::from_utf8_lossy(word);
    if s.chars().count() <= 40 {
        s.into_owned()
    } else {
        let cut: String = s.chars().take(40).collect();
        format!("{cut}…")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_keep_numbers_and_starts() {
        let got: Vec<_> = lines(b"a\r\n\nb c\nlast").map(|l| (l.number, l.start, l.text.to_vec())).collect();
        assert_eq!(got, vec![(1, 0, b"a".to_vec()), (2, 3, vec![]), (3, 4, b"b c".to_vec()), (4, 8, b"last".to_vec())]);
        assert_eq!(lines(b"x\n").count(), 1);
        assert_eq!(lines(b"").count(), 0);
    }

    #[test]
    fn tokens_track_lines_across_breaks() {
        let mut t = Tokens::new(b"  one\n\ntwo three\r\n four", 0, 1, 0);
        let got: Vec<_> = t.by_ref().map(|t| (t.text.to_vec(), t.line, t.line_start)).collect();
        assert_eq!(
            got,
            vec![
                (b"one".to_vec(), 1, 0),
                (b"two".to_vec(), 3, 7),
                (b"three".to_vec(), 3, 7),
                (b"four".to_vec(), 4, 18)
            ]
        );
        assert_eq!(t.here(), (4, 18));
        let mut t = Tokens::new(b"solid name with words\nfacet", 0, 1, 0);
        t.next();
        t.skip_line();
        assert_eq!(t.next().map(|t| (t.text, t.line)), Some((&b"facet"[..], 2)));
    }

    #[test]
    fn numbers_and_shown_words() {
        assert_eq!(parse_f64(b"-2.5e-3"), Some(-2.5e-3));
        assert!(parse_f64(b"NaN").is_some_and(f64::is_nan));
        assert_eq!(parse_f64(b"1,5"), None);
        assert_eq!(parse_u64(b"-1"), None);
        assert_eq!(parse_i64(b"-1"), Some(-1));
        assert_eq!(parse_f64(b"\xff"), None);
        assert_eq!(shown(&[b'x'; 50]).chars().count(), 41);
    }
}
