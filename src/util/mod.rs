//! Helpers that are neither geometry nor file formats, below every layer:
//! the seeded random numbers of the divide step and the sample shapes, and
//! reproducible parallel sums.

pub(crate) mod chunked;
pub(crate) mod mix;
