//! C functions for trimmed offsets: prepare a shape or reuse its axis
//! (`mx_offsets`), take
//! the offset at one or many distances (`mx_offset_layer`), read its loops
//! and regions, free. Mirrors `crate::plane::offset`; no geometry here.
//!
//! Loops are handed out as borrowed arrays laid out as
//! `mx_shape2d_from_bulges` takes them (`x, y, bulge` triples back to back
//! and one length per loop, as in `mx_sites`), valid until the handle that
//! owns them is freed: a caller can feed a layer back as a shape without
//! copying by hand.

use super::axis::{axis_error, mx_axis, mx_progress_fn};
use super::boundary::{check_out, guard, in_pool, nth, ptr_or_null, run_with_progress, slice, write_out};
use super::handles::{arg, compute, free, impl_options, into_raw, options_default, options_init, query, Boxed, Handle};
use super::last_error::FfiError;
use super::shape2d::mx_shape2d;
use super::status::mx_status;
use crate::plane::{AxisOptions, OffsetError, OffsetLayer, OffsetOptions, Offsets};
use crate::shape::Vertex;
use std::ffi::c_void;
use std::mem::size_of;

/// A shape prepared for offsets at any distance: its medial axis and, for
/// outer offsets, the axes of its complement. Opaque; create with
/// `mx_offsets_compute` or `mx_offsets_from_axis`, release with
/// `mx_offsets_free`. Immutable: a `const mx_offsets*` may be used from
/// several threads at once.
pub struct mx_offsets {
    pub(crate) offsets: Offsets,
    /// The worker threads asked for at compute time, used again for layers
    /// and pockets.
    pub(crate) threads: usize,
}

impl Handle for mx_offsets {
    const ARG: &'static str = "offsets";
    type Ownership = Boxed;
}

/// The offset at one distance: closed loops of segments and arcs and the
/// regions they bound. Opaque; from `mx_offsets_layer`,
/// `mx_offsets_layers` (release with `mx_offset_layer_free`) or borrowed
/// from `mx_vcarve_flat`. Immutable.
pub struct mx_offset_layer {
    pub(crate) layer: OffsetLayer,
    loops: FlatLoops,
}

impl Handle for mx_offset_layer {
    const ARG: &'static str = "layer";
    type Ownership = Boxed;
}

/// Options for `mx_offsets_compute` and `mx_offsets_from_axis`.
/// Initialise with `mx_offset_options_init(&o, sizeof o)` (which sets `struct_size`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_offset_options {
    /// `sizeof(mx_offset_options)` as the caller was compiled.
    pub struct_size: usize,
    /// Seed of the divide step's random choices (as `mx_axis_options.seed`).
    pub seed: u64,
    /// Worker threads, as `mx_axis_options.threads`; also used for the
    /// layers and pockets of these offsets.
    pub threads: usize,
    /// Outer offsets (negative distances) are available down to
    /// −`outer_reach`, model units (finite, ≥ 0; default 0: inner offsets
    /// only). A larger reach costs nothing per layer but frames the
    /// complement farther away.
    pub outer_reach: f64,
    /// Optional progress callback, as `mx_axis_options.progress` (called
    /// with 0 before and 1 after; nonzero at 0 cancels).
    pub progress: mx_progress_fn,
    /// Passed unchanged to `progress`.
    pub user: *mut c_void,
}

impl_options!(mx_offset_options, v1: 48 bytes up to user: *mut c_void, defaults: mx_offset_options {
    struct_size: size_of::<Self>(),
    seed: AxisOptions::default().seed,
    threads: 0,
    outer_reach: 0.0,
    progress: None,
    user: std::ptr::null_mut(),
});

