//! Status codes returned by every fallible C function.

use crate::shape::ShapeError;
use std::ffi::c_char;

/// Result of a medax C call. Values are stable across releases; new codes
/// may be added. `MX_OK` is 0; every other value is an error and the
/// thread-local last error (see `mx_last_error_message`) says more.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum mx_status {
    /// Success; out-parameters were written.
    MX_OK = 0,
    /// A required pointer argument was NULL.
    MX_ERR_NULL_ARGUMENT = 1,
    /// An argument is invalid (bad option value, sizes that do not match,
    /// unknown enum value, invalid UTF-8 in a path).
    MX_ERR_INVALID_ARGUMENT = 2,
    /// The caller's buffer is too small; query the size first.
    MX_ERR_BUFFER_TOO_SMALL = 3,
    /// A file could not be read or written.
    MX_ERR_IO = 4,
    /// A file or string could not be parsed (position in the message).
    MX_ERR_PARSE = 5,
    /// The input uses a feature medax does not support (Bézier, ellipse).
    MX_ERR_UNSUPPORTED = 6,
    /// An index (loop, element, vertex) is out of range.
    MX_ERR_INDEX_OUT_OF_RANGE = 7,
    /// A progress callback asked to stop; nothing was computed or written.
    MX_ERR_CANCELLED = 8,
    /// A computation broke down numerically (the message and position in
    /// `mx_error_info` say where). Please report it with the input.
    MX_ERR_NUMERICAL = 9,
    /// The input has no loop.
    MX_ERR_EMPTY = 10,
    /// A loop has too few elements to be closed (needs 2 arcs or 3 segments).
    MX_ERR_TOO_FEW_ELEMENTS = 11,
    /// A coordinate or bulge is NaN or infinite.
    MX_ERR_NON_FINITE = 12,
    /// A coordinate is outside ±1e9.
    MX_ERR_OUT_OF_RANGE = 13,
    /// Elements do not chain into a closed loop.
    MX_ERR_NOT_CLOSED = 14,
    /// A zero-length element, a cusp, or a loop without area.
    MX_ERR_DEGENERATE = 15,
    /// Two elements cross or touch.
    MX_ERR_INTERSECTION = 16,
    /// A hole is not inside the outer loop.
    MX_ERR_HOLE_OUTSIDE = 17,
    /// A hole lies inside another hole.
    MX_ERR_HOLE_INSIDE_HOLE = 18,
    /// An arc's end points are not equidistant from its centre.
    MX_ERR_INCONSISTENT_ARC = 19,
    /// The polygon given is not a unit ball (too few vertices, not convex,
    /// the origin not strictly inside…); `mx_last_error_info`'s `element`
    /// names the vertex.
    MX_ERR_INVALID_BALL = 20,
    /// A solid's surface is not a closed 2-manifold that can be oriented:
    /// an edge with more than two faces, faces pinched at a vertex, or no
    /// consistent orientation; `mx_last_error_info` names the face
    /// (`element`) or the vertex (`other_element`).
    MX_ERR_NOT_MANIFOLD = 21,
    /// A bug in medax: a panic was caught at the C boundary. Please report it
    /// with the input that caused it.
    MX_ERR_PANIC = 99,
}

impl mx_status {
    /// The status for a shape error.
    pub fn of(e: &ShapeError) -> mx_status {
        use mx_status::*;
        match e {
            ShapeError::Parse(p) if p.unsupported => MX_ERR_UNSUPPORTED,
            ShapeError::Parse(_) => MX_ERR_PARSE,
            ShapeError::Io { .. } => MX_ERR_IO,
            ShapeError::Empty | ShapeError::NoProfile { .. } => MX_ERR_EMPTY,
            ShapeError::TooFewElements { .. } => MX_ERR_TOO_FEW_ELEMENTS,
            ShapeError::NonFinite { .. } => MX_ERR_NON_FINITE,
            ShapeError::OutOfRange { .. } => MX_ERR_OUT_OF_RANGE,
            ShapeError::NotClosed { .. } => MX_ERR_NOT_CLOSED,
            ShapeError::Degenerate { .. } => MX_ERR_DEGENERATE,
            ShapeError::Intersection { .. } => MX_ERR_INTERSECTION,
            ShapeError::InconsistentArc { .. } => MX_ERR_INCONSISTENT_ARC,
            ShapeError::HoleOutside { .. } => MX_ERR_HOLE_OUTSIDE,
            ShapeError::HoleInsideHole { .. } => MX_ERR_HOLE_INSIDE_HOLE,
            ShapeError::Unsupported { .. } => MX_ERR_UNSUPPORTED,
            ShapeError::InvalidArgument { .. } => MX_ERR_INVALID_ARGUMENT,
        }
    }

