//! Trimmed offsets from the medial axis (thesis 2.4).
//!
//! The boundary of the inner offset Ω^ρ = {p ∈ Ω : dist(p, ∂Ω) > ρ} is
//! made of offsets of the boundary's own elements: a segment moved by ρ
//! along its inward normal, an arc with its radius changed by ρ, an arc of
//! radius ρ around a reflex vertex. The medial axis says which parts
//! survive: a boundary point f contributes f + ρ·n(f) exactly when the
//! maximal disk touching it at f has a radius above ρ. Each axis edge
//! carries the footpoint ranges of its two primitives (its induced subshape,
//! Definition 2.4.1); split where its radius has an inner extremum
//! (Figure 2.22), the radius is monotonic along every piece, so the offset
//! of each side is kept up to the one disk of radius ρ on it, where the
//! offset turns over to the edge's other side. Walking the boundary's order
//! of the edge sides (the tour round the axis) concatenates the pieces into
//! closed loops. Arcs stay exact arcs.
//!
//! One [`Offsets`] serves any number of distances; each layer costs time
//! linear in the size of the axis.
//!
//! ```
//! use medax::kernel::Point;
//! use medax::plane::{OffsetOptions, Offsets};
//! use medax::shape::{Shape2d, ShapeOptions, Vertex};
//! let v = |x, y| Vertex { p: Point::new(x, y), bulge: 0.0 };
//! // A 4 × 2 rectangle with a 1 × 1 square hole.
//! let shape = Shape2d::from_bulge_loops(
//!     vec![vec![v(0.0, 0.0), v(4.0, 0.0), v(4.0, 2.0), v(0.0, 2.0)],
//!          vec![v(2.5, 0.5), v(3.5, 0.5), v(3.5, 1.5), v(2.5, 1.5)]],
//!     &ShapeOptions::default(),
//! )?;
//! let offsets = Offsets::new(&shape, &OffsetOptions { outer_reach: 1.0, ..OffsetOptions::default() })?;
//! // Inwards by 0.2: the hole grows round (quarter arcs at its corners)
//! // and the outer boundary shrinks to a 3.6 × 1.6 rectangle.
//! let layer = offsets.layer(0.2)?;
//! assert_eq!((layer.loops.len(), layer.regions.len()), (2, 1));
//! let hole = 1.0 + 4.0 * 0.2 + std::f64::consts::PI * 0.2 * 0.2;
//! assert!((layer.area() - (3.6 * 1.6 - hole)).abs() < 1e-12);
//! // At 0.25 the 0.5-wide channels round the hole close: the big part on
//! // the left and two small ones at the hole's right corners.
//! assert_eq!(offsets.layer(0.25)?.regions.len(), 3);
//! // Arcs stay arcs: the hole's loop has four quarter arcs (bulge tan(π/8)).
//! let hole_loop = &layer.loops[layer.regions[0].holes[0]];
//! assert_eq!(hole_loop.vertices.iter().filter(|v| v.bulge != 0.0).count(), 4);
//! // Outwards by 0.5: one region, the hole shrunk to 0 (gone).
//! let grown = offsets.layer(-0.5)?;
//! assert_eq!(grown.loops.len(), 1);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub(crate) mod draw;
pub(crate) mod dxf;
pub(crate) mod json;
pub(crate) mod layer;
pub(crate) mod outer;
pub(crate) mod prim;
pub(crate) mod profile;
pub(crate) mod side_cycle;
pub(crate) mod trim;

pub use layer::{OffsetError, OffsetLayer, OffsetLoop, OffsetRegion};

use crate::kernel::tolerance::Tolerance;
use crate::plane::axis::MedialAxis2d;
use crate::plane::medial::conquer::{medial_axis, AxisOptions};
use crate::plane::offset::trim::Trimmer;
use crate::shape::{LoopKind, Shape2d};

