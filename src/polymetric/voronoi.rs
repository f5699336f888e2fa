//! Voronoi diagrams of point, segment and polygon sites under a polygon
//! ball: thesis 2.3's construction (the sites as holes of a frame Γ, the
//! diagram the medial axis of what lies between) with chapter 3's
//! distance.
//!
//! Points are holes with one vertex that faces every way (an EV class per
//! ball edge), curves holes of zero width whose ends are cusps (see
//! [`super::problem`]). Every axis edge separates two contact classes, so
//! two sites: an edge between two sites is a Voronoi edge, one between a
//! site and the frame is not part of the sites' diagram, and one between two
//! classes of one site is a self-edge (two nearest points on one region).
//!
//! The library's frame is a rectangle far enough that it keeps every
//! Voronoi vertex of the sites. In general position a vertex touches three
//! sites; once every edge of the scaled ball r·B is longer than the sites'
//! diameter D and its width exceeds D, the sites meet the ball within one
//! corner of it, a wedge with two degrees of freedom that three contacts
//! over-determine. So every vertex has r ≤ D / s, with s the ball's
//! shortest edge or its width (at least twice its inradius) if smaller,
//! and its ball lies within 2·r·reach of the sites: a frame that much
//! farther out never touches a vertex's ball. (Ties outside general
//! position are broken by class ids, constant offsets under which two
//! contacts of one ball edge never tie, so the same bound holds.)

use super::build::medial_axis_with_ball;
use super::classes::ShapeFeature;
use super::error::BallAxisError;
use super::graph::BallAxis;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::{BBox, Point};
use crate::shape::index::chain_tree::RunBounds;
use crate::shape::model::error::ElementRef;
use crate::shape::model::site_regions::{frontier_nodes, site_regions};
use crate::shape::SiteRegion;
use crate::shape::{Ball2, ChainTree, Shape2d, ShapeError, ShapeOptions, SiteId, Sites, Vertex, VoronoiEdge};

/// Options for [`voronoi_with_ball`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct BallVoronoiOptions {
    /// Tolerances; the touching tolerance, when not set, is relative to the
    /// sites' bounding box (not the frame's).
    pub shape: ShapeOptions,
    /// The outer boundary Γ (a polygon enclosing every site, then a site
    /// like any other); `None` lets the library choose a rectangle that
    /// keeps every Voronoi vertex of the sites.
    pub boundary: Option<Vec<Vertex>>,
}

/// Why a Voronoi diagram under a ball could not be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum BallVoronoiError {
    /// No site was given.
    NoSites,
    /// The sites (or the boundary) are invalid; `site` names the site.
    Invalid {
        /// The site the error is about, when it names one.
        site: Option<SiteId>,
        /// The validation error.
        error: ShapeError,
    },
    /// Element `element` of a site (or of the boundary) is an arc: polygon
    /// balls work on points, segments and polygons.
    Arc {
        /// The site.
        site: SiteId,
        /// The element in the caller's indexing.
        element: usize,
    },
    /// The axis computation failed.
    Axis(BallAxisError),
}

