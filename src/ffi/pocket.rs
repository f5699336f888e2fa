//! C functions for pocketing: rings for a tool radius and stepover from
//! prepared offsets, their tree and machining order, the area left uncut.
//! Mirrors `crate::cam::pocket`; no geometry here.

use super::boundary::{in_pool, nth, ptr_or_null};
use super::handles::{compute, free, impl_options, options_default, options_init, query, Boxed, Handle};
use super::last_error::FfiError;
use super::offset::{mx_bulge_loops, mx_offsets, offset_error, FlatLoops};
use super::status::mx_status;
use crate::cam::{pocket, CamError, Pocket, PocketOptions, PocketOrder, UncutKind};
use std::mem::size_of;

/// The rings of a pocket. Opaque; create with `mx_pocket_compute`, release
/// with `mx_pocket_free`. Immutable.
pub struct mx_pocket {
    pocket: Pocket,
    rings: Vec<FlatLoops>,
    uncut: Vec<FlatLoops>,
}

impl Handle for mx_pocket {
    const ARG: &'static str = "pocket";
    type Ownership = Boxed;
}

/// The values of `mx_pocket_options.order` (a `uint32_t`, so that an
/// unknown value is an error rather than undefined behaviour).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_pocket_order {
    /// Every ring after the rings inside it (the wall last, as a finishing
    /// pass).
    MX_POCKET_INSIDE_OUT = 0,
    /// Every ring before the rings inside it.
    MX_POCKET_OUTSIDE_IN = 1,
}
const INSIDE_OUT: u32 = mx_pocket_order::MX_POCKET_INSIDE_OUT as u32;
const OUTSIDE_IN: u32 = mx_pocket_order::MX_POCKET_OUTSIDE_IN as u32;

/// `mx_uncut_region.kind`.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum mx_uncut_kind {
    /// A cusp between rings that the stepover left.
    MX_UNCUT_SCALLOP = 0,
    /// Corners and necks along the wall narrower than the tool.
    MX_UNCUT_WALL = 1,
}

/// Options for `mx_pocket_compute`. Initialise with
/// `mx_pocket_options_init(&o, sizeof o)` (which sets `struct_size`), then set
/// `tool_radius` and `stepover`: their defaults (0) are rejected.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_pocket_options {
    /// `sizeof(mx_pocket_options)` as the caller was compiled.
    pub struct_size: usize,
    /// Tool radius r, model units, > 0: the first ring is the offset at r.
    pub tool_radius: f64,
    /// Stepover s between rings, model units, > 0: ring k is the offset at
    /// r + k·s.
    pub stepover: f64,
    /// `MX_POCKET_INSIDE_OUT` (default) or `MX_POCKET_OUTSIDE_IN`.
    pub order: u32,
    /// At most this many levels (default 100 000); beyond it the pocket is
    /// cut short and `mx_pocket_info.truncated` is 1.
    pub max_levels: usize,
}

impl_options!(mx_pocket_options, v1: 40 bytes up to max_levels: usize, defaults: mx_pocket_options {
    struct_size: size_of::<Self>(),
    tool_radius: 0.0,
    stepover: 0.0,
    order: INSIDE_OUT,
    max_levels: PocketOptions::new(0.0, 0.0).max_levels,
});

/// Facts about a whole pocket.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_pocket_info {
    /// Number of rings (`mx_pocket_get_ring`).
    pub ring_count: usize,
    /// Number of levels (the deepest ring's level + 1).
    pub level_count: usize,
    /// Ring indices in machining order, `ring_count` entries; borrowed.
    pub order: *const usize,
    /// Number of uncut regions (`mx_pocket_get_uncut`).
    pub uncut_count: usize,
    /// Their total area, square model units.
    pub uncut_area: f64,
    /// 1 when `max_levels` cut the pocket short.
    pub truncated: i32,
}

/// One ring: the boundary of one connected region of the offset at its
/// level, which the tool centre follows.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_pocket_ring {
    /// Level k (0 at the tool radius).
    pub level: usize,
    /// Offset distance r + k·s, model units.
    pub distance: f64,
    /// 1 when `parent` holds the ring of level k − 1 that encloses this one.
    pub has_parent: i32,
    /// The enclosing ring (valid when `has_parent` is 1).
    pub parent: usize,
    /// The rings of level k + 1 inside this one, `child_count` entries;
    /// borrowed.
    pub children: *const usize,
    /// Number of children.
    pub child_count: usize,
    /// The outer loop first (counter-clockwise), then its holes
    /// (clockwise); borrowed.
    pub loops: mx_bulge_loops,
}

