//! The thread-local last error: set by every failing call, read by the
//! caller on the same thread.

use super::status::mx_status;
use crate::shape::{BallError, ShapeError};
use std::cell::RefCell;
use std::ffi::{c_char, CString};

/// Structured details of the last error on this thread. Indices are −1 when
/// they do not apply. Loop and element indices are the caller's input indices.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_error_info {
    /// The status of the failing call (`MX_OK` when no error is recorded).
    pub status: mx_status,
    /// The loop at fault, or −1.
    pub loop_index: i64,
    /// The element at fault within `loop_index`, or −1.
    pub element: i64,
    /// The second loop, for intersections and nested holes, or −1.
    pub other_loop_index: i64,
    /// The second element, for intersections, or −1.
    pub other_element: i64,
    /// 1 when `x`, `y` hold a position, else 0.
    pub has_position: i32,
    /// Where, model units.
    pub x: f64,
    /// Where, model units.
    pub y: f64,
    /// Line in the input file for parse errors (0: `column` is a byte offset), else −1.
    pub line: i64,
    /// Column (or byte offset) in the input for parse errors, else −1.
    pub column: i64,
}

impl mx_error_info {
    pub(crate) fn none(status: mx_status) -> mx_error_info {
        mx_error_info {
            status,
            loop_index: -1,
            element: -1,
            other_loop_index: -1,
            other_element: -1,
            has_position: 0,
            x: 0.0,
            y: 0.0,
            line: -1,
            column: -1,
        }
    }
}

/// An error on its way to C.
#[derive(Debug, Clone)]
pub(crate) struct FfiError {
    pub info: mx_error_info,
    pub message: String,
}

impl FfiError {
    pub fn new(status: mx_status, message: impl Into<String>) -> FfiError {
        FfiError { info: mx_error_info::none(status), message: message.into() }
    }
}

impl From<BallError> for FfiError {
    fn from(e: BallError) -> FfiError {
        let status = match e {
            BallError::Parse(_) => mx_status::MX_ERR_PARSE,
            BallError::InvalidArgument { .. } => mx_status::MX_ERR_INVALID_ARGUMENT,
            _ => mx_status::MX_ERR_INVALID_BALL,
        };
        let mut info = mx_error_info::none(status);
        if let BallError::Parse(p) = &e {
            info.line = p.line as i64;
            info.column = p.column as i64;
        }
        let vertex = e.vertex().map_or(-1, |v| v as i64);
        info.element = vertex;
        FfiError { info, message: e.to_string() }
    }
}

impl From<ShapeError> for FfiError {
    fn from(e: ShapeError) -> FfiError {
        let mut info = mx_error_info::none(mx_status::of(&e));
        let i = |v: usize| v as i64;
        let pos = |p: crate::kernel::Point, info: &mut mx_error_info| {
            info.has_position = 1;
            info.x = p.x;
            info.y = p.y;
        };
        match &e {
            ShapeError::Parse(p) => {
                info.line = i(p.line);
                info.column = i(p.column);
            }
            ShapeError::TooFewElements { loop_index, .. } => info.loop_index = i(*loop_index),
            ShapeError::NonFinite { at }
            | ShapeError::OutOfRange { at, .. }
            | ShapeError::InconsistentArc { at, .. } => {
                info.loop_index = i(at.loop_index);
                info.element = i(at.element);
            }
            ShapeError::NotClosed { at, position, .. } | ShapeError::Degenerate { at, position, .. } => {
                info.loop_index = i(at.loop_index);
                info.element = i(at.element);
                pos(*position, &mut info);
            }
            ShapeError::Intersection { first, second, position } => {
                info.loop_index = i(first.loop_index);
                info.element = i(first.element);
                info.other_loop_index = i(second.loop_index);
                info.other_element = i(second.element);
                pos(*position, &mut info);
            }
            ShapeError::HoleOutside { hole, position } => {
                info.loop_index = i(*hole);
                pos(*position, &mut info);
            }
            ShapeError::HoleInsideHole { hole, container, position } => {
                info.loop_index = i(*hole);
                info.other_loop_index = i(*container);
                pos(*position, &mut info);
            }
            ShapeError::Io { .. }
            | ShapeError::Empty
            | ShapeError::NoProfile { .. }
            | ShapeError::Unsupported { .. }
            | ShapeError::InvalidArgument { .. } => {}
        }
        FfiError { info, message: e.to_string() }
    }
}

thread_local! {
    static LAST: RefCell<Option<(mx_error_info, CString)>> = const { RefCell::new(None) };
}

pub(crate) fn set_last_error(e: FfiError) {
    // Interior NULs cannot cross into C; replace them rather than lose the text.
    let msg = CString::new(e.message.replace('\0', " ")).unwrap_or_default();
    LAST.with(|l| *l.borrow_mut() = Some((e.info, msg)));
}

/// Length in bytes of the last error message on this thread, including the
/// terminating NUL; 0 when no error is recorded.
#[no_mangle]
pub extern "C" fn mx_last_error_length() -> usize {
    LAST.with(|l| l.borrow().as_ref().map_or(0, |(_, m)| m.as_bytes_with_nul().len()))
}

/// Copies the last error message of this thread into `buf` (at most
/// `buf_len` bytes, always NUL-terminated when `buf_len > 0`, truncated if
/// needed) and returns the full length including the NUL, so a caller can
/// pass `NULL, 0` first to learn the size. Returns 0 when no error is recorded.
///
/// # Safety
/// `buf` must be NULL or point to `buf_len` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_last_error_message(buf: *mut c_char, buf_len: usize) -> usize {
    LAST.with(|l| {
        let guard = l.borrow();
        let Some((_, msg)) = guard.as_ref() else { return 0 };
        let bytes = msg.as_bytes_with_nul();
        if !buf.is_null() && buf_len > 0 {
            let n = (bytes.len() - 1).min(buf_len - 1);
            // SAFETY: the caller guarantees `buf` has `buf_len` bytes; we
            // write n + 1 <= buf_len of them.
            unsafe {
                std::ptr::copy_nonoverlapping(bytes.as_ptr().cast::<c_char>(), buf, n);
                *buf.add(n) = 0;
            }
        }
        bytes.len()
    })
}

/// Writes the structured details of the last error on this thread to `out`
/// (status `MX_OK` and all indices −1 when none is recorded).
///
/// # Safety
/// `out` must be NULL or point to a writable `mx_error_info`.
#[no_mangle]
pub unsafe extern "C" fn mx_last_error_info(out: *mut mx_error_info) -> mx_status {
    if out.is_null() {
        return mx_status::MX_ERR_NULL_ARGUMENT;
    }
    let info = LAST.with(|l| l.borrow().as_ref().map_or(mx_error_info::none(mx_status::MX_OK), |(i, _)| *i));
    // SAFETY: checked non-NULL; the caller guarantees it is writable.
    unsafe { out.write(info) };
    mx_status::MX_OK
}

/// Forgets the last error on this thread.
#[no_mangle]
pub extern "C" fn mx_clear_last_error() {
    LAST.with(|l| *l.borrow_mut() = None);
}
