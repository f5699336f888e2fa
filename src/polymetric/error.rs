//! Why the axis under a polygon ball could not be computed.

use crate::kernel::Point;
use std::fmt;

/// Errors of [`super::medial_axis_with_ball`].
#[derive(Debug, Clone, PartialEq)]
pub enum BallAxisError {
    /// Element `i` of loop `l` (the caller's indexing) is an arc: polygon
    /// balls work on polygons (thesis 3.2); flatten arcs first.
    Arc {
        /// Loop.
        l: usize,
        /// Element in the loop.
        i: usize,
    },
    /// Loop `l` is a point or curve site, not a region (offsets under a
    /// ball are of regions).
    NotRegion {
        /// Loop.
        l: usize,
    },
    /// The exact tracing met a configuration it does not resolve (a bug:
    /// please report the shape and ball); `at` is where, in model units.
    Inconsistent {
        /// Where, model units.
        at: Point,
        /// What went wrong.
        what: &'static str,
    },
}

impl fmt::Display for BallAxisError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BallAxisError::Arc { l, i } => {
                write!(f, "loop {l} element {i} is an arc; the axis under a polygon ball needs a polygon")
            }
            BallAxisError::NotRegion { l } => write!(f, "loop {l} is a point or curve site, not a region"),
            BallAxisError::Inconsistent { at, what } => {
                write!(f, "polygon-ball axis broke down near ({}, {}): {what}", at.x, at.y)
            }
        }
    }
}

impl std::error::Error for BallAxisError {}
