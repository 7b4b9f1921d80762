//! A monotone priority queue (radix heap, Ahuja, Mehlhorn, Orlin and Tarjan, "Faster algorithms
//! for the shortest path problem", *Journal of the ACM* 37(2), 1990): keys are non-negative
//! integers, and no key pushed is smaller than the last one popped — exactly the event times of
//! the blossom algorithm's growth, which never go back. Item `k` lives in bucket
//! `64 − lzcnt(k ⊕ last)` (bucket 0: keys equal to the last popped); a pop from an empty bucket 0
//! moves the smallest non-empty bucket down around its minimum. O(1) push, O(log C) amortised
//! pop for keys spread over C; items of equal key come out last in, first out (deterministic).

/// A radix heap of `(key, item)` pairs.
#[derive(Clone, Debug)]
pub(crate) struct RadixHeap<T> {
    last: u64,
    len: usize,
    buckets: Vec<Vec<(u64, T)>>,
}

impl<T: Copy> RadixHeap<T> {
    pub(crate) fn new() -> Self {
        RadixHeap {
            last: 0,
            len: 0,
            buckets: (0..65).map(|_| Vec::new()).collect(),
        }
    }

    #[inline]
    fn bucket(&self, key: u64) -> usize {
        64 - (key ^ self.last).leading_zeros() as usize
    }

    /// Adds `item` with `key` (at least the last key popped; checked in debug builds).
    #[inline]
    pub(crate) fn push(&mut self, key: u64, item: T) {
        debug_assert!(key >= self.last, "radix heap keys must not decrease");
        let b = self.bucket(key);
        self.buckets[b].push((key, item));
        self.len += 1;
    }

    /// Removes an item of smallest key.
    pub(crate) fn pop(&mut self) -> Option<(u64, T)> {
        if self.len == 0 {
            return None;
        }
        if self.buckets[0].is_empty() {
            let i = (1..65)
                .find(|&i| !self.buckets[i].is_empty())
                .expect("a non-empty bucket");
            let moved = std::mem::take(&mut self.buckets[i]);
            self.last = moved.iter().map(|&(k, _)| k).min().expect("non-empty");
            for &(k, item) in &moved {
                let b = self.bucket(k);
                self.buckets[b].push((k, item));
            }
            // Keep the allocation of the emptied bucket.
            let mut moved = moved;
            moved.clear();
            if self.buckets[i].is_empty() {
                self.buckets[i] = moved;
            }
        }
        self.len -= 1;
        self.buckets[0].pop()
    }

    /// Removes every item and restarts the keys at 0.
    pub(crate) fn clear(&mut self) {
        for b in &mut self.buckets {
            b.clear();
        }
        self.len = 0;
        self.last = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::RadixHeap;

    #[test]
    fn pops_in_key_order_with_monotone_pushes() {
        let mut heap = RadixHeap::new();
        let mut reference = std::collections::BinaryHeap::new();
        let mut state = 12345u64;
        let mut last = 0;
        for step in 0..20_000u32 {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            if step % 3 != 2 {
                let key = last + (state >> 40) % 1000;
                heap.push(key, step);
                reference.push(std::cmp::Reverse(key));
            } else if let Some((key, _)) = heap.pop() {
                let std::cmp::Reverse(expected) = reference.pop().unwrap();
                assert_eq!(key, expected);
                last = key;
            }
        }
        while let Some((key, _)) = heap.pop() {
            assert_eq!(key, reference.pop().unwrap().0);
        }
        assert!(reference.is_empty());
    }
}
