//! C functions for 2D shapes: create, inspect, draw, free. Mirrors
//! `crate::shape`; no geometry is computed here.

use super::boundary::{c_str, check_threads, fill_items, guard, in_pool, index_error, nth, slice};
use super::handles::{arg, create, free, impl_options, options_default, options_init, query, Boxed, Handle, Options};
use super::last_error::FfiError;
use super::shape_kinds::{format_of, mx_bbox, mx_element, mx_joint_kind, ARC, SEGMENT};
use super::status::mx_status;
use crate::kernel::Point;
use crate::shape::{Element, ElementSpec, JointKind, Shape2d, ShapeOptions, Vertex};
use std::ffi::c_char;
use std::mem::size_of;

/// A validated 2D shape: an outer loop and holes of segments and circular
/// arcs. Opaque; create with `mx_shape2d_from_*`, release with
/// `mx_shape2d_free`. Immutable: a `const mx_shape2d*` may be used from
/// several threads at once.
pub struct mx_shape2d {
    pub(crate) inner: Shape2d,
}

impl Handle for mx_shape2d {
    const ARG: &'static str = "shape";
    type Ownership = Boxed;
}

// So that the queries call `Shape2d` methods straight on the handle.
impl std::ops::Deref for mx_shape2d {
    type Target = Shape2d;

    fn deref(&self) -> &Shape2d {
        &self.inner
    }
}

/// Tolerances for building shapes. Initialise with
/// `mx_shape_options_init(&o, sizeof o)` (which sets `struct_size`), then change fields. Lengths in model units.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_shape_options {
    /// `sizeof(mx_shape_options)` as the caller was compiled; lets later
    /// versions add fields without breaking old callers.
    pub struct_size: usize,
    /// Absolute touching / zero-length tolerance; 0 = `relative_tolerance`
    /// times the bounding-box diagonal.
    pub tolerance: f64,
    /// Relative tolerance used when `tolerance` is 0. Default 1e-9.
    pub relative_tolerance: f64,
    /// Joint angle tolerance in radians (smooth vs corner). Default 1e-6.
    pub angle_tolerance: f64,
    /// Arcs with a sagitta at most this become segments; negative = same as
    /// the touching tolerance (default).
    pub flatten_sagitta: f64,
    /// Gap closed when chaining loose elements; 0 = 1e-6 × diagonal (default).
    pub chain_tolerance: f64,
    /// Arcs with a radius above this multiple of the diagonal become
    /// segments (default 1e6; deviation at most diagonal / (8 × ratio)).
    pub max_radius_ratio: f64,
    /// Worker threads that check the shape (crossings, nesting of holes):
    /// 0 = all cores (default), else at most `MX_AXIS_MAX_THREADS`. Added
    /// after 0.1.0: a caller compiled against 0.1.0's struct (whose
    /// `struct_size` ends before this field) gets the default.
    pub threads: usize,
}

// `ShapeOptions::DEFAULT` in C form (0 and −1 stand for "derived").
impl_options!(mx_shape_options, v1: 56 bytes up to max_radius_ratio: f64, defaults: mx_shape_options {
    struct_size: size_of::<Self>(),
    tolerance: 0.0,
    relative_tolerance: ShapeOptions::DEFAULT.relative_tolerance,
    angle_tolerance: ShapeOptions::DEFAULT.angle_tolerance,
    flatten_sagitta: -1.0,
    chain_tolerance: 0.0,
    max_radius_ratio: ShapeOptions::DEFAULT.max_radius_ratio,
    threads: 0,
});

/// Fills the caller's `mx_shape_options` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_shape_options o;
/// mx_shape_options_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_shape_options_init(out: *mut mx_shape_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_shape_options_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_shape_options`.
#[no_mangle]
pub unsafe extern "C" fn mx_shape_options_default(out: *mut mx_shape_options) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