    /// Every status, for `mx_status_str`; `text` matches every variant
    /// exhaustively, and `tests/header.rs` checks this list against the
    /// header's enum, so a new status cannot be left without a string.
    pub(crate) const ALL: [mx_status; 23] = {
        use mx_status::*;
        [
            MX_OK,
            MX_ERR_NULL_ARGUMENT,
            MX_ERR_INVALID_ARGUMENT,
            MX_ERR_BUFFER_TOO_SMALL,
            MX_ERR_IO,
            MX_ERR_PARSE,
            MX_ERR_UNSUPPORTED,
            MX_ERR_INDEX_OUT_OF_RANGE,
            MX_ERR_CANCELLED,
            MX_ERR_NUMERICAL,
            MX_ERR_EMPTY,
            MX_ERR_TOO_FEW_ELEMENTS,
            MX_ERR_NON_FINITE,
            MX_ERR_OUT_OF_RANGE,
            MX_ERR_NOT_CLOSED,
            MX_ERR_DEGENERATE,
            MX_ERR_INTERSECTION,
            MX_ERR_HOLE_OUTSIDE,
            MX_ERR_HOLE_INSIDE_HOLE,
            MX_ERR_INCONSISTENT_ARC,
            MX_ERR_INVALID_BALL,
            MX_ERR_NOT_MANIFOLD,
            MX_ERR_PANIC,
        ]
    };

    fn text(self) -> &'static std::ffi::CStr {
        use mx_status::*;
        match self {
            MX_OK => c"ok",
            MX_ERR_NULL_ARGUMENT => c"a required pointer argument is NULL",
            MX_ERR_INVALID_ARGUMENT => c"invalid argument",
            MX_ERR_BUFFER_TOO_SMALL => c"buffer too small",
            MX_ERR_IO => c"input/output error",
            MX_ERR_PARSE => c"parse error",
            MX_ERR_UNSUPPORTED => c"unsupported input",
            MX_ERR_INDEX_OUT_OF_RANGE => c"index out of range",
            MX_ERR_CANCELLED => c"cancelled by the progress callback",
            MX_ERR_NUMERICAL => c"numerical breakdown",
            MX_ERR_EMPTY => c"the shape has no loops",
            MX_ERR_TOO_FEW_ELEMENTS => c"a loop has too few elements",
            MX_ERR_NON_FINITE => c"a number is NaN or infinite",
            MX_ERR_OUT_OF_RANGE => c"a coordinate is out of range",
            MX_ERR_NOT_CLOSED => c"the boundary is not closed",
            MX_ERR_DEGENERATE => c"degenerate element or loop",
            MX_ERR_INTERSECTION => c"elements intersect or touch",
            MX_ERR_HOLE_OUTSIDE => c"a hole is outside the outer loop",
            MX_ERR_HOLE_INSIDE_HOLE => c"a hole is inside another hole",
            MX_ERR_INCONSISTENT_ARC => c"arc end points are not on one circle",
            MX_ERR_INVALID_BALL => c"the polygon is not a unit ball",
            MX_ERR_NOT_MANIFOLD => c"the surface is not a closed orientable manifold",
            MX_ERR_PANIC => c"internal error (panic caught); please report",
        }
    }
}

/// A static, NUL-terminated English description of `status`; unknown values
/// give "unknown status". Never NULL; do not free.
#[no_mangle]
pub extern "C" fn mx_status_str(status: i32) -> *const c_char {
    mx_status::ALL.iter().find(|s| **s as i32 == status).map_or(c"unknown status".as_ptr(), |s| s.text().as_ptr())
}
