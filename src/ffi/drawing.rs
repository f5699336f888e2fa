//! `mx_drawing`: the shapes of a DXF or SVG drawing (its closed profiles,
//! grouped by containment) and what was left out of them.

use super::boundary::{c_str, guard, in_pool, nth};
use super::handles::{arg, create, free, query, Handle};
use super::last_error::FfiError;
use super::shape2d::{format_of, mx_shape2d, mx_shape_options, options};
use super::status::mx_status;
use crate::shape::{Drawing2d, DrawingOptions, IgnoredKind};
use std::ffi::{c_char, CString};

/// A drawing read through profile extraction: its shapes (largest first)
/// and the things of it in no shape. Immutable; may be shared between
/// threads.
pub struct mx_drawing {
    inner: Drawing2d,
    /// Each ignored thing's layer and reason, NUL-terminated, lent to C.
    texts: Vec<(CString, CString)>,
}

impl Handle for mx_drawing {
    const ARG: &'static str = "drawing";
    type Ownership = super::handles::Boxed;
}

/// `mx_ignored.kind`: curves that close no loop.
pub const MX_IGNORED_OPEN_CHAIN: u32 = 1;
/// `mx_ignored.kind`: an entity that is not a curve medax reads.
pub const MX_IGNORED_ENTITY: u32 = 2;
/// `mx_ignored.kind`: the curves of a layer left out by the selection.
pub const MX_IGNORED_OTHER_LAYER: u32 = 3;
/// `mx_ignored.kind`: a loop enclosing no area in sum.
pub const MX_IGNORED_FLAT_LOOP: u32 = 4;
/// `mx_ignored.kind`: a copy of a loop drawn twice.
pub const MX_IGNORED_DUPLICATE_LOOP: u32 = 5;
/// `mx_ignored.kind`: a hole touching or crossing another loop of its shape.
pub const MX_IGNORED_TOUCHING_LOOP: u32 = 6;
/// `mx_ignored.kind`: an outer loop with its holes that does not validate.
pub const MX_IGNORED_INVALID_SHAPE: u32 = 7;

/// One thing of a drawing in no shape.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_ignored {
    /// What it is: an `MX_IGNORED_*` constant.
    pub kind: u32,
    /// 1-based line (DXF) or byte offset (SVG) of its first entity.
    pub source: usize,
    /// A point of it, model units.
    pub x: f64,
    /// A point of it, model units.
    pub y: f64,
    /// Its layer, NUL-terminated ("" without layers); valid as long as
    /// the drawing.
    pub layer: *const c_char,
    /// Why it was left out, NUL-terminated; valid as long as the drawing.
    pub reason: *const c_char,
}

fn kind_code(k: IgnoredKind) -> u32 {
    match k {
        IgnoredKind::OpenChain => MX_IGNORED_OPEN_CHAIN,
        IgnoredKind::Entity => MX_IGNORED_ENTITY,
        IgnoredKind::OtherLayer => MX_IGNORED_OTHER_LAYER,
        IgnoredKind::FlatLoop => MX_IGNORED_FLAT_LOOP,
        IgnoredKind::DuplicateLoop => MX_IGNORED_DUPLICATE_LOOP,
        IgnoredKind::TouchingLoop => MX_IGNORED_TOUCHING_LOOP,
        IgnoredKind::InvalidShape => MX_IGNORED_INVALID_SHAPE,
    }
}

/// A C string of `s`, interior NULs replaced (they cannot cross into C).
fn c_string(s: &str) -> CString {
    CString::new(s.replace('\0', " ")).unwrap_or_default()
}

/// Reads a drawing file (DXF or SVG through profile extraction; a medax
/// JSON file is one shape; `MX_FORMAT_AUTO` picks by extension, then
/// content) with the curves of the `layer_count` layers named in `layers`
/// (`layer_count` 0: every layer; `layers` may then be NULL). A drawing
/// without a closed profile is not an error: it has no shapes, and its
/// ignored things say why.
///
/// # Safety
/// `path` NULL or NUL-terminated; `options` NULL or valid; `layers` valid
/// for `layer_count` NUL-terminated strings; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_from_file(
    path: *const c_char,
    format: u32,
    options: *const mx_shape_options,
    layers: *const *const c_char,
    layer_count: usize,
    out: *mut *mut mx_drawing,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (path, (opts, threads)) = (c_str(path, "path")?, self::options(options)?);
            let format = format_of(format)?;
            let mut select = DrawingOptions::default();
            if layer_count > 0 {
                if layers.is_null() {
                    return Err(FfiError::new(
                        mx_status::MX_ERR_NULL_ARGUMENT,
                        format!("argument `layers` is NULL but `layer_count` is {layer_count}"),
                    ));
                }
                for k in 0..layer_count {
                    select.layers.push(c_str(*layers.add(k), "layers[k]")?.to_string());
                }
            }
            let inner = in_pool(threads, || -> Result<Drawing2d, FfiError> {
                Ok(match format {
                    None => Drawing2d::from_file(path, &opts, &select)?,
                    Some(f) => {
                        let bytes = std::fs::read(path).map_err(|e| {
                            FfiError::from(crate::shape::ShapeError::Io { path: path.into(), message: e.to_string() })
                        })?;
                        Drawing2d::from_str_as(&String::from_utf8_lossy(&bytes), f, &opts, &select)?
                    }
                })
            })??;
            let texts = inner.ignored.iter().map(|i| (c_string(&i.layer), c_string(&i.reason))).collect();
            Ok(mx_drawing { inner, texts })
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

/// Number of things of the drawing in no shape.
///
/// # Safety
/// `drawing` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_ignored_count(drawing: *const mx_drawing, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(drawing, out, |d| Ok(d.inner.ignored.len())) }
}

/// Ignored thing `index`, in the order found; its strings live as long as
/// the drawing.
///
/// # Safety
/// `drawing` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_get_ignored(
    drawing: *const mx_drawing,
    index: usize,
    out: *mut mx_ignored,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(drawing, out, |d| {
            let i = nth(&d.inner.ignored, index, "ignored thing")?;
            let (layer, reason) = &d.texts[index];
            Ok(mx_ignored {
                kind: kind_code(i.kind),
                source: i.source,
                x: i.position.x,
                y: i.position.y,
                layer: layer.as_ptr(),
                reason: reason.as_ptr(),
            })
        })
    }
}

/// Writes the drawing as JSON (`{"units", "shapes", "ignored", "gaps"}`,
/// each shape in medax shape JSON) to `path`.
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