/// A region the tool does not cut.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_uncut_region {
    /// What was left.
    pub kind: mx_uncut_kind,
    /// Area, square model units.
    pub area: f64,
    /// The outer loop first (counter-clockwise), then its holes
    /// (clockwise); borrowed.
    pub loops: mx_bulge_loops,
}

pub(crate) fn cam_error(e: CamError) -> FfiError {
    match e {
        CamError::BadOption { .. } => FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, e.to_string()),
        CamError::Offset(o) => offset_error(o),
    }
}

/// Fills the caller's `mx_pocket_options` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_pocket_options o;
/// mx_pocket_options_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_options_init(out: *mut mx_pocket_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_pocket_options_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_pocket_options`.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_options_default(out: *mut mx_pocket_options) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

/// The pocket of the prepared shape: rings at r + k·s until nothing is
/// left, as a tree in machining order, with the uncut area. Writes a new
/// handle to `*out`. Fails with `MX_ERR_INVALID_ARGUMENT` (the option
/// named in the message) for a tool radius or stepover that is not finite
/// and > 0, an unknown order or `max_levels` 0; `*out` is then untouched.
///
/// # Safety
/// `offsets` NULL or a live handle; `options` NULL (then it fails: the
/// tool radius must be set) or valid; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_compute(
    offsets: *const mx_offsets,
    options: *const mx_pocket_options,
    out: *mut *mut mx_pocket,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        compute(out, offsets, options, |o, c| {
            let order = match c.order {
                INSIDE_OUT => PocketOrder::InsideOut,
                OUTSIDE_IN => PocketOrder::OutsideIn,
                k => {
                    return Err(FfiError::new(
                        mx_status::MX_ERR_INVALID_ARGUMENT,
                        format!(
                            "mx_pocket_options.order = {k}: use MX_POCKET_INSIDE_OUT (0) or MX_POCKET_OUTSIDE_IN (1)"
                        ),
                    ))
                }
            };
            let opts =
                PocketOptions { tool_radius: c.tool_radius, stepover: c.stepover, order, max_levels: c.max_levels };
            let p = in_pool(o.threads, || pocket(&o.offsets, &opts))?.map_err(cam_error)?;
            let rings = p.rings.iter().map(|r| FlatLoops::new(&r.loops)).collect();
            let uncut = p.uncut.iter().map(|u| FlatLoops::new(&u.loops)).collect();
            Ok(mx_pocket { pocket: p, rings, uncut })
        })
    }
}

/// Releases a pocket. NULL is a no-op.
///
/// # Safety
/// `pocket` must be NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_free(pocket: *mut mx_pocket) {
    // SAFETY: forwarded contract.
    unsafe { free(pocket) }
}

/// Counts, machining order and uncut area of the pocket.
///
/// # Safety
/// `pocket` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_get_info(pocket: *const mx_pocket, out: *mut mx_pocket_info) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(pocket, out, |h| {
            let p = &h.pocket;
            Ok(mx_pocket_info {
                ring_count: p.rings.len(),
                level_count: p.level_count(),
                order: ptr_or_null(&p.order),
                uncut_count: p.uncut.len(),
                uncut_area: p.uncut_area(),
                truncated: p.truncated.into(),
            })
        })
    }
}

/// Ring `index` (`MX_ERR_INDEX_OUT_OF_RANGE` unless below `ring_count`),
/// its children and loops borrowed.
///
/// # Safety
/// `pocket` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_get_ring(
    pocket: *const mx_pocket,
    index: usize,
    out: *mut mx_pocket_ring,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(pocket, out, |h| {
            let r = nth(&h.pocket.rings, index, "ring")?;
            Ok(mx_pocket_ring {
                level: r.level,
                distance: r.distance,
                has_parent: r.parent.is_some().into(),
                parent: r.parent.unwrap_or(0),
                children: ptr_or_null(&r.children),
                child_count: r.children.len(),
                loops: h.rings[index].view(),
            })
        })
    }
}

/// Uncut region `index` (`MX_ERR_INDEX_OUT_OF_RANGE` unless below
/// `uncut_count`), its loops borrowed.
///
/// # Safety
/// `pocket` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_pocket_get_uncut(
    pocket: *const mx_pocket,
    index: usize,
    out: *mut mx_uncut_region,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(pocket, out, |h| {
            let u = nth(&h.pocket.uncut, index, "uncut region")?;
            let kind = match u.kind {
                UncutKind::Scallop => mx_uncut_kind::MX_UNCUT_SCALLOP,
                UncutKind::Wall => mx_uncut_kind::MX_UNCUT_WALL,
            };
            Ok(mx_uncut_region { kind, area: u.area, loops: h.uncut[index].view() })
        })
    }
}
