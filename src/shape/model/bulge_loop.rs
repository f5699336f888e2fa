//! A closed loop of elements stored as bulge vertices.

use crate::kernel::element::Element;
use crate::kernel::{BBox, Kernel, Orientation, Point};

/// A vertex of a loop: the start point of an element and that element's bulge.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Vertex {
    /// The element's start point, model units.
    pub p: Point,
    /// `tan(sweep/4)` of the element starting here; 0 for a segment.
    pub bulge: f64,
}

/// What a loop bounds (thesis 2.3, Observation 6: sites of dimension 2, 1
/// and 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum LoopKind {
    /// A region: the outer boundary or a hole with an area.
    #[default]
    Region,
    /// An open curve site of k elements, stored as the closed loop that runs
    /// along it and back (2k elements, zero width): element `i` and element
    /// `2k − 1 − i` are the same curve travelled both ways ([`Loop::twin`]),
    /// vertices 0 and k are its ends (cusps, reflex with a fan of π).
    Curve,
    /// A point site: one vertex, whose one element is the zero-length
    /// segment from the point to itself (so that every element index holds
    /// the point); reflex with a fan of normals of a whole turn.
    Point,
}

impl From<crate::io::RawVertex> for Vertex {
    fn from(v: crate::io::RawVertex) -> Vertex {
        Vertex { p: Point::new(v.x, v.y), bulge: v.bulge }
    }
}

impl From<Vertex> for crate::io::RawVertex {
    fn from(v: Vertex) -> crate::io::RawVertex {
        crate::io::RawVertex { x: v.p.x, y: v.p.y, bulge: v.bulge }
    }
}

/// A closed chain of segments and arcs. Element `i` runs from vertex `i` to
/// vertex `(i + 1) % len`. Invariants once inside a validated shape: at
/// least 2 elements, no zero-length element, no self-intersection (a curve
/// loop's two sides excepted, see [`LoopKind::Curve`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Loop {
    pub(crate) vertices: Vec<Vertex>,
    pub(crate) kind: LoopKind,
}

impl Loop {
    /// A loop over the given vertices (not validated).
    pub fn new(vertices: Vec<Vertex>) -> Loop {
        Loop { vertices, kind: LoopKind::Region }
    }

    /// The two-sided loop of an open curve through `open` (k + 1 vertices,
    /// the bulge of vertex i is that of element i; the last bulge is
    /// ignored): along the curve, then back with negated bulges.
    pub fn curve(open: &[Vertex]) -> Loop {
        let k = open.len().saturating_sub(1);
        let mut vertices: Vec<Vertex> = open.to_vec();
        if let Some(last) = vertices.last_mut() {
            last.bulge = if k > 0 { -open[k - 1].bulge } else { 0.0 };
        }
        // Back: element k + j runs from vertex k − j to k − j − 1.
        for j in 1..k {
            vertices.push(Vertex { p: open[k - j].p, bulge: -open[k - j - 1].bulge });
        }
        Loop { vertices, kind: LoopKind::Curve }
    }

    /// A closed loop over `vertices` as a caller writes one: a final vertex
    /// repeating the first (of a loop of more than two) is dropped, the
    /// element of the last vertex returning to the first anyway.
    pub fn closed(mut vertices: Vec<Vertex>) -> Loop {
        if vertices.len() > 2 && vertices.first().map(|v| v.p) == vertices.last().map(|v| v.p) {
            vertices.pop();
        }
        Loop::new(vertices)
    }

    /// The loop of a point site at `p`.
    pub fn point(p: Point) -> Loop {
        Loop { vertices: vec![Vertex { p, bulge: 0.0 }], kind: LoopKind::Point }
    }

    /// What the loop bounds.
    pub fn kind(&self) -> LoopKind {
        self.kind
    }

    /// For a curve loop, the element travelling the same piece of curve the
    /// other way; `None` for a region.
    pub fn twin(&self, i: usize) -> Option<usize> {
        (self.kind == LoopKind::Curve).then(|| self.vertices.len() - 1 - i)
    }

    /// For a curve loop, whether vertex `v` is one of the curve's two ends.
    pub fn is_curve_end(&self, v: usize) -> bool {
        self.kind == LoopKind::Curve && (v == 0 || 2 * v == self.vertices.len())
    }

