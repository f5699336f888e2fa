//! The medial axis as a graph (thesis 2.2.3): nodes are maximal disks where
//! something happens, edges are conic arcs between two boundary primitives.
//!
//! An edge keeps its combinatorics, the two primitives and where its disks
//! touch each of them at both ends, so its curve is evaluated lazily by the
//! footpoint parametrisation ([`crate::kernel::bisector`], thesis 2.2.4):
//! nothing is sampled until a caller asks, at the tolerance it asks for.

pub(crate) mod draw;
pub(crate) mod json;

use crate::kernel::apollonius::Site;
use crate::kernel::bisector::{
    bisector_point, bisector_point_near, conic_kind, footpoint_param, sample_along, sample_between, site_radius,
    ConicKind,
};
use crate::kernel::construct::unwrap_near;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::{Disk, Point};
use crate::shape::{Element, ElementRef, Shape2d};

/// A boundary primitive the medial axis is equidistant from. Indices are
/// 32 bits: every axis edge names two primitives, and at 10^6 elements
/// the axis holds about 3·10^6 edges. (A loop of 2^32 elements would take
/// over 100 GB as a shape; the shape's index is 32-bit too.)
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Primitive {
    /// The inside of an element (segment or arc), indexed as in
    /// [`Shape2d::loops`] (normalised orientation).
    Element {
        /// Loop index.
        loop_index: u32,
        /// Element index within the loop.
        element: u32,
    },
    /// A reflex vertex: vertex `vertex` (the start of element `vertex`) of
    /// loop `loop_index`.
    Vertex {
        /// Loop index.
        loop_index: u32,
        /// Vertex index within the loop.
        vertex: u32,
    },
}

impl Primitive {
    /// The inside of element `r`.
    pub fn of_element(r: ElementRef) -> Self {
        debug_assert!(r.loop_index <= u32::MAX as usize && r.element <= u32::MAX as usize);
        Primitive::Element { loop_index: r.loop_index as u32, element: r.element as u32 }
    }

    /// Reflex vertex `vertex` of loop `loop_index`.
    pub fn of_vertex(loop_index: usize, vertex: usize) -> Self {
        debug_assert!(loop_index <= u32::MAX as usize && vertex <= u32::MAX as usize);
        Primitive::Vertex { loop_index: loop_index as u32, vertex: vertex as u32 }
    }

    /// The element, for [`Primitive::Element`].
    pub fn element(&self) -> Option<ElementRef> {
        match *self {
            Primitive::Element { loop_index, element } => {
                Some(ElementRef { loop_index: loop_index as usize, element: element as usize })
            }
            Primitive::Vertex { .. } => None,
        }
    }

    /// The loop it lies on.
    pub fn loop_index(&self) -> usize {
        match *self {
            Primitive::Element { loop_index, .. } | Primitive::Vertex { loop_index, .. } => loop_index as usize,
        }
    }

    /// The element's or the vertex's index within its loop.
    pub fn index(&self) -> usize {
        match *self {
            Primitive::Element { element: i, .. } | Primitive::Vertex { vertex: i, .. } => i as usize,
        }
    }

    /// Distance (model units) from `p` to the primitive itself: to the
    /// vertex, or to the closest point of the element (not of its line or
    /// circle).
    pub fn distance(&self, shape: &Shape2d, p: Point) -> f64 {
        let l = &shape.loops()[self.loop_index()];
        match self {
            Primitive::Vertex { .. } => p.dist(l.vertices()[self.index()].p),
            Primitive::Element { .. } => l.element(self.index()).closest_point(p).0,
        }
    }

    /// An element's footpoint parameters at its start and its end vertex
    /// (in the parametrisation of [`crate::kernel::bisector::footpoint`]:
    /// a segment's length from its start, an arc's angle around its centre,
    /// the end unwrapped from the start by the signed sweep); `None` for a
    /// vertex. An element side's footpoint never leaves this range.
    pub fn element_params(&self, shape: &Shape2d) -> Option<(f64, f64)> {
        let Primitive::Element { .. } = self else { return None };
        Some(match shape.loops()[self.loop_index()].element(self.index()) {
            Element::Segment(s) => (0.0, s.a.dist(s.b)),
            Element::Arc(a) => {
                let start = crate::kernel::direction::angle_of(a.a - a.center);
                (start, start + a.sweep())
            }
        })
    }

