//! The 2D shape model: loops of segments and circular arcs, validated.
//!
//! Thesis Definition 2.1.1 (shapes with a circular-arc representation) and
//! 2.2.1 (joint classification); holes as in 2.3. Built from bulge loops,
//! explicit elements or files, validated once, immutable afterwards.

mod box_pairs;
mod box_tree;
mod bulge_loop;
mod chain;
mod chain_tree;
mod containment;
mod draw;
mod element;
mod error;
mod import;
mod intersect;
mod joints;
mod options;
mod per_element;
pub mod samples;
mod shape2d;
mod sweep;
mod sweep_status;
mod validate;

pub use box_tree::BoxTree;
pub use bulge_loop::{winding_contribution, Loop, LoopKind, Vertex};
pub use chain::{chain_loops, LooseElement};
pub use chain_tree::ChainTree;
pub use draw::{draw_joints, push_loop_path, shape_document, shape_path};
pub use element::{Arc, Element, Segment};
pub use error::{Degeneracy, ElementRef, ShapeError};
pub use import::sniff;
pub use joints::{classify, turning_angle, JointKind};
pub use options::ShapeOptions;
pub use shape2d::{ElementSpec, Shape2d};
pub(crate) use validate::ElementIndex;

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