/// Closed bulge loops, borrowed from the handle that owns them, laid out
/// as `mx_shape2d_from_bulges` takes them. The pointers are NULL when the
/// counts are 0.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_bulge_loops {
    /// `x, y, bulge` triples of every loop back to back (model units;
    /// bulge = tan(sweep/4) of the element starting at that vertex,
    /// positive counter-clockwise). Element `i` of a loop runs from its
    /// vertex `i` to vertex `i + 1`, the last back to the first.
    pub xyb: *const f64,
    /// Doubles in `xyb`: 3 × the sum of `lengths`.
    pub xyb_len: usize,
    /// Vertex count of each loop.
    pub lengths: *const usize,
    /// Number of loops.
    pub count: usize,
}

/// Facts about one offset layer.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_offset_layer_info {
    /// The distance, model units: positive inwards, negative outwards.
    pub distance: f64,
    /// Area of the offset region, square model units.
    pub area: f64,
    /// Number of loops (`mx_offset_layer_get_loop`).
    pub loop_count: usize,
    /// Number of connected regions (`mx_offset_layer_get_region`).
    pub region_count: usize,
}

/// One loop of an offset layer. The region lies on its left: outer loops
/// run counter-clockwise, holes clockwise.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_offset_loop {
    /// `x, y, bulge` triples, 3 × `vertex_count` doubles; borrowed from the
    /// layer.
    pub xyb: *const f64,
    /// Number of vertices (= elements).
    pub vertex_count: usize,
    /// Signed area enclosed, square model units: positive for an outer
    /// loop, negative for a hole.
    pub area: f64,
    /// The region it bounds (`mx_offset_layer_get_region`).
    pub region: usize,
    /// 1 for a hole (clockwise), 0 for an outer loop.
    pub is_hole: i32,
}

/// One connected region of an offset layer: an outer loop and its holes
/// (loop indices).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_offset_region {
    /// Index of the outer loop.
    pub outer: usize,
    /// Indices of the hole loops, `hole_count` entries; borrowed from the
    /// layer (NULL when there are none).
    pub holes: *const usize,
    /// Number of holes.
    pub hole_count: usize,
}

/// Loops stored the way `mx_bulge_loops` shows them.
#[derive(Debug, Clone, Default)]
pub(crate) struct FlatLoops {
    xyb: Vec<f64>,
    lengths: Vec<usize>,
    /// Where each loop starts in `xyb` (triples): kept, though the prefix
    /// sums of `lengths`, so that fetching loop i is O(1) and fetching every
    /// loop is linear.
    starts: Vec<usize>,
}

impl FlatLoops {
    pub(crate) fn new(loops: impl IntoIterator<Item = impl AsRef<[Vertex]>>) -> FlatLoops {
        let mut out = FlatLoops::default();
        for l in loops {
            let l = l.as_ref();
            out.starts.push(out.xyb.len());
            out.lengths.push(l.len());
            out.xyb.extend(l.iter().flat_map(|v| [v.p.x, v.p.y, v.bulge]));
        }
        out
    }

    pub(crate) fn view(&self) -> mx_bulge_loops {
        mx_bulge_loops {
            xyb: ptr_or_null(&self.xyb),
            xyb_len: self.xyb.len(),
            lengths: ptr_or_null(&self.lengths),
            count: self.lengths.len(),
        }
    }

    /// Loop `i`'s triples (NULL when it has no vertices).
    fn one(&self, i: usize) -> *const f64 {
        let start = self.starts[i];
        ptr_or_null(&self.xyb[start..start + 3 * self.lengths[i]])
    }
}

impl mx_offset_layer {
    pub(crate) fn new(layer: OffsetLayer) -> mx_offset_layer {
        let loops = FlatLoops::new(&layer.loops);
        mx_offset_layer { layer, loops }
    }

    pub(crate) fn loop_count(&self) -> usize {
        self.layer.loops.len()
    }
}

pub(crate) fn offset_error(e: OffsetError) -> FfiError {
    let message = e.to_string();
    match e {
        OffsetError::BadDistance(_) | OffsetError::BadReach(_) => {
            FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, message)
        }
        OffsetError::NotRegion { loop_index } => {
            let mut f = FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, message);
            f.info.loop_index = loop_index as i64;
            f
        }
        OffsetError::Axis(a) => {
            let mut f = axis_error(a);
            f.message = message;
            f
        }
        OffsetError::Topology { .. } => FfiError::new(mx_status::MX_ERR_NUMERICAL, message),
    }
}

