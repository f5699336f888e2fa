//! C functions for the medial axis of a 2D shape: compute, inspect, sample,
//! free. Mirrors `crate::plane` (`medial_axis`, `MedialAxis2d`); no geometry
//! is computed here.

use super::boundary::{check_out, fill_items, guard, nth, run_with_progress};
use super::handles::{arg, compute, free, impl_options, options_default, options_init, query, Boxed, Handle};
use super::last_error::FfiError;
use super::shape2d::mx_shape2d;
use super::status::mx_status;
use crate::kernel::bisector::ConicKind;
use crate::plane::{medial_axis, AxisEdge, AxisError, AxisOptions, MedialAxis2d, NodeKind, Primitive};
use crate::polymetric::BallAxis;
use crate::shape::Shape2d;
use std::ffi::{c_int, c_void};
use std::mem::size_of;

/// A computed medial axis of a 2D shape: nodes (maximal disks) joined by
/// conic edges. Opaque; create with `mx_axis_compute`, release with
/// `mx_axis_free`. It owns a copy of the shape, so it stays valid after the
/// shape is freed. Immutable: a `const mx_axis*` may be used from several
/// threads at once.
pub struct mx_axis {
    pub(crate) shape: Shape2d,
    /// The Euclidean axis (empty for an axis under a ball).
    pub(crate) axis: MedialAxis2d,
    /// The axis under a polygon ball (`mx_axis_compute_with_ball`).
    pub(crate) ball: Option<BallAxis>,
}

impl mx_axis {
    /// The Euclidean axis, for the computations built on it alone
    /// (`what` names the caller for the message).
    pub(crate) fn euclidean(&self, what: &str) -> Result<&MedialAxis2d, FfiError> {
        match self.ball {
            None => Ok(&self.axis),
            Some(_) => Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("{what}: the axis was computed under a polygon ball; use mx_axis_offset_layer for its offsets"),
            )),
        }
    }
}

impl Handle for mx_axis {
    const ARG: &'static str = "axis";
    type Ownership = Boxed;
}

/// Progress callback: `fraction` in [0, 1] of the work done; `user` is
/// `mx_axis_options.user`. Return 0 to go on, nonzero to cancel. Called on
/// the thread that called `mx_axis_compute`; it must not throw or unwind.
pub type mx_progress_fn = Option<unsafe extern "C" fn(fraction: f64, user: *mut c_void) -> c_int>;

/// Options for `mx_axis_compute`. Initialise with
/// `mx_axis_options_init(&o, sizeof o)` (which sets `struct_size`), then change fields.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_axis_options {
    /// `sizeof(mx_axis_options)` as the caller was compiled; lets later
    /// versions add fields without breaking old callers.
    pub struct_size: usize,
    /// Seed of the divide step's random choices. The axis is the same for
    /// every seed up to rounding, and bit-identical for one seed whatever
    /// the thread count.
    pub seed: u64,
    /// Worker threads: 0 = the shared pool (all cores, or
    /// `RAYON_NUM_THREADS`), else a pool of exactly this many threads for
    /// this call (at most `MX_AXIS_MAX_THREADS`).
    pub threads: usize,
    /// Optional progress callback (NULL = none). Coarse for now: called with
    /// 0 before the computation and with 1 after it. A nonzero return at 0
    /// cancels (`MX_ERR_CANCELLED`); the return value at 1 is ignored (the
    /// axis is complete by then).
    pub progress: mx_progress_fn,
    /// Passed unchanged to `progress`.
    pub user: *mut c_void,
}

/// The largest accepted `mx_axis_options.threads`.
pub const MX_AXIS_MAX_THREADS: usize = 1024;

// `AxisOptions::default()` in C form.
impl_options!(mx_axis_options, v1: 40 bytes up to user: *mut c_void, defaults: mx_axis_options {
    struct_size: size_of::<Self>(),
    seed: AxisOptions::default().seed,
    threads: 0,
    progress: None,
    user: std::ptr::null_mut(),
});

/// Fills the caller's `mx_axis_options` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_axis_options o;
/// mx_axis_options_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_options_init(out: *mut mx_axis_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_axis_options_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_axis_options`.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_options_default(out: *mut mx_axis_options) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

/// What a node of the medial axis is.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum mx_node_kind {
    /// Three or more edges meet: the disk touches three or more primitives.
    MX_NODE_BRANCH = 0,
    /// A convex vertex of the boundary: radius 0, an end of the axis.
    MX_NODE_CORNER = 1,
    /// The centre of an arc whose whole circle lies inside the shape: an end
    /// of the axis at a curvature maximum.
    MX_NODE_LEAF = 2,
    /// Two edges meet and the pair of boundary primitives changes.
    MX_NODE_JOINT = 3,
    /// Under a polygon ball: two edges meet where a ball vertex sits on a
    /// shape vertex (thesis 3.1.3; where a pruned corner joins the axis).
    MX_NODE_PSEUDO_BRANCH = 4,
}

