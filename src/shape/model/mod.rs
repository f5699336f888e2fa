//! The vocabulary of shapes (thesis Definition 2.1.1; segments and arcs
//! themselves are the kernel's, `kernel::element`): bulge loops and their kinds, joint classes, the options and tolerances,
//! the errors, and parallel maps over all elements of all loops.

pub(crate) mod bulge_loop;
pub(crate) mod error;
pub(crate) mod joints;
pub(crate) mod loose;
pub(crate) mod options;
pub(crate) mod per_element;
pub(crate) mod sites;
