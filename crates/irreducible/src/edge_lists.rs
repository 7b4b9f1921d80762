//! The lists lue and lte of the Ramaswami–Siqueira algorithm (Section 4.1): two doubly linked lists
//! over one index array, with O(1) insertion at both ends, removal, and moves to the front or rear.
//!
//! While a vertex u is processed, every list element is an edge [u, z], and the node of that edge is
//! node `z` (see the module documentation of `ramaswami_siqueira` for this identification). An edge
//! is in at most one of the two lists (Proposition 9 (1)), so one `prev`/`next` pair per node serves
//! both, and each node knows which list holds it: the "pointer from the edge record into lte" of
//! Section 4.4 is the node index itself.

const NIL: u32 = u32::MAX;
const UNLISTED: u8 = u8::MAX;

/// One of the two lists.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum List {
    /// lue: untested edges.
    Lue = 0,
    /// lte: tested edges that failed the link condition.
    Lte = 1,
}

#[derive(Clone, Copy, Debug)]
struct Node {
    prev: u32,
    next: u32,
    list: u8,
}

/// Two intrusive doubly linked lists over nodes `0..n`.
#[derive(Clone, Debug)]
pub(crate) struct EdgeLists {
    nodes: Vec<Node>,
    head: [u32; 2],
    tail: [u32; 2],
}

impl EdgeLists {
    /// Empty lists over nodes `0..n`.
    pub(crate) fn new(n: usize) -> Self {
        Self {
            nodes: vec![
                Node {
                    prev: NIL,
                    next: NIL,
                    list: UNLISTED,
                };
                n
            ],
            head: [NIL; 2],
            tail: [NIL; 2],
        }
    }

    /// The list holding node `i`, if any.
    #[inline]
    pub(crate) fn list_of(&self, i: u32) -> Option<List> {
        match self.nodes[i as usize].list {
            0 => Some(List::Lue),
            1 => Some(List::Lte),
            _ => None,
        }
    }

    /// Whether `list` is empty.
    #[inline]
    pub(crate) fn is_empty(&self, list: List) -> bool {
        self.head[list as usize] == NIL
    }

    /// The first node of `list`.
    #[inline]
    pub(crate) fn front(&self, list: List) -> Option<u32> {
        let h = self.head[list as usize];
        (h != NIL).then_some(h)
    }

    /// Inserts the unlisted node `i` at the front of `list`.
    #[inline]
    pub(crate) fn push_front(&mut self, list: List, i: u32) {
        debug_assert_eq!(self.list_of(i), None, "node {i} is already listed");
        let l = list as usize;
        let old = self.head[l];
        self.nodes[i as usize] = Node {
            prev: NIL,
            next: old,
            list: list as u8,
        };
        if old == NIL {
            self.tail[l] = i;
        } else {
            self.nodes[old as usize].prev = i;
        }
        self.head[l] = i;
    }

    /// Inserts the unlisted node `i` at the rear of `list`.
    #[inline]
    pub(crate) fn push_back(&mut self, list: List, i: u32) {
        debug_assert_eq!(self.list_of(i), None, "node {i} is already listed");
        let l = list as usize;
        let old = self.tail[l];
        self.nodes[i as usize] = Node {
            prev: old,
            next: NIL,
            list: list as u8,
        };
        if old == NIL {
            self.head[l] = i;
        } else {
            self.nodes[old as usize].next = i;
        }
        self.tail[l] = i;
    }

    /// Removes node `i` from the list holding it.
    #[inline]
    pub(crate) fn remove(&mut self, i: u32) {
        let Node { prev, next, list } = self.nodes[i as usize];
        debug_assert_ne!(list, UNLISTED, "node {i} is not listed");
        let l = list as usize;
        if prev == NIL {
            self.head[l] = next;
        } else {
            self.nodes[prev as usize].next = next;
        }
        if next == NIL {
            self.tail[l] = prev;
        } else {
            self.nodes[next as usize].prev = prev;
        }
        self.nodes[i as usize] = Node {
            prev: NIL,
            next: NIL,
            list: UNLISTED,
        };
    }

    /// Removes and returns the first node of `list`.
    #[inline]
    pub(crate) fn pop_front(&mut self, list: List) -> Option<u32> {
        let i = self.front(list)?;
        self.remove(i);
        Some(i)
    }

    /// Moves the listed node `i` to the front of its list.
    #[inline]
    pub(crate) fn move_to_front(&mut self, i: u32) {
        let list = self.list_of(i).expect("moved node is listed");
        if self.head[list as usize] != i {
            self.remove(i);
            self.push_front(list, i);
        }
    }

    /// Moves the listed node `i` to the rear of its list.
    #[inline]
    pub(crate) fn move_to_back(&mut self, i: u32) {
        let list = self.list_of(i).expect("moved node is listed");
        if self.tail[list as usize] != i {
            self.remove(i);
            self.push_back(list, i);
        }
    }

    /// The nodes of `list`, front to rear.
    pub(crate) fn iter(&self, list: List) -> impl Iterator<Item = u32> + '_ {
        std::iter::successors(self.front(list), |&i| {
            let n = self.nodes[i as usize].next;
            (n != NIL).then_some(n)
        })
    }

    /// Empties `list`, in time proportional to its length.
    pub(crate) fn clear(&mut self, list: List) {
        while self.pop_front(list).is_some() {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contents(lists: &EdgeLists, list: List) -> Vec<u32> {
        lists.iter(list).collect()
    }

    #[test]
    fn moves_and_removals_keep_both_lists_consistent() {
        let mut l = EdgeLists::new(8);
        l.push_back(List::Lue, 1);
        l.push_back(List::Lue, 2);
        l.push_front(List::Lue, 3);
        l.push_back(List::Lte, 4);
        l.push_back(List::Lte, 5);
        l.push_back(List::Lte, 6);
        assert_eq!(contents(&l, List::Lue), [3, 1, 2]);
        l.move_to_front(6);
        l.move_to_back(4);
        assert_eq!(contents(&l, List::Lte), [6, 5, 4]);
        l.move_to_back(4);
        l.move_to_front(6);
        assert_eq!(contents(&l, List::Lte), [6, 5, 4]);
        l.remove(5);
        assert_eq!(contents(&l, List::Lte), [6, 4]);
        assert_eq!(l.pop_front(List::Lue), Some(3));
        l.remove(2);
        assert_eq!(contents(&l, List::Lue), [1]);
        assert_eq!(l.list_of(1), Some(List::Lue));
        assert_eq!(l.list_of(4), Some(List::Lte));
        assert_eq!(l.list_of(5), None);
        l.push_front(List::Lue, 5);
        assert_eq!(contents(&l, List::Lue), [5, 1]);
        l.clear(List::Lte);
        assert!(l.is_empty(List::Lte));
        assert_eq!(l.list_of(6), None);
        assert_eq!(contents(&l, List::Lue), [5, 1]);
        assert_eq!(l.pop_front(List::Lue), Some(5));
        assert_eq!(l.pop_front(List::Lue), Some(1));
        assert_eq!(l.pop_front(List::Lue), None);
        assert!(l.is_empty(List::Lue));
    }
}
