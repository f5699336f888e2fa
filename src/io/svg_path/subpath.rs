//! What the reader returns: subpaths of straight segments and elliptical
//! arcs.

/// One drawing segment of a subpath, from the current point to `to`, in
/// absolute SVG user coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathSeg {
    /// Straight segment.
    Line {
        /// End point, user units.
        to: [f64; 2],
    },
    /// Elliptical arc in SVG's endpoint form (the `A` command). The radii are
    /// as written: SVG's corrections for negative, zero or too small radii are
    /// left to the caller.
    Arc {
        /// x radius, user units.
        rx: f64,
        /// y radius, user units.
        ry: f64,
        /// Rotation of the ellipse's x axis, degrees.
        x_rotation_deg: f64,
        /// SVG large-arc flag: take the arc of more than 180 degrees.
        large_arc: bool,
        /// SVG sweep flag: run in the positive-angle direction (clockwise on
        /// screen, where y points down).
        sweep: bool,
        /// End point, user units.
        to: [f64; 2],
    },
}

/// A subpath: a start point and the segments drawn from it.
#[derive(Debug, Clone, PartialEq)]
pub struct SvgSubpath {
    /// Start point, user units.
    pub start: [f64; 2],
    /// Segments in drawing order; may be empty (e.g. a lone `M`).
    pub segs: Vec<PathSeg>,
    /// True when the subpath is closed (`Z`, `<polygon>`, `<rect>`, ...): a
    /// straight segment back to `start` is implied when the last segment does
    /// not already end there.
    pub closed: bool,
    /// Byte offset in the input of the command that started the subpath (`M`,
    /// or the first command after a `Z`), or of the element's `<`.
    pub source: usize,
}

/// A subpath with its segments.
pub(crate) fn subpath(start: [f64; 2], segs: Vec<PathSeg>, closed: bool, source: usize) -> SvgSubpath {
    SvgSubpath { start, segs, closed, source }
}

/// An unrotated elliptical arc in the positive-angle direction of at most
/// 180 degrees: the pieces of circles, ellipses and rounded corners.
pub(crate) fn arc_to(rx: f64, ry: f64, to: [f64; 2]) -> PathSeg {
    PathSeg::Arc { rx, ry, x_rotation_deg: 0.0, large_arc: false, sweep: true, to }
}
