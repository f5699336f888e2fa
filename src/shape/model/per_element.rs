//! Parallel maps over all elements of all loops, in global id order.
//!
//! Shapes come as one loop of a million elements or as half a million
//! small loops; splitting the global id range into fixed chunks keeps both
//! parallel (the chunks and the reproducible sums are `util::chunked`).

use crate::shape::model::bulge_loop::Loop;
use crate::util::chunked::CHUNK;
use rayon::prelude::*;

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
}
