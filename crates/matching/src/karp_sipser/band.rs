//! The band around a path: the nodes within some distance of it, keyed by how far they are from
//! its far end. The guided completion (`guided.rs`) marks a band around a shortest path between
//! two deferred nodes and searches in it; the repairs' depth-first search (`repair.rs`) can be
//! confined to one.

use crate::dual_graph::DualGraph;

/// The nodes within some distance of a path ([`Band::mark`]), each with a key: its distance to
/// the path's far end along the path, plus its depth.
#[derive(Clone, Debug, Default)]
pub(super) struct Band {
    /// Per node slot, made at the first guided search: `[generation, key]`, in the band when the
    /// generation is the current one.
    marks: Vec<[u32; 2]>,
    generation: u32,
    /// The nodes of the current band.
    queue: Vec<u32>,
}

impl Band {
    /// An empty band over `slots` node slots.
    pub(super) fn new(slots: usize) -> Self {
        Band {
            marks: vec![[0, 0]; slots],
            ..Band::default()
        }
    }

    /// A copy with no node in the band (a new generation, nothing marked).
    #[cfg(test)]
    pub(super) fn emptied(&self) -> Self {
        Band {
            generation: self.generation + 1,
            ..self.clone()
        }
    }

    /// The node slots its marks cover (0 before it is made).
    pub(super) fn slots(&self) -> usize {
        self.marks.len()
    }

    /// Whether no node is marked by a later generation than the current one.
    pub(super) fn check_invariants(&self) -> Result<(), String> {
        match self.marks.iter().position(|&[g, _]| g > self.generation) {
            Some(v) => Err(format!(
                "node {v} is marked by a band of a later generation"
            )),
            None => Ok(()),
        }
    }

    /// The key of `v` when it is in the band.
    #[inline]
    pub(super) fn key(&self, v: u32) -> Option<u32> {
        match self.marks[v as usize] {
            [g, key] if g == self.generation => Some(key),
            _ => None,
        }
    }

    /// Whether `v` is in the band.
    #[inline]
    pub(super) fn contains(&self, v: u32) -> bool {
        self.marks[v as usize][0] == self.generation
    }

    /// Marks the nodes within `width` of `path` as the band (a new generation) and keys each by
    /// its distance to the path's far end: along the path from the path node it was reached
    /// from, plus its depth. Returns the number of nodes in the band.
    pub(super) fn mark<G: DualGraph + ?Sized>(
        &mut self,
        graph: &G,
        path: &[u32],
        width: u32,
    ) -> usize {
        self.generation += 1;
        let generation = self.generation;
        let mut queue = std::mem::take(&mut self.queue);
        queue.clear();
        let last = path.len() - 1;
        for (i, &p) in path.iter().enumerate() {
            self.marks[p as usize] = [generation, (last - i) as u32];
            queue.push(p);
        }
        let mut head = 0;
        for _ in 0..width {
            let layer_end = queue.len();
            while head < layer_end {
                let x = queue[head];
                head += 1;
                let key = self.marks[x as usize][1] + 1;
                for (_, y) in graph.adjacent(x) {
                    if self.marks[y as usize][0] != generation {
                        self.marks[y as usize] = [generation, key];
                        queue.push(y);
                    }
                }
            }
        }
        let labelled = queue.len();
        self.queue = queue;
        labelled
    }
}
