//! Solving the leaves of a decomposition: every leaf's base case in
//! parallel, a leaf that breaks down divided again into smaller leaves.

use crate::kernel::AxisKernel;
use crate::plane::medial::base_case::{self, BaseCaseError, LocalAxis};
use crate::plane::medial::conquer::error::AxisError;
use crate::plane::medial::conquer::locals::LocalAxes;
use crate::plane::medial::decompose::divide::{divide_into, leaf_size, Decomposition};
use crate::plane::medial::decompose::subshape::Subshape;
use crate::plane::medial::disk::maximal::DiskFinder;
use rayon::prelude::*;

/// Rounds of [`solve_leaves`] that divide a failed leaf further.
const REFINES: usize = 3;

/// Solves every leaf and stuck subshape of `d` (in parallel); `finder`
/// indexes the shape `d` was made of. A leaf whose base case breaks down
/// numerically (rare: near-degenerate configurations such as many disks
/// alike to within a few tolerances) is divided again into leaves of half
/// its size, with random choices of its own, and those are solved; after
/// `REFINES` rounds the first breakdown is reported. New cuts are
/// appended to `d.cuts`. The order of the result depends only on `d` and
/// `seed`.
pub fn solve_leaves<K: AxisKernel>(
    finder: &DiskFinder<K>,
    d: &mut Decomposition,
    seed: u64,
) -> Result<LocalAxes, AxisError> {
    let shape = finder.shape();
    let tol = shape.tolerance();
    let mut pending: Vec<Subshape> = std::mem::take(&mut d.leaves);
    pending.append(&mut d.stuck);
    let mut locals = LocalAxes::default();
    for round in 0..=REFINES {
        let mut failed = Vec::new();
        // A batch at a time: only one batch of leaves' axes is ever held
        // both as its own vectors and in `locals`.
        // Solved leaves are freed batch by batch: at the end of this
        // step the leaves' axes and the leaves themselves would otherwise
        // both be held.
        // Taken from the end of the reversed list: each batch is split off
        // in its own length (draining the front moves the whole rest).
        pending.reverse();
        while !pending.is_empty() {
            let mut batch = pending.split_off(pending.len().saturating_sub(BATCH));
            batch.reverse();
            let results: Vec<Result<LocalAxis, BaseCaseError>> =
                batch.par_iter().map(|s| base_case::solve(shape, s, &d.cuts, tol, finder)).collect();
            for (s, r) in batch.into_iter().zip(results) {
                match r {
                    Ok(local) => locals.push(local),
                    Err(e) if round == REFINES => return Err(e.into()),
                    Err(_) => failed.push(s),
                }
            }
        }
        if failed.is_empty() {
            break;
        }
        let mut more = Decomposition { cuts: std::mem::take(&mut d.cuts), ..Decomposition::default() };
        for (i, s) in failed.into_iter().enumerate() {
            let size = leaf_size(shape, &s);
            let again = seed ^ ((round as u64) << 32 | i as u64).wrapping_mul(0x2545_f491_4f6c_dd1d);
            // Forced to cut at least once: a failed leaf of three parts is
            // retried as three-part leaves from other random disks.
            divide_into(finder, &mut more, vec![s], again, (size / 2).max(3).min(size.saturating_sub(1)));
        }
        d.cuts = more.cuts;
        pending = more.leaves;
        pending.append(&mut more.stuck);
    }
    locals.shrink_to_fit();
    Ok(locals)
}

/// Leaves solved in parallel at a time: enough to keep every core busy,
/// few enough that their own vectors are a small part of the whole.
const BATCH: usize = 4096;
