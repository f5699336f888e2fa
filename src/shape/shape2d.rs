//! The validated 2D shape: one outer loop and any number of holes.

use crate::kernel::{BBox, Point};
use crate::shape::model::bulge_loop::{Loop, Vertex};
use crate::shape::model::error::{ElementRef, ShapeError};
use crate::shape::model::joints::JointKind;
use crate::shape::model::loose::LooseElement;
use crate::shape::model::options::ShapeOptions;
use crate::shape::validate::validate;
use std::f64::consts::TAU;

/// A shape bounded by segments and circular arcs: loop 0 is the outer
/// boundary, loops 1.. are holes.
///
/// Invariants (established by every constructor, relied on by every
/// algorithm): all numbers finite and within ±[`MAX_COORDINATE`](crate::shape::MAX_COORDINATE);
/// no element shorter than [`tolerance`](Self::tolerance); no two elements
/// closer than the tolerance except consecutive ones at their shared vertex;
/// no cusps; every hole inside the outer loop and outside every other hole;
/// the outer loop counter-clockwise and holes clockwise (so the interior is
/// always on the left). A `Shape2d` is immutable and `Send + Sync`.
#[derive(Debug, Clone, PartialEq)]
pub struct Shape2d {
    loops: Vec<Loop>,
    reversed: Vec<bool>,
    joints: Vec<Vec<JointKind>>,
    flattened: usize,
    tolerance: f64,
    bbox: BBox,
}

/// An element described explicitly, for [`Shape2d::from_elements`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ElementSpec {
    /// A segment from `a` to `b`.
    Segment {
        /// Start point.
        a: Point,
        /// End point.
        b: Point,
    },
    /// An arc of the circle (`center`, `radius`) from angle `start` to angle
    /// `end` (radians, measured counter-clockwise from +x), running
    /// counter-clockwise when `ccw`. Equal angles (mod 2π) mean a full circle.
    ArcAngles {
        /// Centre, model units.
        center: Point,
        /// Radius, model units, > 0.
        radius: f64,
        /// Start angle, radians.
        start: f64,
        /// End angle, radians.
        end: f64,
        /// Direction of travel.
        ccw: bool,
    },
    /// An arc around `center` from `a` to `b`, counter-clockwise when `ccw`.
    /// `a` and `b` must be equally far from `center` within the chaining
    /// tolerance; `a == b` means a full circle.
    ArcPoints {
        /// Start point.
        a: Point,
        /// End point.
        b: Point,
        /// Centre.
        center: Point,
        /// Direction of travel.
        ccw: bool,
    },
}

/// Converts a signed sweep into (possibly two) bulge elements from `a`
/// around `center`: a full turn becomes two half circles, because a bulge
/// cannot express a closed arc.
fn push_arc(out: &mut Vec<LooseElement>, center: Point, a: Point, sweep: f64) {
    if sweep.abs() >= TAU * (1.0 - 1e-15) {
        let s = sweep.signum();
        let opposite = center * 2.0 - a;
        out.push(LooseElement { a, b: opposite, bulge: s });
        out.push(LooseElement { a: opposite, b: a, bulge: s });
    } else {
        let ang = sweep;
        let v = a - center;
        let (sn, cs) = ang.sin_cos();
        let b = center + Point::new(cs * v.x - sn * v.y, sn * v.x + cs * v.y);
        out.push(LooseElement { a, b, bulge: (sweep / 4.0).tan() });
    }
}

/// The sweep from angle `s` to angle `e` in the given direction, in (0, 2π]
/// (negated for clockwise).
fn directed_sweep(s: f64, e: f64, ccw: bool) -> f64 {
    let d = if ccw { e - s } else { s - e };
    let mut m = d.rem_euclid(TAU);
    if m <= 1e-15 * TAU {
        m = TAU;
    }
    if ccw {
        m
    } else {
        -m
    }
}

impl Shape2d {
    /// Builds a shape from bulge loops: `loops[0]` is the outer boundary, the
    /// rest are holes, each a closed chain (the element of the last vertex
    /// returns to the first; a final vertex repeating the first is dropped).
    /// Orientation is normalised; see [`was_reversed`](Self::was_reversed).
    pub fn from_bulge_loops(loops: Vec<Vec<Vertex>>, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        Self::from_loops(loops.into_iter().map(Loop::closed).collect(), opts)
    }