    /// `u` moved into [`element_params`](Self::element_params) (an arc's
    /// angle first taken within half a turn of the range's middle); a
    /// vertex's parameter as it is.
    pub fn clamp_param(&self, shape: &Shape2d, u: f64) -> f64 {
        let Some((start, end)) = self.element_params(shape) else { return u };
        let u = match shape.loops()[self.loop_index()].element(self.index()) {
            Element::Segment(_) => u,
            Element::Arc(_) => crate::kernel::construct::unwrap_near(u, 0.5 * (start + end)),
        };
        u.clamp(start.min(end), start.max(end))
    }

    /// What a disk touching this primitive sees: a sided line, a circle with
    /// its kind of tangency, or a point.
    pub fn site(&self, shape: &Shape2d) -> Site {
        let l = &shape.loops()[self.loop_index()];
        match self {
            Primitive::Vertex { .. } => Site::Point(l.vertices()[self.index()].p),
            Primitive::Element { .. } => match l.element(self.index()) {
                // The interior is left of travel.
                Element::Segment(s) => Site::Line { a: s.a, n: (s.b - s.a).unit().perp() },
                // A counter-clockwise arc curves around the interior: the
                // disks inside touch it from within its circle.
                Element::Arc(a) => Site::Circle { o: a.center, r: a.radius, outside: !a.is_ccw() },
            },
        }
    }
}

/// What happens at a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NodeKind {
    /// Three or more edges meet: the disk touches three or more primitives.
    Branch,
    /// A convex vertex of the boundary: radius 0, an end of the axis.
    Corner,
    /// The centre of an arc whose whole circle lies inside the shape
    /// (thesis Observation 5): an end of the axis at a curvature maximum.
    Leaf,
    /// Two edges meet and the pair of primitives changes (a contact passes
    /// a smooth vertex or the end of a reflex vertex's fan of normals).
    Joint,
}

/// A node of the medial axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisNode {
    /// Centre of the maximal disk, model units.
    pub point: Point,
    /// Radius of the maximal disk, model units (0 at a convex corner).
    pub radius: f64,
    /// What happens here.
    pub kind: NodeKind,
}

/// An edge: a piece of the conic of points equidistant from two primitives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisEdge {
    /// Node index at the start.
    pub from: usize,
    /// Node index at the end.
    pub to: usize,
    /// The two primitives, the first on the left when walking from `from`
    /// to `to`.
    pub sites: [Primitive; 2],
    /// Footpoint parameters on each primitive at `from` and at `to`, in the
    /// parametrisation of [`crate::kernel::bisector::footpoint`]: distance
    /// along a segment from its start, or an angle in radians around an
    /// arc's centre or a reflex vertex. Where the disks hug a stretch of
    /// nearly concentric arcs (they touch all of it within the tolerance)
    /// the stretch is one contact and an element's footpoint can lie on its
    /// circle past the element's end, by up to the stretch's length; the
    /// element itself still touches the disks within the tolerance there.
    /// [`Primitive::clamp_param`] gives the point on the element.
    pub params: [(f64, f64); 2],
    /// The kind of conic the edge lies on.
    pub kind: ConicKind,
    /// The straight segment between the nodes stands for the conic (kind
    /// [`ConicKind::Line`]), the radius going linearly from node to node:
    /// across a band of boundary that stays within a few tolerances of
    /// both nodes' circles, where the order of contacts is rounding. Its
    /// disks touch both primitives (and every element between them)
    /// within twice `Tolerance::hugged_tip` (16τ).
    pub straight: bool,
}

/// The medial axis of a shape.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MedialAxis2d {
    /// Nodes: every branch point, corner, leaf and joint.
    pub nodes: Vec<AxisNode>,
    /// Edges between nodes.
    pub edges: Vec<AxisEdge>,
}

/// The finest sampling tolerance [`AxisEdge::sample`] accepts, relative to
/// the shape's bounding-box diagonal.
pub const MIN_RELATIVE_SAMPLE_TOLERANCE: f64 = 1e-12;