/// The kind of conic an edge of the medial axis lies on.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum mx_conic_kind {
    /// A straight line.
    MX_CONIC_LINE = 0,
    /// A parabola.
    MX_CONIC_PARABOLA = 1,
    /// An ellipse.
    MX_CONIC_ELLIPSE = 2,
    /// A hyperbola branch.
    MX_CONIC_HYPERBOLA = 3,
}

/// A node of the medial axis: the maximal disk centred there.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_axis_node {
    /// Centre x, model units.
    pub x: f64,
    /// Centre y, model units.
    pub y: f64,
    /// Radius of the maximal disk, model units (0 at a convex corner).
    pub r: f64,
    /// What happens here.
    pub kind: mx_node_kind,
}

/// A boundary primitive an edge is equidistant from, in the caller's input
/// numbering (as given to `mx_shape2d_from_*`, before any loop reversal).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_axis_site {
    /// Loop index (0 = outer boundary).
    pub loop_index: usize,
    /// Input element index within the loop when `is_vertex` is 0; input
    /// vertex index (a reflex vertex) when `is_vertex` is 1.
    pub index: usize,
    /// 1 for a reflex vertex, 0 for the inside of a segment or arc.
    pub is_vertex: i32,
}

/// An edge of the medial axis: a piece of the conic of centres equidistant
/// from its two sites.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_axis_edge {
    /// Node index at the start.
    pub from: usize,
    /// Node index at the end.
    pub to: usize,
    /// The conic the edge lies on.
    pub kind: mx_conic_kind,
    /// The two sites; `sites[0]` is on the left when walking from `from` to
    /// `to`.
    pub sites: [mx_axis_site; 2],
}

pub(crate) fn axis_error(e: AxisError) -> FfiError {
    let message = e.to_string();
    match e {
        AxisError::Augment { hole } => {
            let mut f = FfiError::new(mx_status::MX_ERR_NUMERICAL, message);
            f.info.loop_index = hole as i64;
            f
        }
        AxisError::Numerical(p, _) => {
            let mut f = FfiError::new(mx_status::MX_ERR_NUMERICAL, message);
            f.info.has_position = 1;
            f.info.x = p.x;
            f.info.y = p.y;
            f
        }
    }
}

/// Computes the medial axis of `shape` (thesis Algorithm 2) and writes a new
/// handle to `*out`. `options` may be NULL (defaults). The handle keeps its
/// own copy of the shape. Shapes with holes give an axis with one cycle
/// per hole. Fails with `MX_ERR_NUMERICAL` when the construction breaks
/// down (position in `mx_error_info`, or the hole's `loop_index` when no
/// augmenting disk was found for it), `MX_ERR_CANCELLED` when the
/// progress callback asks to stop, `MX_ERR_INVALID_ARGUMENT` for bad
/// options; `*out` is then untouched.
///
/// # Safety
/// `shape` NULL or a live handle; `options` NULL or valid; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_compute(
    shape: *const mx_shape2d,
    options: *const mx_axis_options,
    out: *mut *mut mx_axis,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        compute(out, shape, options, |s, o| {
            // `threads` is checked by `run_with_progress`.
            let opts = AxisOptions { seed: o.seed, ..AxisOptions::default() };
            let axis = run_with_progress("mx_axis_compute", "mx_axis_options", o.threads, o.progress, o.user, || {
                medial_axis(&s.inner, &opts).map_err(axis_error)
            })?;
            Ok(mx_axis { shape: s.inner.clone(), axis, ball: None })
        })
    }
}

/// Releases an axis. NULL is a no-op.
///
/// # Safety
/// `axis` must be NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_free(axis: *mut mx_axis) {
    // SAFETY: forwarded contract.
    unsafe { free(axis) }
}

fn edge_of(a: &mx_axis, i: usize) -> Result<&AxisEdge, FfiError> {
    nth(&a.axis.edges, i, "edge")
}

fn site(shape: &Shape2d, p: Primitive) -> mx_axis_site {
    let (loop_index, i) = (p.loop_index(), p.index());
    match p {
        Primitive::Element { .. } => {
            mx_axis_site { loop_index, index: shape.input_element_index(loop_index, i), is_vertex: 0 }
        }
        Primitive::Vertex { .. } => {
            mx_axis_site { loop_index, index: shape.input_vertex_index(loop_index, i), is_vertex: 1 }
        }
    }
}

/// Number of nodes.
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_node_count(axis: *const mx_axis, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(axis, out, |a| Ok(a.ball.as_ref().map_or(a.axis.nodes.len(), |b| b.nodes.len()))) }
}

