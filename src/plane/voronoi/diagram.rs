//! The Voronoi diagram as computed: the framed shape, its axis, every edge
//! labelled with the sites on its sides, the regions and a nearest-site
//! index.

use crate::kernel::tolerance::Tolerance;
use crate::kernel::Point;
use crate::plane::axis::{MedialAxis2d, Primitive};
use crate::shape::model::site_regions::{frontier_nodes, site_regions};
use crate::shape::SiteRegion;
use crate::shape::{ChainTree, Shape2d};
use crate::shape::{SiteId, VoronoiEdge};

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

impl VoronoiDiagram {
    pub(crate) fn new(
        shape: Shape2d,
        loop_sites: Vec<SiteId>,
        axis: MedialAxis2d,
        auto_frame: bool,
        complete: bool,
    ) -> VoronoiDiagram {
        let site_of = |p: &Primitive| loop_sites[p.loop_index()];
        let edges: Vec<VoronoiEdge> = axis
            .edges
            .iter()
            .map(|e| {
                let sides = [site_of(&e.sites[0]), site_of(&e.sites[1])];
                VoronoiEdge { sides, self_edge: sides[0] == sides[1] }
            })
            .collect();
        let ends = |i: usize| (axis.edges[i].from, axis.edges[i].to);
        let n = axis.nodes.len();
        let frontier = if auto_frame { frontier_nodes(n, ends, &edges) } else { vec![false; n] };
        // The direction an edge leaves a node in, from a point a little
        // way along it (its ends are the nodes themselves).
        let toward = |i: usize, from_start: bool| {
            let e = &axis.edges[i];
            let s = Tolerance::leaving_direction();
            let (node, s) = if from_start { (e.from, s) } else { (e.to, 1.0 - s) };
            let at = axis.nodes[node].point;
            let (a, b) = (axis.nodes[e.from].point, axis.nodes[e.to].point);
            let near = e.eval(&shape, &axis.nodes, s).map_or(a + (b - a) * s, |d| d.center);
            (near - at).unit()
        };
        let regions = site_regions(ends, &edges, &loop_sites, auto_frame, toward);
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

    /// The same diagram, marked as having every Voronoi vertex of the sites
    /// inside its frame.
    pub(crate) fn completed(self) -> VoronoiDiagram {
        VoronoiDiagram { complete: true, ..self }
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
