//! The auxiliary arcs of a subshape (parts of dividing disks' circles) as
//! the base case keeps them: ports through which its axis leaves.

use crate::kernel::CircleArc;

/// An auxiliary arc where a subshape meets a dividing disk: a port through
/// which its axis leaves for the neighbouring subshape.
#[derive(Debug, Clone, Copy)]
pub(super) struct Port {
    /// The dividing disk (index into the divide step's cuts).
    pub(super) disk: usize,
    /// Index of the site after the arc in the cycle (may equal the number
    /// of sites: wrap it).
    pub(super) site_after: usize,
    /// The arc itself.
    pub(super) arc: CircleArc,
}