/// Number of edges.
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_edge_count(axis: *const mx_axis, out: *mut usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(axis, out, |a| Ok(a.ball.as_ref().map_or(a.axis.edges.len(), |b| b.edges.len()))) }
}

/// Node `index` (`MX_ERR_INDEX_OUT_OF_RANGE` unless below
/// `mx_axis_node_count`).
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_get_node(axis: *const mx_axis, index: usize, out: *mut mx_axis_node) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(axis, out, |a| {
            if let Some(b) = &a.ball {
                return super::ball_axis::node(b, index);
            }
            let n = nth(&a.axis.nodes, index, "node")?;
            let kind = match n.kind {
                NodeKind::Branch => mx_node_kind::MX_NODE_BRANCH,
                NodeKind::Corner => mx_node_kind::MX_NODE_CORNER,
                NodeKind::Leaf => mx_node_kind::MX_NODE_LEAF,
                NodeKind::Joint => mx_node_kind::MX_NODE_JOINT,
            };
            Ok(mx_axis_node { x: n.point.x, y: n.point.y, r: n.radius, kind })
        })
    }
}

/// Edge `index` (`MX_ERR_INDEX_OUT_OF_RANGE` unless below
/// `mx_axis_edge_count`): its nodes, conic kind and sites.
///
/// # Safety
/// `axis` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_get_edge(axis: *const mx_axis, index: usize, out: *mut mx_axis_edge) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(axis, out, |a| {
            if let Some(b) = &a.ball {
                return super::ball_axis::edge(&a.shape, b, index);
            }
            let e = edge_of(a, index)?;
            let kind = match e.kind {
                ConicKind::Line => mx_conic_kind::MX_CONIC_LINE,
                ConicKind::Parabola => mx_conic_kind::MX_CONIC_PARABOLA,
                ConicKind::Ellipse => mx_conic_kind::MX_CONIC_ELLIPSE,
                ConicKind::Hyperbola => mx_conic_kind::MX_CONIC_HYPERBOLA,
            };
            Ok(mx_axis_edge { from: e.from, to: e.to, kind, sites: e.sites.map(|p| site(&a.shape, p)) })
        })
    }
}

/// The smallest accepted sampling tolerance, as a fraction of the shape's
/// bounding-box diagonal (finer requests would need billions of samples).
pub const MX_AXIS_MIN_RELATIVE_SAMPLE_TOLERANCE: f64 = 1e-12;

/// Samples edge `index` from its `from` node to its `to` node as `x, y, r`
/// triples (disk centre and radius, model units): the polyline through the
/// centres deviates from the true conic by at most `tolerance` model units
/// (positive, at least `MX_AXIS_MIN_RELATIVE_SAMPLE_TOLERANCE` × the
/// bounding-box diagonal). The first and last triples are the end nodes.
///
/// `capacity` is the number of doubles `xyr` holds (3 per sample, as in
/// `mx_shape2d_loop_vertices`); `*count` receives the number of samples.
/// Size query: `capacity` 0 (`xyr` may be NULL) writes only `*count` and
/// returns `MX_OK`. Otherwise a buffer shorter than 3 × the sample count
/// gives `MX_ERR_BUFFER_TOO_SMALL` with nothing written. Sampling is
/// deterministic, so a query and a fill with the same arguments agree.
///
/// # Safety
/// `axis` NULL or a live handle; `xyr` NULL or `capacity` writable doubles;
/// `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_axis_edge_sample(
    axis: *const mx_axis,
    index: usize,
    tolerance: f64,
    xyr: *mut f64,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        check_out(count, "count")?;
        // SAFETY: caller contract.
        let a = unsafe { arg(axis)? };
        let min = MX_AXIS_MIN_RELATIVE_SAMPLE_TOLERANCE * a.shape.bbox().diagonal();
        if !(tolerance.is_finite() && tolerance >= min) {
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("tolerance = {tolerance}: use a finite length of at least {min} (1e-12 x the diagonal)"),
            ));
        }
        // Under a ball every edge is straight with an affine radius: its
        // ends are the whole edge.
        let samples = match &a.ball {
            Some(b) => super::ball_axis::ends(b, index)?,
            None => edge_of(a, index)?.sample(&a.shape, &a.axis.nodes, tolerance),
        };
        let n = samples.len();
        let xyr_of = samples.iter().flat_map(|d| [d.center.x, d.center.y, d.radius]);
        // SAFETY: caller contract: `xyr` NULL or `3 * capacity` writable doubles.
        unsafe {
            fill_items((xyr, "xyr"), (capacity, count), (n, 3), xyr_of, || {
                format!("edge {index} has {n} samples, the buffer room for {capacity}")
            })?
        };
        Ok(())
    })
}