    /// Number of elements (= number of vertices).
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// True when the loop has no vertex.
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Vertex] {
        &self.vertices
    }

    /// Element `i` (from vertex `i` to vertex `i + 1`, cyclically).
    pub fn element(&self, i: usize) -> Element {
        let n = self.vertices.len();
        let v = self.vertices[i];
        Element::from_bulge(v.p, self.vertices[(i + 1) % n].p, v.bulge)
    }

    /// All elements in order.
    pub fn elements(&self) -> impl ExactSizeIterator<Item = Element> + '_ {
        (0..self.vertices.len()).map(move |i| self.element(i))
    }

    /// Signed enclosed area: positive for counter-clockwise loops. Exact up to
    /// rounding for arcs (no flattening).
    pub fn signed_area(&self) -> f64 {
        let n = self.vertices.len();
        // Shoelace relative to the first vertex keeps the digits of shapes far
        // from the origin.
        let o = self.vertices.first().map(|v| v.p).unwrap_or_default();
        crate::util::chunked::chunked_sum(n, |i| {
            let a = self.vertices[i].p - o;
            let b = self.vertices[(i + 1) % n].p - o;
            let chord = 0.5 * a.cross(b);
            if self.vertices[i].bulge != 0.0 {
                chord + self.element(i).bulge_area()
            } else {
                chord
            }
        })
    }

    /// Tight bounding box of the loop.
    pub fn bbox(&self) -> BBox {
        self.elements().fold(BBox::EMPTY, |b, e| b.union(&e.bbox()))
    }

    /// Total length.
    pub fn perimeter(&self) -> f64 {
        crate::util::chunked::chunked_sum(self.len(), |i| self.element(i).length())
    }

    /// The same loop traversed the other way. Element `k` of the result is
    /// element `(n − 2 − k) mod n` of `self`, reversed.
    pub fn reversed(&self) -> Loop {
        let n = self.vertices.len();
        let vertices = (0..n)
            .map(|k| Vertex { p: self.vertices[n - 1 - k].p, bulge: -self.vertices[(2 * n - 2 - k) % n].bulge })
            .collect();
        Loop { vertices, kind: self.kind }
    }

    /// Winding number of the loop around `p` (+1 inside a counter-clockwise
    /// loop, −1 inside a clockwise one, 0 outside). Undefined for `p` on the
    /// boundary. O(n); see [`winding_contribution`] for the per-element rule.
    pub fn winding_number<K: Kernel>(&self, k: &K, p: Point) -> i32 {
        self.elements().map(|e| winding_contribution(k, &e, p)).sum()
    }
}

