//! C functions for Voronoi diagrams of sites: compute, label, regions,
//! nearest site, free. Mirrors `crate::plane::voronoi`; the geometry of
//! nodes and edges is read through the diagram's `mx_axis`
//! (`mx_voronoi_axis`), whose node and edge indices these functions use.

use super::axis::{axis_error, mx_axis, mx_progress_fn};
use super::ball_voronoi::Diagram;
use super::boundary::{check_out, deref, fill, guard, nth, run_with_progress, slice, write_out};
use super::handles::{
    arg, create, free, impl_options, lend, options_default, options_init, query, Boxed, Handle, Lends, Options,
};
use super::last_error::FfiError;
use super::shape2d::split_bulges;
use super::status::mx_status;
use crate::kernel::Point;
use crate::plane::voronoi::{voronoi, SiteId, Sites, VoronoiError, VoronoiOptions};
use crate::plane::{AxisOptions, SiteRegion};
use crate::shape::ShapeOptions;
use std::ffi::c_void;
use std::mem::size_of;

/// A computed Voronoi diagram. Opaque; create with `mx_voronoi_compute`,
/// release with `mx_voronoi_free`. Immutable: a `const mx_voronoi*` may be
/// used from several threads at once.
pub struct mx_voronoi {
    /// The frame with the sites as holes and its medial axis (for a
    /// Euclidean diagram moved out of `diagram`, whose `axis` is left
    /// empty: the labels below index it).
    pub(super) axis: mx_axis,
    pub(super) diagram: Diagram,
}

impl Handle for mx_voronoi {
    const ARG: &'static str = "vd";
    type Ownership = Boxed;
}

impl Lends<mx_axis> for mx_voronoi {
    fn lent(&self) -> &mx_axis {
        &self.axis
    }
}

/// The input sites, as plain arrays (model units). Every array may be NULL
/// when its count is 0. Sites must be pairwise disjoint.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_sites {
    /// `x, y` pairs, `2 × point_count` doubles.
    pub points_xy: *const f64,
    /// Number of point sites.
    pub point_count: usize,
    /// `x, y, bulge` triples of every open curve back to back (the bulge of
    /// a curve's last vertex is ignored).
    pub curves_xyb: *const f64,
    /// Doubles in `curves_xyb`: 3 × the curve lengths' sum.
    pub curves_xyb_len: usize,
    /// Vertex count of each curve.
    pub curve_lengths: *const usize,
    /// Number of curve sites.
    pub curve_count: usize,
    /// `x, y, bulge` triples of every closed region back to back, as the
    /// holes of `mx_shape2d_from_bulges`.
    pub regions_xyb: *const f64,
    /// Doubles in `regions_xyb`: 3 × the region lengths' sum.
    pub regions_xyb_len: usize,
    /// Vertex count of each region.
    pub region_lengths: *const usize,
    /// Number of region sites.
    pub region_count: usize,
    /// The caller's outer boundary Γ as `x, y, bulge` triples enclosing
    /// every site (a site itself then), or NULL to let the library choose
    /// a frame that keeps every Voronoi vertex.
    pub boundary_xyb: *const f64,
    /// Vertex count of the boundary (0 with NULL); the array holds 3 ×
    /// this many doubles.
    pub boundary_count: usize,
}

/// Options for `mx_voronoi_compute`. Initialise with
/// `mx_voronoi_options_init(&o, sizeof o)` (which sets `struct_size`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct mx_voronoi_options {
    /// `sizeof(mx_voronoi_options)` as the caller was compiled.
    pub struct_size: usize,
    /// Seed of the divide step's random choices (as `mx_axis_options.seed`).
    pub seed: u64,
    /// Worker threads, as `mx_axis_options.threads`.
    pub threads: usize,
    /// Absolute touching tolerance, model units; 0 = 1e-9 × the sites'
    /// bounding-box diagonal.
    pub tolerance: f64,
    /// Optional progress callback, as `mx_axis_options.progress` (called
    /// with 0 before and 1 after; nonzero at 0 cancels).
    pub progress: mx_progress_fn,
    /// Passed unchanged to `progress`.
    pub user: *mut c_void,
}

