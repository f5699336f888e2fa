//! Triangle and polygon mesh files as plain data: OBJ, OFF, STL and PLY.
//!
//! Readers return the mesh as the file holds it, a [`RawMesh`]: positions
//! and polygon faces with each face's source position. Nothing is welded,
//! triangulated or validated here (STL's facets keep their own three
//! vertices each; NaN coordinates pass through): the shape layer does that
//! and reports problems with the vertex or face. What a reader does promise
//! is the structure: every face has at least three vertices, every index is
//! in range, and any byte string gives `Ok` or a [`MeshParseError`] with a
//! position, never a panic, nor an allocation sized by an unchecked count.

mod obj;
mod off;
mod ply;
mod ply_data;
mod stl;
mod text;
mod write;

pub use write::{write_obj, write_off, write_ply};

use std::fmt;

/// Mesh file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// Wavefront OBJ (read with `tobj`).
    Obj,
    /// Geomview OFF, with the `C`, `N` and `ST` variants.
    Off,
    /// STL, ASCII or binary.
    Stl,
    /// PLY, ASCII or binary little-endian.
    Ply,
}

impl MeshFormat {
    /// Guesses the format from a file name's extension (case-insensitive).
    pub fn from_path(path: &std::path::Path) -> Option<MeshFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "obj" => Some(MeshFormat::Obj),
            "off" => Some(MeshFormat::Off),
            "stl" => Some(MeshFormat::Stl),
            "ply" => Some(MeshFormat::Ply),
            _ => None,
        }
    }

    /// Guesses the format from the content: a binary STL by its size
    /// (84 + 50 × its facet count), a `ply` first line, an OFF keyword as the
    /// first word after comments, a `solid` start, or OBJ `v`/`f` lines.
    ///
    /// The size test goes first because a binary STL's 80-byte header is free
    /// text that may well start with `solid`; a text file passes it only if
    /// bytes 80–84 happen to encode its own size, which needs control bytes.
    pub fn sniff(bytes: &[u8]) -> Option<MeshFormat> {
        if stl::binary_size_matches(bytes) {
            return Some(MeshFormat::Stl);
        }
        let first_line = bytes.split(|&b| b == b'\n').next().unwrap_or_default();
        if first_line.trim_ascii() == b"ply" {
            return Some(MeshFormat::Ply);
        }
        if off::starts_with_keyword(bytes) {
            return Some(MeshFormat::Off);
        }
        if stl::starts_with_solid(bytes) {
            return Some(MeshFormat::Stl);
        }
        if obj::has_vertex_or_face_line(bytes) {
            return Some(MeshFormat::Obj);
        }
        None
    }

    /// Upper-case name, as used in messages.
    pub fn name(self) -> &'static str {
        match self {
            MeshFormat::Obj => "OBJ",
            MeshFormat::Off => "OFF",
            MeshFormat::Stl => "STL",
            MeshFormat::Ply => "PLY",
        }
    }
}

/// A mesh as the file holds it: positions and polygon faces (0-based vertex
/// indices, already range-checked), with where each face came from.
#[derive(Debug, Clone, PartialEq)]
pub struct RawMesh {
    /// Vertex positions in file order (for STL, three per facet).
    pub positions: Vec<[f64; 3]>,
    /// All faces' vertex indices back to back; each is `< positions.len()`.
    pub indices: Vec<u32>,
    /// Face `i` is `indices[face_starts[i]..face_starts[i + 1]]`; one more
    /// entry than there are faces, starting at 0, never decreasing, and each
    /// face at least 3 long.
    pub face_starts: Vec<u32>,
    /// Per face: its 1-based line for text formats, or its 0-based facet or
    /// face record number for binary ones.
    pub face_source: Vec<u32>,
    /// True when `face_source` holds lines.
    pub source_is_line: bool,
}

impl Default for RawMesh {
    fn default() -> Self {
        RawMesh {
            positions: Vec::new(),
            indices: Vec::new(),
            face_starts: vec![0],
            face_source: Vec::new(),
            source_is_line: true,
        }
    }
}

impl RawMesh {
    /// The number of faces.
    pub fn face_count(&self) -> usize {
        self.face_starts.len().saturating_sub(1)
    }

