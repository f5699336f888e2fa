//! The 2D shape model: loops of segments and circular arcs, validated.
//!
//! Thesis Definition 2.1.1 (shapes with a circular-arc representation) and
//! 2.2.1 (joint classification); holes as in 2.3. Built from bulge loops,
//! explicit elements or files, validated once, immutable afterwards.
//!
//! The folders depend on each other in one direction only
//! (`docs/ARCHITECTURE.md` draws the graph):
//!
//! * `model/`: the vocabulary: elements, bulge loops, joints, options,
//!   errors, parallel maps over all elements.
//! * `index/`: spatial indexes over elements: box tree, chain tree, pairs
//!   of nearby boxes.
//! * `validate/`: the validation pipeline: intersections (box pairs or a
//!   plane sweep), holes' containment.
//! * `shape2d.rs`: the validated [`Shape2d`] and its constructors.
//! * `build/`: shapes from loose elements and files, generated test shapes.
//! * `draw.rs`: SVG pictures of a shape.
//! * `ball/`: unit balls of convex distance functions (chapter 3): the
//!   plane's convex polygons ([`Ball2`]), gauge distances, contact features.
//! * `mesh/`: triangulated solids ([`Mesh3d`]): welded, triangulated,
//!   validated (closed, manifold, oriented outward, nested components).

pub(crate) mod ball;
pub(crate) mod build;
pub(crate) mod draw;
pub(crate) mod draw_sites;
pub(crate) mod index;
pub(crate) mod mesh;
pub(crate) mod model;
pub(crate) mod shape2d;
pub(crate) mod validate;

pub use crate::kernel::element::{Arc, Element, Segment};
pub use ball::{
    touch_exact, Ball2, Ball3, BallEdge3, BallError, BallFacet3, ExactTouch, Feature, Feature3, Reach, ReachHint,
    TouchPoint, TrianglePart, TriangleReach,
};
pub use build::chain::chain_loops;
pub use build::import::sniff;
pub use build::profiles::{profiles, unit_name, Drawing2d, DrawingOptions, Ignored, IgnoredKind, Touching};
pub use build::samples;
pub use draw::{draw_joints, push_loop_path, shape_document, shape_path};
pub use index::box_tree::BoxTree;
pub use index::chain_tree::ChainTree;
pub use mesh::samples as mesh_samples;
pub use mesh::{
    BallContact, Closest, ContactKind3, ExactContact, ExactContacts, ExactMaximalBall, Hit, MaximalBall, SurfacePart,
    TriangleTree,
};
pub use mesh::{Component, FaceRef, Faces, Mesh3d, MeshError, MeshOptions, MeshReport};
pub use model::bulge_loop::{winding_contribution, Loop, LoopKind, Vertex};
pub use model::error::{Degeneracy, ElementRef, ShapeError};
pub use model::joints::{classify, turning_angle, JointKind};
pub use model::loose::LooseElement;
pub use model::options::ShapeOptions;
pub use model::site_regions::SiteRegion;
pub use model::sites::{SiteId, Sites, VoronoiEdge};
pub use shape2d::{ElementSpec, Shape2d};

/// Largest absolute coordinate medax accepts, in model units (vertices and
/// arc extents). Within it, products of coordinates stay far from `f64`
/// overflow and a relative tolerance of 1e-9 still resolves 1e-6 units at
/// the edge, so micrometre CAM data in millimetres fits with room to spare.
pub const MAX_COORDINATE: f64 = 1e9;

/// Floor of the touching tolerance relative to the largest coordinate
/// magnitude (about 2^-46 = 256 ulps): a smaller tolerance, including 0, is
/// raised to it, because constructed crossing points carry that much rounding.
pub const MIN_RELATIVE_TOLERANCE: f64 = 1.0 / (1u64 << 46) as f64;

/// Smallest bounding-box diagonal medax accepts, in model units. Below it,
/// squared lengths and areas approach `f64` underflow and a relative
/// tolerance stops meaning anything.
pub const MIN_EXTENT: f64 = 1e-100;
