//! The medial axis of a solid from C (issue 20, thesis 3.3): `mx_axis3d`,
//! a handle of its own (not `mx_axis`) so that no call made for a plane
//! axis can receive a space one. Vertices with radii, triangles, sheets
//! with their two contact classes; progress and cancellation while it
//! runs (a solid of a few thousand triangles takes minutes).

use super::axis::mx_progress_fn;
use super::ball::mx_ball;
use super::boundary::{check_threads, fill_items, guard, in_pool, nth};
use super::handles::{arg, create, free, impl_options, options_init, query, Boxed, Handle, Options};
use super::last_error::FfiError;
use super::mesh3d::mx_mesh3d;
use super::mesh3d_contacts::{ball_part_of, mx_ball_part3, mx_surface_part3};
use super::mesh3d_query::{kind_of, mx_contact3_kind};
use super::status::mx_status;
use crate::shape::SurfacePart;
use crate::space::{medial_axis_3d_watched, Axis3, Axis3Error, Opposite, Watch};
use std::ffi::{c_int, c_void};
use std::mem::size_of;

/// The medial axis of a solid under a space ball (`mx_mesh3d_axis`).
/// Immutable: a `const mx_axis3d*` may be used from several threads at
/// once.
pub struct mx_axis3d {
    pub(crate) axis: Axis3,
}

impl Handle for mx_axis3d {
    const ARG: &'static str = "axis";
    type Ownership = Boxed;
}

/// Options for `mx_mesh3d_axis`. Initialise with
/// `mx_axis3d_options_init(&o, sizeof o)`, then change fields.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_axis3d_options {
    /// `sizeof(mx_axis3d_options)` as the caller was compiled.
    pub struct_size: usize,
    /// Worker threads: 0 = the shared pool (all cores), else a pool of
    /// exactly this many (at most `MX_AXIS_MAX_THREADS`).
    pub threads: usize,
    /// Called on the calling thread about every 50 ms with the fraction of
    /// the contact domains done; a nonzero return cancels
    /// (`MX_ERR_CANCELLED`, soon after: the domains under way finish).
    /// NULL: none.
    pub progress: mx_progress_fn,
    /// Passed to `progress`.
    pub user: *mut c_void,
}

impl_options!(mx_axis3d_options, v1: 32 bytes up to user: *mut c_void, defaults: mx_axis3d_options {
    struct_size: size_of::<Self>(),
    threads: 0,
    progress: None,
    user: std::ptr::null_mut(),
});

/// Fills the caller's `mx_axis3d_options` with the defaults (`size` its
/// `sizeof`; as `mx_axis_options_init`).
///
/// # Safety
/// `out` NULL or valid for `size` bytes of writes.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_options_init(out: *mut mx_axis3d_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// A contact class of a sheet: a ball feature and a surface feature.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct mx_axis3d_class {
    /// The contact type: VF, EE or FV.
    pub kind: mx_contact3_kind,
    /// The ball's feature: a vertex, an edge or a facet.
    pub ball_part: mx_ball_part3,
    /// Its index into the ball's vertices, edges or facets.
    pub ball_part_index: usize,
    /// The surface's feature: a face (VF), an edge (EE) or a vertex (FV).
    pub surface_part: mx_surface_part3,
    /// A face: its triangle index twice; an edge: its two vertices, the
    /// lesser first; a vertex: its index twice.
    pub surface_index: [usize; 2],
}

/// A sheet of the axis: its two contact classes and triangles.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct mx_axis3d_sheet {
    /// The two classes, the lesser first.
    pub classes: [mx_axis3d_class; 2],
    /// 1 for a jump sheet (the classes' ball features share a vertex: its
    /// balls are maximal* but not maximal inscribed), else 0.
    pub jump: c_int,
    /// Its number of triangles (`mx_axis3d_sheet_triangles`).
    pub triangle_count: usize,
}

fn class_of(c: &Opposite) -> mx_axis3d_class {
    let (ball_part, ball_part_index) = ball_part_of(c.ball);
    let (surface_part, surface_index) = match c.surface {
        SurfacePart::Vertex(v) => (mx_surface_part3::MX_SURFACE_VERTEX, [v as usize; 2]),
        SurfacePart::Edge([a, b]) => (mx_surface_part3::MX_SURFACE_EDGE, [a as usize, b as usize]),
        SurfacePart::Face(t) => (mx_surface_part3::MX_SURFACE_FACE, [t as usize; 2]),
    };
    mx_axis3d_class { kind: kind_of(c.kind), ball_part, ball_part_index, surface_part, surface_index }
}

fn axis_error(e: Axis3Error) -> FfiError {
    let status = match e {
        Axis3Error::Cancelled => mx_status::MX_ERR_CANCELLED,
        Axis3Error::FaceParallelToBall { .. }
        | Axis3Error::EdgeParallelToBall { .. }
        | Axis3Error::CornerParallelToBall { .. }
        | Axis3Error::BallFacetNotPlanar { .. } => mx_status::MX_ERR_DEGENERATE,
        Axis3Error::OppositeFaceVertex { .. } | Axis3Error::Arrangement { .. } => mx_status::MX_ERR_NUMERICAL,
    };
    FfiError::new(status, format!("mx_mesh3d_axis: {e}"))
}