/// An edge along which both footpoints move less than this fraction of its
/// chord is evaluated from its chord ([`AxisEdge::eval`]): its disks slide
/// along their normals, so a footpoint parameter fixes the centre badly
/// (measured: the spoke from near the centre of a curve within 10^-3 of a
/// circle to the curvature centre of one small arc, 0.33 long, moved both
/// footpoints by 10^-5, and the middle footpoint parameter gave a disk at
/// one end of it).
const STALLED_FOOTPOINTS: f64 = 1.0 / 16.0;

/// The driver for footpoint ranges `reaches` (as lengths): the primitive
/// whose footpoint moves furthest, ties to the first.
fn driver_of(reaches: [f64; 2]) -> usize {
    usize::from(reaches[1] > reaches[0] * (1.0 + Tolerance::point_range()))
}

impl AxisEdge {
    /// The footpoint range on primitive `k` scaled to a length: a segment's
    /// parameter is a length already, an arc's angle times its radius, a
    /// vertex's angle times the larger radius at the ends.
    fn reach(&self, shape: &Shape2d, k: usize, r_max: f64) -> f64 {
        let (u0, u1) = self.params[k];
        match self.sites[k].site(shape) {
            Site::Line { .. } => (u1 - u0).abs(),
            Site::Circle { r, .. } => (u1 - u0).abs() * r,
            Site::Point(_) => (u1 - u0).abs() * r_max,
        }
    }

    /// The primitive whose footpoint moves furthest along the edge: the
    /// better-conditioned parametrisation.
    pub(crate) fn driver(&self, shape: &Shape2d, r_max: f64) -> usize {
        driver_of([self.reach(shape, 0, r_max), self.reach(shape, 1, r_max)])
    }

    /// The maximal disk at fraction `s` ∈ [0, 1] along the edge: of the
    /// footpoint range of the better-conditioned primitive, or of the
    /// segment between the nodes for a straight edge (whose footpoint
    /// parametrisation degenerates between nearly parallel lines), or
    /// reached from that segment along the curve's normal where both
    /// footpoints move less than 1/16 of it or the
    /// footpoint parametrisation leaves the edge. Centre and
    /// radius, model units. `None` if no disk is tangent there (never for
    /// an edge of a valid axis).
    pub fn eval(&self, shape: &Shape2d, nodes: &[AxisNode], s: f64) -> Option<Disk> {
        if self.kind == ConicKind::Line {
            let (a, b) = (nodes[self.from], nodes[self.to]);
            let c = a.point + (b.point - a.point) * s;
            if self.straight {
                return Some(Disk::new(c, a.radius + (b.radius - a.radius) * s));
            }
            return Some(Disk::new(c, site_radius(&self.sites[0].site(shape), c)));
        }
        let reaches = self.reaches(shape, nodes);
        if self.footpoint_travel(nodes, reaches) >= STALLED_FOOTPOINTS {
            if let Some(d) = self.by_footpoints(shape, s, driver_of(reaches)) {
                return Some(d);
            }
        }
        self.near_chord(shape, nodes, s).map(|(c, r, _)| Disk::new(c, r))
    }

    /// [`reach`](Self::reach) of both primitives.
    fn reaches(&self, shape: &Shape2d, nodes: &[AxisNode]) -> [f64; 2] {
        let r_max = nodes[self.from].radius.max(nodes[self.to].radius);
        [self.reach(shape, 0, r_max), self.reach(shape, 1, r_max)]
    }

