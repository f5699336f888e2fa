//! Parallel maps over all elements of all loops, in global id order.
//!
//! Shapes come as one loop of a million elements or as half a million
//! small loops; splitting the global id range into fixed chunks keeps both
//! parallel, and fixed chunks keep floating-point sums reproducible.

use crate::shape::model::bulge_loop::Loop;
use rayon::prelude::*;

/// Elements per parallel task.
const CHUNK: usize = 1 << 13;

/// Global id of element 0 of each loop, plus the total at the end.
pub(crate) fn offsets(loops: &[Loop]) -> Vec<usize> {
    let mut offsets = Vec::with_capacity(loops.len() + 1);
    let mut total = 0;
    for l in loops {
        offsets.push(total);
        total += l.len();
    }
    offsets.push(total);
    offsets
}

/// `f(loop index, element index)` for every element, in global id order.
pub(crate) fn map_elements<T: Send>(loops: &[Loop], offsets: &[usize], f: impl Fn(usize, usize) -> T + Sync) -> Vec<T> {
    let total = offsets.last().copied().unwrap_or(0);
    (0..total.div_ceil(CHUNK))
        .into_par_iter()
        .flat_map_iter(|c| {
            let (start, end) = (c * CHUNK, ((c + 1) * CHUNK).min(total));
            let mut l = offsets.partition_point(|&o| o <= start) - 1;
            let mut i = start - offsets[l];
            let f = &f;
            (start..end).map(move |_| {
                while i >= loops[l].len() {
                    l += 1;
                    i = 0;
                }
                let out = f(l, i);
                i += 1;
                out
            })
        })
        .collect()
}

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
    use crate::kernel::Point;
    use crate::shape::Vertex;

    #[test]
    fn visits_every_element_once_in_order() {
        let sizes = [3usize, 20_000, 2, 9000, 5, 16_384, 1];
        let loops: Vec<Loop> =
            sizes.iter().map(|&n| Loop::new(vec![Vertex { p: Point::new(0.0, 0.0), bulge: 0.0 }; n])).collect();
        let off = offsets(&loops);
        let got = map_elements(&loops, &off, |l, i| (l, i));
        let want: Vec<(usize, usize)> =
            sizes.iter().enumerate().flat_map(|(l, &n)| (0..n).map(move |i| (l, i))).collect();
        assert_eq!(got, want);
    }

    #[test]
    fn chunked_sum_matches_in_order_chunks() {
        let f = |i: usize| 1.0 / (1.0 + i as f64);
        let n = 100_000;
        let want: f64 = (0..n).collect::<Vec<_>>().chunks(CHUNK).map(|c| c.iter().map(|&i| f(i)).sum::<f64>()).sum();
        assert_eq!(chunked_sum(n, f), want);
    }
}
