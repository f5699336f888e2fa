//! Elements read from files before they are chained into loops.

use crate::kernel::Point;

/// An element with both end points and a bulge, not yet in a loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LooseElement {
    /// Start point.
    pub a: Point,
    /// End point.
    pub b: Point,
    /// Bulge from `a` to `b` (0 = segment).
    pub bulge: f64,
}
