//! What an offset computation returns: loops in bulge form, grouped into
//! regions, per distance; and why it can fail.

use crate::plane::medial::conquer::AxisError;
use crate::shape::Vertex;

/// Why offsets could not be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum OffsetError {
    /// The distance is not finite, or an outer distance beyond
    /// [`OffsetOptions::outer_reach`](crate::plane::OffsetOptions::outer_reach).
    BadDistance(f64),
    /// The reach for outer offsets is negative or not finite.
    BadReach(f64),
    /// The shape holds a loop that bounds no region (a point or curve site):
    /// offsets are of regions.
    NotRegion {
        /// The loop, in the shape's indexing.
        loop_index: usize,
    },
    /// A medial axis (of the shape or of its complement) failed.
    Axis(AxisError),
    /// The axis did not close into loops at this distance: its edges do not
    /// form the tour round the boundary they should (a defect, reported
    /// instead of a wrong offset).
    Topology {
        /// The distance asked for.
        distance: f64,
        /// What went wrong.
        what: &'static str,
    },
}

impl std::fmt::Display for OffsetError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OffsetError::BadDistance(d) => write!(f, "offset distance {d} is not finite or beyond the outer reach"),
            OffsetError::BadReach(r) => write!(f, "outer reach {r} must be finite and at least 0"),
            OffsetError::NotRegion { loop_index } => {
                write!(f, "loop {loop_index} is a point or curve site; offsets are of regions")
            }
            OffsetError::Axis(e) => write!(f, "medial axis: {e}"),
            OffsetError::Topology { distance, what } => write!(f, "offset at distance {distance}: {what}"),
        }
    }
}

impl std::error::Error for OffsetError {}

impl From<AxisError> for OffsetError {
    fn from(e: AxisError) -> Self {
        OffsetError::Axis(e)
    }
}

/// One closed offset loop: segments and exact arcs in bulge form, the
/// region on its left (outer loops counter-clockwise, holes clockwise).
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetLoop {
    /// The vertices; element `i` runs from vertex `i` to vertex `i + 1`
    /// (cyclically) with `vertices[i].bulge`. No element is shorter than the
    /// shape's tolerance.
    pub vertices: Vec<Vertex>,
    /// Signed area enclosed, square model units: positive for an outer
    /// loop, negative for a hole.
    pub area: f64,
    /// Index of the region in [`OffsetLayer::regions`] this loop bounds.
    pub region: usize,
}

impl OffsetLoop {
    /// Whether the loop bounds a hole of its region (clockwise).
    pub fn is_hole(&self) -> bool {
        self.area < 0.0
    }
}

/// Its vertices: the writers take offset loops and plain vertex loops
/// alike.
impl AsRef<[Vertex]> for OffsetLoop {
    fn as_ref(&self) -> &[Vertex] {
        &self.vertices
    }
}

/// A connected part of the offset region: one outer loop and its holes.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetRegion {
    /// Index of the outer loop in [`OffsetLayer::loops`].
    pub outer: usize,
    /// Indices of the hole loops.
    pub holes: Vec<usize>,
}

/// The offset at one distance.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetLayer {
    /// The distance, model units: positive inwards, negative outwards.
    pub distance: f64,
    /// Every loop of the offset boundary.
    pub loops: Vec<OffsetLoop>,
    /// The connected regions the loops bound (for an inner offset, the
    /// components of Ω^ρ; for an outer one, of the grown shape).
    pub regions: Vec<OffsetRegion>,
    /// For each region, a monotonic edge piece of the inner axis inside it
    /// (`usize::MAX` for a disk's one region and for outer offsets), and the
    /// region of each edge piece above the distance (`u32::MAX` below): how
    /// the CAM layer nests the regions of successive layers without
    /// geometry.
    pub(crate) anchors: Vec<usize>,
    pub(crate) piece_region: Vec<u32>,
}

impl OffsetLayer {
    /// Total signed area of the offset region, square model units.
    pub fn area(&self) -> f64 {
        self.loops.iter().map(|l| l.area).sum()
    }

    /// The empty offset at `distance`.
    pub fn empty(distance: f64) -> OffsetLayer {
        OffsetLayer { distance, loops: Vec::new(), regions: Vec::new(), anchors: Vec::new(), piece_region: Vec::new() }
    }

    /// A layer of loops computed elsewhere (the offsets under a polygon
    /// ball), so the writers and pictures serve it too. It carries no axis
    /// anchors: the pocketing layer cannot nest it.
    pub fn from_loops(distance: f64, loops: Vec<OffsetLoop>, regions: Vec<OffsetRegion>) -> OffsetLayer {
        let anchors = vec![usize::MAX; regions.len()];
        OffsetLayer { distance, loops, regions, anchors, piece_region: Vec::new() }
    }

    /// Whether nothing is left at this distance.
    pub fn is_empty(&self) -> bool {
        self.loops.is_empty()
    }

    /// The loops of region `r`: its outer loop first, then its holes.
    pub fn region_loops(&self, r: usize) -> Vec<OffsetLoop> {
        let region = &self.regions[r];
        std::iter::once(region.outer).chain(region.holes.iter().copied()).map(|i| self.loops[i].clone()).collect()
    }

    /// The region of this layer that encloses region `r` of `deeper`, an
    /// inner offset of the same [`Offsets`](crate::plane::Offsets) at a larger distance. Read off
    /// the axis: the piece of axis inside `r` lies above this layer's
    /// distance too, in exactly one of its regions.
    pub fn region_enclosing(&self, deeper: &OffsetLayer, r: usize) -> Option<usize> {
        let piece = *deeper.anchors.get(r)?;
        if piece == usize::MAX {
            // A disk's single region.
            return (self.regions.len() == 1).then_some(0);
        }
        let found = *self.piece_region.get(piece)?;
        (found != u32::MAX).then_some(found as usize)
    }
}
