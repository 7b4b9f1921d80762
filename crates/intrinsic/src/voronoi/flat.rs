//! Growable lists, one per id, stored in one flat vector: the wave's constellations X_Δ (one per
//! triangle) and side lists (Lemma 41's, one per side) are small and many, so they share one
//! allocation instead of taking one each (Appendix D.2's structures are unchanged; only where
//! their items live).

/// One list per id in one vector: list `i` holds `len[i]` items from `start[i]`, with room for
/// `room[i]`; a full list moves to the end of the vector with twice the room (its old slots are
/// left unused: at most as many as the live items, so the memory stays linear).
#[derive(Clone, Debug)]
pub(crate) struct FlatLists<T> {
    items: Vec<T>,
    start: Vec<usize>,
    len: Vec<u32>,
    room: Vec<u32>,
    /// The value unused slots hold.
    filler: T,
}

impl<T: Clone> FlatLists<T> {
    /// `count` empty lists with room for `room` items each, unused slots holding `filler`.
    pub(crate) fn new(count: usize, room: u32, filler: T) -> Self {
        Self {
            items: vec![filler.clone(); count * room as usize],
            start: (0..count).map(|i| i * room as usize).collect(),
            len: vec![0; count],
            room: vec![room; count],
            filler,
        }
    }

    /// List `i`.
    pub(crate) fn get(&self, i: usize) -> &[T] {
        let start = self.start[i];
        &self.items[start..start + self.len[i] as usize]
    }

    /// The length of list `i`.
    pub(crate) fn len(&self, i: usize) -> usize {
        self.len[i] as usize
    }

    /// The lengths of the lists.
    pub(crate) fn lens(&self) -> impl Iterator<Item = usize> + '_ {
        self.len.iter().map(|&l| l as usize)
    }

    /// Makes room for `needed` items in list `i` (moving it to the end when full).
    fn reserve(&mut self, i: usize, needed: usize) {
        if needed <= self.room[i] as usize {
            return;
        }
        let room = needed.max(2 * self.room[i] as usize).max(1);
        let (start, len) = (self.start[i], self.len[i] as usize);
        let new_start = self.items.len();
        self.items.extend_from_within(start..start + len);
        self.items
            .extend(std::iter::repeat_n(self.filler.clone(), room - len));
        self.start[i] = new_start;
        self.room[i] = room as u32;
    }

    /// Appends `x` to list `i`.
    pub(crate) fn push(&mut self, i: usize, x: T) {
        let len = self.len[i] as usize;
        self.reserve(i, len + 1);
        self.items[self.start[i] + len] = x;
        self.len[i] += 1;
    }

    /// Replaces items `l..r` of list `i` by those of `run` (drained), as `Vec::splice` does.
    pub(crate) fn splice(&mut self, i: usize, l: usize, r: usize, run: &mut Vec<T>) {
        let len = self.len[i] as usize;
        debug_assert!(l <= r && r <= len);
        let new_len = len - (r - l) + run.len();
        self.reserve(i, new_len);
        let start = self.start[i];
        let list = &mut self.items[start..start + self.room[i] as usize];
        if run.len() > r - l {
            // The tail moves right, over unused slots.
            list[r..new_len].rotate_right(run.len() - (r - l));
        } else {
            // The tail moves left; the slots after it keep removed items.
            list[l + run.len()..len].rotate_left(r - l - run.len());
            for x in &mut list[new_len..len] {
                *x = self.filler.clone();
            }
        }
        for (slot, x) in list[l..].iter_mut().zip(run.drain(..)) {
            *slot = x;
        }
        self.len[i] = new_len as u32;
    }
}
