//! Disjoint sets over the ids `0..n`, for the passes that group corners, faces or sides into
//! classes (vertex fans and components when a mesh is built from a soup, the vertices of a
//! portalgon, the regions of a Delaunay tessellation).

/// Disjoint sets over `0..n` with path halving. A union links the larger root under the smaller,
/// so the root of a set is always its smallest element (deterministic, whatever the order of the
/// unions). Path halving without union by rank: O(log n) amortized per operation (Tarjan and van
/// Leeuwen, 1984).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    /// `n` singletons `{0}, {1}, …, {n - 1}`.
    pub fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n as u32).collect(),
        }
    }

    /// The root of the set of `x` (its smallest element), halving the path on the way.
    ///
    /// # Panics
    /// If `x` is not below `n`.
    #[inline]
    pub fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let grandparent = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = grandparent;
            x = grandparent;
        }
        x
    }

    /// Unites the sets of `a` and `b` and returns the root of the union (the smaller of the two
    /// roots; the common root when they were one set already).
    ///
    /// # Panics
    /// If `a` or `b` is not below `n`.
    #[inline]
    pub fn union(&mut self, a: u32, b: u32) -> u32 {
        let (ra, rb) = (self.find(a), self.find(b));
        let (lo, hi) = (ra.min(rb), ra.max(rb));
        self.parent[hi as usize] = lo;
        lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_are_the_smallest_elements_of_their_sets() {
        let mut sets = UnionFind::new(8);
        assert_eq!(sets.union(5, 7), 5);
        assert_eq!(sets.union(7, 3), 3);
        assert_eq!(sets.union(6, 1), 1);
        assert_eq!(sets.find(5), 3);
        assert_eq!(sets.union(5, 3), 3, "already one set");
        assert_eq!(sets.union(6, 7), 1);
        let roots: Vec<u32> = (0..8).map(|x| sets.find(x)).collect();
        assert_eq!(roots, [0, 1, 2, 1, 4, 1, 1, 1]);
    }
}