/// Options from C, checked, with the thread count; NULL means defaults.
pub(crate) unsafe fn options(p: *const mx_shape_options) -> Result<(ShapeOptions, usize), FfiError> {
    // SAFETY: forwarded contract.
    let Some(o) = (unsafe { mx_shape_options::read(p)? }) else {
        return Ok((ShapeOptions::default(), 0));
    };
    check_threads("mx_shape_options", o.threads)?;
    let length = |name: &str, v: f64| -> Result<Option<f64>, FfiError> {
        if v == 0.0 {
            Ok(None)
        } else if v.is_finite() && v > 0.0 {
            Ok(Some(v))
        } else {
            Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("mx_shape_options.{name} = {v}: use 0 for the default or a positive length"),
            ))
        }
    };
    let opts = ShapeOptions {
        tolerance: length("tolerance", o.tolerance)?,
        relative_tolerance: o.relative_tolerance,
        angle_tolerance: o.angle_tolerance,
        flatten_sagitta: if o.flatten_sagitta < 0.0 { None } else { Some(o.flatten_sagitta) },
        chain_tolerance: length("chain_tolerance", o.chain_tolerance)?,
        max_radius_ratio: o.max_radius_ratio,
    };
    opts.check()?;
    Ok((opts, o.threads))
}

/// The shape `build` makes, checked on `threads` threads (0: all cores).
fn built(threads: usize, build: impl FnOnce() -> Result<Shape2d, FfiError> + Send) -> Result<mx_shape2d, FfiError> {
    Ok(mx_shape2d { inner: in_pool(threads, build)?? })
}

/// `x, y, bulge` triples for chains back to back (`data`), cut into
/// chains of `lens[i]` vertices; `name` names the array in errors.
pub(crate) fn split_bulges(data: &[f64], lens: &[usize], name: &str) -> Result<Vec<Vec<Vertex>>, FfiError> {
    let total = lens.iter().try_fold(0usize, |a, &n| a.checked_add(n));
    if total.and_then(|t| t.checked_mul(3)) != Some(data.len()) {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!(
                "{name} holds {} doubles but the lengths add up to {:?} vertices (3 doubles each)",
                data.len(),
                total
            ),
        ));
    }
    let mut out = Vec::with_capacity(lens.len());
    let mut at = 0;
    for &n in lens {
        out.push(
            data[at..at + 3 * n].chunks_exact(3).map(|c| Vertex { p: Point::new(c[0], c[1]), bulge: c[2] }).collect(),
        );
        at += 3 * n;
    }
    Ok(out)
}

/// Creates a shape from bulge loops. `xyb` holds `x, y, bulge` triples for
/// all loops back to back (`xyb_len` doubles = 3 × total vertices);
/// `loop_lengths[i]` is the vertex count of loop `i`; loop 0 is the outer
/// boundary, the rest are holes. Bulge = tan(sweep/4) of the element from a
/// vertex to the next (cyclic), positive counter-clockwise. Orientation is
/// normalised (see `mx_shape2d_loop_reversed`). `options` may be NULL.
/// On failure `*out` is untouched and the last error names the element.
///
/// # Safety
/// Pointers must be NULL or valid for the given lengths; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_from_bulges(
    xyb: *const f64,
    xyb_len: usize,
    loop_lengths: *const usize,
    loop_count: usize,
    options: *const mx_shape_options,
    out: *mut *mut mx_shape2d,
) -> mx_status {
    // SAFETY: caller contract on pointer/length pairs.
    unsafe {
        create(out, || {
            let (data, lens, (opts, threads)) = (
                slice(xyb, xyb_len, "xyb")?,
                slice(loop_lengths, loop_count, "loop_lengths")?,
                self::options(options)?,
            );
            let loops = split_bulges(data, lens, "xyb")?;
            built(threads, || Ok(Shape2d::from_bulge_loops(loops, &opts)?))
        })
    }
}

/// Creates a shape from explicit segments and arcs (see `mx_element` for the
/// fields read). `elements` holds all loops back to back; `loop_lengths[i]`
/// is the element count of loop `i`; loop 0 is the outer boundary.
/// Consecutive elements must meet within the chaining tolerance.
///
/// # Safety
/// Pointers must be NULL or valid for the given lengths; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_from_elements(
    elements: *const mx_element,
    element_count: usize,
    loop_lengths: *const usize,
    loop_count: usize,
    options: *const mx_shape_options,
    out: *mut *mut mx_shape2d,
) -> mx_status {
    // SAFETY: caller contract on pointer/length pairs.
    unsafe {
        create(out, || {
            elements_shape(
                slice(elements, element_count, "elements")?,
                slice(loop_lengths, loop_count, "loop_lengths")?,
                self::options(options)?,
            )
        })
    }
}

