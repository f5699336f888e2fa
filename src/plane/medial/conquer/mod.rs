//! The conquer step (thesis 2.2.3–2.2.4): the axes of all subshapes glued
//! at the centres of the dividing disks into one graph.
//!
//! Each subshape's axis ends at the centres of the disks whose circles
//! carry its auxiliary arcs; those become one node per disk. A dividing
//! disk that touches only two primitives, both in the inside of their
//! elements, is no node of the true axis: its two edges lie on one conic
//! and are merged back into one.
//!
//! The files: `error.rs` (why an axis could not be computed), `refine.rs`
//! (solving the leaves, dividing again a leaf whose base case broke down),
//! `glue.rs` (the leaves' axes joined at the dividing disks' centres),
//! `merge.rs` (graph surgery after gluing: pass-through disks and
//! coinciding branch points merged, branch points polished) and `check.rs`
//! (the result checked: connected with one cycle per hole, a corner per
//! convex vertex, every disk maximal).

pub(crate) mod check;
pub(crate) mod error;
pub(crate) mod glue;
pub(crate) mod locals;
pub(crate) mod merge;
pub(crate) mod refine;
pub(crate) mod rounding;
pub(crate) mod self_stubs;
pub(crate) mod stray_conics;
pub(crate) mod thin_cycles;

pub use error::AxisError;
pub use glue::glue;
pub use refine::solve_leaves;

use crate::kernel::{AxisKernel, FilteredKernel, Point};
use crate::plane::axis::MedialAxis2d;
use crate::plane::medial::conquer::check::{check_corners, check_coverage, check_disks};
use crate::plane::medial::decompose::augment::augment;
use crate::plane::medial::decompose::divide::{decompose_in, decompose_plain_in};
use crate::plane::medial::disk::maximal::DiskFinder;
use crate::shape::Shape2d;

/// Options for [`medial_axis`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisOptions {
    /// Seed of the divide step's random choices; the axis is the same for
    /// every seed up to rounding, and bit-identical for one seed whatever
    /// the thread count.
    pub seed: u64,
    /// Subshapes with at most this many original element parts are solved
    /// directly (the thesis stops at 3; larger leaves mean fewer maximal
    /// disks to grow). At least 3.
    pub leaf_parts: usize,
}

impl Default for AxisOptions {
    fn default() -> Self {
        AxisOptions { seed: 0x006d_6564_6178, leaf_parts: 32 }
    }
}

/// The medial axis of a shape, with any number of holes (thesis Algorithm
/// 2 on the augmented domain of 2.3.1).
///
/// Node positions and radii are in model units, accurate to a few
/// multiples of the shape's tolerance ([`Shape2d::tolerance`], by default
/// 1e-9 × the bounding-box diagonal). A numerical breakdown is an
/// [`AxisError::Numerical`], never a wrong axis: the result is checked to
/// be a tree.
///
/// ```
/// use medax::plane::{medial_axis, AxisOptions, NodeKind};
/// use medax::shape::{Shape2d, ShapeOptions};
///
/// let shape = Shape2d::from_json_str(r#"{"loops": [[[0, 0], [4, 0], [4, 2], [0, 2]]]}"#, &ShapeOptions::default())?;
/// let axis = medial_axis(&shape, &AxisOptions::default())?;
/// // A 4 x 2 rectangle: two branch points of radius 1 joined by a spine.
/// let branches: Vec<_> = axis.nodes.iter().filter(|n| n.kind == NodeKind::Branch).collect();
/// assert_eq!(branches.len(), 2);
/// assert!(branches.iter().all(|b| (b.radius - 1.0).abs() < 1e-9));
/// for edge in &axis.edges {
///     // Centres and radii along the edge, within 1e-6 of the true conic.
///     assert!(edge.sample(&shape, &axis.nodes, 1e-6).len() >= 2);
/// }
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn medial_axis(shape: &Shape2d, opts: &AxisOptions) -> Result<MedialAxis2d, AxisError> {
    medial_axis_with(shape, opts, FilteredKernel)
}

/// [`medial_axis`] with every geometric question answered by `kernel`
/// (constructions, contact and emptiness decisions, orientations): the
/// algorithm is the same for every [`AxisKernel`].
pub fn medial_axis_with<K: AxisKernel>(
    shape: &Shape2d,
    opts: &AxisOptions,
    kernel: K,
) -> Result<MedialAxis2d, AxisError> {
    let finder = DiskFinder::with_kernel(shape, kernel);
    // The augmentation is only the divide step's input; dropped once
    // divided (a plate of random holes held 0.06 kB per element in it
    // through the base cases) and built again only for a retry.
    let mut aug = Some(augment(&finder)?);
    // The divide step is randomized: a numerical breakdown in one
    // decomposition is retried with other random choices (derived from the
    // seed, so the result stays deterministic); the first error is
    // reported if every try fails. The first try takes balanced cuts on
    // large subshapes (fast on spiky polygons); the retries take the first
    // random disk that divides, with the same seed and then another, so
    // that they do not pick the same largest disks again.
    let mut first_error = None;
    for attempt in 0..RETRIES {
        let seed = opts.seed.wrapping_add(attempt.saturating_sub(1).wrapping_mul(0x9e37_79b9_7f4a_7c15));
        let leaf_parts = opts.leaf_parts.max(3);
        let a = match aug.take() {
            Some(a) => a,
            None => augment(&finder)?,
        };
        let mut d = if attempt == 0 {
            decompose_in(&finder, &a, seed, leaf_parts)
        } else {
            decompose_plain_in(&finder, &a, seed, leaf_parts)
        };
        drop(a);
        let solved = solve_leaves(&finder, &mut d, seed);
        match solved
            .and_then(|locals| glue(&finder, &d.cuts, locals))
            .and_then(|axis| final_check(&finder, &axis).map(|_| axis))
        {
            Ok(axis) => return Ok(axis),
            Err(e) => {
                first_error.get_or_insert(e);
            }
        }
    }
    Err(first_error.unwrap_or(AxisError::Numerical(Point::default(), "no attempt")))
}

/// The checks an assembled axis passes before [`medial_axis`] returns it:
/// one corner node at each convex vertex, every boundary element a
/// primitive of an edge or on the circle of a node beside it, then every
/// node's and edge sample's disk touching its primitives and holding no
/// boundary (within
/// [`Tolerance::final_check`](crate::kernel::tolerance::Tolerance::final_check)).
pub fn final_check<K: AxisKernel>(finder: &DiskFinder<K>, axis: &MedialAxis2d) -> Result<(), AxisError> {
    check_corners(finder.shape(), axis)
        .and_then(|_| check_coverage(finder.shape(), axis))
        .and_then(|_| check_disks(finder, axis))
}

/// Decompositions tried before a numerical breakdown is reported.
const RETRIES: u64 = 3;
