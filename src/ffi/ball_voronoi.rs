//! The Voronoi diagram under a polygon ball through the C API: the same
//! `mx_voronoi` handle and `mx_voronoi_*` queries as the Euclidean one,
//! over either kind of diagram.

use super::axis::mx_axis;
use super::ball::mx_ball;
use super::ball_axis::ball_axis_error;
use super::boundary::{deref, run_with_progress};
use super::handles::{arg, create, Options};
use super::last_error::FfiError;
use super::status::mx_status;
use super::voronoi::{mx_sites, mx_voronoi, mx_voronoi_compute, mx_voronoi_options, read_sites, shape_options};
use crate::kernel::Point;
use crate::plane::voronoi::VoronoiDiagram;
use crate::polymetric::{voronoi_with_ball, BallVoronoi, BallVoronoiError, BallVoronoiOptions};
use crate::shape::{SiteId, SiteRegion, VoronoiEdge};

/// A diagram under the Euclidean distance or under a polygon ball.
pub(super) enum Diagram {
    Euclidean(VoronoiDiagram),
    Ball(BallVoronoi),
}

impl Diagram {
    pub(super) fn auto_frame(&self) -> bool {
        match self {
            Diagram::Euclidean(d) => d.auto_frame,
            Diagram::Ball(d) => d.auto_frame,
        }
    }

    /// Every Voronoi vertex inside the frame: under a ball the frame's
    /// margin is a proven bound, so always.
    pub(super) fn complete(&self) -> bool {
        match self {
            Diagram::Euclidean(d) => d.complete,
            Diagram::Ball(_) => true,
        }
    }

    pub(super) fn regions(&self) -> &[SiteRegion] {
        match self {
            Diagram::Euclidean(d) => &d.regions,
            Diagram::Ball(d) => &d.regions,
        }
    }

    pub(super) fn edges(&self) -> &[VoronoiEdge] {
        match self {
            Diagram::Euclidean(d) => &d.edges,
            Diagram::Ball(d) => &d.edges,
        }
    }

    pub(super) fn frontier(&self) -> &[bool] {
        match self {
            Diagram::Euclidean(d) => &d.frontier,
            Diagram::Ball(d) => &d.frontier,
        }
    }

    pub(super) fn region(&self, site: SiteId) -> Option<&SiteRegion> {
        self.regions().iter().find(|r| r.site == site)
    }

    pub(super) fn nearest_site(&self, p: Point) -> Option<(SiteId, f64, Point)> {
        match self {
            Diagram::Euclidean(d) => d.nearest_site(p),
            Diagram::Ball(d) => d.nearest_site(p),
        }
    }
}

/// Computes the Voronoi diagram of `sites` under the unit ball `ball`
/// (thesis chapter 3: the distance from a point p to a site is the least r
/// with the ball `p + r·B` touching it) and writes a new handle to `*out`;
/// `ball` NULL computes the Euclidean diagram (`mx_voronoi_compute`).
/// Sites must be polygonal (points, polylines, polygons: a bulge gives
/// `MX_ERR_UNSUPPORTED` naming the site). The library's frame lies past
/// every Voronoi vertex by a proven margin, so `complete` is always 1. The
/// geometry is read through `mx_voronoi_axis` (an axis under the ball:
/// straight edges, `mx_axis_edge_contacts`), the labels, regions and
/// nearest site (under the ball's distance) through the other
/// `mx_voronoi_*` functions. `options` may be NULL; its `seed` does not
/// apply (the construction is deterministic). Fails as
/// `mx_voronoi_compute`; `*out` is then untouched.
///
/// # Safety
/// `sites` NULL or valid with arrays valid for their counts; `ball` NULL
/// or a live handle; `options` NULL or valid; `out` NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn mx_voronoi_compute_with_ball(
    sites: *const mx_sites,
    ball: *const mx_ball,
    options: *const mx_voronoi_options,
    out: *mut *mut mx_voronoi,
) -> mx_status {
    if ball.is_null() {
        // SAFETY: forwarded contract.
        return unsafe { mx_voronoi_compute(sites, options, out) };
    }
    // SAFETY: caller contract.
    unsafe {
        create(out, || {
            let (s, o) = (deref(sites, "sites")?, mx_voronoi_options::read_or_default(options)?);
            let shape = shape_options(&o)?;
            let b = arg(ball)?.as_plane()?;
            let (sites, boundary) = read_sites(s)?;
            let opts = BallVoronoiOptions { shape, boundary };
            let export = "mx_voronoi_compute_with_ball";
            let diagram = run_with_progress(export, "mx_voronoi_options", o.threads, o.progress, o.user, || {
                voronoi_with_ball(&sites, b, &opts).map_err(ball_voronoi_error)
            })?;
            let axis =
                mx_axis { shape: diagram.shape().clone(), axis: Default::default(), ball: Some(diagram.axis.clone()) };
            Ok(mx_voronoi { axis, diagram: Diagram::Ball(diagram) })
        })
    }
}

fn ball_voronoi_error(e: BallVoronoiError) -> FfiError {
    let message = e.to_string();
    let mut f = match e {
        BallVoronoiError::NoSites => FfiError::new(mx_status::MX_ERR_EMPTY, String::new()),
        BallVoronoiError::Invalid { error, .. } => FfiError::from(error),
        BallVoronoiError::Arc { .. } => FfiError::new(mx_status::MX_ERR_UNSUPPORTED, String::new()),
        BallVoronoiError::Axis(a) => ball_axis_error(a),
    };
    // The diagram's message names the site; the shape's would name a loop.
    f.message = message;
    f
}