/// Fills the caller's `mx_offset_options` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_offset_options o;
/// mx_offset_options_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_options_init(out: *mut mx_offset_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_offset_options_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_offset_options`.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_options_default(out: *mut mx_offset_options) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

/// Checks the options' `outer_reach` and runs `prepare` with the Rust
/// options they stand for as the export `export`, with their threads and
/// progress.
fn prepare(
    export: &str,
    o: mx_offset_options,
    prepare: impl FnOnce(&OffsetOptions) -> Result<Offsets, OffsetError> + Send,
) -> Result<mx_offsets, FfiError> {
    if !(o.outer_reach.is_finite() && o.outer_reach >= 0.0) {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("mx_offset_options.outer_reach = {}: use a finite value >= 0", o.outer_reach),
        ));
    }
    let opts =
        OffsetOptions { axis: AxisOptions { seed: o.seed, ..AxisOptions::default() }, outer_reach: o.outer_reach };
    let offsets = run_with_progress(export, "mx_offset_options", o.threads, o.progress, o.user, || {
        prepare(&opts).map_err(offset_error)
    })?;
    Ok(mx_offsets { offsets, threads: o.threads })
}

/// Prepares `shape` for offsets (thesis 2.4: its medial axis, and for
/// `outer_reach` > 0 the axes of its complement) and writes a new handle
/// to `*out`. `options` may be NULL. The handle does not borrow the shape.
/// The convenience form of `mx_offsets_from_axis` for a caller without an
/// axis. Fails with `MX_ERR_INVALID_ARGUMENT` for bad options (a negative
/// or non-finite `outer_reach`, too many threads), `MX_ERR_NUMERICAL` or
/// `MX_ERR_CANCELLED` as `mx_axis_compute`; `*out` is then untouched.
///
/// # Safety
/// `shape` NULL or a live handle; `options` NULL or valid; `out` NULL or
/// writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offsets_compute(
    shape: *const mx_shape2d,
    options: *const mx_offset_options,
    out: *mut *mut mx_offsets,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        compute(out, shape, options, |s, o| prepare("mx_offsets_compute", o, |opts| Offsets::new(&s.inner, opts)))
    }
}

/// Prepares offsets from an axis the caller already has (of `axis`'s own
/// copy of the shape): only the complement's axes are computed, for
/// `outer_reach` > 0 (with the options' seed, threads and progress). The
/// handle does not borrow the axis. Fails as `mx_offsets_compute`; `*out`
/// is then untouched.
///
/// # Safety
/// `axis` NULL or a live handle; `options` NULL or valid; `out` NULL or
/// writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offsets_from_axis(
    axis: *const mx_axis,
    options: *const mx_offset_options,
    out: *mut *mut mx_offsets,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        compute(out, axis, options, |a, o| {
            let axis = a.euclidean("mx_offsets_from_axis")?;
            prepare("mx_offsets_from_axis", o, |opts| Offsets::from_axis(&a.shape, axis)?.with_outer(&a.shape, opts))
        })
    }
}

/// Releases prepared offsets (layers taken from them stay valid). NULL is
/// a no-op.
///
/// # Safety
/// `offsets` must be NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_offsets_free(offsets: *mut mx_offsets) {
    // SAFETY: forwarded contract.
    unsafe { free(offsets) }
}

/// The largest inner distance with anything left (the radius of the
/// largest inscribed disk), model units.
///
/// # Safety
/// `offsets` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offsets_max_inner_distance(offsets: *const mx_offsets, out: *mut f64) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(offsets, out, |o| Ok(o.offsets.max_inner_distance())) }
}

