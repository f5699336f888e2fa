//! The sites of a Voronoi diagram and the labels its edges carry (shared
//! by the Euclidean diagram and the one under a polygon ball).

use crate::kernel::{BBox, Point};
use crate::shape::{Element, ElementRef, Loop, Vertex};

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

impl Sites {
    /// The site of every loop of the framed shape the diagram is computed
    /// on: the frame, then regions, curves and points in order.
    pub fn loop_sites(&self) -> Vec<SiteId> {
        let mut out = vec![SiteId::Frame];
        out.extend((0..self.regions.len()).map(SiteId::Region));
        out.extend((0..self.curves.len()).map(SiteId::Curve));
        out.extend((0..self.points.len()).map(SiteId::Point));
        out
    }

    /// The first site with a non-finite number, and where (the loop index
    /// counts the frame as loop 0, as [`Sites::loop_sites`] does).
    pub fn first_non_finite(&self) -> Option<(SiteId, ElementRef)> {
        let at = |loop_index: usize, element: usize| ElementRef { loop_index, element };
        let finite = |v: &Vertex| v.p.is_finite() && v.bulge.is_finite();
        let (nr, nc) = (self.regions.len(), self.curves.len());
        for (i, r) in self.regions.iter().enumerate() {
            if let Some(k) = r.iter().position(|v| !finite(v)) {
                return Some((SiteId::Region(i), at(1 + i, k)));
            }
        }
        for (i, c) in self.curves.iter().enumerate() {
            if let Some(k) = c.iter().position(|v| !finite(v)) {
                return Some((SiteId::Curve(i), at(1 + nr + i, k)));
            }
        }
        let i = self.points.iter().position(|p| !p.is_finite())?;
        Some((SiteId::Point(i), at(1 + nr + nc + i, 0)))
    }

    /// Bounding box of every site's vertices and elements.
    pub fn bbox(&self) -> BBox {
        let mut b = BBox::EMPTY;
        for &p in &self.points {
            b.add_point(p);
        }
        for l in self.regions.iter() {
            b = b.union(&Loop::new(l.clone()).bbox());
        }
        for c in &self.curves {
            for w in c.windows(2) {
                b = b.union(&Element::from_bulge(w[0].p, w[1].p, w[0].bulge).bbox());
            }
            if let [v] = c.as_slice() {
                b.add_point(v.p);
            }
        }
        b
    }
}
