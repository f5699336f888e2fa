//! Wavefront OBJ, read with `tobj`: positions (`v`, with an optional `w`)
//! and polygon faces (`f`, with relative indices and `v/vt/vn` forms).
//! Groups, objects, materials, polylines (`l`) and points are ignored, and
//! polygons stay polygons: the shape layer triangulates.
//!
//! `tobj` gives no line numbers, splits the mesh at every `o`, `g` and
//! `usemtl`, keeps only the positions faces use (in the order they are
//! first used), and trusts texture and normal indices enough to overflow on
//! absurd ones. So what it sees is prepared: a scan of the lines (which
//! records each face's line, checks every face's indices and length, and
//! finds non-UTF-8 lines) hands it the `v`, `vt`, `vn` and `f` lines only,
//! each in its place (other lines blank), behind one made-up first face
//! `f 1 2 … n` that uses every vertex in file order. The result is one model
//! whose positions are the file's, all of them, in its order; the made-up
//! face is then dropped.

use super::text::{self, Line};
use super::{MeshFormat, MeshParseError, RawMesh};
use std::borrow::Cow;
use std::io::Write as _;

const FORMAT: MeshFormat = MeshFormat::Obj;

/// The lines that matter: `v`, `vt`, `vn` (indexed as in the counts) and `f`.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Data(usize),
    Face,
    Other,
}

fn kind(line: &[u8]) -> Kind {
    match text::words(line).next() {
        Some(b"v") => Kind::Data(0),
        Some(b"vt") => Kind::Data(1),
        Some(b"vn") => Kind::Data(2),
        Some(b"f") => Kind::Face,
        _ => Kind::Other,
    }
}

/// Whether some line is a vertex or a face with something after the keyword.
pub(super) fn has_vertex_or_face_line(bytes: &[u8]) -> bool {
    text::lines(bytes).any(|l| {
        let mut ws = text::words(l.text);
        matches!(ws.next(), Some(b"v" | b"f")) && ws.next().is_some()
    })
}

/// A line as `tobj` gets it: a vertex with a colour (`v x y z r g b`) loses
/// the colour, since `tobj` fails a file where only some vertices have one.
fn for_tobj(s: &str) -> Cow<'_, str> {
    let words: Vec<&str> = s.split_whitespace().take(8).collect();
    if words.len() == 7 && words[0] == "v" {
        Cow::Owned(words[..4].join(" "))
    } else {
        Cow::Borrowed(s)
    }
}

/// Checks a face line (without the `f`) the way `tobj` will read it, but
/// with the indices checked against what the file has: a position index
/// must name a vertex, and texture and normal indices must name one where
/// the file has any (`tobj` ignores them where it has none). Negative
/// indices count back from the last one so far.
fn check_face(rest: std::str::SplitWhitespace, so_far: [usize; 3], totals: [usize; 3]) -> Result<(), String> {
    let mut n = 0;
    for token in rest {
        n += 1;
        for (i, part) in token.split('/').enumerate() {
            if part.is_empty() {
                if i == 0 {
                    return Err(format!("`{token}` has no vertex index"));
                }
                continue;
            }
            let what =
                ["vertex", "texture", "normal"].get(i).ok_or_else(|| format!("`{token}` has too many indices"))?;
            let x: isize = part.parse().map_err(|_| format!("`{token}`: `{part}` is not an index"))?;
            if i > 0 && totals[i] == 0 {
                continue;
            }
            let ok = match x {
                0 => false,
                x if x > 0 => x.unsigned_abs() <= totals[i],
                x => x.unsigned_abs() <= so_far[i],
            };
            if !ok {
                let have = if x < 0 { format!("{} so far", so_far[i]) } else { totals[i].to_string() };
                return Err(format!("{what} index {x} is out of range (the file has {have})"));
            }
        }
    }
    if n < 3 {
        return Err(format!("{n} vertices; a face needs at least 3"));
    }
    Ok(())
}

fn err(l: &Line, msg: String) -> MeshParseError {
    MeshParseError::at_line(FORMAT, l.number, l.start, msg)
}

fn options() -> tobj::LoadOptions {
    // The update keeps this compiling if another crate turns on tobj's
    // `merging` or `reordering`, which add fields.
    #[allow(clippy::needless_update)]
    tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: false,
        ignore_lines: false,
        ..Default::default()
    }
}

/// `tobj` with no material files (the input has no `mtllib` left anyway).
fn tobj_read(input: &[u8]) -> tobj::LoadResult {
    tobj::load_obj_buf(&mut &input[..], &options(), |_| Err(tobj::LoadError::OpenFileFailed))
}

