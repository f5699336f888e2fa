//! Geomview OFF: `[ST][C][N]OFF`, then `nv nf ne`, then one vertex per line
//! (`x y z` and whatever the variant adds: normals, a colour, texture
//! coordinates) and one face per line (`n i1 … in` and an optional colour).
//!
//! Read by lines, not by a free token stream: the variants' extra numbers
//! (a colour has 1, 3 or 4) can then be skipped without knowing how many
//! there are, which is what CGAL's and Geomview's own files need. `#` starts
//! a comment anywhere. The keyword may be missing (Geomview allows it) and
//! the counts may share its line.

use super::text::{self, Line};
use super::{capacity, MeshFormat, MeshParseError, RawMesh};

const FORMAT: MeshFormat = MeshFormat::Off;

/// Whether `word` is an OFF keyword: `Some(Ok)` for one this reader reads,
/// `Some(Err(why))` for one it recognises but does not read (4-dimensional
/// and n-dimensional vertices), `None` when it is no OFF keyword.
fn keyword(word: &[u8]) -> Option<Result<(), &'static str>> {
    let mut rest = word.strip_suffix(b"OFF")?;
    // Geomview's order is ST, C, N, but NCOFF is seen too: any order, each once.
    let mut unused = [&b"ST"[..], b"C", b"N"].map(Some);
    while let Some(slot) = unused.iter_mut().find(|p| p.is_some_and(|p| rest.starts_with(p))) {
        rest = &rest[slot.take().map_or(0, <[u8]>::len)..];
    }
    let four = rest.strip_prefix(b"4");
    rest = four.unwrap_or(rest);
    let dim = rest.strip_prefix(b"n");
    rest = dim.unwrap_or(rest);
    if !rest.is_empty() {
        return None;
    }
    Some(match (four.is_some(), dim.is_some()) {
        (false, false) => Ok(()),
        (true, _) => Err("4-dimensional (homogeneous) OFF vertices are not read"),
        (false, true) => Err("n-dimensional OFF (nOFF) is not read"),
    })
}

/// A line's content before any `#` comment.
fn strip_comment(text: &[u8]) -> &[u8] {
    text.iter().position(|&b| b == b'#').map_or(text, |i| &text[..i])
}

/// The lines that hold something, comments cut.
fn records(bytes: &[u8]) -> impl Iterator<Item = Line<'_>> {
    text::lines(bytes).filter_map(|l| {
        let t = strip_comment(l.text);
        text::words(t).next().is_some().then_some(Line { text: t, ..l })
    })
}

/// Whether the first word after comments and blank lines is an OFF keyword.
pub(super) fn starts_with_keyword(bytes: &[u8]) -> bool {
    records(bytes).next().and_then(|l| text::words(l.text).next()).and_then(keyword).is_some()
}

