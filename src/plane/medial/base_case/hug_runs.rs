//! One footpoint per stretch of boundary that an event's circle hugs.
//!
//! A circle of nearly the boundary's own curvature stays within the
//! tolerance of it for a length of about √(2τ/Δκ) (Δκ the difference of
//! curvatures): on a nearly circular curve of 3·10^5 arcs that is a
//! hundred elements, each touching "within the tolerance" at its own
//! closest point. Kept as separate footpoints, their order against the
//! footpoints of the neighbouring events (whose circles hug the same
//! stretch) is rounding, and the walk finds no consistent pocket. The true
//! contact is the tangency point, where the boundary comes closest to the
//! centre; the distance grows with the square of the length from it, so
//! that point is found to about √(2ε/Δκ) (ε the rounding of a distance),
//! far below an element's length.

use super::sites::SiteRef;
use super::{Builder, Key};
use crate::kernel::{AxisKernel, Point};

impl<K: AxisKernel> Builder<'_, K> {
    /// `feet` and `own` (contacts placed exactly: a joint's own foot, a
    /// branch point's three) in cycle order, where each run of consecutive
    /// footpoints with the boundary between them hugging the circle
    /// (`c`, `r`) ([`hugs`](Self::hugs)) is one footpoint: its `own` ones
    /// if it has any, else the one closest to `c`. Sites in `whole` (an
    /// arc on the circle itself) are never merged across.
    pub(super) fn one_per_hug(&self, c: Point, r: f64, mut feet: Vec<Key>, own: &[Key], whole: &[SiteRef]) -> Vec<Key> {
        // (key, own, hugged from it to the next): one list, and `feet`
        // reused for the result: this runs for every event, and its
        // scratch lists were a third of the base cases' allocations.
        let mut all: Vec<(Key, bool, bool)> =
            feet.iter().map(|&k| (k, false, false)).chain(own.iter().map(|&k| (k, true, false))).collect();
        let m = all.len();
        feet.clear();
        if m < 2 {
            feet.extend(all.iter().map(|a| a.0));
            return feet;
        }
        all.sort_by(|a, b| self.pos(a.0).total_cmp(&self.pos(b.0)));
        // `all[i].2`: footpoints i and i + 1 (cyclically) are one contact.
        for i in 0..m {
            all[i].2 = self.hugged_between(all[i].0, all[(i + 1) % m].0, c, r, whole);
        }
        let Some(brk) = all.iter().position(|a| !a.2) else {
            // The circle hugs the whole cycle: nothing to choose by.
            feet.extend(all.iter().map(|a| a.0));
            return feet;
        };
        let depth = |k: Key| c.dist(self.point_of(k.site, self.u_at(k.site, k.w)));
        // Runs are the footpoints `brk + start ..= brk + s` (cyclically).
        let mut start = 1;
        for s in 1..=m {
            if all[(brk + s) % m].2 {
                continue;
            }
            let run = (start..=s).map(|t| all[(brk + t) % m]);
            if run.clone().any(|a| a.1) {
                feet.extend(run.filter(|a| a.1).map(|a| a.0));
            } else if let Some(a) = run.min_by(|a, b| depth(a.0).total_cmp(&depth(b.0))) {
                feet.push(a.0);
            }
            start = s + 1;
        }
        feet
    }

    /// True when the boundary from key `a` forward to key `b` runs through
    /// joined sites only, none in `whole`, and hugs the circle (`c`, `r`).
    fn hugged_between(&self, a: Key, b: Key, c: Point, r: f64, whole: &[SiteRef]) -> bool {
        let n = self.n();
        let mut i = a.site;
        let mut lo = a.w;
        // At most once round the cycle.
        for _ in 0..=n {
            if whole.contains(&i) {
                return false;
            }
            let last = i == b.site && (i != a.site || lo <= b.w);
            let hi = if last { b.w } else { 1.0 };
            if hi > lo && !self.hugs(i, lo, hi, c, r) {
                return false;
            }
            if last {
                return true;
            }
            if !self.sites[i].joined_next {
                return false;
            }
            i = i.next(n);
            lo = 0.0;
        }
        false
    }
}