    /// Builds a shape with Voronoi sites (thesis 2.3, Observation 6):
    /// `loops` as in [`from_bulge_loops`](Self::from_bulge_loops) (the outer
    /// boundary, then holes), and `curves`, open chains of k + 1 vertices
    /// each (the bulge of vertex i is that of element i, the last one's is
    /// ignored), which become the next loops, of kind
    /// [`LoopKind::Curve`](crate::shape::model::bulge_loop::LoopKind::Curve): 2k elements, the curve
    /// and its way back; then `points`, loops of kind
    /// [`LoopKind::Point`](crate::shape::model::bulge_loop::LoopKind::Point), one vertex each.
    pub fn from_sites(
        loops: Vec<Vec<Vertex>>,
        curves: Vec<Vec<Vertex>>,
        points: Vec<Point>,
        opts: &ShapeOptions,
    ) -> Result<Shape2d, ShapeError> {
        let mut all: Vec<Loop> = loops.into_iter().map(Loop::closed).collect();
        all.extend(curves.iter().map(|c| Loop::curve(c)));
        all.extend(points.into_iter().map(Loop::point));
        Self::from_loops(all, opts)
    }

    /// Builds a shape from explicit elements: `loops[0]` is the outer
    /// boundary. Consecutive elements (and the last and first) must meet
    /// within the chaining tolerance; the loop's vertices are the elements'
    /// start points. Full circles are split into two half arcs, which shifts
    /// the element indices after them.
    pub fn from_elements(loops: &[Vec<ElementSpec>], opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        opts.check()?;
        let mut loose: Vec<Vec<LooseElement>> = Vec::with_capacity(loops.len());
        let mut scale = BBox::EMPTY;
        for (li, specs) in loops.iter().enumerate() {
            let mut out = Vec::with_capacity(specs.len());
            for (i, s) in specs.iter().enumerate() {
                let here = ElementRef { loop_index: li, element: out.len() };
                match *s {
                    ElementSpec::Segment { a, b } => {
                        if !(a.is_finite() && b.is_finite()) {
                            return Err(ShapeError::NonFinite { at: here });
                        }
                        out.push(LooseElement { a, b, bulge: 0.0 })
                    }
                    ElementSpec::ArcAngles { center, radius, start, end, ccw } => {
                        if !(center.is_finite() && radius.is_finite() && start.is_finite() && end.is_finite()) {
                            return Err(ShapeError::NonFinite { at: here });
                        }
                        if radius <= 0.0 {
                            return Err(ShapeError::InvalidArgument {
                                what: format!("loop {li} element {i}: arc radius {radius} must be > 0"),
                            });
                        }
                        let a = center + Point::new(start.cos(), start.sin()) * radius;
                        push_arc(&mut out, center, a, directed_sweep(start, end, ccw));
                    }
                    ElementSpec::ArcPoints { a, b, center, ccw } => {
                        if !(a.is_finite() && b.is_finite() && center.is_finite()) {
                            return Err(ShapeError::NonFinite { at: here });
                        }
                        let (va, vb) = (a - center, b - center);
                        let deviation = (va.norm() - vb.norm()).abs();
                        scale.add_point(a);
                        scale.add_point(b);
                        let tol = opts.chain_tolerance_for(scale.diagonal().max(va.norm()));
                        if deviation > tol {
                            return Err(ShapeError::InconsistentArc { at: here, deviation });
                        }
                        let sweep = directed_sweep(va.y.atan2(va.x), vb.y.atan2(vb.x), ccw);
                        if a == b {
                            push_arc(&mut out, center, a, sweep);
                        } else {
                            out.push(LooseElement { a, b, bulge: (sweep / 4.0).tan() });
                        }
                    }
                }
            }
            for e in &out {
                scale.add_point(e.a);
                scale.add_point(e.b);
            }
            loose.push(out);
        }
        let tol = opts.chain_tolerance_for(scale.diagonal());
        let mut result = Vec::with_capacity(loose.len());
        for (li, elems) in loose.iter().enumerate() {
            let n = elems.len();
            for i in 0..n {
                let (end, next) = (elems[i].b, elems[(i + 1) % n].a);
                let gap = end.dist(next);
                if gap.is_nan() || gap > tol {
                    return Err(ShapeError::NotClosed {
                        at: ElementRef { loop_index: li, element: i },
                        gap,
                        position: end,
                    });
                }
            }
            result.push(Loop::new(elems.iter().map(|e| Vertex { p: e.a, bulge: e.bulge }).collect()));
        }
        Self::from_loops(result, opts)
    }

    /// Validates loops (outer first) into a shape.
    pub(crate) fn from_loops(loops: Vec<Loop>, opts: &ShapeOptions) -> Result<Shape2d, ShapeError> {
        let v = validate(loops, opts)?;
        Ok(Shape2d {
            loops: v.loops,
            reversed: v.reversed,
            joints: v.joints,
            flattened: v.flattened,
            tolerance: v.tolerance,
            bbox: v.bbox,
        })
    }

