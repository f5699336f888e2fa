//! Medial axes, Voronoi diagrams and trimmed offsets of shapes bounded by
//! segments and circular arcs, in the Euclidean plane (thesis chapter 2).
//!
//! The folders follow the thesis and depend on each other in one direction
//! only (`docs/ARCHITECTURE.md` draws the graph):
//!
//! * `axis/`: the output graph, [`MedialAxis2d`] (thesis 2.2.3–2.2.4), its
//!   JSON contract and pictures. It knows nothing of how it was computed.
//! * `medial/`: the randomized divide-and-conquer that computes it:
//!   maximal disks (`disk/`, 2.2.1–2.2.2), subshapes and the divide step
//!   with holes (`decompose/`, 2.2.1, 2.3.1), the base cases
//!   (`base_case/`, 2.2.2.2–2.2.3) and the conquer step (`conquer/`, 2.2.4).
//! * `voronoi/`: Voronoi diagrams of sites as the axis of a framed shape
//!   (2.3).
//! * `offset/`: trimmed offsets read off the axis (2.4).
//!
//! This module re-exports the public API; everything else is crate-private.
//! Tests, fuzz targets and developer tools reach the algorithm's internals
//! through `internals`, compiled only with the `internals` feature.

pub(crate) mod axis;
pub(crate) mod medial;
pub(crate) mod offset;
pub(crate) mod voronoi;

pub use crate::shape::SiteRegion;
pub use axis::draw::AxisPicture;
pub use axis::json::site_json;
pub use axis::{AxisEdge, AxisNode, MedialAxis2d, NodeKind, Primitive, MIN_RELATIVE_SAMPLE_TOLERANCE};
pub use medial::conquer::{medial_axis, medial_axis_with, AxisError, AxisOptions};
pub use medial::decompose::subshape::{BoundaryPos, Cut, Piece, Subshape};
pub use medial::disk::maximal::{DiskFinder, Footpoint, MaxDisk};
pub use offset::draw::{layer_colour, offsets_to_svg};
pub use offset::dxf::offsets_to_dxf;
pub use offset::json::{offsets_to_json, write_offsets_json};
pub use offset::{OffsetError, OffsetLayer, OffsetLoop, OffsetOptions, OffsetRegion, Offsets};
pub use voronoi::json::{read_sites, shape_or_sites, site_id_json};
pub use voronoi::{voronoi, SiteId, Sites, VoronoiDiagram, VoronoiEdge, VoronoiError, VoronoiOptions};

/// The algorithm's internal steps, for the project's own tests, fuzz
/// targets and developer tools (leaf dumps, replays, profiles). Not a
/// stable API: compiled only with the `internals` cargo feature.
#[cfg(feature = "internals")]
pub mod internals {
    /// The base-case solver: one leaf's axis, computed directly.
    pub mod base_case {
        pub use crate::plane::medial::base_case::{solve, BaseCaseError, EventKind, LocalAxis};
    }
    /// Leaf dumps as exact text, to replay a breakdown.
    pub mod leaf_text {
        pub use crate::plane::medial::decompose::leaf_text::{read_leaf, write_leaf, LeafTextError};
    }
    pub use crate::plane::medial::conquer::locals::{LocalAxes, LocalView};
    pub use crate::plane::medial::conquer::{final_check, glue, solve_leaves};
    pub use crate::plane::medial::decompose::augment::augment;
    pub use crate::plane::medial::decompose::divide::{
        decompose, decompose_in, decompose_plain_in, decompose_with, divide_into, leaf_size, Decomposition,
    };
    pub use crate::plane::medial::decompose::leaf_text::{read_leaf, write_leaf};
    pub use crate::plane::medial::decompose::subshape::ChainParts;
}