    /// The disk of the footpoint parametrisation at fraction `s` of the
    /// range of primitive `k` (the driver); between two arcs or vertices,
    /// only if its footpoint on the other primitive lies within that one's
    /// range widened by its width on either side: between two arcs of
    /// circles tangent within rounding the curve is a hyperbola so thin
    /// that a middle parameter gave a disk 5·10^5 tolerances off an edge of
    /// 4·10^3 (or none), whose other footpoint was far out of range, while
    /// both footpoints moved a quarter of the chord to 12 times it. (A
    /// conic with a line for a site has at most one focus and is not that
    /// thin.)
    fn by_footpoints(&self, shape: &Shape2d, s: f64, k: usize) -> Option<Disk> {
        let (u0, u1) = self.params[k];
        let (sk, so) = (self.sites[k].site(shape), self.sites[1 - k].site(shape));
        let (c, r) = bisector_point(&sk, &so, u0 + (u1 - u0) * s)?;
        if matches!(sk, Site::Line { .. }) || matches!(so, Site::Line { .. }) {
            return Some(Disk::new(c, r));
        }
        let (v0, v1) = self.params[1 - k];
        let mid = 0.5 * (v0 + v1);
        let v = unwrap_near(footpoint_param(&so, c, r), mid);
        let slack = 1.5 * (v1 - v0).abs() + Tolerance::point_range() * (1.0 + mid.abs());
        ((v - mid).abs() <= slack).then(|| Disk::new(c, r))
    }

    /// How far the footpoints move along the edge for the chord between
    /// its nodes: the larger of `reaches` (footpoint ranges as lengths) over the chord,
    /// infinite for a chord of length 0. Below [`STALLED_FOOTPOINTS`] the
    /// footpoint parametrisation is ill conditioned and the curve close to
    /// its chord.
    fn footpoint_travel(&self, nodes: &[AxisNode], reaches: [f64; 2]) -> f64 {
        reaches[0].max(reaches[1]) / nodes[self.from].point.dist(nodes[self.to].point)
    }

    /// The disk of the curve reached from the point at fraction `s` of the
    /// chord between the nodes, along the curve's normal, as a sample with
    /// parameter `s` (steps no longer than the chord).
    fn near_chord(&self, shape: &Shape2d, nodes: &[AxisNode], s: f64) -> Option<(Point, f64, f64)> {
        let (a, b) = (nodes[self.from], nodes[self.to]);
        let p = a.point + (b.point - a.point) * s;
        bisector_point_near(&self.sites[0].site(shape), &self.sites[1].site(shape), p, a.point.dist(b.point))
            .map(|(c, r)| (c, r, s))
    }

    /// Samples along the edge, from its `from` node to its `to` node, as
    /// maximal disks: the polyline through the centres deviates from the
    /// true conic by at most `tol` model units, raised to at least
    /// [`MIN_RELATIVE_SAMPLE_TOLERANCE`] × the shape's diagonal (a finer
    /// or zero tolerance would ask for billions of samples). The first and
    /// last samples are the nodes themselves.
    pub fn sample(&self, shape: &Shape2d, nodes: &[AxisNode], tol: f64) -> Vec<Disk> {
        let tol = tol.max(MIN_RELATIVE_SAMPLE_TOLERANCE * shape.bbox().diagonal());
        let (a, b) = (nodes[self.from], nodes[self.to]);
        let r_max = a.radius.max(b.radius);
        let k = self.driver(shape, r_max);
        let (u0, u1) = self.params[k];
        let (sk, so) = (self.sites[k].site(shape), self.sites[1 - k].site(shape));
        // The ends are the nodes (computed by their own, better
        // conditioned constructions); a line needs nothing in between.
        let ends = [Disk::new(a.point, a.radius), Disk::new(b.point, b.radius)];
        let reaches = self.reaches(shape, nodes);
        let ill = || {
            self.footpoint_travel(nodes, reaches) < STALLED_FOOTPOINTS
                || self.by_footpoints(shape, 0.5, driver_of(reaches)).is_none()
        };
        if self.kind != ConicKind::Line && ill() {
            let at = |s: f64| self.near_chord(shape, nodes, s);
            return match sample_along(at, (a.point, a.radius, 0.0), (b.point, b.radius, 1.0), tol) {
                Some(s) => s.into_iter().map(|(c, r, _)| Disk::new(c, r)).collect(),
                None => ends.to_vec(),
            };
        }
        if (u1 - u0).abs() <= Tolerance::point_range() * (1.0 + u0.abs()) || self.kind == ConicKind::Line {
            return ends.to_vec();
        }
        let (start, end) = ((a.point, a.radius, u0), (b.point, b.radius, u1));
        match sample_between(&sk, &so, start, end, tol) {
            Some(s) => s.into_iter().map(|(c, r, _)| Disk::new(c, r)).collect(),
            None => ends.to_vec(),
        }
    }
}

