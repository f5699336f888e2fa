//! Outer offsets as inner offsets of the complement (thesis 2.4.1)
//! (placeholder while the implementation lands).

use super::offset::{OffsetError, OffsetLayer, OffsetOptions, Offsets};
use super::offset_trim::Trimmer;
use crate::shape::Shape2d;

pub(crate) fn complement_trimmers(shape: &Shape2d, opts: &OffsetOptions) -> Result<Vec<Trimmer>, OffsetError> {
    let _ = (shape, opts);
    unimplemented!("outer offsets")
}

pub(crate) fn outer_layer(offsets: &Offsets, distance: f64) -> Result<OffsetLayer, OffsetError> {
    let _ = (offsets, distance);
    unimplemented!("outer offsets")
}
