//! ℓ and ε: counting link-condition tests per edge id, for all three algorithms.

use surftopo_mesh::EdgeId;

/// Per-edge test state as two bitsets (tested at least once, tested more than once: 2 bits per
/// edge, so that the random accesses of the link tests stay in cache) and the totals.
#[derive(Clone, Debug)]
pub(crate) struct TestTally {
    tested: Vec<u64>,
    repeated: Vec<u64>,
    /// ℓ.
    pub(crate) link_tests: u64,
    /// ε.
    pub(crate) repeated_edges: u64,
}

impl TestTally {
    /// A tally for edge ids `0..edge_slots`.
    pub(crate) fn new(edge_slots: usize) -> Self {
        let words = edge_slots.div_ceil(64);
        Self {
            tested: vec![0; words],
            repeated: vec![0; words],
            link_tests: 0,
            repeated_edges: 0,
        }
    }

    /// Records one link-condition test of `e`; returns whether it is the first test of `e`.
    #[inline]
    pub(crate) fn record(&mut self, e: EdgeId) -> bool {
        self.link_tests += 1;
        let (word, bit) = (e.idx() / 64, 1u64 << (e.idx() % 64));
        if self.tested[word] & bit == 0 {
            self.tested[word] |= bit;
            return true;
        }
        if self.repeated[word] & bit == 0 {
            self.repeated[word] |= bit;
            self.repeated_edges += 1;
        }
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_tests_and_edges_tested_more_than_once() {
        let mut t = TestTally::new(130);
        assert!(t.record(EdgeId(1)));
        assert!(t.record(EdgeId(2)));
        assert!(!t.record(EdgeId(1)));
        assert!(!t.record(EdgeId(1)));
        assert!(!t.record(EdgeId(2)));
        assert!(t.record(EdgeId(129)));
        assert!(!t.record(EdgeId(129)));
        assert!(t.record(EdgeId(65)));
        assert_eq!((t.link_tests, t.repeated_edges), (8, 3));
    }
}
