//! Spatial indexes over a shape's elements: the box tree (box and ray
//! queries, best-first search), the chain tree (nearest elements and the
//! first contacts of a growing disk) and all pairs of nearby boxes.

pub(crate) mod box_pairs;
pub(crate) mod box_tree;
pub(crate) mod chain_tree;