/// The conic kind of the edge between primitives `a` and `b` (interior
/// disks are nested inside counter-clockwise arcs' circles). An element
/// and one of its own end vertices share only that vertex: the disks
/// touching both touch the element there, so their centres lie on its
/// normal at the vertex (a parabola or conic whose focus lies on its
/// directrix degenerates to that line). Such an edge is the end of a fan
/// too narrow to hold a footpoint, a few tolerances long.
pub fn edge_kind(shape: &Shape2d, a: Primitive, b: Primitive) -> ConicKind {
    if own_end_pair(shape, a, b) {
        return ConicKind::Line;
    }
    conic_kind(&a.site(shape), &b.site(shape), [true, true])
}

/// Whether one of `a`, `b` is an element and the other a vertex at one of
/// its ends (the edge between them runs along the element's normal there).
pub(crate) fn own_end_pair(shape: &Shape2d, a: Primitive, b: Primitive) -> bool {
    let own_end = |v: Primitive, e: Primitive| match (v, e) {
        (Primitive::Vertex { loop_index, vertex }, Primitive::Element { loop_index: l, element })
            if l == loop_index =>
        {
            let n = shape.loops()[loop_index as usize].len() as u32;
            vertex == element || vertex == (element + 1) % n
        }
        _ => false,
    };
    own_end(a, b) || own_end(b, a)
}

impl MedialAxis2d {
    /// Number of edges at each node.
    pub fn degrees(&self) -> Vec<usize> {
        let mut d = vec![0; self.nodes.len()];
        for e in &self.edges {
            d[e.from] += 1;
            d[e.to] += 1;
        }
        d
    }

    /// Every edge sampled to chordal tolerance `tol` (model units), in edge
    /// order; see [`AxisEdge::sample`].
    pub fn sampled(&self, shape: &Shape2d, tol: f64) -> Vec<Vec<Disk>> {
        use rayon::prelude::*;
        self.edges.par_iter().map(|e| e.sample(shape, &self.nodes, tol)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::{ShapeOptions, Vertex};

    #[test]
    fn an_element_and_its_own_end_vertex_bound_a_straight_edge() {
        // An L-shaped hexagon: vertex 3 at (1, 1) is reflex, between
        // element 2 (from (2, 1)) and element 3 (to (1, 2)).
        let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)];
        let lp = pts.iter().map(|&(x, y)| Vertex { p: Point::new(x, y), bulge: 0.0 }).collect();
        let shape = Shape2d::from_bulge_loops(vec![lp], &ShapeOptions::default()).unwrap();
        let v = Primitive::Vertex { loop_index: 0, vertex: 3 };
        let e = |element| Primitive::of_element(ElementRef { loop_index: 0, element });
        assert_eq!(edge_kind(&shape, v, e(2)), ConicKind::Line);
        assert_eq!(edge_kind(&shape, e(3), v), ConicKind::Line);
        // Another element's vertex: the ordinary parabola.
        assert_eq!(edge_kind(&shape, v, e(0)), ConicKind::Parabola);
        // Along element 2's normal at the vertex (pointing down, -y), the
        // disks touch the vertex and the element there: the edge evaluates
        // between its nodes with the distance to both as radius.
        let nodes = [
            AxisNode { point: Point::new(1.0, 0.9), radius: 0.1, kind: NodeKind::Joint },
            AxisNode { point: Point::new(1.0, 0.8), radius: 0.2, kind: NodeKind::Joint },
        ];
        let edge = AxisEdge {
            from: 0,
            to: 1,
            sites: [e(2), v],
            params: [(1.0, 1.0), (0.0, 0.0)],
            kind: edge_kind(&shape, e(2), v),
            straight: false,
        };
        let Disk { center: c, radius: r } = edge.eval(&shape, &nodes, 0.5).unwrap();
        assert!(c.dist(Point::new(1.0, 0.85)) < 1e-15 && (r - 0.15).abs() < 1e-15, "{c:?} {r}");
        assert!((c.dist(Point::new(1.0, 1.0)) - r).abs() < 1e-15);
    }
}