/// Reads an OFF file.
pub(super) fn read(bytes: &[u8]) -> Result<RawMesh, MeshParseError> {
    let err = |l: &Line, msg: String| MeshParseError::at_line(FORMAT, l.number, l.start, msg);
    // Where "the file ends" errors point: the last line.
    let at_end = |msg: String| {
        let (n, s) = text::lines(bytes).last().map_or((1, 0), |l| (l.number, l.start));
        MeshParseError::at_line(FORMAT, n, s, msg)
    };
    let mut recs = records(bytes);
    let Some(first) = recs.next() else { return Err(at_end("empty file: no OFF header".into())) };
    let mut header = text::words(first.text);
    let w0 = header.next().unwrap_or_default();
    let mut counts_line = first;
    let mut counts: Vec<&[u8]> = match keyword(w0) {
        Some(Ok(())) => {
            let rest: Vec<&[u8]> = header.take(3).collect();
            if rest.first().is_some_and(|w| w.eq_ignore_ascii_case(b"BINARY")) {
                return Err(err(&first, "binary OFF is not read".into()).unsupported());
            }
            rest
        }
        Some(Err(why)) => return Err(err(&first, why.into()).unsupported()),
        // No keyword: Geomview allows the counts to come first.
        None if text::parse_u64(w0).is_some() => text::words(first.text).take(3).collect(),
        None => return Err(err(&first, format!("expected the OFF keyword, found `{}`", text::shown(w0)))),
    };
    if counts.is_empty() {
        let Some(l) = recs.next() else { return Err(at_end("the file ends before the vertex and face counts".into())) };
        counts = text::words(l.text).take(3).collect();
        counts_line = l;
    }
    let count = |i: usize| counts.get(i).and_then(|w| text::parse_u64(w)).and_then(|c| usize::try_from(c).ok());
    let (Some(nv), Some(nf)) = (count(0), count(1)) else {
        let found = counts.iter().map(|w| text::shown(w)).collect::<Vec<_>>().join(" ");
        return Err(err(&counts_line, format!("expected the vertex and face counts, found `{found}`")));
    };
    if nv > u32::MAX as usize {
        return Err(err(&counts_line, format!("{nv} vertices: more than medax reads (2^32 - 1)")));
    }

    let mut mesh = RawMesh::new(true);
    // A vertex line is at least "0 0 0\n", a face line "3 0 0 0\n".
    mesh.positions.reserve(capacity(nv, bytes.len(), 6));
    mesh.face_starts.reserve(capacity(nf, bytes.len(), 8));
    mesh.face_source.reserve(capacity(nf, bytes.len(), 8));
    mesh.indices.reserve(capacity(nf, bytes.len(), 8).saturating_mul(3));
    for i in 0..nv {
        let Some(l) = recs.next() else { return Err(at_end(format!("the file ends after {i} of {nv} vertices"))) };
        let mut ws = text::words(l.text);
        let mut p = [0.0; 3];
        for c in &mut p {
            let w = ws.next().unwrap_or_default();
            *c = text::parse_f64(w).ok_or_else(|| {
                err(&l, format!("vertex {i}: expected three coordinates, found `{}`", text::shown(l.text.trim_ascii())))
            })?;
        }
        mesh.positions.push(p);
    }
    for k in 0..nf {
        let Some(l) = recs.next() else { return Err(at_end(format!("the file ends after {k} of {nf} faces"))) };
        let mut ws = text::words(l.text);
        let w = ws.next().unwrap_or_default();
        let n = text::parse_u64(w)
            .ok_or_else(|| err(&l, format!("face {k}: expected its vertex count, found `{}`", text::shown(w))))?;
        if n < 3 {
            return Err(err(&l, format!("face {k} has {n} vertices; a face needs at least 3")));
        }
        for j in 0..n {
            let Some(w) = ws.next() else {
                return Err(err(&l, format!("face {k}: expected {n} vertex indices, found {j}")));
            };
            let index = text::parse_u64(w)
                .ok_or_else(|| err(&l, format!("face {k}: `{}` is not a vertex index", text::shown(w))))?;
            if index >= nv as u64 {
                return Err(err(
                    &l,
                    format!("face {k}: vertex index {index} is out of range (the file has {nv} vertices)"),
                ));
            }
            mesh.indices.push(index as u32);
        }
        mesh.end_face(l.number).map_err(|m| err(&l, m))?;
    }
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keywords() {
        for k in ["OFF", "COFF", "NOFF", "NCOFF", "CNOFF", "STOFF", "STCNOFF"] {
            assert_eq!(keyword(k.as_bytes()), Some(Ok(())), "{k}");
        }
        for k in ["4OFF", "C4OFF", "nOFF", "4nOFF"] {
            assert!(matches!(keyword(k.as_bytes()), Some(Err(_))), "{k}");
        }
        for k in ["OF", "off", "XOFF", "OFFX", "NCNOFF"] {
            assert_eq!(keyword(k.as_bytes()), None, "{k}");
        }
    }
}
