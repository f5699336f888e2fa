//! Triangulated solids (thesis chapter 3 in space): read, welded,
//! triangulated and validated once, immutable afterwards.
//!
//! * `options.rs`, `error.rs`: what the caller sets and what can go wrong
//!   (typed errors naming the vertex, face or edge, and the file line).
//! * `weld.rs`: vertices at one place become one.
//! * `triangulate.rs`: polygon faces into triangles (exact ear clipping).
//! * `topology.rs`: edges, orientation, components, vertex fans.
//! * `nesting.rs`: which component lies inside which (cavities).
//! * `mesh3d.rs`: the validated [`Mesh3d`] and its facts.
//! * `read.rs`: solids from files, readers' output and arrays.
//! * `samples.rs`: generated solids (tori, spheres, boxes) for tests and
//!   benchmarks.

mod aabb;
mod error;
mod mesh3d;
mod nesting;
mod options;
mod read;
pub mod samples;
mod topology;
mod triangulate;
mod weld;

pub use aabb::{
    BallContact, Closest, ContactKind3, ExactContact, ExactContacts, ExactMaximalBall, Hit, MaximalBall, SurfacePart,
    TriangleTree,
};
pub use error::{FaceRef, MeshError};
pub use mesh3d::{Component, Faces, Mesh3d, MeshReport};
pub use options::MeshOptions;