/// The shape of `elems` cut into loops of `lens` elements.
fn elements_shape(
    elems: &[mx_element],
    lens: &[usize],
    (opts, threads): (ShapeOptions, usize),
) -> Result<mx_shape2d, FfiError> {
    if lens.iter().try_fold(0usize, |a, &n| a.checked_add(n)) != Some(elems.len()) {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("element_count = {} does not match the sum of loop_lengths", elems.len()),
        ));
    }
    let mut loops = Vec::with_capacity(lens.len());
    let mut at = 0;
    for (li, &n) in lens.iter().enumerate() {
        let mut specs = Vec::with_capacity(n);
        for (i, e) in elems[at..at + n].iter().enumerate() {
            let (a, b) = (Point::new(e.x0, e.y0), Point::new(e.x1, e.y1));
            specs.push(match e.kind {
                SEGMENT => ElementSpec::Segment { a, b },
                ARC => ElementSpec::ArcPoints { a, b, center: Point::new(e.cx, e.cy), ccw: e.ccw != 0 },
                k => {
                    return Err(FfiError::new(
                        mx_status::MX_ERR_INVALID_ARGUMENT,
                        format!("loop {li} element {i}: unknown kind {k}"),
                    ))
                }
            });
        }
        loops.push(specs);
        at += n;
    }
    built(threads, || Ok(Shape2d::from_elements(&loops, &opts)?))
}

/// Reads a shape file (JSON, DXF or SVG; `MX_FORMAT_AUTO` picks by extension,
/// then content). `path` is UTF-8.
///
/// # Safety
/// `path` must be NULL or NUL-terminated; `options` NULL or valid; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_from_file(
    path: *const c_char,
    format: u32,
    options: *const mx_shape_options,
    out: *mut *mut mx_shape2d,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (path, (opts, threads)) = (c_str(path, "path")?, self::options(options)?);
            let format = format_of(format)?;
            built(threads, || {
                Ok(match format {
                    None => Shape2d::from_file(path, &opts)?,
                    Some(f) => {
                        let text = std::fs::read(path).map_err(|e| {
                            FfiError::from(crate::shape::ShapeError::Io { path: path.into(), message: e.to_string() })
                        })?;
                        Shape2d::from_str_as(&String::from_utf8_lossy(&text), f, &opts)?
                    }
                })
            })
        })
    }
}

/// Parses a shape from a NUL-terminated string in the given format
/// (`MX_FORMAT_AUTO` guesses from the content).
///
/// # Safety
/// `text` must be NULL or NUL-terminated; `options` NULL or valid; `out` writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_from_string(
    text: *const c_char,
    format: u32,
    options: *const mx_shape_options,
    out: *mut *mut mx_shape2d,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (text, (opts, threads)) = (c_str(text, "text")?, self::options(options)?);
            let f = format_of(format)?.unwrap_or_else(|| crate::shape::sniff(text));
            built(threads, || Ok(Shape2d::from_str_as(text, f, &opts)?))
        })
    }
}

/// Releases a shape. NULL is a no-op.
///
/// # Safety
/// `shape` must be NULL or a shape from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_free(shape: *mut mx_shape2d) {
    // SAFETY: forwarded contract.
    unsafe { free(shape) }
}

fn loop_of(s: &Shape2d, l: usize) -> Result<&crate::shape::Loop, FfiError> {
    nth(s.loops(), l, "loop")
}

/// Number of loops (1 + number of holes).
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_loop_count(shape: *const mx_shape2d, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(shape, out, |s| Ok(s.loops().len())) }
}

/// Number of elements (= vertices) of loop `loop_index`.
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_loop_size(
    shape: *const mx_shape2d,
    loop_index: usize,
    out: *mut usize,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(shape, out, |s| Ok(loop_of(s, loop_index)?.len())) }
}

/// Writes 1 to `out` when loop `loop_index` was given in the other
/// orientation and was reversed (outer loops are stored counter-clockwise,
/// holes clockwise); stored element `k` of an n-element reversed loop is
/// input element `(n - 2 - k) mod n`.
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_loop_reversed(
    shape: *const mx_shape2d,
    loop_index: usize,
    out: *mut i32,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(shape, out, |s| {
            loop_of(s, loop_index)?;
            Ok(i32::from(s.was_reversed(loop_index)))
        })
    }
}