/// The offset at `distance` (model units: positive inwards, negative
/// outwards down to −`outer_reach`, 0 the shape's own boundary) as a new
/// handle in `*out`; beyond the largest inscribed disk it has no loops.
/// `MX_ERR_INVALID_ARGUMENT` for a non-finite distance or one beyond the
/// outer reach; `*out` is then untouched.
///
/// # Safety
/// `offsets` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offsets_layer(
    offsets: *const mx_offsets,
    distance: f64,
    out: *mut *mut mx_offset_layer,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(offsets, out, |o| {
            let layer = in_pool(o.threads, || o.offsets.layer(distance))?.map_err(offset_error)?;
            Ok(into_raw(mx_offset_layer::new(layer)))
        })
    }
}

/// The offsets at `count` distances, computed in parallel: `out[k]`
/// receives a new handle for `distances[k]` (each to be freed with
/// `mx_offset_layer_free`). On failure (the first bad distance is named in
/// the message) nothing is written and nothing needs freeing.
///
/// # Safety
/// `offsets` NULL or a live handle; `distances` NULL or `count` readable
/// doubles; `out` NULL or `count` writable pointers.
#[no_mangle]
pub unsafe extern "C" fn mx_offsets_layers(
    offsets: *const mx_offsets,
    distances: *const f64,
    count: usize,
    out: *mut *mut mx_offset_layer,
) -> mx_status {
    guard(|| {
        check_out(out, "out")?;
        // SAFETY: caller contract.
        let (o, ds) = unsafe { (arg(offsets)?, slice(distances, count, "distances")?) };
        let layers = in_pool(o.threads, || o.offsets.layers(ds))?.map_err(offset_error)?;
        for (k, layer) in layers.into_iter().enumerate() {
            // SAFETY: k < count entries, writable per the contract.
            unsafe { write_out(out.add(k), into_raw(mx_offset_layer::new(layer))) };
        }
        Ok(())
    })
}

/// Releases a layer. NULL is a no-op; never pass the borrowed layer of
/// `mx_vcarve_flat`.
///
/// # Safety
/// `layer` must be NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_layer_free(layer: *mut mx_offset_layer) {
    // SAFETY: forwarded contract.
    unsafe { free(layer) }
}

/// Distance, area and counts of a layer.
///
/// # Safety
/// `layer` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_layer_get_info(
    layer: *const mx_offset_layer,
    out: *mut mx_offset_layer_info,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(layer, out, |l| {
            let layer = &l.layer;
            Ok(mx_offset_layer_info {
                distance: layer.distance,
                area: layer.area(),
                loop_count: layer.loops.len(),
                region_count: layer.regions.len(),
            })
        })
    }
}

/// Every loop of the layer at once, borrowed (valid while the layer
/// lives), in loop index order: ready for `mx_shape2d_from_bulges` after
/// picking a region's loops.
///
/// # Safety
/// `layer` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_layer_loops(layer: *const mx_offset_layer, out: *mut mx_bulge_loops) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(layer, out, |l| Ok(l.loops.view())) }
}

/// Loop `index` of the layer (`MX_ERR_INDEX_OUT_OF_RANGE` unless below
/// `loop_count`), its vertices borrowed.
///
/// # Safety
/// `layer` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_layer_get_loop(
    layer: *const mx_offset_layer,
    index: usize,
    out: *mut mx_offset_loop,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(layer, out, |l| {
            let lp = nth(&l.layer.loops, index, "loop")?;
            Ok(mx_offset_loop {
                xyb: l.loops.one(index),
                vertex_count: lp.vertices.len(),
                area: lp.area,
                region: lp.region,
                is_hole: lp.is_hole().into(),
            })
        })
    }
}

/// Region `index` of the layer (`MX_ERR_INDEX_OUT_OF_RANGE` unless below
/// `region_count`), its hole indices borrowed.
///
/// # Safety
/// `layer` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_offset_layer_get_region(
    layer: *const mx_offset_layer,
    index: usize,
    out: *mut mx_offset_region,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(layer, out, |l| {
            let r = nth(&l.layer.regions, index, "region")?;
            Ok(mx_offset_region { outer: r.outer, holes: ptr_or_null(&r.holes), hole_count: r.holes.len() })
        })
    }
}
