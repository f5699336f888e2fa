//! What an `mx_drawing` reports besides its shapes: the things left out
//! (`mx_ignored`) and the warnings (`mx_warning`: gaps closed, shapes that
//! touch), each naming the entities at fault by line and DXF handle.

use super::boundary::{index_error, nth};
use super::drawing::mx_drawing;
use super::handles::query;
use super::status::mx_status;
use crate::shape::IgnoredKind;
use std::ffi::c_char;

/// `mx_ignored.kind`: why something of a drawing is in no shape.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_ignored_kind {
    /// Curves that close no loop.
    MX_IGNORED_OPEN_CHAIN = 1,
    /// An entity that is not a curve medax reads.
    MX_IGNORED_ENTITY = 2,
    /// The curves of a layer left out by the selection.
    MX_IGNORED_OTHER_LAYER = 3,
    /// A loop enclosing no area in sum.
    MX_IGNORED_FLAT_LOOP = 4,
    /// A copy of a loop drawn twice.
    MX_IGNORED_DUPLICATE_LOOP = 5,
    /// A hole touching or crossing another loop of its shape.
    MX_IGNORED_TOUCHING_LOOP = 6,
    /// An outer loop with its holes that does not validate.
    MX_IGNORED_INVALID_SHAPE = 7,
}
use mx_ignored_kind::*;

/// One thing of a drawing in no shape.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_ignored {
    /// What it is.
    pub kind: mx_ignored_kind,
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
    /// The DXF handle (group 5) of its first entity, or of the block
    /// reference that placed it; 0 where the file gives none.
    pub handle: u64,
    /// For `MX_IGNORED_DUPLICATE_LOOP` the handle of the copy kept, for
    /// `MX_IGNORED_TOUCHING_LOOP` and `MX_IGNORED_INVALID_SHAPE` that of
    /// the entity met; 0 otherwise.
    pub other_handle: u64,
}

fn kind_code(k: IgnoredKind) -> mx_ignored_kind {
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
                handle: i.handles.first().copied().unwrap_or(0),
                other_handle: i.handles.get(1).copied().unwrap_or(0),
            })
        })
    }
}

/// `mx_warning.kind`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_warning_kind {
    /// Curve ends that did not meet within the validation tolerance were
    /// joined (within the chaining tolerance).
    MX_WARNING_GAP_CLOSED = 1,
    /// Two shapes touch or cross (both kept).
    MX_WARNING_TOUCHING_SHAPES = 2,
}
use mx_warning_kind::*;

/// Something of a drawing's shapes worth knowing: a gap closed, or two
/// shapes that touch.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_warning {
    /// What it is.
    pub kind: mx_warning_kind,
    /// Where, model units.
    pub x: f64,
    /// Where, model units.
    pub y: f64,
    /// `MX_WARNING_GAP_CLOSED`: the gap joined, model units; else 0.
    pub gap: f64,
    /// `MX_WARNING_TOUCHING_SHAPES`: the two shapes (indices for
    /// `mx_drawing_shape`); else 0, 0.
    pub shapes: [usize; 2],
    /// `MX_WARNING_TOUCHING_SHAPES`: the 1-based lines (DXF) or byte
    /// offsets (SVG) of the two entities that meet; else 0, 0.
    pub sources: [usize; 2],
    /// `MX_WARNING_TOUCHING_SHAPES`: their DXF handles (0 where none).
    pub handles: [u64; 2],
}

/// Number of warnings: the gaps closed (widest first), then the pairs of
/// shapes that touch.
///
/// # Safety
/// `drawing` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_warning_count(drawing: *const mx_drawing, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(drawing, out, |d| Ok(d.inner.gaps.len() + d.inner.touching.len())) }
}

/// Warning `index` (see `mx_drawing_warning_count` for the order).
///
/// # Safety
/// `drawing` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_drawing_get_warning(
    drawing: *const mx_drawing,
    index: usize,
    out: *mut mx_warning,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(drawing, out, |d| {
            let (gaps, touching) = (&d.inner.gaps, &d.inner.touching);
            if let Some(&(p, gap)) = gaps.get(index) {
                return Ok(mx_warning {
                    kind: MX_WARNING_GAP_CLOSED,
                    x: p.x,
                    y: p.y,
                    gap,
                    shapes: [0; 2],
                    sources: [0; 2],
                    handles: [0; 2],
                });
            }
            let t = match index.checked_sub(gaps.len()) {
                Some(k) if k < touching.len() => &touching[k],
                _ => return Err(index_error("warning", index, gaps.len() + touching.len())),
            };
            Ok(mx_warning {
                kind: MX_WARNING_TOUCHING_SHAPES,
                x: t.position.x,
                y: t.position.y,
                gap: 0.0,
                shapes: t.shapes,
                sources: t.sources,
                handles: t.handles,
            })
        })
    }
}
