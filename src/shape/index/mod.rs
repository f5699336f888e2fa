//! Spatial indexes over a shape's elements: the box tree (box and ray
//! queries, best-first search), the chain tree (nearest elements and the
//! first contacts of a growing disk), all pairs of nearby boxes, and all
//! elements of all loops in one box tree with global ids.

pub(crate) mod box_pairs;
pub(crate) mod box_tree;
pub(crate) mod chain_tree;
pub(crate) mod element_index;
