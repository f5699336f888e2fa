//! The plain C types of `mx_shape2d`'s queries: boundary elements, boxes,
//! joint kinds and the file formats the readers take.

use super::last_error::FfiError;
use super::status::mx_status;
use crate::io::mesh::MeshFormat;
use crate::io::Format;

/// The values of `mx_element.kind` (a `uint32_t`: the struct is also
/// input, where an unknown value is an error rather than undefined
/// behaviour).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_element_kind {
    /// A line segment.
    MX_ELEMENT_SEGMENT = 0,
    /// A circular arc.
    MX_ELEMENT_ARC = 1,
}
pub(crate) const SEGMENT: u32 = mx_element_kind::MX_ELEMENT_SEGMENT as u32;
pub(crate) const ARC: u32 = mx_element_kind::MX_ELEMENT_ARC as u32;

/// One boundary element. As output all fields are set. As input
/// (`mx_shape2d_from_elements`), a segment reads `x0 y0 x1 y1`; an arc reads
/// `x0 y0 x1 y1 cx cy ccw` (start, end, centre, direction; start == end is a
/// full circle) and ignores `bulge` and `radius`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct mx_element {
    /// An `mx_element_kind`: `MX_ELEMENT_SEGMENT` or `MX_ELEMENT_ARC`.
    pub kind: u32,
    /// 1 when the arc runs counter-clockwise, else 0 (0 for segments; as
    /// input any non-zero value means counter-clockwise).
    pub ccw: i32,
    /// Start point x.
    pub x0: f64,
    /// Start point y.
    pub y0: f64,
    /// End point x.
    pub x1: f64,
    /// End point y.
    pub y1: f64,
    /// Arc centre x (0 for segments).
    pub cx: f64,
    /// Arc centre y (0 for segments).
    pub cy: f64,
    /// Arc radius (0 for segments).
    pub radius: f64,
    /// tan(sweep/4), positive counter-clockwise (0 for segments).
    pub bulge: f64,
}

/// An axis-aligned box, model units.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct mx_bbox {
    /// Smallest x.
    pub xmin: f64,
    /// Smallest y.
    pub ymin: f64,
    /// Largest x.
    pub xmax: f64,
    /// Largest y.
    pub ymax: f64,
}

/// What `mx_shape2d_joint` reports of a vertex.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_joint_kind {
    /// Tangent-continuous joint.
    MX_JOINT_SMOOTH = 0,
    /// Convex corner (interior angle below 180°).
    MX_JOINT_CONVEX = 1,
    /// Reflex corner (interior angle above 180°).
    MX_JOINT_REFLEX = 2,
}

/// The values of the `format` argument of the file readers (a
/// `uint32_t`: an unknown value is an error).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_format {
    /// Guess from the file extension or content.
    MX_FORMAT_AUTO = 0,
    /// medax shape JSON.
    MX_FORMAT_JSON = 1,
    /// ASCII DXF.
    MX_FORMAT_DXF = 2,
    /// SVG document or path data.
    MX_FORMAT_SVG = 3,
    /// Wavefront OBJ (solids).
    MX_FORMAT_OBJ = 4,
    /// OFF, Object File Format (solids).
    MX_FORMAT_OFF = 5,
    /// STL, ASCII or binary (solids).
    MX_FORMAT_STL = 6,
    /// PLY, ASCII or binary little-endian (solids).
    MX_FORMAT_PLY = 7,
}

/// The format a reader's `format` argument names; `None` guesses.
pub(crate) fn format_of(code: u32) -> Result<Option<Format>, FfiError> {
    match code {
        c if c == mx_format::MX_FORMAT_AUTO as u32 => Ok(None),
        c if c == mx_format::MX_FORMAT_JSON as u32 => Ok(Some(Format::Json)),
        c if c == mx_format::MX_FORMAT_DXF as u32 => Ok(Some(Format::Dxf)),
        c if c == mx_format::MX_FORMAT_SVG as u32 => Ok(Some(Format::Svg)),
        4..=7 => Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("format {code} is a solid's (OBJ, OFF, STL, PLY): read it with mx_mesh3d_from_file"),
        )),
        other => Err(FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("unknown format {other}"))),
    }
}

/// The solid format a reader's `format` argument names; `None` guesses.
pub(crate) fn mesh_format_of(code: u32) -> Result<Option<MeshFormat>, FfiError> {
    match code {
        0 => Ok(None),
        4 => Ok(Some(MeshFormat::Obj)),
        5 => Ok(Some(MeshFormat::Off)),
        6 => Ok(Some(MeshFormat::Stl)),
        7 => Ok(Some(MeshFormat::Ply)),
        1..=3 => Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("format {code} is a 2D shape's (JSON, DXF, SVG): read it with mx_shape2d_from_file"),
        )),
        other => Err(FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("unknown format {other}"))),
    }
}
