//! Helpers that are neither geometry nor file formats, below every layer:
//! the seeded random numbers of the divide step and the sample shapes,
//! reproducible parallel sums, a fast hasher for the library's own
//! integer keys, and a stack kept inline for the index walks.

pub(crate) mod chunked;
pub(crate) mod fast_hash;
pub(crate) mod mix;
pub(crate) mod small_stack;