/// Options for [`Offsets::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OffsetOptions {
    /// Options of the medial-axis computations (the shape's axis, and for
    /// outer offsets the axes of the shape's complement).
    pub axis: AxisOptions,
    /// Outer offsets (negative distances) are available up to this distance,
    /// model units; 0 for inner offsets only. Outer offsets are inner
    /// offsets of the complement (thesis 2.4.1): the shape as a hole in a
    /// circle that far away, and each hole as a region of its own.
    pub outer_reach: f64,
}

impl Default for OffsetOptions {
    fn default() -> Self {
        OffsetOptions { axis: AxisOptions::default(), outer_reach: 0.0 }
    }
}

/// A shape prepared for offsetting at any distance: its medial axis, and
/// for outer offsets the axes of its complement.
#[derive(Debug, Clone)]
pub struct Offsets {
    pub(crate) inner: Trimmer,
    /// The complement's parts: the shape as a hole in a far circle (first),
    /// then each hole as a region.
    pub(crate) outer: Vec<Trimmer>,
    pub(crate) outer_reach: f64,
    tolerance: f64,
}

impl Offsets {
    /// Computes the shape's medial axis (and, for `opts.outer_reach > 0`,
    /// the complement's) and prepares the offsets.
    pub fn new(shape: &Shape2d, opts: &OffsetOptions) -> Result<Offsets, OffsetError> {
        check_regions(shape)?;
        let axis = medial_axis(shape, &opts.axis)?;
        Offsets::from_axis(shape, &axis)?.with_outer(shape, opts)
    }

    /// Adds outer offsets up to `opts.outer_reach` (nothing for 0): the
    /// axes of `shape`'s complement, computed with `opts.axis`. `shape` is
    /// the shape these offsets were prepared from.
    pub fn with_outer(mut self, shape: &Shape2d, opts: &OffsetOptions) -> Result<Offsets, OffsetError> {
        if opts.outer_reach != 0.0 {
            self.outer = outer::complement_trimmers(shape, &opts.axis, opts.outer_reach)?;
            self.outer_reach = opts.outer_reach;
        }
        Ok(self)
    }

    /// Inner offsets from an axis computed by the caller (of this very
    /// shape).
    pub fn from_axis(shape: &Shape2d, axis: &MedialAxis2d) -> Result<Offsets, OffsetError> {
        check_regions(shape)?;
        let inner = Trimmer::new(shape, axis);
        inner.check().map_err(|what| OffsetError::Topology { distance: 0.0, what })?;
        Ok(Offsets { inner, outer: Vec::new(), outer_reach: 0.0, tolerance: shape.tolerance() })
    }

    /// The largest inner distance with anything left: the radius of the
    /// largest inscribed disk, model units.
    pub fn max_inner_distance(&self) -> f64 {
        self.inner.max_radius()
    }

    /// The outer reach these offsets were prepared for, model units.
    pub fn outer_reach(&self) -> f64 {
        self.outer_reach
    }

    /// The offset at `distance`: inwards for positive distances, outwards for
    /// negative ones (up to the outer reach), the shape's own boundary at 0.
    pub fn layer(&self, distance: f64) -> Result<OffsetLayer, OffsetError> {
        // The reach itself is allowed up to rounding (r·k/k).
        if !distance.is_finite() || -distance > self.outer_reach * (1.0 + Tolerance::reach_rounding()) {
            return Err(OffsetError::BadDistance(distance));
        }
        if distance >= 0.0 {
            self.inner.layer(distance, self.tolerance)
        } else {
            outer::outer_layer(&self.outer, self.tolerance, -distance)
        }
    }

    /// The offsets at several distances, computed in parallel, in the order
    /// given.
    pub fn layers(&self, distances: &[f64]) -> Result<Vec<OffsetLayer>, OffsetError> {
        use rayon::prelude::*;
        distances.par_iter().map(|&d| self.layer(d)).collect()
    }

    /// The shape's touching tolerance, model units.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }
}

fn check_regions(shape: &Shape2d) -> Result<(), OffsetError> {
    match (0..shape.loops().len()).find(|&l| shape.kind(l) != LoopKind::Region) {
        Some(loop_index) => Err(OffsetError::NotRegion { loop_index }),
        None => Ok(()),
    }
}
