//! Voronoi diagrams of sites through the medial axis (thesis 2.3,
//! Observation 6).
//!
//! The sites become holes of a shape whose outer boundary is a frame Γ;
//! the medial axis of that shape is the closure of the Voronoi edge graph
//! of the sites and Γ. Γ is either the caller's (then it is a site like
//! any other) or chosen here: a circle around the sites, grown until every
//! Voronoi vertex of the sites alone lies inside it (`voronoi_frame`).
//!
//! Each edge of the axis separates two primitives; an edge whose two
//! primitives belong to one site is a *self-edge* (points with two nearest
//! points on that site, Figure 2.15). The region of a site (Corollary 2) is
//! bounded by one closed walk of the edges between it and other sites
//! ([`super::voronoi_regions`]).
//!
//! Sites are points, open curves and closed regions bounded by segments
//! and arcs. Points and curves are holes of zero area
//! ([`LoopKind`](crate::shape::LoopKind)): a curve is its way out and its
//! way back, so both of its sides face the diagram.

use super::axis::{MedialAxis2d, Primitive};
use super::conquer::{medial_axis, AxisError, AxisOptions};
use super::voronoi_frame::{frame_loop, FrameCheck};
use super::voronoi_regions::{site_regions, SiteRegion};
use crate::kernel::{BBox, Point};
use crate::shape::{ChainTree, Element, Loop, Shape2d, ShapeError, ShapeOptions, Vertex};

/// A site of a Voronoi diagram, numbered as the caller gave it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SiteId {
    /// `points[i]`.
    Point(usize),
    /// `curves[i]`.
    Curve(usize),
    /// `regions[i]`.
    Region(usize),
    /// The outer boundary Γ: the caller's, or the frame chosen by the
    /// library (whose edges are not part of the sites' diagram).
    Frame,
}

impl std::fmt::Display for SiteId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SiteId::Point(i) => write!(f, "point site {i}"),
            SiteId::Curve(i) => write!(f, "curve site {i}"),
            SiteId::Region(i) => write!(f, "region site {i}"),
            SiteId::Frame => write!(f, "the outer boundary"),
        }
    }
}

/// The input sites, model units. Sites must be pairwise disjoint (no two
/// closer than the touching tolerance) and lie inside the caller's outer
/// boundary when one is given.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Sites {
    /// Point sites.
    pub points: Vec<Point>,
    /// Open curves: chains of vertices, each with the bulge of the element
    /// to the next vertex (the last vertex's bulge is ignored). Both sides
    /// of a curve face the diagram.
    pub curves: Vec<Vec<Vertex>>,
    /// Closed regions: bulge loops in either orientation, as the holes of
    /// a shape.
    pub regions: Vec<Vec<Vertex>>,
}

impl Sites {
    /// Number of sites of every kind.
    pub fn len(&self) -> usize {
        self.points.len() + self.curves.len() + self.regions.len()
    }

    /// True when there is no site.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

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

/// What an edge of the diagram separates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct VoronoiEdge {
    /// The sites of the axis edge's two primitives, left first (walking
    /// from the edge's `from` node to its `to` node).
    pub sides: [SiteId; 2],
    /// Both primitives belong to one site: points with two nearest points
    /// on that site (thesis Figure 2.15).
    pub self_edge: bool,
}

