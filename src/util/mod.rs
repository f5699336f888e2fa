//! Helpers that are neither geometry nor file formats, below every layer:
//! the seeded random numbers of the divide step and the sample shapes,
//! reproducible parallel sums, and a fast hasher for the library's own
//! integer keys.

pub(crate) mod chunked;
pub(crate) mod fast_hash;
pub(crate) mod mix;