    /// The vertex indices of face `i` (empty when `i` is out of range).
    pub fn face(&self, i: usize) -> &[u32] {
        let (Some(&a), Some(&b)) = (self.face_starts.get(i), self.face_starts.get(i + 1)) else { return &[] };
        self.indices.get(a as usize..b as usize).unwrap_or_default()
    }

    /// An empty mesh whose face sources are lines or record numbers.
    fn new(source_is_line: bool) -> Self {
        RawMesh { source_is_line, ..RawMesh::default() }
    }

    /// Closes the face made of the indices pushed since the last one. The
    /// caller has checked the length (≥ 3) and the indices; this only fails
    /// past 2³² indices, which `face_starts` cannot address.
    fn end_face(&mut self, source: usize) -> Result<(), String> {
        let end = u32::try_from(self.indices.len()).map_err(|_| "more than 2^32 face indices".to_string())?;
        let source = u32::try_from(source).map_err(|_| "more than 2^32 faces or lines".to_string())?;
        self.face_starts.push(end);
        self.face_source.push(source);
        Ok(())
    }
}

/// A mesh file that could not be read, with where: a 1-based line for the
/// text formats (and OBJ), otherwise line 0 and a byte offset.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshParseError {
    /// Which format was being read. When sniffing could not tell, `Obj`
    /// (with `unsupported` set): the format whose content has least to
    /// recognise it by.
    pub format: MeshFormat,
    /// 1-based line, or 0 when `offset` is the position.
    pub line: usize,
    /// Byte offset: of the line's start when `line > 0`, of the bad data
    /// otherwise.
    pub offset: usize,
    /// What was wrong, for a person.
    pub message: String,
    /// True when the input is well-formed but uses something medax does not
    /// read: big-endian PLY, binary or 4-dimensional OFF, an unknown format.
    pub unsupported: bool,
}

impl MeshParseError {
    fn at_line(format: MeshFormat, line: usize, offset: usize, message: impl Into<String>) -> Self {
        MeshParseError { format, line, offset, message: message.into(), unsupported: false }
    }

    fn at_byte(format: MeshFormat, offset: usize, message: impl Into<String>) -> Self {
        MeshParseError { format, line: 0, offset, message: message.into(), unsupported: false }
    }

    fn unsupported(mut self) -> Self {
        self.unsupported = true;
        self
    }
}

impl fmt::Display for MeshParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{} parse error at byte {}: {}", self.format.name(), self.offset, self.message)
        } else {
            write!(f, "{} parse error at line {}: {}", self.format.name(), self.line, self.message)
        }
    }
}

impl std::error::Error for MeshParseError {}

/// Reads a mesh file of the given format, or of the format [`MeshFormat::sniff`]
/// finds when `format` is `None` (an error when it finds none).
pub fn read_mesh(bytes: &[u8], format: Option<MeshFormat>) -> Result<RawMesh, MeshParseError> {
    let format = match format.or_else(|| MeshFormat::sniff(bytes)) {
        Some(f) => f,
        None => {
            return Err(MeshParseError::at_byte(MeshFormat::Obj, 0, "not a mesh file medax knows (OBJ, OFF, STL, PLY)")
                .unsupported())
        }
    };
    match format {
        MeshFormat::Obj => obj::read(bytes),
        MeshFormat::Off => off::read(bytes),
        MeshFormat::Stl => stl::read(bytes),
        MeshFormat::Ply => ply::read(bytes),
    }
}

/// At most how many records to reserve room for: the count a header
/// claims, capped by how many of the smallest possible record the
/// remaining bytes could hold, so that a lying header costs nothing.
fn capacity(count: usize, bytes_left: usize, min_record: usize) -> usize {
    count.min(bytes_left / min_record.max(1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn faces_and_capacity() {
        let m = RawMesh::default();
        assert_eq!((m.face_count(), m.face(0)), (0, &[][..]));
        let m = RawMesh {
            positions: vec![[0.0; 3]; 4],
            indices: vec![0, 1, 2, 3, 2, 1],
            face_starts: vec![0, 3, 6],
            face_source: vec![1, 2],
            source_is_line: true,
        };
        assert_eq!((m.face_count(), m.face(1), m.face(2)), (2, &[3, 2, 1][..], &[][..]));
        assert_eq!(capacity(usize::MAX, 100, 8), 12);
        assert_eq!(capacity(3, 100, 0), 3);
    }
}
