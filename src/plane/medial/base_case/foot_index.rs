//! Every event's footpoints in cycle order, so that the walk finds the
//! first and the last footpoint of another event in a pocket by a binary
//! search and a short scan instead of looking at every footpoint: the scan
//! over all of them was a quarter of the base cases' time on polygons.

use super::events::{Event, EventRef};
use super::{Builder, Key};
use crate::kernel::AxisKernel;

/// One footpoint: its cycle position (kept for the binary searches) and
/// its key's lag (the order), then the event and the footpoint's index in
/// it (the order among exact ties, the order in which the walk once met
/// them).
#[derive(Debug, Clone, Copy)]
struct Entry {
    pos: f64,
    event: usize,
    foot: usize,
    key: Key,
}

impl Entry {
    fn new<K: AxisKernel>(b: &Builder<'_, K>, event: usize, foot: usize, key: Key) -> Entry {
        Entry { pos: b.pos(key), event, foot, key }
    }

    fn order(&self, o: &Entry) -> std::cmp::Ordering {
        self.pos
            .total_cmp(&o.pos)
            .then(self.key.lag.total_cmp(&o.key.lag))
            .then(self.event.cmp(&o.event))
            .then(self.foot.cmp(&o.foot))
    }
}

/// A footpoint of another event met walking into a pocket.
#[derive(Debug, Clone, Copy)]
pub(super) struct Met {
    /// Offset along the cycle from the pocket's start.
    pub(super) offset: f64,
    /// The event it belongs to.
    pub(super) event: EventRef,
    /// Where it lies.
    pub(super) key: Key,
}

impl Met {
    /// Whether `self` comes before `other` walking into the pocket: by
    /// offset, and where both share a position by their contacts' lags.
    fn before(&self, other: &Met) -> bool {
        self.offset < other.offset || (self.offset == other.offset && self.key.lag < other.key.lag)
    }

    /// Same offset and lag: the earlier event (then footpoint) is the one
    /// met, as in a scan of the events in order.
    fn tied(&self, other: &Met) -> bool {
        self.offset == other.offset && self.key.lag == other.key.lag
    }
}

/// The footpoints of all events, sorted by [`Entry::order`].
#[derive(Debug)]
pub(super) struct FootIndex {
    entries: Vec<Entry>,
}

impl FootIndex {
    /// Every footpoint of `events`.
    pub(super) fn new<K: AxisKernel>(b: &Builder<'_, K>, events: &[Event]) -> FootIndex {
        let mut entries: Vec<Entry> = events
            .iter()
            .enumerate()
            .flat_map(|(event, e)| e.feet.iter().enumerate().map(move |(foot, &key)| Entry::new(b, event, foot, key)))
            .collect();
        entries.sort_by(Entry::order);
        FootIndex { entries }
    }

    /// Replaces event `id`'s footpoints by `feet` (its new list).
    pub(super) fn update<K: AxisKernel>(&mut self, b: &Builder<'_, K>, id: EventRef, feet: &[Key]) {
        self.entries.retain(|e| e.event != id.0);
        for (foot, &key) in feet.iter().enumerate() {
            let entry = Entry::new(b, id.0, foot, key);
            let at = self.entries.partition_point(|e| e.order(&entry).is_lt());
            self.entries.insert(at, entry);
        }
    }

    /// The first and the last footpoint of an event other than `d` inside
    /// the pocket from `a` to `b` (offsets in (0, `span`), or at an end
    /// with the contact on the inner side): what a scan over every event's
    /// footpoints in order would find.
    pub(super) fn first_and_last<K: AxisKernel>(
        &self,
        bld: &Builder<'_, K>,
        d: EventRef,
        a: Key,
        b: Key,
        span: f64,
    ) -> (Option<Met>, Option<Met>) {
        let n = self.entries.len();
        if n == 0 {
            return (None, None);
        }
        let (pa, pb) = (bld.pos(a), bld.pos(b));
        let inside = |e: &Entry| {
            let o = bld.offset(a, e.key);
            let inside = match () {
                _ if o == 0.0 => e.key.lag > a.lag,
                _ if o == span => e.key.lag < b.lag,
                _ => o > 0.0 && o < span,
            };
            (e.event != d.0 && inside).then_some(Met { offset: o, event: EventRef(e.event), key: e.key })
        };
        // The entries from just after `a` to just before `b` in cycle order
        // (the whole cycle from `a` when the pocket goes round): offsets grow
        // along them, so the first inside is met first scanning forwards and
        // the last scanning backwards. Offsets that rounding makes equal for
        // distinct positions are settled by `Met::before`, as in a full scan.
        let start = self.entries.partition_point(|e| e.pos < pa || (e.pos == pa && e.key.lag <= a.lag));
        let stop = self.entries.partition_point(|e| e.pos < pb || (e.pos == pb && e.key.lag < b.lag));
        let count = if a == b { n } else { (stop + n - start) % n };
        let at = |k: usize| &self.entries[(start + k) % n];
        let mut first: Option<Met> = None;
        for k in 0..count {
            let e = at(k);
            if first.is_some_and(|f| bld.offset(a, e.key) > f.offset) {
                break;
            }
            if let Some(m) = inside(e) {
                if first.is_none_or(|f| m.before(&f)) {
                    first = Some(m);
                }
            }
        }
        let mut last: Option<Met> = None;
        for k in (0..count).rev() {
            let e = at(k);
            if last.is_some_and(|l| bld.offset(a, e.key) < l.offset) {
                break;
            }
            if let Some(m) = inside(e) {
                if last.is_none_or(|l| l.before(&m) || m.tied(&l)) {
                    last = Some(m);
                }
            }
        }
        (first, last)
    }
}
