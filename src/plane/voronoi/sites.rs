//! The sites of a Voronoi diagram and the labels its edges carry.

use crate::kernel::Point;
use crate::shape::Vertex;

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