impl std::fmt::Display for BallVoronoiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            BallVoronoiError::NoSites => write!(f, "no sites"),
            BallVoronoiError::Invalid { site: Some(s), error } => write!(f, "{s}: {error}"),
            BallVoronoiError::Invalid { site: None, error } => write!(f, "{error}"),
            BallVoronoiError::Arc { site, element } => write!(
                f,
                "{site}: element {element} is an arc; Voronoi diagrams under a polygon ball need points, segments \
                 and polygons"
            ),
            BallVoronoiError::Axis(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for BallVoronoiError {}

/// The Voronoi diagram of sites under a polygon ball: the axis of the
/// framed space, every edge labelled with the sites on its sides.
#[derive(Debug, Clone)]
pub struct BallVoronoi {
    /// The axis of the frame with the sites as holes (radii: the gauge
    /// distance to the nearest sites).
    pub axis: BallAxis,
    /// `edges[i]` says what `axis.edges[i]` separates (left side first).
    pub edges: Vec<VoronoiEdge>,
    /// Per axis node: an edge between sites meets the library's frame
    /// there, so in the sites' own diagram it runs on to infinity.
    pub frontier: Vec<bool>,
    /// The frame was chosen by the library.
    pub auto_frame: bool,
    /// The region of every site, in loop order (regions first); the
    /// library's frame has none.
    pub regions: Vec<SiteRegion>,
    loop_sites: Vec<SiteId>,
    /// The site loops (the library's frame left out), for nearest sites.
    site_index: ChainTree,
    /// The frame with the sites as holes: what the axis's classes index.
    shape: Shape2d,
}

impl BallVoronoi {
    /// The site a shape feature of the axis belongs to.
    pub fn site_of(&self, f: ShapeFeature) -> SiteId {
        self.loop_sites[self.axis.locate(f).0]
    }

    /// The frame with the sites as holes, whose axis this is.
    pub fn shape(&self) -> &Shape2d {
        &self.shape
    }

    /// The region of `site` (`None` for a site that does not exist, or the
    /// library's frame).
    pub fn region(&self, site: SiteId) -> Option<&SiteRegion> {
        self.regions.iter().find(|r| r.site == site)
    }

    /// The site nearest to `p` under the ball (the least r with `p + r·B`
    /// touching it), that distance and a point of the site where the ball
    /// touches; the first in input order among equally near sites within
    /// rounding. The library's frame is never the answer; a caller's
    /// boundary is, where it is nearest. `None` only for a point too far
    /// away for `f64`.
    pub fn nearest_site(&self, p: Point) -> Option<(SiteId, f64, Point)> {
        let first = usize::from(self.auto_frame);
        let loops = &self.shape.loops()[first..];
        let ball = &self.axis.ball;
        let reach = ball.vertices().iter().map(|v| v.norm()).fold(0.0, f64::max);
        // The ball lies in the disk of radius `reach`, so the gauge
        // distance is at least the Euclidean one over `reach`.
        let bound = |run: RunBounds, _| Some(run.distance_to(p).max(0.0) / reach);
        let element = |r: ElementRef| loops[r.loop_index].element(r.element);
        let key = |r: ElementRef| {
            let e = element(r);
            Some(ball.distance_to_segment(p, e.start(), e.end())).filter(|d| d.is_finite())
        };
        let &(r, d) = self.site_index.first_by_bound(f64::INFINITY, 0.0, bound, key).first()?;
        let e = element(r);
        let (_, foot) = ball.nearest_on_segment(p, e.start(), e.end());
        Some((self.loop_sites[r.loop_index + first], d, foot))
    }

    /// The diagram as JSON: the ball, then the kept edges (between
    /// sites; self-edges too when `self_edges`; edges to a caller's
    /// boundary, never to the library's frame) with `sides` naming the
    /// sites ("point 3", "curve 0", "region 2", "boundary"), `samples`
    /// their two ends with the radius, `jump`; then the nodes they use,
    /// renumbered, with `frontier` where an edge runs on to infinity.
    pub fn write_json(&self, self_edges: bool, mut out: impl std::io::Write) -> std::io::Result<()> {
        #[derive(serde::Serialize)]
        struct EdgeOut {
            from: usize,
            to: usize,
            kind: &'static str,
            jump: bool,
            self_edge: bool,
            sides: [String; 2],
            samples: [[f64; 3]; 2],
        }
        #[derive(serde::Serialize)]
        struct NodeOut {
            x: f64,
            y: f64,
            r: f64,
            frontier: bool,
        }
        let name = |s: SiteId| match s {
            SiteId::Point(i) => format!("point {i}"),
            SiteId::Curve(i) => format!("curve {i}"),
            SiteId::Region(i) => format!("region {i}"),
            SiteId::Frame => "boundary".to_string(),
        };
        let kept: Vec<usize> = (0..self.edges.len())
            .filter(|&i| {
                let e = &self.edges[i];
                !(self.auto_frame && e.sides.contains(&SiteId::Frame)) && (self_edges || !e.self_edge)
            })
            .collect();
        let mut id = vec![usize::MAX; self.axis.nodes.len()];
        let mut used = Vec::new();
        for &i in &kept {
            for n in [self.axis.edges[i].from, self.axis.edges[i].to] {
                if id[n] == usize::MAX {
                    id[n] = used.len();
                    used.push(n);
                }
            }
        }
        out.write_all(b"{\"ball\":{\"vertices\":")?;
        let ball: Vec<[f64; 2]> = self.axis.ball.vertices().iter().map(|p| [p.x, p.y]).collect();
        serde_json::to_writer(&mut out, &ball)?;
        out.write_all(b"},\"edges\":[")?;
        for (k, &i) in kept.iter().enumerate() {
            let e = &self.axis.edges[i];
            let (a, b) = (&self.axis.nodes[e.from], &self.axis.nodes[e.to]);
            let v = EdgeOut {
                from: id[e.from],
                to: id[e.to],
                kind: "line",
                jump: e.jump,
                self_edge: self.edges[i].self_edge,
                sides: self.edges[i].sides.map(name),
                samples: [[a.at.x, a.at.y, a.r], [b.at.x, b.at.y, b.r]],
            };
            if k > 0 {
                out.write_all(b",")?;
            }
            serde_json::to_writer(&mut out, &v)?;
        }
        out.write_all(b"],\"nodes\":[")?;
        for (k, &n) in used.iter().enumerate() {
            if k > 0 {
                out.write_all(b",")?;
            }
            let nd = &self.axis.nodes[n];
            serde_json::to_writer(&mut out, &NodeOut { x: nd.at.x, y: nd.at.y, r: nd.r, frontier: self.frontier[n] })?;
        }
        out.write_all(b"]}\n")?;
        out.flush()
    }

    /// Indices of the axis edges between two different sites, the frame
    /// left out when the library chose it: the sites' diagram.
    pub fn site_edges(&self) -> impl Iterator<Item = usize> + '_ {
        self.edges.iter().enumerate().filter_map(move |(i, e)| {
            let framed = self.auto_frame && e.sides.contains(&SiteId::Frame);
            (!e.self_edge && !framed).then_some(i)
        })
    }
}