/// Computes the medial axis of the solid `mesh` under the space ball
/// `ball` (thesis 3.3): a non-manifold triangle mesh of planar sheets
/// whose vertices carry the radius of their largest ball. `options` NULL:
/// the defaults. Errors: `MX_ERR_INVALID_ARGUMENT` for a plane ball or bad
/// options, `MX_ERR_DEGENERATE` for input outside general position (a
/// face, reflex edge or vertex's edge parallel to a ball feature, or a
/// turned ball's facet not exactly planar with reflex edges; the message
/// names the element), `MX_ERR_NUMERICAL` when a contact arrangement could
/// not be resolved, `MX_ERR_CANCELLED`; `*out` is then untouched.
///
/// # Safety
/// `mesh`, `ball` NULL or live handles; `options` NULL or valid; `out`
/// NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_mesh3d_axis(
    mesh: *const mx_mesh3d,
    ball: *const mx_ball,
    options: *const mx_axis3d_options,
    out: *mut *mut mx_axis3d,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let m = &arg(mesh)?.inner;
            let b = arg(ball)?.as_space()?;
            let o = mx_axis3d_options::read_or_default(options)?;
            check_threads("mx_axis3d_options", o.threads)?;
            let watch = Watch::default();
            let cancelled = || {
                // SAFETY: the caller supplied the callback and `user` for
                // this call, on this thread.
                o.progress.is_some_and(|f| f(watch.fraction(), o.user) != 0)
            };
            if cancelled() {
                return Err(axis_error(Axis3Error::Cancelled));
            }
            let got = std::thread::scope(|scope| {
                let job = scope.spawn(|| in_pool(o.threads, || medial_axis_3d_watched(m, b, &watch)));
                while !job.is_finished() {
                    std::thread::sleep(std::time::Duration::from_millis(50));
                    if cancelled() {
                        watch.cancel();
                    }
                }
                job.join()
            });
            let axis = match got {
                Ok(r) => r?.map_err(axis_error)?,
                Err(_) => return Err(FfiError::new(mx_status::MX_ERR_PANIC, "mx_mesh3d_axis: a worker panicked")),
            };
            if let Some(f) = o.progress {
                f(1.0, o.user);
            }
            Ok(mx_axis3d { axis })
        })
    }
}

/// Releases an axis. NULL is a no-op.
///
/// # Safety
/// `axis` NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_free(axis: *mut mx_axis3d) {
    // SAFETY: forwarded contract.
    unsafe { free(axis) }
}

/// Copies the vertices as x, y, z, r quadruples (`r` the radius of the
/// largest ball `c + r·B` inside the solid there) into `xyzr` of
/// `capacity` vertices and writes their number to `*count` (capacity 0: a
/// size query; a shorter buffer: `MX_ERR_BUFFER_TOO_SMALL`, nothing
/// written).
///
/// # Safety
/// `axis` NULL or a live handle; `xyzr` NULL or `4 * capacity` writable
/// doubles; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_vertices(
    axis: *const mx_axis3d,
    xyzr: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let a = unsafe { arg(axis)? };
        let n = a.axis.vertices.len();
        // SAFETY: caller contract.
        unsafe {
            fill_items((xyzr, "xyzr"), (capacity, count), (n, 4), a.axis.vertices.iter().flatten().copied(), || {
                format!("the axis has {n} vertices, the buffer room for {capacity}")
            })
        }
    })
}

/// Copies the triangles as vertex index triples into `abc` of `capacity`
/// triangles and writes their number to `*count` (the buffer protocol of
/// `mx_axis3d_vertices`).
///
/// # Safety
/// `axis` NULL or a live handle; `abc` NULL or `3 * capacity` writable
/// `uint32_t`; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_triangles(
    axis: *const mx_axis3d,
    abc: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let a = unsafe { arg(axis)? };
        let n = a.axis.triangles.len();
        // SAFETY: caller contract.
        unsafe {
            fill_items((abc, "abc"), (capacity, count), (n, 3), a.axis.triangles.iter().flatten().copied(), || {
                format!("the axis has {n} triangles, the buffer room for {capacity}")
            })
        }
    })
}

/// Number of sheets.
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_sheet_count(axis: *const mx_axis3d, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(axis, out, |a| Ok(a.axis.sheets.len())) }
}

/// Sheet `index` (`MX_ERR_INDEX_OUT_OF_RANGE` unless below
/// `mx_axis3d_sheet_count`).
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_get_sheet(
    axis: *const mx_axis3d,
    index: usize,
    out: *mut mx_axis3d_sheet,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(axis, out, |a| {
            let s = nth(&a.axis.sheets, index, "sheet")?;
            Ok(mx_axis3d_sheet {
                classes: [class_of(&s.classes[0]), class_of(&s.classes[1])],
                jump: c_int::from(s.jump),
                triangle_count: s.triangles.len(),
            })
        })
    }
}

/// Copies the triangle indices (into `mx_axis3d_triangles`) of sheet
/// `index` into `triangles` of `capacity` and writes their number to
/// `*count` (the buffer protocol of `mx_axis3d_vertices`).
///
/// # Safety
/// `axis` NULL or a live handle; `triangles` NULL or `capacity` writable
/// `uint32_t`; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis3d_sheet_triangles(
    axis: *const mx_axis3d,
    index: usize,
    triangles: *mut u32,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        // SAFETY: caller contract.
        let a = unsafe { arg(axis)? };
        let s = nth(&a.axis.sheets, index, "sheet")?;
        let n = s.triangles.len();
        // SAFETY: caller contract.
        unsafe {
            fill_items((triangles, "triangles"), (capacity, count), (n, 1), s.triangles.iter().copied(), || {
                format!("sheet {index} has {n} triangles, the buffer room for {capacity}")
            })
        }
    })
}