    /// All loops: `[outer, holes...]`, normalised (outer counter-clockwise, holes clockwise).
    pub fn loops(&self) -> &[Loop] {
        &self.loops
    }

    /// The outer boundary (counter-clockwise).
    pub fn outer(&self) -> &Loop {
        &self.loops[0]
    }

    /// The holes (clockwise), in input order.
    pub fn holes(&self) -> &[Loop] {
        &self.loops[1..]
    }

    /// True when loop `l` was given in the other orientation and reversed.
    /// Element `k` of a reversed loop is input element `(n − 2 − k) mod n`.
    pub fn was_reversed(&self, l: usize) -> bool {
        self.reversed[l]
    }

    /// The input element index of stored element `k` of loop `l`. For a
    /// curve site, elements on the way back give the index of the curve
    /// element they run over (see [`on_way_back`](Self::on_way_back)).
    pub fn input_element_index(&self, l: usize, k: usize) -> usize {
        let n = self.loops[l].len();
        if self.loops[l].kind() == crate::shape::model::bulge_loop::LoopKind::Curve {
            // The way back (stored elements n/2..n) runs over the curve's
            // elements in reverse: element n − 1 − k of the curve.
            return k.min(n - 1 - k);
        }
        if self.reversed[l] {
            (2 * n - 2 - k) % n
        } else {
            k
        }
    }

    /// The input vertex index of stored vertex `v` of loop `l` (the start of
    /// stored element `v`).
    pub fn input_vertex_index(&self, l: usize, v: usize) -> usize {
        let n = self.loops[l].len();
        if self.loops[l].kind() == crate::shape::model::bulge_loop::LoopKind::Curve {
            // Vertex n/2 is the curve's far end; past it the way back.
            return v.min(n - v);
        }
        if self.reversed[l] {
            (2 * n - 1 - v) % n
        } else {
            v
        }
    }

    /// True when stored element `k` of curve loop `l` is on the curve's way
    /// back (its right side, walking the curve as given); false for the
    /// way out and for every other kind of loop.
    pub fn on_way_back(&self, l: usize, k: usize) -> bool {
        let lp = &self.loops[l];
        lp.kind() == crate::shape::model::bulge_loop::LoopKind::Curve && 2 * k >= lp.len()
    }

    /// What loop `l` bounds: a region or a curve site.
    pub fn kind(&self, l: usize) -> crate::shape::model::bulge_loop::LoopKind {
        self.loops[l].kind()
    }

    /// Joint kind at vertex `i` of loop `l` (between elements `i − 1` and `i`
    /// of the stored, normalised loop).
    pub fn joint(&self, l: usize, i: usize) -> JointKind {
        self.joints[l][i]
    }

    /// Counts of (smooth, convex, reflex) joints over all loops.
    pub fn joint_counts(&self) -> [usize; 3] {
        let mut c = [0; 3];
        for j in self.joints.iter().flatten() {
            c[*j as usize] += 1;
        }
        c
    }

    /// Counts of (segments, arcs) over all loops.
    pub fn element_counts(&self) -> (usize, usize) {
        let arcs = self.loops.iter().flat_map(|l| l.vertices.iter()).filter(|v| v.bulge != 0.0).count();
        (self.element_count() - arcs, arcs)
    }

    /// Total number of elements over all loops.
    pub fn element_count(&self) -> usize {
        self.loops.iter().map(Loop::len).sum()
    }

    /// Enclosed area: outer area minus holes, in square model units.
    pub fn area(&self) -> f64 {
        self.loops.iter().map(Loop::signed_area).sum()
    }

    /// Tight bounding box of the boundary.
    pub fn bbox(&self) -> BBox {
        self.bbox
    }

    /// The absolute length tolerance this shape was validated with (model units).
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// How many input arcs were flatter than the flattening bound and became segments.
    pub fn flattened_arcs(&self) -> usize {
        self.flattened
    }

    /// The loops as plain `[x, y, bulge]` vertex lists, as stored.
    pub fn to_raw_loops(&self) -> Vec<Vec<crate::io::RawVertex>> {
        self.loops.iter().map(|l| l.vertices.iter().map(|&v| crate::io::RawVertex::from(v)).collect()).collect()
    }

    /// The shape in medax JSON (`{"loops": ...}`), normalised orientation.
    pub fn to_json(&self) -> String {
        crate::io::json::write_loops(&self.to_raw_loops())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn sweep_directions() {
        assert!((directed_sweep(0.0, PI / 2.0, true) - PI / 2.0).abs() < 1e-15);
        assert!((directed_sweep(0.0, PI / 2.0, false) + 1.5 * PI).abs() < 1e-15);
        assert_eq!(directed_sweep(1.0, 1.0, true), TAU);
    }
}
