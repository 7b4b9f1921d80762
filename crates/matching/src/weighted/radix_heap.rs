//! A monotone priority queue (a radix heap, Ahuja, Mehlhorn, Orlin and Tarjan, "Faster
//! algorithms for the shortest path problem", *Journal of the ACM* 37(2), 1990, with one digit
//! of 8 bits per level rather than one bit): keys are non-negative integers, and no key pushed is
//! smaller than the last one popped — exactly the event times of the blossom algorithm's growth,
//! which never go back.
//!
//! An item of key `k` lives at level `l` = the index of the highest byte in which `k` differs from
//! the last key popped (level 0 when they are equal), in the bucket of that byte's value in `k`.
//! The buckets of level 0 hold one key each, in increasing order of their digit; a pop from an
//! empty level 0 takes the first non-empty bucket of the lowest non-empty level, makes its
//! smallest key the last one and moves its items down. An item moves down at most 7 times
//! (a 64-bit key has 8 bytes), against up to 64 times with one bit per level; per level, a
//! 256-bit mask of the non-empty buckets finds the first one. O(1) push, amortised O(8) moves per
//! item and O(1) mask scans per pop. Items of equal key come out last in, first out
//! (deterministic).

/// Levels: one per byte of a `u64` key.
const LEVELS: usize = 8;
/// Buckets per level: one per value of a byte.
const DIGITS: usize = 256;

/// A radix heap of `(key, item)` pairs.
#[derive(Clone, Debug)]
pub(crate) struct RadixHeap<T> {
    last: u64,
    len: usize,
    /// Bucket `(level, digit)` at `level * DIGITS + digit`.
    buckets: Vec<Vec<(u64, T)>>,
    /// Per level, which of its buckets are non-empty (bit `digit`).
    nonempty: [[u64; DIGITS / 64]; LEVELS],
}

impl<T: Copy> RadixHeap<T> {
    pub(crate) fn new() -> Self {
        RadixHeap {
            last: 0,
            len: 0,
            buckets: (0..LEVELS * DIGITS).map(|_| Vec::new()).collect(),
            nonempty: [[0; DIGITS / 64]; LEVELS],
        }
    }

    /// The level and digit of `key` against the last key popped.
    #[inline]
    fn place(&self, key: u64) -> (usize, usize) {
        let differ = key ^ self.last;
        let level = if differ == 0 {
            0
        } else {
            (63 - differ.leading_zeros() as usize) / 8
        };
        (level, ((key >> (8 * level)) & 0xff) as usize)
    }

    #[inline]
    fn insert(&mut self, key: u64, item: T) {
        let (level, digit) = self.place(key);
        self.buckets[level * DIGITS + digit].push((key, item));
        self.nonempty[level][digit / 64] |= 1 << (digit % 64);
    }

    /// The first non-empty bucket of `level`, if any.
    #[inline]
    fn first_digit(&self, level: usize) -> Option<usize> {
        let words = &self.nonempty[level];
        (0..words.len())
            .find(|&w| words[w] != 0)
            .map(|w| 64 * w + words[w].trailing_zeros() as usize)
    }

    /// Adds `item` with `key` (at least the last key popped; checked in debug builds).
    #[inline]
    pub(crate) fn push(&mut self, key: u64, item: T) {
        debug_assert!(key >= self.last, "radix heap keys must not decrease");
        self.insert(key, item);
        self.len += 1;
    }

    /// The item the next [`RadixHeap::pop`] returns, when it is already at level 0 (`None`
    /// otherwise, or when empty): a cheap look ahead.
    #[inline]
    pub(crate) fn peek(&self) -> Option<T> {
        let digit = self.first_digit(0)?;
        self.buckets[digit].last().map(|&(_, item)| item)
    }

    /// Removes an item of smallest key.
    pub(crate) fn pop(&mut self) -> Option<(u64, T)> {
        if self.len == 0 {
            return None;
        }
        let digit = match self.first_digit(0) {
            Some(digit) => digit,
            None => {
                let (level, digit) = (1..LEVELS)
                    .find_map(|l| self.first_digit(l).map(|d| (l, d)))
                    .expect("a non-empty bucket");
                let index = level * DIGITS + digit;
                let mut moved = std::mem::take(&mut self.buckets[index]);
                self.nonempty[level][digit / 64] &= !(1 << (digit % 64));
                self.last = moved.iter().map(|&(k, _)| k).min().expect("non-empty");
                for &(k, item) in &moved {
                    self.insert(k, item);
                }
                // Keep the allocation of the emptied bucket.
                moved.clear();
                self.buckets[index] = moved;
                self.first_digit(0)
                    .expect("the smallest key moved to level 0")
            }
        };
        let bucket = &mut self.buckets[digit];
        let popped = bucket.pop();
        if bucket.is_empty() {
            self.nonempty[0][digit / 64] &= !(1 << (digit % 64));
        }
        let (key, _) = popped.expect("a non-empty bucket");
        self.last = key;
        self.len -= 1;
        popped
    }

    /// Removes every item and restarts the keys at 0.
    pub(crate) fn clear(&mut self) {
        for b in &mut self.buckets {
            b.clear();
        }
        self.nonempty = [[0; DIGITS / 64]; LEVELS];
        self.len = 0;
        self.last = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::RadixHeap;

    /// Pops against a binary heap under monotone pushes: gaps of up to 2^k for k up to 40, so
    /// that items cross many levels.
    #[test]
    fn pops_in_key_order_with_monotone_pushes() {
        for spread in [1u64 << 4, 1 << 10, 1 << 20, 1 << 40] {
            let mut heap = RadixHeap::new();
            let mut reference = std::collections::BinaryHeap::new();
            let mut state = 12345u64;
            let mut last = 0;
            for step in 0..20_000u32 {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                if step % 3 != 2 {
                    let key = last + (state >> 20) % spread;
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

    #[test]
    fn equal_keys_come_out_last_in_first_out() {
        let mut heap = RadixHeap::new();
        heap.push(1000, 'a');
        heap.push(1000, 'b');
        heap.push(7, 'c');
        assert_eq!(heap.pop(), Some((7, 'c')));
        assert_eq!(heap.pop(), Some((1000, 'b')));
        assert_eq!(heap.pop(), Some((1000, 'a')));
        assert_eq!(heap.pop(), None);
    }
}