/// Copies loop `loop_index` as `x, y, bulge` triples into `xyb` of
/// `capacity` vertices and writes their number to `*count`. Size query:
/// `capacity` 0 (`xyb` may be NULL) writes only `*count`; a shorter buffer
/// gives `MX_ERR_BUFFER_TOO_SMALL` with nothing written.
///
/// # Safety
/// `shape` NULL or a live handle; `xyb` NULL or `3 * capacity` writable
/// doubles; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_loop_vertices(
    shape: *const mx_shape2d,
    loop_index: usize,
    xyb: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let s = unsafe { arg(shape)? };
        let l = loop_of(s, loop_index)?;
        let n = l.len();
        let triples = l.vertices().iter().flat_map(|v| [v.p.x, v.p.y, v.bulge]);
        // SAFETY: caller contract.
        unsafe {
            fill_items((xyb, "xyb"), (capacity, count), (n, 3), triples, || {
                format!("loop {loop_index} has {n} vertices, the buffer room for {capacity}")
            })
        }
    })
}

/// Element `index` of loop `loop_index` (stored orientation) with all its
/// geometry.
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_element(
    shape: *const mx_shape2d,
    loop_index: usize,
    index: usize,
    out: *mut mx_element,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(shape, out, |s| {
            let l = loop_of(s, loop_index)?;
            if index >= l.len() {
                return Err(index_error("element", index, l.len()));
            }
            let e = l.element(index);
            let (a, b) = (e.start(), e.end());
            let mut m = mx_element { x0: a.x, y0: a.y, x1: b.x, y1: b.y, ..Default::default() };
            if let Element::Arc(arc) = e {
                m.kind = ARC;
                m.ccw = i32::from(arc.is_ccw());
                m.cx = arc.center.x;
                m.cy = arc.center.y;
                m.radius = arc.radius;
                m.bulge = arc.bulge;
            }
            Ok(m)
        })
    }
}

/// The joint at vertex `index` of loop `loop_index`: `MX_JOINT_SMOOTH`,
/// `MX_JOINT_CONVEX` or `MX_JOINT_REFLEX` (seen from the shape's interior).
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_joint(
    shape: *const mx_shape2d,
    loop_index: usize,
    index: usize,
    out: *mut mx_joint_kind,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(shape, out, |s| {
            let l = loop_of(s, loop_index)?;
            if index >= l.len() {
                return Err(index_error("vertex", index, l.len()));
            }
            Ok(match s.joint(loop_index, index) {
                JointKind::Smooth => mx_joint_kind::MX_JOINT_SMOOTH,
                JointKind::Convex => mx_joint_kind::MX_JOINT_CONVEX,
                JointKind::Reflex => mx_joint_kind::MX_JOINT_REFLEX,
            })
        })
    }
}

/// Tight bounding box of the boundary (arcs included exactly).
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_bbox(shape: *const mx_shape2d, out: *mut mx_bbox) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(shape, out, |s| {
            let b = s.bbox();
            Ok(mx_bbox { xmin: b.min.x, ymin: b.min.y, xmax: b.max.x, ymax: b.max.y })
        })
    }
}

/// Enclosed area (outer minus holes), square model units; arcs exact.
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_area(shape: *const mx_shape2d, out: *mut f64) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(shape, out, |s| Ok(s.area())) }
}

/// The absolute length tolerance the shape was validated with (model units).
///
/// # Safety
/// `shape` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_tolerance(shape: *const mx_shape2d, out: *mut f64) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(shape, out, |s| Ok(s.tolerance())) }
}

/// Writes a picture of the shape (SVG, arcs exact) to `path`.
///
/// # Safety
/// `shape` NULL or a live handle; `path` NULL or NUL-terminated.
#[no_mangle]
pub unsafe extern "C" fn mx_shape2d_write_svg(shape: *const mx_shape2d, path: *const c_char) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let (s, path) = unsafe { (arg(shape)?, c_str(path, "path")?) };
        std::fs::write(path, s.inner.to_svg(900.0))
            .map_err(|e| FfiError::new(mx_status::MX_ERR_IO, format!("cannot write {path}: {e}")))
    })
}
