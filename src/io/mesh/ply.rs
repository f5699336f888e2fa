//! PLY: the header (this file) and the body ([`super::ply_data`]).
//!
//! The header lists elements, each a count and properties: scalars of the
//! eight PLY types (under their old and their sized names) and lists.
//! `vertex` must have `x`, `y` and `z`; `face` must have the list
//! `vertex_indices` (or the older `vertex_index`). Every other property and
//! element is skipped, which needs only its types, so any PLY of ASCII or
//! binary little-endian data reads, with or without normals, colours,
//! edges or materials.

use super::text::{self, Line};
use super::{MeshFormat, MeshParseError, RawMesh};

const FORMAT: MeshFormat = MeshFormat::Ply;

/// A PLY scalar type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(word: &[u8]) -> Option<Scalar> {
        Some(match word {
            b"char" | b"int8" => Scalar::I8,
            b"uchar" | b"uint8" => Scalar::U8,
            b"short" | b"int16" => Scalar::I16,
            b"ushort" | b"uint16" => Scalar::U16,
            b"int" | b"int32" => Scalar::I32,
            b"uint" | b"uint32" => Scalar::U32,
            b"float" | b"float32" => Scalar::F32,
            b"double" | b"float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Its size in binary data.
    pub fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    fn is_int(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }
}

/// A property's type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Prop {
    /// One value.
    Scalar(Scalar),
    /// A count, then that many items.
    List { count: Scalar, item: Scalar },
}

/// What the reader does with an element.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Role {
    /// Positions: the indices of the `x`, `y`, `z` properties.
    Vertex([usize; 3]),
    /// Faces: the index of the vertex index list.
    Face(usize),
    /// Skipped.
    Other,
}

/// An element of the header.
#[derive(Debug, Clone)]
pub(super) struct Element {
    pub name: String,
    pub count: usize,
    pub props: Vec<Prop>,
    names: Vec<Vec<u8>>,
    pub role: Role,
    line: usize,
    line_start: usize,
}

/// What the header says.
#[derive(Debug, Clone)]
pub(super) struct Header {
    pub binary: bool,
    pub elements: Vec<Element>,
    /// The byte after `end_header`'s line break, and that line's number.
    pub data_start: usize,
    pub data_line: usize,
}

fn err(l: &Line, msg: String) -> MeshParseError {
    MeshParseError::at_line(FORMAT, l.number, l.start, msg)
}

fn scalar(l: &Line, word: Option<&[u8]>) -> Result<Scalar, MeshParseError> {
    let w = word.unwrap_or_default();
    Scalar::parse(w).ok_or_else(|| err(l, format!("`{}` is not a PLY type", text::shown(w))))
}