impl_options!(mx_voronoi_options, v1: 48 bytes up to user: *mut c_void, defaults: mx_voronoi_options {
    struct_size: size_of::<Self>(),
    seed: AxisOptions::default().seed,
    threads: 0,
    tolerance: 0.0,
    progress: None,
    user: std::ptr::null_mut(),
});

/// What kind of site an `mx_site` is.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum mx_site_kind {
    /// `points[index]`.
    MX_SITE_POINT = 0,
    /// `curves[index]`.
    MX_SITE_CURVE = 1,
    /// `regions[index]`.
    MX_SITE_REGION = 2,
    /// The outer boundary (the caller's, or the library's frame); `index` 0.
    MX_SITE_BOUNDARY = 3,
}

/// A site, numbered as the caller gave it.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_site {
    /// Which list.
    pub kind: mx_site_kind,
    /// Index in that list.
    pub index: usize,
}

/// What an edge of the diagram's axis separates.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_voronoi_edge {
    /// The sites on either side; `sides[0]` is on the left walking from the
    /// edge's `from` node to its `to` node (`mx_axis_get_edge`).
    pub sides: [mx_site; 2],
    /// 1 when both sides are one site (points with two nearest points on
    /// it), else 0.
    pub is_self: i32,
    /// 1 when the edge belongs to the sites' diagram: 0 only for edges
    /// facing the library's frame.
    pub in_diagram: i32,
}

/// Facts about a whole diagram.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_voronoi_info {
    /// 1 when the library chose the frame, 0 for the caller's boundary.
    pub auto_frame: i32,
    /// 1 when every Voronoi vertex of the sites lies inside the frame; 0
    /// when the frame stopped growing first (nearly collinear sites).
    pub complete: i32,
    /// Number of sites with a region (the library's frame has none).
    pub region_count: usize,
}

/// The region of one site.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct mx_voronoi_region {
    /// Edges in the boundary walk (`mx_voronoi_region_walk`).
    pub walk_length: usize,
    /// Closed walks the boundary edges form: 1 for a valid diagram, 0 for a
    /// site without edges to other sites.
    pub walks: usize,
    /// Number of the site's self-edges.
    pub self_edge_count: usize,
    /// 1 when the region reaches the library's frame (unbounded).
    pub unbounded: i32,
}

/// The site nearest to a point.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct mx_nearest_site {
    /// The site.
    pub site: mx_site,
    /// Its distance, model units.
    pub distance: f64,
    /// The nearest point on it, x.
    pub foot_x: f64,
    /// The nearest point on it, y.
    pub foot_y: f64,
}

/// Fills the caller's `mx_voronoi_options` with the defaults: `size` is its
/// `sizeof` as the caller was compiled; the first `min(size, this
/// release's size)` bytes are written and `struct_size` set to that, so an
/// older caller's struct is never overrun. `MX_ERR_INVALID_ARGUMENT` for a
/// size below the first release's.
///
/// ```c
/// mx_voronoi_options o;
/// mx_voronoi_options_init(&o, sizeof o);
/// ```
///
/// # Safety
/// `out` must be NULL or point to `size` writable bytes.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_options_init(out: *mut mx_voronoi_options, size: usize) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_init(out, size) }
}

/// For callers built against medax 0.1 (not in the header): the defaults
/// in the 0.1 layout only, `struct_size` its size, nothing written past
/// it. New code calls `mx_voronoi_options_init`.
///
/// # Safety
/// `out` must be NULL or point to a writable 0.1 `mx_voronoi_options`.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_options_default(out: *mut mx_voronoi_options) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { options_default(out) }
}

