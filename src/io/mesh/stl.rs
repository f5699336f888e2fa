//! STL, ASCII and binary. Each facet keeps its own three vertices (STL has
//! no shared vertices; welding them is the shape layer's business).
//!
//! Which of the two a file is: binary when its size is exactly 84 + 50 × the
//! facet count in bytes 80–84, whatever its header says (exporters often
//! start binary headers with `solid`); otherwise ASCII when it starts with
//! `solid` and has no NUL byte early on (ASCII STL never has one, binary
//! floats and counts nearly always do); otherwise binary, which then reports
//! where it is cut short.

use super::text::{self, Token, Tokens};
use super::{MeshFormat, MeshParseError, RawMesh};

const FORMAT: MeshFormat = MeshFormat::Stl;
const HEADER: usize = 84;
const RECORD: usize = 50;

/// The facet count of a binary STL's header, if the file is long enough.
fn binary_count(bytes: &[u8]) -> Option<u32> {
    let c = bytes.get(80..HEADER)?;
    Some(u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
}

/// Whether the size is that of a binary STL with the header's facet count.
pub(super) fn binary_size_matches(bytes: &[u8]) -> bool {
    binary_count(bytes).is_some_and(|n| bytes.len() as u64 == HEADER as u64 + RECORD as u64 * u64::from(n))
}

/// Whether the file starts with the word `solid` (any case, after blanks).
pub(super) fn starts_with_solid(bytes: &[u8]) -> bool {
    let t = bytes.trim_ascii_start();
    t.get(..5).is_some_and(|w| w.eq_ignore_ascii_case(b"solid")) && t.get(5).is_none_or(|b| b.is_ascii_whitespace())
}

/// Reads an STL file, ASCII or binary.
pub(super) fn read(bytes: &[u8]) -> Result<RawMesh, MeshParseError> {
    if binary_size_matches(bytes) {
        return read_binary(bytes);
    }
    let head = &bytes[..bytes.len().min(512)];
    if starts_with_solid(bytes) && !head.contains(&0) {
        read_ascii(bytes)
    } else {
        read_binary(bytes)
    }
}

fn read_binary(bytes: &[u8]) -> Result<RawMesh, MeshParseError> {
    let Some(n) = binary_count(bytes) else {
        return Err(MeshParseError::at_byte(
            FORMAT,
            bytes.len(),
            format!("{} bytes: too short for a binary STL (80-byte header and facet count)", bytes.len()),
        ));
    };
    let n = n as usize;
    let whole = (bytes.len() - HEADER) / RECORD;
    if whole < n {
        let need = HEADER as u64 + RECORD as u64 * n as u64;
        return Err(MeshParseError::at_byte(
            FORMAT,
            HEADER + RECORD * whole,
            format!(
                "the file ends in facet {whole} of {n} (a binary STL of {n} facets has {need} bytes, this one {})",
                bytes.len()
            ),
        ));
    }
    let too_many = || MeshParseError::at_byte(FORMAT, 80, format!("{n} facets: more than medax reads (2^32 / 3)"));
    u32::try_from(n.checked_mul(3).ok_or_else(too_many)?).map_err(|_| too_many())?;
    let mut mesh = RawMesh::new(false);
    mesh.positions.reserve(3 * n);
    mesh.indices.reserve(3 * n);
    mesh.face_starts.reserve(n);
    mesh.face_source.reserve(n);
    let f = |r: &[u8], at: usize| f64::from(f32::from_le_bytes([r[at], r[at + 1], r[at + 2], r[at + 3]]));
    for (k, r) in bytes[HEADER..HEADER + RECORD * n].chunks_exact(RECORD).enumerate() {
        // Bytes 0..12 are the normal, which the vertices' order already says.
        for v in 0..3 {
            let at = 12 + 12 * v;
            mesh.positions.push([f(r, at), f(r, at + 4), f(r, at + 8)]);
            mesh.indices.push((3 * k + v) as u32);
        }
        mesh.end_face(k).map_err(|m| MeshParseError::at_byte(FORMAT, HEADER + RECORD * k, m))?;
    }
    Ok(mesh)
}

/// A keyword test: STL keywords are case-insensitive.
fn is(t: &Token, word: &str) -> bool {
    t.text.eq_ignore_ascii_case(word.as_bytes())
}

fn err(t: &Token, msg: String) -> MeshParseError {
    MeshParseError::at_line(FORMAT, t.line, t.line_start, msg)
}

/// The next word, or an error naming `what` should have come.
fn next<'a>(toks: &mut Tokens<'a>, what: &str) -> Result<Token<'a>, MeshParseError> {
    toks.next().ok_or_else(|| {
        let (line, start) = toks.here();
        MeshParseError::at_line(FORMAT, line, start, format!("the file ends where {what} should be"))
    })
}

