//! The magnitude of a [`super::BigInt`]: little-endian `u64` limbs kept
//! inline up to [`INLINE`] limbs, on the heap beyond.
//!
//! Why: the polygon-ball axis computes with integers of one to ten limbs
//! (input coordinates of ~60 bits, node coordinates of ~7 times that), and
//! with a `Vec` every product and sum allocated and freed: a quarter of the
//! axis's time went to the allocator. Eight limbs (512 bits) hold a node's
//! coordinates and most of the products of predicates; larger values spill
//! to the heap unchanged.

use std::ops::{Deref, DerefMut};

/// Limbs held without allocation.
pub(crate) const INLINE: usize = 8;

/// A growable list of limbs; compares as its slice.
#[derive(Clone)]
pub(crate) enum Limbs {
    Inline { len: u8, buf: [u64; INLINE] },
    Heap(Vec<u64>),
}

impl Default for Limbs {
    fn default() -> Self {
        Limbs::Inline { len: 0, buf: [0; INLINE] }
    }
}

impl Limbs {
    /// `n` zero limbs.
    pub(crate) fn zeroed(n: usize) -> Limbs {
        if n <= INLINE {
            Limbs::Inline { len: n as u8, buf: [0; INLINE] }
        } else {
            Limbs::Heap(vec![0; n])
        }
    }

    /// Empty, with room for `n` limbs.
    pub(crate) fn with_capacity(n: usize) -> Limbs {
        if n <= INLINE {
            Limbs::default()
        } else {
            Limbs::Heap(Vec::with_capacity(n))
        }
    }

    pub(crate) fn push(&mut self, v: u64) {
        match self {
            Limbs::Inline { len, buf } if (*len as usize) < INLINE => {
                buf[*len as usize] = v;
                *len += 1;
            }
            Limbs::Inline { buf, .. } => {
                let mut heap = Vec::with_capacity(2 * INLINE);
                heap.extend_from_slice(&buf[..]);
                heap.push(v);
                *self = Limbs::Heap(heap);
            }
            Limbs::Heap(h) => h.push(v),
        }
    }

    /// Drops the most significant limbs that are zero.
    pub(crate) fn trim(&mut self) {
        match self {
            Limbs::Inline { len, buf } => {
                while *len > 0 && buf[*len as usize - 1] == 0 {
                    *len -= 1;
                }
            }
            Limbs::Heap(h) => {
                while h.last() == Some(&0) {
                    h.pop();
                }
            }
        }
    }
}

impl Deref for Limbs {
    type Target = [u64];
    fn deref(&self) -> &[u64] {
        match self {
            Limbs::Inline { len, buf } => &buf[..*len as usize],
            Limbs::Heap(h) => h,
        }
    }
}

impl DerefMut for Limbs {
    fn deref_mut(&mut self) -> &mut [u64] {
        match self {
            Limbs::Inline { len, buf } => &mut buf[..*len as usize],
            Limbs::Heap(h) => h,
        }
    }
}

impl PartialEq for Limbs {
    fn eq(&self, o: &Self) -> bool {
        **self == **o
    }
}

impl Eq for Limbs {}

impl std::fmt::Debug for Limbs {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spills_to_the_heap_and_compares_as_slices() {
        let mut a = Limbs::default();
        for i in 0..20u64 {
            a.push(i);
            assert_eq!(a.len(), i as usize + 1);
        }
        assert!(matches!(a, Limbs::Heap(_)));
        let mut b = Limbs::zeroed(3);
        b[1] = 7;
        b.push(0);
        b.trim();
        assert_eq!(&b[..], &[0, 7]);
        let mut c = Limbs::Heap(vec![0, 7, 0, 0]);
        c.trim();
        assert_eq!(b, c);
        assert_eq!(format!("{b:?}"), "[0, 7]");
    }
}
