//! The medial axis of a shape bounded by segments and arcs, by randomized
//! divide-and-conquer with maximal disks (thesis 2.2, holes 2.3.1).
//!
//! `disk/` answers the maximal disk at a boundary point; `decompose/` cuts
//! the shape with such disks into subshapes down to leaves; `base_case/`
//! computes a leaf's axis directly; `conquer/` glues the leaves' axes at
//! the dividing disks' centres and checks the result.

pub(crate) mod base_case;
pub(crate) mod conquer;
pub(crate) mod decompose;
pub(crate) mod disk;
