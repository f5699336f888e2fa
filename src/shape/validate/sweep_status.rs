//! The sweep-line status: items kept in the order of an external comparator,
//! with the in-order neighbours of each inserted or removed item reported by
//! the same descent. A treap in an arena indexed by item id (items are
//! 0..capacity, each inserted at most once at a time), so no allocation per
//! operation and one O(log n) expected search per insert or remove.

use std::cmp::Ordering;

const NIL: u32 = u32::MAX;

#[derive(Clone, Copy)]
struct Node {
    left: u32,
    right: u32,
    prio: u32,
}

/// An ordered set of item ids `0..capacity` under a caller-supplied order.
pub(crate) struct SweepStatus {
    nodes: Vec<Node>,
    root: u32,
}

fn priority(i: u32) -> u32 {
    // A fixed hash (not a random source) keeps runs reproducible.
    let mut x = i.wrapping_mul(0x9e37_79b9) ^ 0x85eb_ca6b;
    x ^= x >> 15;
    x = x.wrapping_mul(0x2c1b_3c6d);
    x ^ (x >> 12)
}

/// Neighbours of an item in the order: (below, above).
pub(crate) type Neighbours = (Option<u32>, Option<u32>);

impl SweepStatus {
    /// An empty set for items `0..capacity`.
    pub fn new(capacity: usize) -> SweepStatus {
        let nodes = (0..capacity as u32).map(|i| Node { left: NIL, right: NIL, prio: priority(i) }).collect();
        SweepStatus { nodes, root: NIL }
    }

    fn some(i: u32) -> Option<u32> {
        (i != NIL).then_some(i)
    }

    fn leftmost(&self, mut t: u32) -> u32 {
        while t != NIL && self.nodes[t as usize].left != NIL {
            t = self.nodes[t as usize].left;
        }
        t
    }

    fn rightmost(&self, mut t: u32) -> u32 {
        while t != NIL && self.nodes[t as usize].right != NIL {
            t = self.nodes[t as usize].right;
        }
        t
    }

    /// Splits `t` into items ordered before `key` and after it (`key` is not in `t`).
    fn split(&mut self, t: u32, key: u32, cmp: &impl Fn(u32, u32) -> Ordering) -> (u32, u32) {
        if t == NIL {
            return (NIL, NIL);
        }
        if cmp(t, key) == Ordering::Less {
            let (l, r) = self.split(self.nodes[t as usize].right, key, cmp);
            self.nodes[t as usize].right = l;
            (t, r)
        } else {
            let (l, r) = self.split(self.nodes[t as usize].left, key, cmp);
            self.nodes[t as usize].left = r;
            (l, t)
        }
    }

    /// Joins two treaps where every item of `a` orders before every item of `b`.
    fn merge(&mut self, a: u32, b: u32) -> u32 {
        if a == NIL {
            return b;
        }
        if b == NIL {
            return a;
        }
        if self.nodes[a as usize].prio > self.nodes[b as usize].prio {
            let r = self.merge(self.nodes[a as usize].right, b);
            self.nodes[a as usize].right = r;
            a
        } else {
            let l = self.merge(a, self.nodes[b as usize].left);
            self.nodes[b as usize].left = l;
            b
        }
    }

    /// Makes `child` the left or right child of `parent`, or the root when
    /// `parent` is NIL.
    fn attach(&mut self, parent: u32, left: bool, child: u32) {
        if parent == NIL {
            self.root = child;
        } else if left {
            self.nodes[parent as usize].left = child;
        } else {
            self.nodes[parent as usize].right = child;
        }
    }

    /// Inserts `item` and returns its neighbours. One descent: down to where
    /// the item's priority places it, then the subtree there is split around it.
    pub fn insert(&mut self, item: u32, cmp: &impl Fn(u32, u32) -> Ordering) -> Neighbours {
        let prio = self.nodes[item as usize].prio;
        let (mut below, mut above) = (NIL, NIL);
        let (mut parent, mut went_left) = (NIL, false);
        let mut t = self.root;
        while t != NIL && self.nodes[t as usize].prio > prio {
            parent = t;
            went_left = cmp(item, t) == Ordering::Less;
            if went_left {
                above = t;
                t = self.nodes[t as usize].left;
            } else {
                below = t;
                t = self.nodes[t as usize].right;
            }
        }
        let (l, r) = self.split(t, item, cmp);
        if l != NIL {
            below = self.rightmost(l);
        }
        if r != NIL {
            above = self.leftmost(r);
        }
        self.nodes[item as usize].left = l;
        self.nodes[item as usize].right = r;
        self.attach(parent, went_left, item);
        (Self::some(below), Self::some(above))
    }

    /// Removes `item` and returns its former neighbours, or `None` when the
    /// order no longer leads to it (the comparator became inconsistent).
    pub fn remove(&mut self, item: u32, cmp: &impl Fn(u32, u32) -> Ordering) -> Option<Neighbours> {
        let (mut parent, mut went_left) = (NIL, false);
        let (mut below, mut above) = (NIL, NIL);
        let mut t = self.root;
        while t != NIL && t != item {
            parent = t;
            if cmp(item, t) == Ordering::Less {
                above = t;
                went_left = true;
                t = self.nodes[t as usize].left;
            } else {
                below = t;
                went_left = false;
                t = self.nodes[t as usize].right;
            }
        }
        if t == NIL {
            return None;
        }
        let Node { left, right, .. } = self.nodes[item as usize];
        if left != NIL {
            below = self.rightmost(left);
        }
        if right != NIL {
            above = self.leftmost(right);
        }
        let joined = self.merge(left, right);
        self.attach(parent, went_left, joined);
        Some((Self::some(below), Self::some(above)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    #[test]
    fn matches_a_btree_under_random_inserts_and_removes() {
        // Items ordered by a key table, like pieces ordered by height.
        let keys: Vec<i64> = (0..2000).map(|i: i64| (i * 7919) % 2003 - 1000).collect();
        let cmp = |a: u32, b: u32| keys[a as usize].cmp(&keys[b as usize]).then(a.cmp(&b));
        let mut set = SweepStatus::new(keys.len());
        let mut reference: BTreeSet<(i64, u32)> = BTreeSet::new();
        let mut present = vec![false; keys.len()];
        let mut x = 12345u64;
        for _ in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let i = (x % keys.len() as u64) as u32;
            let k = (keys[i as usize], i);
            let want = (
                reference.range(..k).next_back().map(|e| e.1),
                reference.range((std::ops::Bound::Excluded(k), std::ops::Bound::Unbounded)).next().map(|e| e.1),
            );
            if present[i as usize] {
                assert_eq!(set.remove(i, &cmp), Some(want));
                reference.remove(&k);
            } else {
                assert_eq!(set.insert(i, &cmp), want);
                reference.insert(k);
            }
            present[i as usize] = !present[i as usize];
        }
    }
}