/// The Voronoi diagram of a set of sites.
#[derive(Debug, Clone)]
pub struct VoronoiDiagram {
    /// Γ with the sites as holes: what the axis's primitives index.
    shape: Shape2d,
    /// The site of each loop of `shape`.
    loop_sites: Vec<SiteId>,
    /// The medial axis of `shape`: nodes and conic edges, with radii the
    /// distance to the nearest sites (model units).
    pub axis: MedialAxis2d,
    /// `edges[i]` says what `axis.edges[i]` separates.
    pub edges: Vec<VoronoiEdge>,
    /// Per axis node: the node is where an edge between sites meets the
    /// library's frame, so that edge runs on to infinity in the sites'
    /// own diagram. Always false for a caller's boundary.
    pub frontier: Vec<bool>,
    /// The region of every site, in loop order (regions first); the frame
    /// has none.
    pub regions: Vec<SiteRegion>,
    /// The frame was chosen by the library.
    pub auto_frame: bool,
    /// The library's frame is so large that every Voronoi vertex of the
    /// sites lies inside it (checked against the convex hull of the sites:
    /// the edges reaching the frame are exactly those that run to
    /// infinity). False when growing it to its limit (2^18 of the sites'
    /// diagonals, or the coordinate range) did not get there: vertices of
    /// nearly collinear sites, very far away; always true for a caller's
    /// boundary.
    pub complete: bool,
    /// Index of the sites' elements (loops `first_site_loop..`), for
    /// nearest-site queries.
    site_index: ChainTree,
    /// 1 when loop 0 is the library's frame (no site), else 0.
    first_site_loop: usize,
}

/// The Voronoi diagram of `sites` (thesis 2.3): the medial axis of the
/// frame with the sites as holes, its edges labelled with the sites they
/// separate.
///
/// ```
/// use medax::plane::voronoi::{voronoi, SiteId, Sites, VoronoiOptions};
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
    let bbox = sites_bbox(sites);
    // The length every relative quantity is measured against: the sites'
    // diagonal, or for sites at a single place a unit that keeps the
    // coordinates' digits.
    // (Non-finite coordinates or an empty curve give a unit here, so that
    // validation names the site rather than the tolerance derived from
    // them.)
    let scale = match bbox.diagonal() {
        d if d > 0.0 && d.is_finite() => d,
        _ if bbox.min.is_finite() => 1.0_f64.max(1e-6 * bbox.min.x.abs().max(bbox.min.y.abs())),
        _ => 1.0,
    };
    let mut loop_sites = vec![SiteId::Frame];
    loop_sites.extend((0..sites.regions.len()).map(SiteId::Region));
    loop_sites.extend((0..sites.curves.len()).map(SiteId::Curve));
    loop_sites.extend((0..sites.points.len()).map(SiteId::Point));
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
            return Ok(Computed::Diagram(Box::new(VoronoiDiagram { complete: true, ..vd })));
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
    let bad = |l: usize, site: SiteId, k: usize| {
        let at = crate::shape::ElementRef { loop_index: l, element: k };
        Err(VoronoiError::Invalid { site: Some(site), error: ShapeError::NonFinite { at } })
    };
    let finite = |v: &Vertex| v.p.is_finite() && v.bulge.is_finite();
    let (nr, nc) = (sites.regions.len(), sites.curves.len());
    for (i, r) in sites.regions.iter().enumerate() {
        if let Some(k) = r.iter().position(|v| !finite(v)) {
            return bad(1 + i, SiteId::Region(i), k);
        }
    }
    for (i, c) in sites.curves.iter().enumerate() {
        if let Some(k) = c.iter().position(|v| !finite(v)) {
            return bad(1 + nr + i, SiteId::Curve(i), k);
        }
    }
    match sites.points.iter().position(|p| !p.is_finite()) {
        Some(i) => bad(1 + nr + nc + i, SiteId::Point(i), 0),
        None => Ok(()),
    }
}

/// Bounding box of every site's vertices and elements.
fn sites_bbox(sites: &Sites) -> BBox {
    let mut b = BBox::EMPTY;
    for &p in &sites.points {
        b.add_point(p);
    }
    for l in sites.regions.iter() {
        b = b.union(&Loop::new(l.clone()).bbox());
    }
    for c in &sites.curves {
        for w in c.windows(2) {
            b = b.union(&Element::from_bulge(w[0].p, w[1].p, w[0].bulge).bbox());
        }
        if let [v] = c.as_slice() {
            b.add_point(v.p);
        }
    }
    b
}

