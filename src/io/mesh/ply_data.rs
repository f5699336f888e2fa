//! PLY's body: the elements' records in header order, as ASCII words or
//! binary little-endian values. Errors name the line (ASCII) or the byte
//! offset (binary); faces remember their line or their record number.

use super::ply::{Header, Prop, Role, Scalar};
use super::text::{self, Tokens};
use super::{capacity, MeshFormat, MeshParseError, RawMesh};

const FORMAT: MeshFormat = MeshFormat::Ply;

/// Where values come from.
enum Source<'a> {
    Ascii { tokens: Tokens<'a>, line: usize, line_start: usize },
    Binary { bytes: &'a [u8], pos: usize },
}

impl<'a> Source<'a> {
    /// An error at the current position.
    fn err(&self, msg: String) -> MeshParseError {
        match self {
            Source::Ascii { line, line_start, .. } => MeshParseError::at_line(FORMAT, *line, *line_start, msg),
            Source::Binary { pos, .. } => MeshParseError::at_byte(FORMAT, *pos, msg),
        }
    }

    /// Bytes left, for capping reservations.
    fn left(&self, all: usize) -> usize {
        match self {
            Source::Ascii { line_start, .. } => all.saturating_sub(*line_start),
            Source::Binary { pos, .. } => all.saturating_sub(*pos),
        }
    }

    /// The next ASCII word, or an error naming `what` when the file ends.
    fn word(&mut self, what: &dyn Fn() -> String) -> Result<&'a [u8], MeshParseError> {
        let Source::Ascii { tokens, line, line_start } = self else {
            return Err(self.err("internal: not ASCII".into()));
        };
        match tokens.next() {
            Some(t) => {
                (*line, *line_start) = (t.line, t.line_start);
                Ok(t.text)
            }
            None => {
                (*line, *line_start) = tokens.here();
                Err(self.err(format!("the file ends in {}", what())))
            }
        }
    }

    /// The next `n` binary bytes.
    fn take(&mut self, n: usize, what: &dyn Fn() -> String) -> Result<&'a [u8], MeshParseError> {
        let Source::Binary { bytes, pos } = self else { return Err(self.err("internal: not binary".into())) };
        let (bytes, at) = (*bytes, *pos);
        match at.checked_add(n).and_then(|end| bytes.get(at..end)) {
            Some(s) => {
                *pos = at + n;
                Ok(s)
            }
            None => Err(self.err(format!("the file ends in {}", what()))),
        }
    }

    /// A value as a float (a coordinate).
    fn float(&mut self, s: Scalar, what: &dyn Fn() -> String) -> Result<f64, MeshParseError> {
        if let Source::Ascii { .. } = self {
            let w = self.word(what)?;
            return text::parse_f64(w)
                .ok_or_else(|| self.err(format!("{}: `{}` is not a number", what(), text::shown(w))));
        }
        let b = self.take(s.size(), what)?;
        Ok(match s {
            Scalar::F32 => f64::from(f32::from_le_bytes(array(b))),
            Scalar::F64 => f64::from_le_bytes(array(b)),
            _ => binary_int(s, b) as f64,
        })
    }

    /// A value of an integer type (a count or an index).
    fn int(&mut self, s: Scalar, what: &dyn Fn() -> String) -> Result<i64, MeshParseError> {
        if let Source::Ascii { .. } = self {
            let w = self.word(what)?;
            return text::parse_i64(w)
                .ok_or_else(|| self.err(format!("{}: `{}` is not an integer", what(), text::shown(w))));
        }
        let b = self.take(s.size(), what)?;
        Ok(binary_int(s, b))
    }

    /// Skips a property's value or list.
    fn skip(&mut self, p: Prop, what: &dyn Fn() -> String) -> Result<(), MeshParseError> {
        let (n, item) = match p {
            Prop::Scalar(s) => (1, s),
            Prop::List { count, item } => {
                let n = self.int(count, what)?;
                let n = u64::try_from(n).map_err(|_| self.err(format!("{}: list length {n}", what())))?;
                (n, item)
            }
        };
        match self {
            Source::Ascii { .. } => {
                for _ in 0..n {
                    self.word(what)?;
                }
            }
            Source::Binary { .. } => {
                let len = usize::try_from(n).ok().and_then(|n| n.checked_mul(item.size()));
                self.take(len.unwrap_or(usize::MAX), what)?;
            }
        }
        Ok(())
    }
}

