//! The walk into every pocket between consecutive footpoints of an event:
//! an edge to the one event met from both ends, or a branch point first.

use super::branch::Pocket;
use super::events::EventRef;
use super::foot_index::FootIndex;
use super::sites::SiteRef;
use super::{BaseCaseError, Builder, EventKind, Key, LocalAxis, LocalEdge, LocalNode};
use crate::kernel::apollonius::Site;
use crate::kernel::tolerance::Tolerance;
use crate::kernel::{AxisKernel, Point};

impl<K: AxisKernel> Builder<'_, K> {
    /// True when the pocket of event `d` from `a` to `b` holds no more
    /// boundary than a sliver of [`SLIVER`] tolerances, besides the sites the
    /// disk touches along their whole range or hugs.
    pub(super) fn pocket_is_empty(&self, d: EventRef, a: Key, b: Key) -> bool {
        let ev = &self.events[d];
        let n = self.n();
        let len = if a == b { 2.0 * n as f64 } else { self.offset(a, b) };
        let eps = Tolerance::cycle_position();
        let mut content = 0.0;
        // Site i occupies [2i, 2i + 1] on the cycle.
        let mut x = self.pos(a);
        let end = x + len;
        while x < end - eps {
            let block = (x / 2.0).floor();
            let i = SiteRef(block as usize % n);
            let (lo, hi) = (x - 2.0 * block, (end - 2.0 * block).min(1.0));
            if hi > lo && !ev.whole.contains(&i) && !self.hugs(i, lo, hi, ev.center, ev.radius) {
                content += self.length(i, lo, hi, ev.radius);
            }
            x = 2.0 * block + 2.0;
        }
        content <= self.tol.sliver_pocket()
    }

    /// Footpoint parameters on site `i` of the disks of events `d` and `e`,
    /// from the disks themselves: cycle keys are clamped to the site's
    /// range, and a clamped end would send the edge's curve past its node.
    /// A corner (radius 0) or a disk concentric with an arc has no
    /// direction: its key (fractions `w`) stands in.
    pub(super) fn params_between(&self, i: SiteRef, d: EventRef, e: EventRef, w: (f64, f64)) -> (f64, f64) {
        let at = |ev: EventRef, w: f64| {
            let (c, r) = (self.events[ev].center, self.events[ev].radius);
            let degenerate = match self.sites[i].site {
                Site::Point(q) => c.dist(q) <= self.tol.touch(),
                Site::Circle { o, .. } => c.dist(o) <= self.tol.touch(),
                Site::Line { .. } => false,
            };
            if degenerate || r == 0.0 {
                self.u_at(i, w)
            } else {
                self.param(i, c, r)
            }
        };
        (at(d, w.0), at(e, w.1))
    }

    pub(super) fn walk(mut self) -> Result<LocalAxis, BaseCaseError> {
        // A tree on the events has one edge fewer than events; every
        // footpoint starts a pocket.
        let mut edges: Vec<LocalEdge> = Vec::with_capacity(self.events.len());
        let mut linked: Vec<(EventRef, EventRef)> = Vec::with_capacity(self.events.len());
        // (event, index of the footpoint that starts the pocket)
        let mut work: Vec<(EventRef, usize)> = Vec::with_capacity(self.events.iter().map(|e| e.feet.len()).sum());
        for (d, e) in self.events.iter().enumerate() {
            work.extend((0..e.feet.len()).map(|j| (EventRef(d), j)));
        }
        // Every pocket is walked a few times (once more per branch point
        // found in it); far more steps means the walk is going round.
        let budget = 64 * (self.n() + self.events.len()) + 64;
        let mut index = FootIndex::new(&self, &self.events);
        let mut steps = 0;
        while let Some((d, j)) = work.pop() {
            steps += 1;
            if steps > budget {
                return Err(BaseCaseError::Budget);
            }
            let feet = &self.events[d].feet;
            let (a, b) = (feet[j], feet[(j + 1) % feet.len()]);
            let span = if a == b { 2.0 * self.n() as f64 } else { self.offset(a, b) };
            // The first footpoints of other events met from either end.
            let (first, last) = index.first_and_last(&self, d, a, b, span);
            // A pocket with no other event in it must hold no boundary (but
            // slivers); one with events is walked even if it is thin.
            let (Some(first), Some(last)) = (first, last) else {
                if self.pocket_is_empty(d, a, b) {
                    continue;
                }
                return Err(BaseCaseError::EmptyPocket(self.events[d].center));
            };
            let (s1, w1a) = self.site_after(a);
            let (s2, w2b) = self.site_before(b);
            if first.event == last.event {
                let e = first.event;
                let pair = (d.min(e), d.max(e));
                if !linked.contains(&pair) {
                    linked.push(pair);
                    // A footpoint tied with the pocket's end lies just
                    // inside it, on the end's own site.
                    let (t1, w1e) = if first.offset == 0.0 { (s1, w1a) } else { self.site_before(first.key) };
                    let (t2, w2e) = if last.offset == span { (s2, w2b) } else { self.site_after(last.key) };
                    if t1 != s1 || t2 != s2 {
                        return Err(BaseCaseError::Inconsistent(self.events[d].center));
                    }
                    // Walking from d into the pocket, s1 (after a) is on the right.
                    edges.push(LocalEdge {
                        from: d.0,
                        to: e.0,
                        sites: [self.sites[s2].prim, self.sites[s1].prim],
                        params: [self.params_between(s2, d, e, (w2b, w2e)), self.params_between(s1, d, e, (w1a, w1e))],
                        straight: false,
                    });
                }
                continue;
            }
            let pocket = Pocket { event: d, start: a, span, first_site: s1, last_site: s2 };
            let Some(found) = self.branch(&pocket, first.offset, last.offset) else {
                return Err(BaseCaseError::NoBranch(self.events[d].center));
            };
            let (c, r) = (found.center, found.radius);
            // The three contacts the construction placed are footpoints
            // even where rounding puts them a hair beyond the tolerance:
            // without them the pocket would be walked to the same branch
            // point again. Where two of them were pulled apart, the
            // snapped position they shared is not a footpoint.
            let (mut feet, whole) = self.touching(c, r);
            feet.retain(|k| found.snapped.iter().zip(&found.contacts).all(|(sn, ct)| k != sn || sn == ct));
            let feet = self.one_per_hug(c, r, feet, &found.contacts, &whole);
            let id = self.add_event(c, r, EventKind::Branch, feet, whole);
            index.update(&self, id, &self.events[id].feet);
            work.push((d, j));
            work.extend((0..self.events[id].feet.len()).map(|k| (id, k)));
        }
        let nodes =
            self.events.iter().map(|e| LocalNode { center: e.center, radius: e.radius, kind: e.kind }).collect();
        // A subshape's axis is a tree: a pocket walked to the wrong event
        // shows up as a missing or a doubled edge.
        if edges.len() + 1 != self.events.len() {
            return Err(BaseCaseError::Inconsistent(self.events.first().map_or(Point::default(), |e| e.center)));
        }
        Ok(LocalAxis { nodes, edges, aliases: Vec::new() })
    }
}

#[cfg(test)]
mod tests {
    use super::super::fixtures::{rectangle, with_events};
    use super::*;

    #[test]
    fn the_walk_links_every_event_into_a_tree() {
        let axis = with_events(&rectangle(), |b| b.walk()).unwrap();
        assert_eq!(axis.edges.len() + 1, axis.nodes.len());
        // Every node is reached.
        let mut degree = vec![0; axis.nodes.len()];
        for e in &axis.edges {
            degree[e.from] += 1;
            degree[e.to] += 1;
        }
        assert!(degree.iter().all(|&d| d > 0));
    }

    #[test]
    fn an_empty_pocket_holds_no_boundary() {
        with_events(&rectangle(), |b| {
            // Each corner's one footpoint is a pocket round the whole cycle,
            // which is not empty; a pocket from a key to a key just after
            // it holds nothing.
            let a = b.events[0].feet[0];
            assert!(!b.pocket_is_empty(EventRef(0), a, a));
            let just_after = Key::at(a.site, a.w + 1e-15);
            assert!(b.pocket_is_empty(EventRef(0), a, just_after));
        });
    }
}