/// Reads the header, up to and including `end_header`.
fn read_header(bytes: &[u8]) -> Result<Header, MeshParseError> {
    let mut lines = text::lines(bytes);
    let first = lines.next();
    if first.is_none_or(|l| l.text.trim_ascii() != b"ply") {
        return Err(MeshParseError::at_line(FORMAT, 1, 0, "the first line is not `ply`"));
    }
    let mut binary = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut last = first;
    for l in lines {
        last = Some(l);
        let mut ws = text::words(l.text);
        let Some(keyword) = ws.next() else { continue };
        match keyword {
            b"format" => {
                let f = ws.next().unwrap_or_default();
                binary = Some(match f {
                    b"ascii" => false,
                    b"binary_little_endian" => true,
                    b"binary_big_endian" => {
                        return Err(err(&l, "binary big-endian PLY is not read".into()).unsupported());
                    }
                    _ => return Err(err(&l, format!("unknown PLY format `{}`", text::shown(f)))),
                });
            }
            b"comment" | b"obj_info" => {}
            b"element" => {
                let (Some(name), Some(count)) = (ws.next(), ws.next()) else {
                    return Err(err(&l, "expected `element <name> <count>`".into()));
                };
                let count = text::parse_u64(count).and_then(|c| usize::try_from(c).ok()).ok_or_else(|| {
                    err(&l, format!("element `{}`: `{}` is not a count", text::shown(name), text::shown(count)))
                })?;
                let name = String::from_utf8_lossy(name).into_owned();
                elements.push(Element {
                    name,
                    count,
                    props: Vec::new(),
                    names: Vec::new(),
                    role: Role::Other,
                    line: l.number,
                    line_start: l.start,
                });
            }
            b"property" => {
                let Some(el) = elements.last_mut() else {
                    return Err(err(&l, "a property before any element".into()));
                };
                let t = ws.next();
                let prop = if t == Some(b"list") {
                    let (count, item) = (scalar(&l, ws.next())?, scalar(&l, ws.next())?);
                    if !count.is_int() {
                        return Err(err(&l, "a list count must have an integer type".into()));
                    }
                    Prop::List { count, item }
                } else {
                    Prop::Scalar(scalar(&l, t)?)
                };
                let Some(name) = ws.next() else { return Err(err(&l, "the property has no name".into())) };
                el.props.push(prop);
                el.names.push(name.to_vec());
            }
            b"end_header" => {
                let Some(binary) = binary else { return Err(err(&l, "the header has no `format` line".into())) };
                let data_start =
                    bytes[l.start..].iter().position(|&b| b == b'\n').map_or(bytes.len(), |i| l.start + i + 1);
                return Ok(Header { binary, elements, data_start, data_line: l.number + 1 });
            }
            _ => return Err(err(&l, format!("unknown header line `{}`", text::shown(keyword)))),
        }
    }
    let (n, s) = last.map_or((1, 0), |l| (l.number, l.start));
    Err(MeshParseError::at_line(FORMAT, n, s, "the file ends before `end_header`"))
}

/// Gives each element its role and checks that the header describes a mesh.
fn assign_roles(header: &mut Header) -> Result<(), MeshParseError> {
    let mut seen = [false; 2];
    for el in &mut header.elements {
        let err = |msg: String| MeshParseError::at_line(FORMAT, el.line, el.line_start, msg);
        let find = |name: &[u8]| el.names.iter().position(|n| n == name);
        match el.name.as_str() {
            "vertex" => {
                if std::mem::replace(&mut seen[0], true) {
                    return Err(err("a second `vertex` element".into()));
                }
                let mut xyz = [0; 3];
                for (slot, axis) in xyz.iter_mut().zip(["x", "y", "z"]) {
                    let i = find(axis.as_bytes())
                        .ok_or_else(|| err(format!("the vertex element has no `{axis}` property")))?;
                    if !matches!(el.props[i], Prop::Scalar(_)) {
                        return Err(err(format!("the vertex property `{axis}` is a list")));
                    }
                    *slot = i;
                }
                el.role = Role::Vertex(xyz);
            }
            "face" => {
                if std::mem::replace(&mut seen[1], true) {
                    return Err(err("a second `face` element".into()));
                }
                let i = find(b"vertex_indices")
                    .or_else(|| find(b"vertex_index"))
                    .ok_or_else(|| err("the face element has no `vertex_indices` property".into()))?;
                match el.props[i] {
                    Prop::List { item, .. } if item.is_int() => el.role = Role::Face(i),
                    Prop::List { .. } => return Err(err("vertex indices must have an integer type".into())),
                    Prop::Scalar(_) => return Err(err("the face property `vertex_indices` is no list".into())),
                }
            }
            "tristrips" if el.count > 0 => {
                return Err(err("triangle strips (`tristrips`) are not read".into()).unsupported());
            }
            _ => {}
        }
    }
    if !seen[0] {
        return Err(MeshParseError::at_line(FORMAT, 1, 0, "the header has no `vertex` element"));
    }
    Ok(())
}

/// Reads a PLY file.
pub(super) fn read(bytes: &[u8]) -> Result<RawMesh, MeshParseError> {
    let mut header = read_header(bytes)?;
    assign_roles(&mut header)?;
    super::ply_data::read_body(bytes, &header)
}
