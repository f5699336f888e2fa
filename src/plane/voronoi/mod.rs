//! Voronoi diagrams of sites through the medial axis (thesis 2.3,
//! Observation 6).
//!
//! The sites become holes of a shape whose outer boundary is a frame Γ;
//! the medial axis of that shape is the closure of the Voronoi edge graph
//! of the sites and Γ. Γ is either the caller's (then it is a site like
//! any other) or chosen here: a circle around the sites, grown until every
//! Voronoi vertex of the sites alone lies inside it (`frame.rs`).
//!
//! Each edge of the axis separates two primitives; an edge whose two
//! primitives belong to one site is a *self-edge* (points with two nearest
//! points on that site, Figure 2.15). The region of a site (Corollary 2) is
//! bounded by one closed walk of the edges between it and other sites
//! ([`crate::shape::SiteRegion`]).
//!
//! Sites are points, open curves and closed regions bounded by segments
//! and arcs. Points and curves are holes of zero area
//! ([`LoopKind`](crate::shape::LoopKind)): a curve is its way out and its
//! way back, so both of its sides face the diagram.

pub(crate) mod diagram;
pub(crate) mod draw;
pub(crate) mod frame;
pub(crate) mod json;

pub use crate::shape::{SiteId, Sites, VoronoiEdge};
pub use diagram::VoronoiDiagram;

use crate::kernel::tolerance::Tolerance;
use crate::plane::medial::conquer::{medial_axis, AxisError, AxisOptions};
use crate::plane::voronoi::frame::{frame_loop, FrameCheck};
use crate::shape::{Shape2d, ShapeError, ShapeOptions, Vertex};

/// Options for [`voronoi`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct VoronoiOptions {
    /// The medial axis computation's options (seed, leaf size).
    pub axis: AxisOptions,
    /// Tolerances. The touching tolerance, when not set, is relative to the
    /// sites' bounding box (not the frame's), so a large frame costs no
    /// precision.
    pub shape: ShapeOptions,
    /// The outer boundary Γ as a bulge loop enclosing every site; `None`
    /// lets the library choose a circle that keeps every Voronoi vertex of
    /// the sites.
    pub boundary: Option<Vec<Vertex>>,
}

/// Why a Voronoi diagram could not be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum VoronoiError {
    /// No site was given.
    NoSites,
    /// The sites (or the outer boundary) are invalid: `error` numbers loops
    /// as the shape does (loop 0 the outer boundary, then the region sites);
    /// `site` names the site it is about.
    Invalid {
        /// The site the error is about, when it names one.
        site: Option<SiteId>,
        /// The validation error.
        error: ShapeError,
    },
    /// The medial axis computation failed.
    Axis(AxisError),
}

impl std::fmt::Display for VoronoiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            VoronoiError::NoSites => write!(f, "no sites"),
            VoronoiError::Invalid { site: Some(s), error } => {
                write!(f, "{s}: {error} (loops: the outer boundary, then regions, curves and points in order)")
            }
            VoronoiError::Invalid { site: None, error } => write!(f, "{error}"),
            VoronoiError::Axis(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for VoronoiError {}

impl From<AxisError> for VoronoiError {
    fn from(e: AxisError) -> Self {
        VoronoiError::Axis(e)
    }
}

/// The Voronoi diagram of `sites` (thesis 2.3): the medial axis of the
/// frame with the sites as holes, its edges labelled with the sites they
/// separate.
///
/// ```
/// use medax::plane::{voronoi, SiteId, Sites, VoronoiOptions};
/// use medax::shape::Vertex;
/// use medax::kernel::Point;
/// let square = |x: f64, y: f64| -> Vec<Vertex> {
///     [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
///         .iter()
///         .map(|&(a, b)| Vertex { p: Point::new(x + a, y + b), bulge: 0.0 })
///         .collect()
/// };
/// let sites = Sites { regions: vec![square(0.0, 0.0), square(3.0, 0.0)], ..Sites::default() };
/// let vd = voronoi(&sites, &VoronoiOptions::default())?;
/// // The two squares are separated by the line x = 2 (one edge or a few
/// // joined at joints), and each has one region.
/// assert!(vd.edges.iter().any(|e| e.sides.contains(&SiteId::Region(0)) && e.sides.contains(&SiteId::Region(1))));
/// assert_eq!(vd.regions.len(), 2);
/// assert_eq!(vd.nearest_site(Point::new(2.4, 0.5)).map(|n| n.0), Some(SiteId::Region(1)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn voronoi(sites: &Sites, opts: &VoronoiOptions) -> Result<VoronoiDiagram, VoronoiError> {
    match voronoi_from(sites, opts, false)? {
        Computed::Diagram(vd) => Ok(*vd),
        Computed::FirstShape(_) => unreachable!("only asked for with `shape_only`"),
    }
}