fn site_c(s: SiteId) -> mx_site {
    let (kind, index) = match s {
        SiteId::Point(i) => (mx_site_kind::MX_SITE_POINT, i),
        SiteId::Curve(i) => (mx_site_kind::MX_SITE_CURVE, i),
        SiteId::Region(i) => (mx_site_kind::MX_SITE_REGION, i),
        SiteId::Frame => (mx_site_kind::MX_SITE_BOUNDARY, 0),
    };
    mx_site { kind, index }
}

/// A site named by C: `kind` an `mx_site_kind` value, read as a plain
/// integer because an out-of-range enum value would be undefined in Rust.
fn site_rust(kind: u32, index: usize) -> Result<SiteId, FfiError> {
    Ok(match kind {
        0 => SiteId::Point(index),
        1 => SiteId::Curve(index),
        2 => SiteId::Region(index),
        3 => SiteId::Frame,
        _ => {
            return Err(FfiError::new(
                mx_status::MX_ERR_INVALID_ARGUMENT,
                format!("site kind {kind}: use an mx_site_kind value (0 to 3)"),
            ))
        }
    })
}

fn voronoi_error(e: VoronoiError) -> FfiError {
    let message = e.to_string();
    match e {
        VoronoiError::NoSites => FfiError::new(mx_status::MX_ERR_EMPTY, message),
        VoronoiError::Invalid { error, .. } => {
            let mut f = FfiError::from(error);
            f.message = message;
            f
        }
        VoronoiError::Axis(a) => axis_error(a),
    }
}

/// The sites from C arrays, checked.
pub(super) unsafe fn read_sites(s: &mx_sites) -> Result<(Sites, Option<Vec<crate::shape::Vertex>>), FfiError> {
    let two = s.point_count.checked_mul(2).ok_or_else(|| {
        FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("point_count = {} is too large", s.point_count))
    })?;
    // SAFETY: caller contract on every pointer/count pair.
    let (pts, curve_lens, region_lens) = unsafe {
        (
            slice(s.points_xy, two, "points_xy")?,
            slice(s.curve_lengths, s.curve_count, "curve_lengths")?,
            slice(s.region_lengths, s.region_count, "region_lengths")?,
        )
    };
    let boundary_len = s.boundary_count.checked_mul(3).ok_or_else(|| {
        FfiError::new(mx_status::MX_ERR_INVALID_ARGUMENT, format!("boundary_count = {} is too large", s.boundary_count))
    })?;
    // SAFETY: as above; `split_bulges` checks the lengths add up.
    let (curves_xyb, regions_xyb, boundary_xyb) = unsafe {
        (
            slice(s.curves_xyb, s.curves_xyb_len, "curves_xyb")?,
            slice(s.regions_xyb, s.regions_xyb_len, "regions_xyb")?,
            slice(s.boundary_xyb, boundary_len, "boundary_xyb")?,
        )
    };
    let sites = Sites {
        points: pts.chunks_exact(2).map(|c| Point::new(c[0], c[1])).collect(),
        curves: split_bulges(curves_xyb, curve_lens, "curves_xyb")?,
        regions: split_bulges(regions_xyb, region_lens, "regions_xyb")?,
    };
    let boundary = if s.boundary_xyb.is_null() {
        None
    } else {
        split_bulges(boundary_xyb, &[s.boundary_count], "boundary_xyb")?.pop()
    };
    Ok((sites, boundary))
}

