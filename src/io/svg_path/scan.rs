//! Scanning the text: numbers, flags and separators as SVG writes them,
//! with errors at byte offsets.

use crate::io::{Format, ParseError};
use std::fmt;

pub(crate) fn error(at: usize, message: String) -> ParseError {
    ParseError { format: Format::Svg, line: 0, column: at, message, unsupported: false }
}

/// At most the first 40 characters of a name, so that garbage input cannot
/// make a huge message.
pub(crate) fn clip(s: &str) -> &str {
    s.char_indices().nth(40).and_then(|(i, _)| s.get(..i)).unwrap_or(s)
}

pub(crate) fn is_wsp(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | b'\x0c')
}

/// What is being parsed, for messages.
#[derive(Clone, Copy)]
pub(crate) enum Ctx<'a> {
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
pub(crate) struct Cursor<'a> {
    text: &'a str,
    pub(crate) pos: usize,
    base: usize,
    pub(crate) ctx: Ctx<'a>,
}

impl<'a> Cursor<'a> {
    pub(crate) fn new(text: &'a str, base: usize, ctx: Ctx<'a>) -> Cursor<'a> {
        Cursor { text, pos: 0, base, ctx }
    }

    pub(crate) fn peek(&self) -> Option<u8> {
        self.text.as_bytes().get(self.pos).copied()
    }

    /// The character at the cursor, quoted, for messages.
    pub(crate) fn found(&self) -> String {
        match self.text.get(self.pos..).and_then(|s| s.chars().next()) {
            Some(c) => format!("{c:?}"),
            None => "the end".into(),
        }
    }

    pub(crate) fn error_here(&self, message: String) -> ParseError {
        error(self.base + self.pos, message)
    }

    pub(crate) fn skip_wsp(&mut self) {
        while self.peek().is_some_and(is_wsp) {
            self.pos += 1;
        }
    }

    pub(crate) fn skip_comma_wsp(&mut self) {
        self.skip_wsp();
        if self.peek() == Some(b',') {
            self.pos += 1;
            self.skip_wsp();
        }
    }

    pub(crate) fn digits(&mut self) -> usize {
        let start = self.pos;
        while self.peek().is_some_and(|b| b.is_ascii_digit()) {
            self.pos += 1;
        }
        self.pos - start
    }

    /// Skips separators and says whether another argument follows, which
    /// makes the previous command repeat.
    pub(crate) fn more_args(&mut self) -> bool {
        self.skip_comma_wsp();
        matches!(self.peek(), Some(b'0'..=b'9' | b'+' | b'-' | b'.'))
    }

    /// An SVG number: sign, digits with an optional fraction, optional
    /// exponent. It ends where the grammar does, so "-1-2" and ".5.5" are two
    /// numbers each.
    pub(crate) fn number(&mut self) -> Result<f64, ParseError> {
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

    pub(crate) fn pair(&mut self) -> Result<[f64; 2], ParseError> {
        let x = self.number()?;
        self.skip_comma_wsp();
        Ok([x, self.number()?])
    }

    /// An arc flag: a single `0` or `1`, which needs no separator after it.
    pub(crate) fn flag(&mut self) -> Result<bool, ParseError> {
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