/// The Voronoi diagram of `sites` under `ball` (its gauge distance from a
/// point to a site: the least r with the ball `p + r·B` touching it).
///
/// ```
/// use medax::kernel::Point;
/// use medax::polymetric::{voronoi_with_ball, BallVoronoiOptions};
/// use medax::shape::{Ball2, SiteId, Sites};
///
/// // Under L∞ (the square) two points side by side are split by x = 1
/// // where |y| ≤ 1 (beyond, both are equally far on a whole region: the
/// // tie goes to one of them, deterministically).
/// let sites = Sites { points: vec![Point::new(0.0, 0.0), Point::new(2.0, 0.0)], ..Sites::default() };
/// let vd = voronoi_with_ball(&sites, &Ball2::square(), &BallVoronoiOptions::default())?;
/// let split: Vec<usize> = vd.site_edges().collect();
/// assert!(!split.is_empty());
/// for &i in &split {
///     assert!(vd.edges[i].sides.contains(&SiteId::Point(0)) && vd.edges[i].sides.contains(&SiteId::Point(1)));
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`BallVoronoiError::NoSites`], [`BallVoronoiError::Invalid`] (sites that
/// overlap or touch, non-finite numbers, a boundary not enclosing them),
/// [`BallVoronoiError::Arc`], and [`BallVoronoiError::Axis`] if the tracing
/// breaks down (a bug).
pub fn voronoi_with_ball(
    sites: &Sites,
    ball: &Ball2,
    opts: &BallVoronoiOptions,
) -> Result<BallVoronoi, BallVoronoiError> {
    if sites.is_empty() {
        return Err(BallVoronoiError::NoSites);
    }
    if let Some((site, at)) = sites.first_non_finite() {
        return Err(BallVoronoiError::Invalid { site: Some(site), error: ShapeError::NonFinite { at } });
    }
    let loop_sites = sites.loop_sites();
    check_polygonal(sites, opts.boundary.as_deref())?;
    let bbox = sites.bbox();
    let scale = match bbox.diagonal() {
        d if d > 0.0 => d,
        _ => Tolerance::unit_at(bbox.min.x.abs().max(bbox.min.y.abs())),
    };
    let tolerance = opts.shape.tolerance_for(scale);
    let shape_opts = ShapeOptions { tolerance: Some(tolerance), ..opts.shape };
    let outer = match &opts.boundary {
        Some(b) => b.clone(),
        None => frame(&bbox, scale, ball),
    };
    let mut loops = vec![outer];
    loops.extend(sites.regions.iter().cloned());
    let shape =
        Shape2d::from_sites(loops, sites.curves.clone(), sites.points.clone(), &shape_opts).map_err(|error| {
            BallVoronoiError::Invalid { site: error.loop_index().and_then(|l| loop_sites.get(l).copied()), error }
        })?;
    let axis = medial_axis_with_ball(&shape, ball).map_err(BallVoronoiError::Axis)?;
    let auto_frame = opts.boundary.is_none();
    let site = |f: ShapeFeature| loop_sites[axis.locate(f).0];
    let edges: Vec<VoronoiEdge> = axis
        .edges
        .iter()
        .map(|e| {
            let sides = [site(e.left.shape), site(e.right.shape)];
            VoronoiEdge { sides, self_edge: sides[0] == sides[1] }
        })
        .collect();
    let ends = |i: usize| (axis.edges[i].from, axis.edges[i].to);
    let frontier =
        if auto_frame { frontier_nodes(axis.nodes.len(), ends, &edges) } else { vec![false; axis.nodes.len()] };
    let toward = |i: usize, from_start: bool| {
        let e = &axis.edges[i];
        let (a, b) = (axis.nodes[e.from].at, axis.nodes[e.to].at);
        if from_start {
            (b - a).unit()
        } else {
            (a - b).unit()
        }
    };
    let regions = site_regions(ends, &edges, &loop_sites, auto_frame, toward);
    let site_index = ChainTree::new(&shape.loops()[usize::from(auto_frame)..]);
    Ok(BallVoronoi { axis, edges, frontier, auto_frame, regions, loop_sites, site_index, shape })
}

/// Refuses arcs, naming the site and element.
fn check_polygonal(sites: &Sites, boundary: Option<&[Vertex]>) -> Result<(), BallVoronoiError> {
    let arc = |site: SiteId, vs: &[Vertex], closed: bool| {
        let n = if closed { vs.len() } else { vs.len().saturating_sub(1) };
        match vs[..n].iter().position(|v| v.bulge != 0.0) {
            Some(element) => Err(BallVoronoiError::Arc { site, element }),
            None => Ok(()),
        }
    };
    if let Some(b) = boundary {
        arc(SiteId::Frame, b, true)?;
    }
    for (i, r) in sites.regions.iter().enumerate() {
        arc(SiteId::Region(i), r, true)?;
    }
    for (i, c) in sites.curves.iter().enumerate() {
        arc(SiteId::Curve(i), c, false)?;
    }
    Ok(())
}

/// The library's frame: the sites' box grown by a margin past every
/// Voronoi vertex's ball (module docs), counter-clockwise.
fn frame(bbox: &BBox, scale: f64, ball: &Ball2) -> Vec<Vertex> {
    let v = ball.vertices();
    let k = v.len();
    let reach = v.iter().map(|p| p.norm()).fold(0.0, f64::max);
    let shortest = (0..k).map(|i| (v[(i + 1) % k] - v[i]).norm()).fold(f64::INFINITY, f64::min);
    let s = shortest.min(2.0 * ball.inradius());
    // Twice the bound, and a diameter more, for slack.
    let margin = 4.0 * reach * scale / s + scale;
    let (x0, y0, x1, y1) = (bbox.min.x - margin, bbox.min.y - margin, bbox.max.x + margin, bbox.max.y + margin);
    [(x0, y0), (x1, y0), (x1, y1), (x0, y1)].map(|(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 }).to_vec()
}
