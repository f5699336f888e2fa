//! Medial axes of shapes bounded by segments and circular arcs, in the
//! Euclidean plane (thesis chapter 2).
//!
//! Built so far: maximal disks ([`maxdisk`], thesis 2.2.1, Algorithm 1),
//! answered by a branch-and-bound search over the shape's element index
//! instead of the thesis's scan of all elements, and the subshapes a disk
//! cuts a shape into ([`subshape`]). The divide loop, the base cases and the
//! conquer step (2.2.1–2.2.4) build on them.

pub mod divide;
pub mod maxdisk;
pub mod maxdisk_star;
pub mod subshape;

pub use maxdisk::{DiskFinder, Footpoint, MaxDisk};
pub use subshape::{BoundaryPos, Cut, Piece, Subshape};
