//! Why an axis could not be computed, and how the steps' own errors map
//! onto it.

use crate::kernel::Point;
use crate::plane::medial::base_case::BaseCaseError;
use crate::plane::medial::decompose::augment::AugmentError;

/// Why an axis could not be computed.
#[derive(Debug, Clone, PartialEq)]
pub enum AxisError {
    /// Hole `hole` (loop index) got no augmenting disk (thesis 2.3.1):
    /// every direction tried touched more than two places, or rounding on
    /// nearly touching loops broke the order of the disks.
    Augment {
        /// Loop index of the hole.
        hole: usize,
    },
    /// A subshape's axis broke down numerically near this point (what
    /// failed, for the error message).
    Numerical(Point, &'static str),
}

impl std::fmt::Display for AxisError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            AxisError::Augment { hole } => write!(f, "hole {hole} (loop {hole}) got no augmenting maximal disk"),
            AxisError::Numerical(p, what) => {
                write!(f, "medial axis computation broke down near ({}, {}): {what}", p.x, p.y)
            }
        }
    }
}

impl std::error::Error for AxisError {}

impl From<AugmentError> for AxisError {
    fn from(e: AugmentError) -> Self {
        match e {
            AugmentError::NoDisk { hole } | AugmentError::Cycle { hole } => AxisError::Augment { hole },
        }
    }
}

impl From<BaseCaseError> for AxisError {
    fn from(e: BaseCaseError) -> Self {
        match e {
            BaseCaseError::NoDisk(p) => AxisError::Numerical(p, "no maximal disk at a joint"),
            BaseCaseError::EmptyPocket(p) => AxisError::Numerical(p, "a pocket without events"),
            BaseCaseError::Inconsistent(p) => AxisError::Numerical(p, "footpoint order inconsistent"),
            BaseCaseError::NoBranch(p) => AxisError::Numerical(p, "no branch point in a pocket"),
            BaseCaseError::Budget => AxisError::Numerical(Point::default(), "step budget exhausted"),
        }
    }
}