/// The shape whose axis [`voronoi`] computes first: the caller's boundary
/// or the library's first frame, with the sites as holes. A breakdown
/// deep inside a large diagram is reproduced on it by the diagnosis tools
/// (`examples/axis_debug`, `examples/leaf_replay`) and by tests.
#[doc(hidden)]
pub fn first_shape(sites: &Sites, opts: &VoronoiOptions) -> Result<Shape2d, VoronoiError> {
    match voronoi_from(sites, opts, true)? {
        Computed::FirstShape(shape) => Ok(shape),
        Computed::Diagram(_) => unreachable!("`shape_only` returns before any axis"),
    }
}

/// What [`voronoi_from`] stopped at.
enum Computed {
    Diagram(Box<VoronoiDiagram>),
    FirstShape(Shape2d),
}

/// [`voronoi`], or with `shape_only` the first shape it would compute on.
fn voronoi_from(sites: &Sites, opts: &VoronoiOptions, shape_only: bool) -> Result<Computed, VoronoiError> {
    if sites.is_empty() {
        return Err(VoronoiError::NoSites);
    }
    check_finite(sites)?;
    let bbox = sites.bbox();
    // The length every relative quantity is measured against: the sites'
    // diagonal, or for sites at a single place a unit that keeps the
    // coordinates' digits.
    // (Non-finite coordinates or an empty curve give a unit here, so that
    // validation names the site rather than the tolerance derived from
    // them.)
    let scale = match bbox.diagonal() {
        d if d > 0.0 && d.is_finite() => d,
        _ if bbox.min.is_finite() => Tolerance::unit_at(bbox.min.x.abs().max(bbox.min.y.abs())),
        _ => 1.0,
    };
    let loop_sites = sites.loop_sites();
    let tolerance = opts.shape.tolerance_for(scale);
    let shape_opts = ShapeOptions { tolerance: Some(tolerance), ..opts.shape };
    let build = |outer: Vec<Vertex>| {
        let mut loops = vec![outer];
        loops.extend(sites.regions.iter().cloned());
        Shape2d::from_sites(loops, sites.curves.clone(), sites.points.clone(), &shape_opts).map_err(|error| {
            VoronoiError::Invalid { site: error.loop_index().and_then(|l| loop_sites.get(l).copied()), error }
        })
    };
    if let Some(outer) = &opts.boundary {
        let shape = build(outer.clone())?;
        if shape_only {
            return Ok(Computed::FirstShape(shape));
        }
        let axis = medial_axis(&shape, &opts.axis)?;
        return Ok(Computed::Diagram(Box::new(VoronoiDiagram::new(shape, loop_sites, axis, false, true))));
    }
    let mut check = FrameCheck::new(sites, bbox, scale, tolerance);
    let mut last: Option<VoronoiDiagram> = None;
    let mut first_error = None;
    loop {
        let shape = build(frame_loop(check.center(), check.radius()))?;
        if shape_only {
            return Ok(Computed::FirstShape(shape));
        }
        // A larger frame that breaks down leaves the smaller one's
        // diagram, incomplete, as the answer; when the first frame breaks
        // down, a small one is tried, then larger ones (other disks,
        // another decomposition).
        let axis = match (medial_axis(&shape, &opts.axis), last) {
            (Ok(axis), _) => axis,
            (Err(_), Some(vd)) => return Ok(Computed::Diagram(Box::new(vd))),
            (Err(e), None) => {
                let e = first_error.get_or_insert(VoronoiError::from(e)).clone();
                if !check.after_breakdown() {
                    return Err(e);
                }
                last = None;
                continue;
            }
        };
        let vd = VoronoiDiagram::new(shape, loop_sites.clone(), axis, true, false);
        if check.accepts(&vd) {
            return Ok(Computed::Diagram(Box::new(vd.completed())));
        }
        if !check.grow() {
            return Ok(Computed::Diagram(Box::new(vd)));
        }
        last = Some(vd);
    }
}

/// Non-finite numbers are reported for their site before they reach the
/// frame (whose centre and size come from the sites).
fn check_finite(sites: &Sites) -> Result<(), VoronoiError> {
    match sites.first_non_finite() {
        Some((site, at)) => Err(VoronoiError::Invalid { site: Some(site), error: ShapeError::NonFinite { at } }),
        None => Ok(()),
    }
}