/// Computes the Voronoi diagram of `sites` (thesis 2.3: the medial axis of
/// the frame with the sites as holes) and writes a new handle to `*out`.
/// `options` may be NULL. Fails with `MX_ERR_EMPTY` without sites,
/// a validation status (e.g. `MX_ERR_INTERSECTION`) naming the site for
/// overlapping or invalid sites, `MX_ERR_NUMERICAL` or `MX_ERR_CANCELLED`
/// as `mx_axis_compute`; `*out` is then untouched.
///
/// # Safety
/// `sites` NULL or valid with arrays valid for their counts; `options` NULL
/// or valid; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_compute(
    sites: *const mx_sites,
    options: *const mx_voronoi_options,
    out: *mut *mut mx_voronoi,
) -> mx_status {
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (s, o) = (deref(sites, "sites")?, mx_voronoi_options::read_or_default(options)?);
            let shape = shape_options(&o)?;
            let (sites, boundary) = read_sites(s)?;
            let opts = VoronoiOptions { axis: AxisOptions { seed: o.seed, ..AxisOptions::default() }, shape, boundary };
            let mut diagram =
                run_with_progress("mx_voronoi_compute", "mx_voronoi_options", o.threads, o.progress, o.user, || {
                    voronoi(&sites, &opts).map_err(voronoi_error)
                })?;
            let axis = mx_axis { shape: diagram.shape().clone(), axis: std::mem::take(&mut diagram.axis), ball: None };
            Ok(mx_voronoi { axis, diagram: Diagram::Euclidean(diagram) })
        })
    }
}

/// Releases a diagram (and its axis). NULL is a no-op.
///
/// # Safety
/// `vd` must be NULL or a handle from medax not yet freed.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_free(vd: *mut mx_voronoi) {
    // SAFETY: forwarded contract.
    unsafe { free(vd) }
}

/// The diagram's medial axis: nodes, edges and their samples through the
/// `mx_axis_*` functions (loop 0 of its sites is the frame, then one loop
/// per region, curve and point in that order; a curve's loop runs along
/// it and back, its way-back elements naming the curve element they run
/// over). Borrowed: valid until `mx_voronoi_free`; do not free it.
///
/// # Safety
/// `vd` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_axis(vd: *const mx_voronoi, out: *mut *const mx_axis) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { lend(vd, out) }
}

/// Facts about the diagram.
///
/// # Safety
/// `vd` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_get_info(vd: *const mx_voronoi, out: *mut mx_voronoi_info) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(vd, out, |v| {
            Ok(mx_voronoi_info {
                auto_frame: v.diagram.auto_frame().into(),
                complete: v.diagram.complete().into(),
                region_count: v.diagram.regions().len(),
            })
        })
    }
}

/// What axis edge `index` separates.
///
/// # Safety
/// `vd` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_get_edge(
    vd: *const mx_voronoi,
    index: usize,
    out: *mut mx_voronoi_edge,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(vd, out, |v| {
            let e = nth(v.diagram.edges(), index, "edge")?;
            let facing_frame = v.diagram.auto_frame() && e.sides.contains(&SiteId::Frame);
            Ok(mx_voronoi_edge {
                sides: e.sides.map(site_c),
                is_self: e.self_edge.into(),
                in_diagram: (!facing_frame).into(),
            })
        })
    }
}

/// 1 when axis node `index` is where an edge between sites meets the
/// library's frame (it runs on to infinity there), else 0.
///
/// # Safety
/// `vd` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_node_frontier(vd: *const mx_voronoi, index: usize, out: *mut i32) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe { query(vd, out, |v| nth(v.diagram.frontier(), index, "node").map(|&b| b.into())) }
}

fn region_of(v: &mx_voronoi, kind: u32, index: usize) -> Result<&SiteRegion, FfiError> {
    let site = site_rust(kind, index)?;
    v.diagram
        .region(site)
        .ok_or_else(|| FfiError::new(mx_status::MX_ERR_INDEX_OUT_OF_RANGE, format!("no region for {site}")))
}

/// The region of the site (`site_kind` an `mx_site_kind` value,
/// `site_index` its index; `MX_ERR_INDEX_OUT_OF_RANGE` for a site that
/// does not exist, or the library's frame).
///
/// # Safety
/// `vd` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_get_region(
    vd: *const mx_voronoi,
    site_kind: u32,
    site_index: usize,
    out: *mut mx_voronoi_region,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(vd, out, |v| {
            let r = region_of(v, site_kind, site_index)?;
            Ok(mx_voronoi_region {
                walk_length: r.boundary.len(),
                walks: r.walks,
                self_edge_count: r.self_edges.len(),
                unbounded: r.unbounded.into(),
            })
        })
    }
}