/// A slice of the right length as an array; `take` gave it that length.
fn array<const N: usize>(b: &[u8]) -> [u8; N] {
    let mut a = [0; N];
    a.iter_mut().zip(b).for_each(|(d, s)| *d = *s);
    a
}

/// A binary integer of type `s` (floats truncated; the header only lets
/// integer types reach this for counts and indices).
fn binary_int(s: Scalar, b: &[u8]) -> i64 {
    match s {
        Scalar::I8 => i64::from(i8::from_le_bytes(array(b))),
        Scalar::U8 => i64::from(u8::from_le_bytes(array(b))),
        Scalar::I16 => i64::from(i16::from_le_bytes(array(b))),
        Scalar::U16 => i64::from(u16::from_le_bytes(array(b))),
        Scalar::I32 => i64::from(i32::from_le_bytes(array(b))),
        Scalar::U32 => i64::from(u32::from_le_bytes(array(b))),
        Scalar::F32 => f32::from_le_bytes(array(b)) as i64,
        Scalar::F64 => f64::from_le_bytes(array(b)) as i64,
    }
}

/// The fewest bytes (binary) or words (ASCII, each at least two bytes with
/// its separator) a record of these properties can take.
fn min_record(props: &[Prop], binary: bool) -> usize {
    props
        .iter()
        .map(|p| match (p, binary) {
            (Prop::Scalar(s), true) | (Prop::List { count: s, .. }, true) => s.size(),
            (_, false) => 2,
        })
        .sum()
}

/// Reads the body of a PLY file whose header (with roles) is `header`.
pub(super) fn read_body(bytes: &[u8], header: &Header) -> Result<RawMesh, MeshParseError> {
    let mut src = if header.binary {
        Source::Binary { bytes, pos: header.data_start }
    } else {
        let tokens = Tokens::new(bytes, header.data_start, header.data_line, header.data_start);
        Source::Ascii { tokens, line: header.data_line, line_start: header.data_start }
    };
    let nv = header.elements.iter().find(|e| matches!(e.role, Role::Vertex(_))).map_or(0, |e| e.count);
    if nv > u32::MAX as usize {
        return Err(src.err(format!("{nv} vertices: more than medax reads (2^32 - 1)")));
    }
    let mut mesh = RawMesh::new(!header.binary);
    for el in &header.elements {
        // Records without properties take no bytes: nothing to read, and a
        // huge count must not become a long loop.
        if el.props.is_empty() {
            continue;
        }
        let cap = capacity(el.count, src.left(bytes.len()), min_record(&el.props, header.binary));
        match el.role {
            Role::Vertex(xyz) => {
                mesh.positions.reserve(cap);
                for i in 0..el.count {
                    let what = || format!("vertex {i}");
                    let mut p = [0.0; 3];
                    for (j, &prop) in el.props.iter().enumerate() {
                        match (xyz.iter().position(|&a| a == j), prop) {
                            (Some(axis), Prop::Scalar(s)) => p[axis] = src.float(s, &what)?,
                            _ => src.skip(prop, &what)?,
                        }
                    }
                    mesh.positions.push(p);
                }
            }
            Role::Face(list) => {
                mesh.face_starts.reserve(cap);
                mesh.face_source.reserve(cap);
                for k in 0..el.count {
                    let what = || format!("face {k}");
                    let mut source = k;
                    for (j, &prop) in el.props.iter().enumerate() {
                        let Prop::List { count, item } = prop else {
                            src.skip(prop, &what)?;
                            continue;
                        };
                        if j != list {
                            src.skip(prop, &what)?;
                            continue;
                        }
                        let n = src.int(count, &what)?;
                        if let Source::Ascii { line, .. } = src {
                            source = line;
                        }
                        if n < 3 {
                            return Err(src.err(format!("face {k} has {n} vertices; a face needs at least 3")));
                        }
                        for _ in 0..n {
                            let index = src.int(item, &what)?;
                            if !(0..nv as i64).contains(&index) {
                                return Err(src.err(format!(
                                    "face {k}: vertex index {index} is out of range (the file has {nv} vertices)"
                                )));
                            }
                            mesh.indices.push(index as u32);
                        }
                    }
                    mesh.end_face(source).map_err(|m| src.err(m))?;
                }
            }
            Role::Other => {
                for r in 0..el.count {
                    let what = || format!("element `{}` record {r}", el.name);
                    for &prop in &el.props {
                        src.skip(prop, &what)?;
                    }
                }
            }
        }
    }
    Ok(mesh)
}
