//! V-carving: a V-bit of included angle α follows the medial axis at depth
//! r / tan(α/2) where r is the radius of the maximal disk (its flanks touch
//! both walls); where that would pass the maximum depth the bottom is flat
//! and bounded by the offset at the capped radius.

use super::CamError;
use crate::plane::{MedialAxis2d, OffsetLayer};
use crate::shape::Shape2d;

/// Options for [`vcarve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VCarveOptions {
    /// Included angle of the V-bit, degrees, in (0, 180).
    pub angle_deg: f64,
    /// Maximum depth, model units, > 0 (infinite: no cap).
    pub max_depth: f64,
    /// Chordal tolerance for the sampled axis curves, model units (0: the
    /// shape's tolerance × 1000).
    pub tolerance: f64,
}

/// One tool path along the axis: points (x, y, depth), depth ≥ 0 measured
/// down from the surface.
#[derive(Debug, Clone, PartialEq)]
pub struct VCarvePath {
    /// (x, y, depth), model units.
    pub points: Vec<[f64; 3]>,
}

/// V-carve paths.
#[derive(Debug, Clone, PartialEq)]
pub struct VCarve {
    /// Paths along the axis, shallower than the maximum depth.
    pub paths: Vec<VCarvePath>,
    /// The radius where the depth is capped: max_depth · tan(α/2).
    pub flat_radius: f64,
    /// The offset rings at the capped radius, cut at the maximum depth
    /// (empty when the cap is never reached).
    pub flat: OffsetLayer,
}

/// V-carve paths of `shape` from its medial axis `axis`.
pub fn vcarve(shape: &Shape2d, axis: &MedialAxis2d, opts: &VCarveOptions) -> Result<VCarve, CamError> {
    let _ = (shape, axis, opts);
    unimplemented!("v-carve")
}