impl VoronoiDiagram {
    fn new(
        shape: Shape2d,
        loop_sites: Vec<SiteId>,
        axis: MedialAxis2d,
        auto_frame: bool,
        complete: bool,
    ) -> VoronoiDiagram {
        let site_of = |p: &Primitive| {
            let l = match *p {
                Primitive::Element(r) => r.loop_index,
                Primitive::Vertex { loop_index, .. } => loop_index,
            };
            loop_sites[l]
        };
        let edges: Vec<VoronoiEdge> = axis
            .edges
            .iter()
            .map(|e| {
                let sides = [site_of(&e.sites[0]), site_of(&e.sites[1])];
                VoronoiEdge { sides, self_edge: sides[0] == sides[1] }
            })
            .collect();
        let mut frontier = vec![false; axis.nodes.len()];
        if auto_frame {
            let mut at_frame = vec![false; axis.nodes.len()];
            let mut at_sites = vec![false; axis.nodes.len()];
            for (e, v) in axis.edges.iter().zip(&edges) {
                let seen = if v.sides.contains(&SiteId::Frame) { &mut at_frame } else { &mut at_sites };
                seen[e.from] = true;
                seen[e.to] = true;
            }
            for (f, (a, b)) in frontier.iter_mut().zip(at_frame.iter().zip(&at_sites)) {
                *f = *a && *b;
            }
        }
        // The direction an edge leaves a node in, from a point a little
        // way along it (its ends are the nodes themselves).
        let toward = |i: usize, from_start: bool| {
            let e = &axis.edges[i];
            let (node, s) = if from_start { (e.from, 1e-3) } else { (e.to, 1.0 - 1e-3) };
            let at = axis.nodes[node].point;
            let (a, b) = (axis.nodes[e.from].point, axis.nodes[e.to].point);
            let near = e.eval(&shape, &axis.nodes, s).map_or(a + (b - a) * s, |(c, _)| c);
            (near - at).unit()
        };
        let regions = site_regions(&axis, &edges, &loop_sites, auto_frame, toward);
        let first_site_loop = usize::from(auto_frame);
        let site_index = ChainTree::new(&shape.loops()[first_site_loop..]);
        VoronoiDiagram {
            shape,
            loop_sites,
            axis,
            edges,
            frontier,
            regions,
            auto_frame,
            complete,
            site_index,
            first_site_loop,
        }
    }

    /// Γ with the sites as holes, the shape whose axis this is (loop 0 is
    /// Γ, then one loop per region, per curve and per point, in that
    /// order; [`loop_site`](Self::loop_site) names them): evaluate and
    /// sample the axis's edges against it.
    pub fn shape(&self) -> &Shape2d {
        &self.shape
    }

    /// The site of loop `l` of [`shape`](Self::shape).
    pub fn loop_site(&self, l: usize) -> SiteId {
        self.loop_sites[l]
    }

    /// The axis edges that belong to the sites' diagram: every edge when
    /// the caller gave the boundary, else those between two sites; without
    /// self-edges unless `self_edges`.
    pub fn diagram_edges(&self, self_edges: bool) -> Vec<usize> {
        (0..self.edges.len())
            .filter(|&i| {
                let e = &self.edges[i];
                (self_edges || !e.self_edge) && !(self.auto_frame && e.sides.contains(&SiteId::Frame))
            })
            .collect()
    }

    /// The region of `site`, if it has one (the library's frame does not).
    pub fn region(&self, site: SiteId) -> Option<&SiteRegion> {
        self.regions.iter().find(|r| r.site == site)
    }

    /// The site nearest to `p`, its distance and the nearest point on it
    /// (model units); the first in input order among equally near sites
    /// within rounding. The library's frame is never the answer; a
    /// caller's boundary is, where it is nearest.
    pub fn nearest_site(&self, p: Point) -> Option<(SiteId, f64, Point)> {
        let loops = &self.shape.loops()[self.first_site_loop..];
        let (r, d) = self.site_index.nearest(loops, p)?;
        let foot = loops[r.loop_index].element(r.element).closest_point(p).1;
        Some((self.loop_sites[r.loop_index + self.first_site_loop], d, foot))
    }
}
