//! Medial axes of shapes bounded by segments and circular arcs, in the
//! Euclidean plane (thesis chapter 2).
//!
//! Built so far: maximal disks ([`maxdisk`], thesis 2.2.1, Algorithm 1),
//! answered by a branch-and-bound search over the shape's element index
//! instead of the thesis's scan of all elements, and the subshapes a disk
//! cuts a shape into ([`subshape`]). The divide loop, the base cases and the
//! conquer step (2.2.1–2.2.4) build on them.

pub mod augment;
pub mod axis;
pub mod axis_json;
pub mod base_case;
pub mod conquer;
pub mod divide;
pub mod draw;
mod fan_cut;
pub mod leaf_text;
pub mod maxdisk;
pub mod maxdisk_star;
pub mod offset;
pub mod offset_draw;
pub mod offset_dxf;
pub mod offset_json;
mod offset_outer;
mod offset_prim;
mod offset_profile;
mod offset_tour;
pub(crate) mod offset_trim;
pub mod subshape;
mod tour;
pub mod voronoi;
mod voronoi_draw;
mod voronoi_frame;
pub mod voronoi_json;
pub mod voronoi_regions;

pub use axis::{AxisEdge, AxisNode, MedialAxis2d, NodeKind, Primitive};
pub use conquer::{medial_axis, medial_axis_with, AxisError, AxisOptions};
pub use draw::AxisPicture;
pub use maxdisk::{DiskFinder, Footpoint, MaxDisk};
pub use offset::{OffsetError, OffsetLayer, OffsetLoop, OffsetOptions, OffsetRegion, Offsets};
pub use subshape::{BoundaryPos, Cut, Piece, Subshape};
pub use voronoi::{voronoi, SiteId, Sites, VoronoiDiagram, VoronoiEdge, VoronoiError, VoronoiOptions};
pub use voronoi_regions::SiteRegion;