/// The boundary walk of the site's region (site as in
/// `mx_voronoi_get_region`), counter-clockwise round the site, each
/// self-edge of the site twice (once each way):
/// `edges[k]` an axis edge index, `forward[k]` 1 when walked from its
/// `from` node to its `to` node. `capacity` entries each (`forward` may be
/// NULL); `*count` receives the walk length. Size query: `capacity` 0
/// writes only `*count`; a shorter buffer gives `MX_ERR_BUFFER_TOO_SMALL`.
///
/// # Safety
/// `vd` NULL or a live handle; `edges` and `forward` NULL or `capacity`
/// writable entries; `count` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_region_walk(
    vd: *const mx_voronoi,
    site_kind: u32,
    site_index: usize,
    edges: *mut usize,
    forward: *mut i32,
    capacity: usize,
    count: *mut usize,
) -> mx_status {
    guard(|| {
        check_out(count, "count")?;
        // SAFETY: caller contract.
        let v = unsafe { arg(vd)? };
        let walk = &region_of(v, site_kind, site_index)?.boundary;
        if capacity != 0 {
            let too_small = || format!("the walk has {} edges, the buffer holds {capacity}", walk.len());
            // SAFETY: caller contract: `edges` and `forward` NULL or
            // `capacity` writable entries; `forward` is optional, and only
            // written once `edges` was.
            unsafe {
                fill(edges, "edges", capacity, walk.len(), walk.iter().map(|&(i, _)| i), too_small)?;
                if !forward.is_null() {
                    fill(forward, "forward", capacity, walk.len(), walk.iter().map(|&(_, f)| f.into()), too_small)?;
                }
            }
        }
        // SAFETY: checked non-NULL above.
        unsafe { write_out(count, walk.len()) };
        Ok(())
    })
}

/// The site nearest to (`x`, `y`) (model units), its distance and nearest
/// point; never the library's frame. `MX_ERR_INVALID_ARGUMENT` for a
/// non-finite point.
///
/// # Safety
/// `vd` NULL or a live handle; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_nearest_site(
    vd: *const mx_voronoi,
    x: f64,
    y: f64,
    out: *mut mx_nearest_site,
) -> mx_status {
    // SAFETY: forwarded contract.
    unsafe {
        query(vd, out, |v| {
            let p = Point::new(x, y);
            if !p.is_finite() {
                return Err(FfiError::new(
                    mx_status::MX_ERR_INVALID_ARGUMENT,
                    format!("point ({x}, {y}) is not finite"),
                ));
            }
            let (s, d, f) = v.diagram.nearest_site(p).ok_or_else(|| {
                FfiError::new(
                    mx_status::MX_ERR_INVALID_ARGUMENT,
                    format!("point ({x}, {y}) is too far from the sites for a distance in f64"),
                )
            })?;
            Ok(mx_nearest_site { site: site_c(s), distance: d, foot_x: f.x, foot_y: f.y })
        })
    }
}

/// The shape options `o` asks for (its tolerance checked).
pub(super) fn shape_options(o: &mx_voronoi_options) -> Result<ShapeOptions, FfiError> {
    if !(o.tolerance.is_finite() && o.tolerance >= 0.0) {
        return Err(FfiError::new(
            mx_status::MX_ERR_INVALID_ARGUMENT,
            format!("mx_voronoi_options.tolerance = {}: use a finite value >= 0", o.tolerance),
        ));
    }
    Ok(ShapeOptions { tolerance: (o.tolerance > 0.0).then_some(o.tolerance), ..ShapeOptions::default() })
}