/// The part of a loop's winding number around `p` that element `e` adds:
/// the crossing of its chord with the rightward ray from `p` (the half-open
/// rule of Sunday's winding algorithm, signs from the kernel), plus ±1 when
/// `p` lies strictly inside the circular segment between an arc and its chord
/// (the closed curve "arc, then chord back" winds once around it, in the
/// arc's direction). Summing over a loop gives its winding number.
pub fn winding_contribution<K: Kernel>(k: &K, e: &Element, p: Point) -> i32 {
    let (a, b) = (e.start(), e.end());
    // A point on an arc's chord is not on the boundary, but both terms below
    // depend on its side of the chord. Ties are broken by one perturbation
    // shared by every element: p moved up by ε and right by ε² (the same
    // one the half-open rule on y applies), so all terms stay consistent.
    let d = b - a;
    let left = match k.orientation(a, b, p) {
        Orientation::Left => true,
        Orientation::Right => false,
        Orientation::Collinear => d.x > 0.0 || (d.x == 0.0 && d.y < 0.0),
    };
    let mut w = 0;
    if a.y <= p.y {
        if b.y > p.y && left {
            w += 1;
        }
    } else if b.y <= p.y && !left {
        w -= 1;
    }
    if let Element::Arc(arc) = e {
        let on_arc_side = if arc.is_ccw() { !left } else { left };
        if on_arc_side && (p - arc.center).norm2() < arc.radius * arc.radius {
            w += if arc.is_ccw() { 1 } else { -1 };
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::FilteredKernel;

    fn v(x: f64, y: f64, b: f64) -> Vertex {
        Vertex { p: Point::new(x, y), bulge: b }
    }

    #[test]
    fn area_of_circle_from_two_half_arcs() {
        let l = Loop::new(vec![v(1.0, 0.0, 1.0), v(-1.0, 0.0, 1.0)]);
        assert!((l.signed_area() - std::f64::consts::PI).abs() < 1e-14);
        assert!((l.reversed().signed_area() + std::f64::consts::PI).abs() < 1e-14);
    }

    #[test]
    fn reversal_maps_elements_back() {
        let l = Loop::new(vec![v(0.0, 0.0, 0.0), v(2.0, 0.0, 0.3), v(2.0, 2.0, -0.2), v(0.0, 2.0, 0.0)]);
        let r = l.reversed();
        let n = l.len();
        for k in 0..n {
            let e = r.element(k);
            let o = l.element((2 * n - 2 - k) % n);
            assert_eq!(e.start(), o.end());
            assert_eq!(e.end(), o.start());
            assert_eq!(e.bulge(), -o.bulge());
        }
        assert_eq!(r.reversed(), l);
    }

    #[test]
    fn winding_number_sees_arc_bulges() {
        let k = FilteredKernel;
        // Unit square whose right side bulges out to a half circle.
        let l = Loop::new(vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 1.0), v(1.0, 1.0, 0.0), v(0.0, 1.0, 0.0)]);
        assert_eq!(l.winding_number(&k, Point::new(0.5, 0.5)), 1);
        assert_eq!(l.winding_number(&k, Point::new(1.4, 0.5)), 1);
        assert_eq!(l.winding_number(&k, Point::new(1.6, 0.5)), 0);
        assert_eq!(l.winding_number(&k, Point::new(-0.1, 0.5)), 0);
        assert_eq!(l.reversed().winding_number(&k, Point::new(1.4, 0.5)), -1);
        // Same side bulging in: the point at 0.9 is now outside.
        let l = Loop::new(vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, -0.5), v(1.0, 1.0, 0.0), v(0.0, 1.0, 0.0)]);
        assert_eq!(l.winding_number(&k, Point::new(0.9, 0.5)), 0);
        assert_eq!(l.winding_number(&k, Point::new(0.5, 0.5)), 1);
    }

    #[test]
    fn winding_number_of_points_on_an_arc_chord() {
        // Found by fuzzing: a point exactly on the chord of an outward arc
        // is inside; on the chord of an inward arc it is outside.
        let k = FilteredKernel;
        let out = Loop::new(vec![v(0.0, 0.0, 0.4), v(4.0, 2.0, 0.0), v(2.0, 6.0, 0.0), v(0.0, 3.0, 0.0)]);
        assert_eq!(out.winding_number(&k, Point::new(2.0, 1.0)), 1);
        assert_eq!(out.reversed().winding_number(&k, Point::new(2.0, 1.0)), -1);
        let inward = Loop::new(vec![v(0.0, 0.0, -0.4), v(4.0, 2.0, 0.0), v(2.0, 6.0, 0.0), v(0.0, 3.0, 0.0)]);
        assert_eq!(inward.winding_number(&k, Point::new(2.0, 1.0)), 0);
        assert_eq!(inward.reversed().winding_number(&k, Point::new(2.0, 1.0)), 0);
        // A circle's two half arcs share one chord, run both ways: a point
        // on it is inside (found by fuzzing DXF circles).
        let circle = Loop::new(vec![v(1.5, 1.0, 1.0), v(0.5, 1.0, 1.0)]);
        for p in [Point::new(1.05, 1.0), Point::new(0.6, 1.0), Point::new(1.0, 1.0)] {
            assert_eq!(circle.winding_number(&k, p), 1);
            assert_eq!(circle.reversed().winding_number(&k, p), -1);
        }
        let vertical = Loop::new(vec![v(0.0, 1.0, 1.0), v(0.0, -1.0, 1.0)]);
        assert_eq!(vertical.winding_number(&k, Point::new(0.0, 0.3)), 1);
        assert_eq!(vertical.reversed().winding_number(&k, Point::new(0.0, 0.3)), -1);
    }
}
