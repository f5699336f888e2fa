//! The vocabulary of shapes (thesis Definition 2.1.1; segments and arcs
//! themselves are the kernel's, `kernel::element`): bulge loops and their kinds, joint classes, the options and tolerances,
//! the errors, parallel maps over all elements of all loops, and the sites
//! of Voronoi diagrams with their regions (shared by chapters 2 and 3).

pub(crate) mod bulge_loop;
pub(crate) mod error;
pub(crate) mod joints;
pub(crate) mod loose;
pub(crate) mod options;
pub(crate) mod per_element;
pub(crate) mod site_regions;
pub(crate) mod sites;
