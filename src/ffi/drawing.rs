//! `mx_drawing`: the shapes of a DXF or SVG drawing (its closed profiles,
//! grouped by containment) and what was left out of them.

use super::boundary::{c_str, guard, in_pool, nth, slice};
use super::handles::{arg, create, free, impl_options, options_default, options_init, query, Handle, Options};
use super::last_error::FfiError;
use super::shape2d::{mx_shape2d, mx_shape_options, options};
use super::shape_kinds::format_of;
use super::status::mx_status;
use crate::shape::{Drawing2d, DrawingOptions};
use std::ffi::{c_char, CString};

/// A drawing read through profile extraction: its shapes (largest first)
/// and the things of it in no shape. Immutable; may be shared between
/// threads.
pub struct mx_drawing {
    pub(super) inner: Drawing2d,
    /// Each ignored thing's layer and reason, NUL-terminated, lent to C.
    pub(super) texts: Vec<(CString, CString)>,
}

impl mx_drawing {
    fn new(inner: Drawing2d) -> mx_drawing {
        let texts = inner.ignored.iter().map(|i| (c_string(&i.layer), c_string(&i.reason))).collect();
        mx_drawing { inner, texts }
    }
}

impl Handle for mx_drawing {
    const ARG: &'static str = "drawing";
    type Ownership = super::handles::Boxed;
}

/// A C string of `s`, interior NULs replaced (they cannot cross into C).
fn c_string(s: &str) -> CString {
    CString::new(s.replace('\0', " ")).unwrap_or_default()
}

/// What to take out of a drawing. Initialise with
/// `mx_drawing_select_init(&o, sizeof o)` (which sets `struct_size` and selects
/// everything), then change fields.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_drawing_select {
    /// `sizeof(mx_drawing_select)` as the caller was compiled; lets later
    /// versions add fields without breaking old callers.
    pub struct_size: usize,
    /// Take the curves of these layers only (DXF group 8, UTF-8,
    /// NUL-terminated): `layer_count` of them; NULL when 0.
    pub layers: *const *const c_char,
    /// How many `layers` (0: every layer).
    pub layer_count: usize,
    /// Take the curves of these colours only: AutoCAD colour indices
    /// 1-255 ("by layer" and "by block" resolved; 7 where nothing says);
    /// NULL when `colour_count` is 0.
    pub colours: *const i16,
    /// How many `colours` (0: every colour).
    pub colour_count: usize,
    /// 1: keep both copies of a loop drawn twice (they then meet and are
    /// reported); 0: merge them into one, reported as
    /// `MX_IGNORED_DUPLICATE_LOOP`. (A `uint8_t` before 0.2.0; the first
    /// layout now ends at byte 44 of 48.)
    pub keep_duplicates: i32,
}

// Everything selected.
impl_options!(mx_drawing_select, v1: 44 bytes up to keep_duplicates: i32, defaults: mx_drawing_select {
    struct_size: size_of::<Self>(),
    layers: std::ptr::null(),
    layer_count: 0,
    colours: std::ptr::null(),
    colour_count: 0,
    keep_duplicates: 0,
});

/// Fills the caller's `mx_drawing_select` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_drawing_select o;
/// mx_drawing_select_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_select_init(out: *mut mx_drawing_select, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_drawing_select_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_drawing_select`.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_select_default(out: *mut mx_drawing_select) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

/// The selection `select` points to (NULL: everything).
///
/// # Safety
/// `select` NULL or valid, its arrays valid for their counts.
unsafe fn selection(select: *const mx_drawing_select) -> Result<DrawingOptions, FfiError> {
    let mut out = DrawingOptions::default();
    // SAFETY: caller contract.
    let Some(s) = (unsafe { mx_drawing_select::read(select)? }) else {
        return Ok(out);
    };
    // SAFETY: caller contract.
    for &name in unsafe { slice(s.layers, s.layer_count, "select.layers")? } {
        // SAFETY: caller contract.
        out.layers.push(unsafe { c_str(name, "select.layers[k]")? }.to_string());
    }
    // SAFETY: caller contract.
    out.colours = unsafe { slice(s.colours, s.colour_count, "select.colours")? }.to_vec();
    if let Some(c) = out.colours.iter().find(|c| !(1..=255).contains(*c)) {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("select.colours: {c} is not a colour index 1-255"),
        ));
    }
    out.keep_duplicates = s.keep_duplicates != 0;
    Ok(out)
}

