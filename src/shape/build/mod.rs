//! Shapes from what files and callers hold: loose elements chained into
//! loops, files (JSON, DXF, SVG) read into shapes, and generated sample
//! shapes for tests, benchmarks and demos.

pub(crate) mod chain;
pub(crate) mod drawing;
pub(crate) mod import;
pub(crate) mod profile_graph;
pub(crate) mod profiles;
pub mod samples;
pub(crate) mod touching;
