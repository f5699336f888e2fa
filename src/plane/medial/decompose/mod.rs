//! The divide step (thesis 2.2.1, Algorithm 2): subshapes bounded by
//! original chains and auxiliary arcs, holes joined into one boundary
//! cycle by augmenting disks (2.3.1), random dividing disks down to leaves.

pub(crate) mod augment;
pub(crate) mod cut;
pub(crate) mod cut_rules;
pub(crate) mod divide;
pub(crate) mod fan_cut;
// Leaf dumps serve only the replay tools and tests.
#[cfg(feature = "internals")]
pub(crate) mod leaf_text;
pub(crate) mod parts;
pub(crate) mod subshape;
pub(crate) mod tour;