/// Reads a drawing file (DXF or SVG through profile extraction; medax shape
/// JSON is one shape, drawing JSON its shapes; `MX_FORMAT_AUTO` picks by
/// extension, then content), taking what `select` selects (NULL:
/// everything). A drawing without a closed profile is not an error: it has
/// no shapes, and its ignored things say why.
///
/// # Safety
/// `path` NULL or NUL-terminated; `options` NULL or valid; `select` NULL or
/// valid; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_from_file(
    path: *const c_char,
    format: u32,
    options: *const mx_shape_options,
    select: *const mx_drawing_select,
    out: *mut *mut mx_drawing,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (path, options, select) = (c_str(path, "path")?, self::options(options)?, selection(select)?);
            let format = format_of(format)?.or_else(|| crate::io::Format::from_path(path.as_ref()));
            let bytes = std::fs::read(path).map_err(|e| {
                FfiError::from(crate::shape::ShapeError::Io { path: path.into(), message: e.to_string() })
            })?;
            read(&bytes, format, options, &select)
        })
    }
}

/// A drawing from a file's bytes: the work of both constructors, after
/// their arguments were checked.
fn read(
    bytes: &[u8],
    format: Option<crate::io::Format>,
    (opts, threads): (crate::shape::ShapeOptions, usize),
    select: &DrawingOptions,
) -> Result<mx_drawing, FfiError> {
    let inner = in_pool(threads, || Drawing2d::from_bytes(bytes, format, &opts, select))??;
    Ok(mx_drawing::new(inner))
}
/// Reads a drawing from `len` bytes in memory (a file's content: UTF-8,
/// other bytes replaced; `MX_FORMAT_AUTO` guesses from the content), as
/// `mx_drawing_from_file` does.
///
/// # Safety
/// `data` NULL (only when `len` is 0) or `len` readable bytes; `options`
/// and `select` NULL or valid; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_from_memory(
    data: *const u8,
    len: usize,
    format: u32,
    options: *const mx_shape_options,
    select: *const mx_drawing_select,
    out: *mut *mut mx_drawing,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (bytes, options, select) = (slice(data, len, "data")?, self::options(options)?, selection(select)?);
            read(bytes, format_of(format)?, options, &select)
        })
    }
}

/// Frees a drawing; NULL is fine. Shapes taken from it stay valid.
///
/// # Safety
/// `drawing` NULL or a live handle, not used afterwards.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_free(drawing: *mut mx_drawing) {
    // SAFETY: forwarded contract.
    unsafe { free(drawing) }
}

/// Number of shapes (0 when the drawing has no closed profile).
///
/// # Safety
/// `drawing` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_shape_count(drawing: *const mx_drawing, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(drawing, out, |d| Ok(d.inner.shapes.len())) }
}

/// A new handle holding shape `index` (0 = the largest); the caller frees
/// it with `mx_shape2d_free`.
///
/// # Safety
/// `drawing` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_shape(
    drawing: *const mx_drawing,
    index: usize,
    out: *mut *mut mx_shape2d,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        create(out, || {
            let d = arg(drawing)?;
            Ok(mx_shape2d { inner: nth(&d.inner.shapes, index, "shape")?.clone() })
        })
    }
}

/// Writes the drawing as JSON (`{"units", "shapes", "ignored",
/// "warnings"}`, each shape in medax shape JSON; see README) to `path`.
///
/// # Safety
/// `drawing` NULL or a live handle; `path` NULL or NUL-terminated.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_write_json(drawing: *const mx_drawing, path: *const c_char) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let (d, path) = unsafe { (arg(drawing)?, c_str(path, "path")?) };
        std::fs::write(path, d.inner.to_json())
            .map_err(|e| FfiError::new(mx_status::MX_ERR_IO, format!("cannot write {path}: {e}")))
    })
}
