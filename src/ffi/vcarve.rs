//! C functions for V-carving: paths along the medial axis with depth for a
//! V-bit, and the flat-bottom rings where the depth is capped. Mirrors
//! `crate::cam::vcarve`; no geometry here.

use super::axis::mx_axis;
use super::boundary::{nth, ptr_or_null};
use super::handles::{compute, free, impl_options, lend, options_default, options_init, query, Boxed, Handle, Lends};
use super::offset::mx_offset_layer;
use super::pocket::cam_error;
use super::status::mx_status;
use crate::cam::{vcarve, VCarveOptions, VCarvePath};
use std::mem::size_of;

/// V-carve paths and the flat bottom. Opaque; create with
/// `mx_vcarve_compute`, release with `mx_vcarve_free`. Immutable.
pub struct mx_vcarve {
    paths: Vec<VCarvePath>,
    /// The flat bottom (at the flat radius), in the form `mx_vcarve_flat`
    /// lends.
    flat: mx_offset_layer,
}

impl Handle for mx_vcarve {
    const ARG: &'static str = "vcarve";
    type Ownership = Boxed;
}

impl Lends<mx_offset_layer> for mx_vcarve {
    fn lent(&self) -> &mx_offset_layer {
        &self.flat
    }
}

/// Options for `mx_vcarve_compute`. Initialise with
/// `mx_vcarve_options_init(&o, sizeof o)` (which sets `struct_size`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_vcarve_options {
    /// `sizeof(mx_vcarve_options)` as the caller was compiled.
    pub struct_size: usize,
    /// Included angle of the V-bit, degrees, in (0, 180); default 90.
    pub angle_deg: f64,
    /// Maximum depth, model units, > 0; default `INFINITY` (no cap).
    pub max_depth: f64,
    /// Chordal tolerance of the paths along the axis's curves, model units;
    /// 0 (default) = 1000 × the shape's tolerance.
    pub tolerance: f64,
}

impl_options!(mx_vcarve_options, v1: 32 bytes up to tolerance: f64, defaults: mx_vcarve_options {
    struct_size: size_of::<Self>(),
    angle_deg: 90.0,
    max_depth: f64::INFINITY,
    tolerance: 0.0,
});

/// Facts about a V-carve.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_vcarve_info {
    /// Number of paths (`mx_vcarve_get_path`).
    pub path_count: usize,
    /// The disk radius where the depth is capped: max_depth · tan(α/2),
    /// model units (infinite without a cap).
    pub flat_radius: f64,
    /// Number of flat-bottom rings (loops of `mx_vcarve_flat`).
    pub flat_loop_count: usize,
}

/// One V-carve path: the tool tip's points along the medial axis.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_vcarve_path {
    /// `x, y, depth` triples, 3 × `point_count` doubles, model units; depth
    /// ≥ 0 measured down from the surface. Borrowed.
    pub xyd: *const f64,
    /// Number of points.
    pub point_count: usize,
}

/// Fills the caller's `mx_vcarve_options` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_vcarve_options o;
/// mx_vcarve_options_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_options_init(out: *mut mx_vcarve_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_vcarve_options_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_vcarve_options`.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_options_default(out: *mut mx_vcarve_options) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

/// Computes the V-carve paths along the medial axis `axis` (of the
/// axis's own copy of the shape) for the options' V-bit, and writes a new
/// handle to `*out`. `options` may be NULL (a 90° bit, no depth cap).
/// Fails with `MX_ERR_INVALID_ARGUMENT` (the option named in the message)
/// for an angle outside (0, 180), a maximum depth ≤ 0 or NaN or a negative
/// tolerance, `MX_ERR_NUMERICAL` when the flat bottom's offset breaks
/// down; `*out` is then untouched. The handle does not borrow the axis.
///
/// # Safety
/// `axis` NULL or a live handle; `options` NULL or valid; `out` NULL or
/// writable.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_compute(
    axis: *const mx_axis,
    options: *const mx_vcarve_options,
    out: *mut *mut mx_vcarve,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        compute(out, axis, options, |a, o| {
            let opts = VCarveOptions { angle_deg: o.angle_deg, max_depth: o.max_depth, tolerance: o.tolerance };
            let v = vcarve(&a.shape, a.euclidean("mx_vcarve_compute")?, &opts).map_err(cam_error)?;
            Ok(mx_vcarve { paths: v.paths, flat: mx_offset_layer::new(v.flat) })
        })
    }
}

/// Releases a V-carve (and its flat layer). NULL is a no-op.
///
/// # Safety
/// `vcarve` must be NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_free(vcarve: *mut mx_vcarve) {
    // SAFETY: forwarded contract.
    unsafe { free(vcarve) }
}

/// Counts and the flat radius.
///
/// # Safety
/// `vcarve` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_get_info(vcarve: *const mx_vcarve, out: *mut mx_vcarve_info) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(vcarve, out, |v| {
            Ok(mx_vcarve_info {
                path_count: v.paths.len(),
                flat_radius: v.flat.layer.distance,
                flat_loop_count: v.flat.loop_count(),
            })
        })
    }
}

/// Path `index` (`MX_ERR_INDEX_OUT_OF_RANGE` unless below `path_count`),
/// its points borrowed.
///
/// # Safety
/// `vcarve` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_get_path(
    vcarve: *const mx_vcarve,
    index: usize,
    out: *mut mx_vcarve_path,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(vcarve, out, |v| {
            let p = nth(&v.paths, index, "path")?;
            Ok(mx_vcarve_path { xyd: ptr_or_null(&p.points).cast(), point_count: p.points.len() })
        })
    }
}

/// The flat bottom's rings at the capped radius, as an offset layer read
/// with the `mx_offset_layer_*` functions (no loops when the cap is never
/// reached). Borrowed: valid until `mx_vcarve_free`; do not free it.
///
/// # Safety
/// `vcarve` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_vcarve_flat(vcarve: *const mx_vcarve, out: *mut *const mx_offset_layer) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { lend(vcarve, out) }
}
