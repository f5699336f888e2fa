//! The trimming walk of thesis 2.4.3 for one axis (placeholder while the
//! implementation lands).

use super::offset::OffsetLayer;
use super::MedialAxis2d;
use crate::shape::Shape2d;

/// One axis prepared for offsets at any distance.
#[derive(Debug, Clone)]
pub(crate) struct Trimmer {
    max_radius: f64,
}

impl Trimmer {
    pub(crate) fn new(shape: &Shape2d, axis: &MedialAxis2d) -> Trimmer {
        let _ = shape;
        Trimmer { max_radius: axis.nodes.iter().map(|n| n.radius).fold(0.0, f64::max) }
    }

    pub(crate) fn max_radius(&self) -> f64 {
        self.max_radius
    }

    pub(crate) fn layer(&self, distance: f64, tolerance: f64) -> Result<OffsetLayer, super::OffsetError> {
        let _ = (distance, tolerance);
        unimplemented!("trimmed offsets")
    }
}