/// Reads an OBJ file.
pub(super) fn read(bytes: &[u8]) -> Result<RawMesh, MeshParseError> {
    let mut totals = [0usize; 3];
    for l in text::lines(bytes) {
        if let Kind::Data(i) = kind(l.text) {
            totals[i] += 1;
        }
    }
    let nv = totals[0];
    let mut input = Vec::with_capacity(bytes.len() + 8 * nv + 8);
    if nv > 0 {
        input.push(b'f');
        for i in 1..=nv {
            let _ = write!(input, " {i}");
        }
    }
    input.push(b'\n');
    let mut so_far = [0usize; 3];
    let mut face_lines: Vec<(usize, usize)> = Vec::new();
    for l in text::lines(bytes) {
        let k = kind(l.text);
        if k != Kind::Other {
            let s = std::str::from_utf8(l.text).map_err(|_| err(&l, "the line is not UTF-8 text".into()))?;
            if k == Kind::Face {
                let mut rest = s.split_whitespace();
                rest.next();
                check_face(rest, so_far, totals).map_err(|m| err(&l, format!("face {}: {m}", face_lines.len())))?;
                face_lines.push((l.number, l.start));
            } else if let Kind::Data(i) = k {
                so_far[i] += 1;
            }
            input.extend_from_slice(for_tobj(s).as_bytes());
        }
        input.push(b'\n');
    }

    let (models, _) = tobj_read(&input).map_err(|e| locate(bytes, e))?;
    let internal = |msg: &str| MeshParseError::at_line(FORMAT, 1, 0, format!("internal: tobj {msg}"));
    let mut mesh = RawMesh::new(true);
    let mut made_up_face = nv > 0;
    let mut faces = face_lines.iter();
    for m in &models {
        let m = &m.mesh;
        let base = mesh.positions.len();
        mesh.positions.extend(m.positions.chunks_exact(3).map(|c| [c[0], c[1], c[2]]));
        // No arities: all triangles.
        let arities: Box<dyn Iterator<Item = usize>> = if m.face_arities.is_empty() {
            Box::new(std::iter::repeat_n(3, m.indices.len() / 3))
        } else {
            Box::new(m.face_arities.iter().map(|&a| a as usize))
        };
        let mut at = 0;
        for a in arities {
            let face = m.indices.get(at..at + a).ok_or_else(|| internal("face past its indices"))?;
            at += a;
            if std::mem::take(&mut made_up_face) {
                continue;
            }
            let &(line, start) = faces.next().ok_or_else(|| internal("returned more faces than the file has"))?;
            for &i in face {
                let i = base + i as usize;
                if a < 3 || i >= mesh.positions.len() {
                    return Err(internal("returned a bad face"));
                }
                mesh.indices.push(u32::try_from(i).map_err(|_| internal("returned over 2^32 vertices"))?);
            }
            mesh.end_face(line).map_err(|m| MeshParseError::at_line(FORMAT, line, start, m))?;
        }
    }
    if faces.next().is_some() || mesh.positions.len() != nv {
        return Err(internal("lost faces or vertices"));
    }
    Ok(mesh)
}

/// The line `tobj` failed on. Its errors without line are all about one
/// `v`, `vt` or `vn` line once the faces are checked, and a line alone
/// fails the same way, so the first line that fails alone is the one.
fn locate(bytes: &[u8], e: tobj::LoadError) -> MeshParseError {
    for l in text::lines(bytes) {
        let (Kind::Data(_), Ok(s)) = (kind(l.text), std::str::from_utf8(l.text)) else { continue };
        if let Err(e) = tobj_read(for_tobj(s).as_bytes()) {
            return err(&l, format!("{e} in `{}`", text::shown(s.trim().as_bytes())));
        }
    }
    MeshParseError::at_line(FORMAT, 1, 0, format!("tobj: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn face_checks_follow_obj_indexing() {
        let check = |s: &str, so_far, totals| check_face(s.split_whitespace(), so_far, totals);
        assert_eq!(check("1 2 3", [3, 0, 0], [3, 0, 0]), Ok(()));
        assert_eq!(check("-1 -2 -3", [3, 0, 0], [9, 0, 0]), Ok(()));
        assert!(check("-1 -2 -4", [3, 0, 0], [9, 0, 0]).is_err());
        // Forward references are fine (tobj resolves them at the end).
        assert_eq!(check("7 8 9", [3, 0, 0], [9, 0, 0]), Ok(()));
        assert!(check("1 2 10", [3, 0, 0], [9, 0, 0]).is_err());
        // Texture indices only count where the file has texture coordinates.
        assert_eq!(check("1/5 2/5 3/5", [3, 0, 0], [3, 0, 0]), Ok(()));
        assert!(check("1/5 2/5 3/5", [3, 1, 0], [3, 1, 0]).is_err());
        assert!(check(&format!("1/{} 2 3", isize::MIN), [3, 1, 1], [3, 1, 1]).is_err());
        assert!(check("1 2 99999999999999999999999", [3, 0, 0], [3, 0, 0]).is_err());
    }

    #[test]
    fn coloured_vertices_lose_their_colour() {
        assert_eq!(for_tobj("v 1 2 3 0.5 0.5 0.5"), "v 1 2 3");
        assert_eq!(for_tobj("v 1 2 3 2"), "v 1 2 3 2");
        assert_eq!(for_tobj("vn 1 2 3 4 5 6"), "vn 1 2 3 4 5 6");
    }
}
