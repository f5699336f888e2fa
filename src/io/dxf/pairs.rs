//! The syntax of ASCII DXF: group code/value line pairs, their numbers, and
//! the errors that point at a line.

use crate::io::{Format, ParseError};

pub(crate) fn error(line: usize, message: String) -> ParseError {
    ParseError { format: Format::Dxf, line, column: 1, message, unsupported: false }
}

/// Quotes a file value for a message, shortened so that a huge garbage line
/// does not produce a huge message.
fn shown(value: &str) -> String {
    const MAX: usize = 40;
    let v = value.trim();
    match v.char_indices().nth(MAX) {
        Some((cut, _)) => format!("{:?}...", &v[..cut]),
        None => format!("{v:?}"),
    }
}

/// One group: code, raw value, and the 1-based line of the code (the value is
/// on the next line).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pair<'a> {
    pub(crate) code: i32,
    pub(crate) value: &'a str,
    pub(crate) line: usize,
}

/// Splits the text into group code/value pairs, one pair at a time.
pub(crate) struct Pairs<'a> {
    rest: &'a str,
    pub(crate) line: usize,
    eol: char,
}

impl<'a> Pairs<'a> {
    pub(crate) fn new(text: &'a str) -> Pairs<'a> {
        // Files from classic Mac OS end lines with a bare CR.
        let eol = if !text.contains('\n') && text.contains('\r') { '\r' } else { '\n' };
        Pairs { rest: text, line: 0, eol }
    }

    fn next_line(&mut self) -> Option<&'a str> {
        if self.rest.is_empty() {
            return None;
        }
        let (l, rest) = self.rest.split_once(self.eol).unwrap_or((self.rest, ""));
        self.rest = rest;
        self.line += 1;
        Some(l.strip_suffix('\r').unwrap_or(l))
    }

    pub(crate) fn next_pair(&mut self) -> Result<Option<Pair<'a>>, ParseError> {
        let Some(code) = self.next_line() else { return Ok(None) };
        let line = self.line;
        let code = code.trim();
        // Trailing blank lines are common (and harmless) when there is no EOF.
        // This scan happens at most once: otherwise the blank code is an error.
        if code.is_empty() && self.rest.trim_start().is_empty() {
            return Ok(None);
        }
        let code = code
            .parse::<i32>()
            .map_err(|_| error(line, format!("expected an integer group code, found {}", shown(code))))?;
        let Some(value) = self.next_line() else {
            return Err(error(line, format!("file ends after group code {code}, in the middle of a code/value pair")));
        };
        Ok(Some(Pair { code, value, line }))
    }
}

/// Parses a value that must be a real number.
pub(crate) fn number(entity: &str, at: usize, g: &Pair) -> Result<f64, ParseError> {
    g.value.trim().parse::<f64>().map_err(|_| {
        let msg = format!("{entity} at line {at}: group {} should be a number, found {}", g.code, shown(g.value));
        error(g.line + 1, msg)
    })
}

/// Parses a value that must be an integer (flags).
pub(crate) fn integer(entity: &str, at: usize, g: &Pair) -> Result<i64, ParseError> {
    g.value.trim().parse::<i64>().map_err(|_| {
        let msg = format!("{entity} at line {at}: group {} should be an integer, found {}", g.code, shown(g.value));
        error(g.line + 1, msg)
    })
}