fn expect(toks: &mut Tokens, word: &str) -> Result<(), MeshParseError> {
    let t = next(toks, &format!("`{word}`"))?;
    if is(&t, word) {
        Ok(())
    } else {
        Err(err(&t, format!("expected `{word}`, found `{}`", text::shown(t.text))))
    }
}

fn number(toks: &mut Tokens, what: &str) -> Result<f64, MeshParseError> {
    let t = next(toks, what)?;
    text::parse_f64(t.text).ok_or_else(|| err(&t, format!("expected {what}, found `{}`", text::shown(t.text))))
}

fn read_ascii(bytes: &[u8]) -> Result<RawMesh, MeshParseError> {
    let mut toks = Tokens::new(bytes, 0, 1, 0);
    // The `solid` the caller has seen, and its name.
    toks.next();
    toks.skip_line();
    let mut mesh = RawMesh::new(true);
    let mut in_solid = true;
    let mut k = 0usize;
    while let Some(t) = toks.next() {
        if in_solid && is(&t, "facet") {
            expect(&mut toks, "normal")?;
            for _ in 0..3 {
                number(&mut toks, "a normal coordinate")?;
            }
            expect(&mut toks, "outer")?;
            expect(&mut toks, "loop")?;
            let first = mesh.positions.len();
            let mut v = next(&mut toks, "`vertex` or `endloop`")?;
            while is(&v, "vertex") {
                let mut p = [0.0; 3];
                for c in &mut p {
                    *c = number(&mut toks, "a vertex coordinate")?;
                }
                mesh.positions.push(p);
                v = next(&mut toks, "`vertex` or `endloop`")?;
            }
            if !is(&v, "endloop") {
                return Err(err(&v, format!("expected `vertex` or `endloop`, found `{}`", text::shown(v.text))));
            }
            expect(&mut toks, "endfacet")?;
            let count = mesh.positions.len() - first;
            if count < 3 {
                return Err(err(&t, format!("facet {k} has {count} vertices; a facet needs at least 3")));
            }
            for i in first..mesh.positions.len() {
                let i = u32::try_from(i).map_err(|_| err(&t, "more than 2^32 vertices".into()))?;
                mesh.indices.push(i);
            }
            mesh.end_face(t.line).map_err(|m| err(&t, m))?;
            k += 1;
        } else if in_solid && is(&t, "endsolid") {
            toks.skip_line();
            in_solid = false;
        } else if !in_solid && is(&t, "solid") {
            // Some exporters write one solid after another.
            toks.skip_line();
            in_solid = true;
        } else {
            let expected = if in_solid { "`facet` or `endsolid`" } else { "`solid` or the end of the file" };
            return Err(err(&t, format!("expected {expected}, found `{}`", text::shown(t.text))));
        }
    }
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binary_size_and_solid() {
        let mut b = vec![0u8; 84 + 50];
        b[80] = 1;
        assert!(binary_size_matches(&b));
        b.push(0);
        assert!(!binary_size_matches(&b));
        assert!(!binary_size_matches(&b[..83]));
        assert!(starts_with_solid(b"  SOLID x"));
        assert!(starts_with_solid(b"solid"));
        assert!(!starts_with_solid(b"solidworks"));
    }
}
