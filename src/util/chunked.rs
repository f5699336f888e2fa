//! Work split into fixed chunks: parallel, and floating-point sums that do
//! not depend on the number of threads.

use rayon::prelude::*;

/// Elements per parallel task.
pub(crate) const CHUNK: usize = 1 << 13;

/// Sum of `f(i)` over `0..n`, in fixed chunks summed in order, so the
/// result does not depend on the number of threads.
pub(crate) fn chunked_sum(n: usize, f: impl Fn(usize) -> f64 + Sync) -> f64 {
    if n <= CHUNK {
        return (0..n).map(f).sum();
    }
    let parts: Vec<f64> =
        (0..n.div_ceil(CHUNK)).into_par_iter().map(|c| (c * CHUNK..((c + 1) * CHUNK).min(n)).map(&f).sum()).collect();
    parts.into_iter().sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chunked_sum_matches_in_order_chunks() {
        let f = |i: usize| 1.0 / (1.0 + i as f64);
        let n = 100_000;
        let want: f64 = (0..n).collect::<Vec<_>>().chunks(CHUNK).map(|c| c.iter().map(|&i| f(i)).sum::<f64>()).sum();
        assert_eq!(chunked_sum(n, f), want);
    }
}
