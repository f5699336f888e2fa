//! A stack that keeps its first items inline and spills to the heap only
//! past them: the index walks run millions of times per axis, and each
//! one's stack rarely holds more than a tree's depth of entries, so a heap
//! allocation per walk was most of its allocator traffic.

/// Last in, first out; the first `N` items live in an array.
pub(crate) struct SmallStack<T: Copy, const N: usize> {
    inline: [T; N],
    len: usize,
    /// Items pushed while the array was full, in push order; only ever
    /// non-empty while the array is full, so popping it first keeps the
    /// order.
    spill: Vec<T>,
}

impl<T: Copy, const N: usize> SmallStack<T, N> {
    /// An empty stack; `fill` only initialises the unused array.
    pub(crate) fn new(fill: T) -> Self {
        SmallStack { inline: [fill; N], len: 0, spill: Vec::new() }
    }

    pub(crate) fn push(&mut self, x: T) {
        if self.len < N {
            self.inline[self.len] = x;
            self.len += 1;
        } else {
            self.spill.push(x);
        }
    }

    pub(crate) fn pop(&mut self) -> Option<T> {
        if let Some(x) = self.spill.pop() {
            return Some(x);
        }
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        Some(self.inline[self.len])
    }
}

impl<T: Copy, const N: usize> Extend<T> for SmallStack<T, N> {
    fn extend<I: IntoIterator<Item = T>>(&mut self, items: I) {
        items.into_iter().for_each(|x| self.push(x));
    }
}

#[cfg(test)]
mod tests {
    use super::SmallStack;

    #[test]
    fn last_in_first_out_across_the_spill() {
        let mut s: SmallStack<u32, 4> = SmallStack::new(0);
        s.extend(0..10);
        s.push(10);
        let mut popped = Vec::new();
        while let Some(x) = s.pop() {
            popped.push(x);
            if x == 6 {
                // Pushed after popping into the array again.
                s.push(100);
                s.push(101);
            }
        }
        assert_eq!(popped, [10, 9, 8, 7, 6, 101, 100, 5, 4, 3, 2, 1, 0]);
        assert_eq!(s.pop(), None);
    }
}
