//! Canonical labelling of a triangulated closed surface (orientable or not), isomorphism and
//! chirality.
//!
//! A triangulated surface is rigid once a *flag* is fixed — a face with an order of its three
//! corners: the faces across its edges, their apexes, and so on are then determined, so a
//! breadth-first walk over the faces labels every vertex (SURFACES.md, "Canonical form"; the same
//! idea as the rigidity that plantri's and Lutz's isomorph rejection rely on). The walk from a
//! start flag (a, b, c) of face f0: label a, b, c with 0, 1, 2; take faces in queue order; for
//! each, its three edges in the order of their labels ((l0,l1), (l0,l2), (l1,l2) with l0 < l1 <
//! l2); the face across an edge not yet reached is queued and its apex recorded in the *code*
//! (labelled next if new). Every face but f0 is reached once, so the code has F − 1 entries.
//! Replaying a code rebuilds the labelled face list (each entry names the apex of the face across
//! a known edge; whether that face was already reached is known from the faces rebuilt so far),
//! so equal codes mean equal labelled triangulations, and a simplicial isomorphism maps the code
//! of a flag to the same code of its image. The canonical code is the least over the start flags;
//! every flag of every vertex of an isomorphism-invariant class is tried (the class of least size
//! of the vertex invariant `(degree, sorted degrees of the neighbours)`, ties to the largest
//! invariant), with both corner orders: mirror images are identified. The canonical form is the
//! face list labelled by a least code's walk, each face sorted, the list sorted.
//!
//! Cost: O(F) per start flag with early abort against the best code so far, so O(F · s) for s
//! start flags (at most 2 · deg · |class|); on the census's triangulations (at most a few dozen
//! faces) a few microseconds. On a vertex-transitive mesh every vertex is a start and the codes
//! agree to the end, so the canonical form costs O(F · n) there; [`isomorphic`] instead walks one
//! flag of the first surface against the second's flags and stops at the first equal code (O(F)
//! on isomorphic symmetric meshes).
//!
//! Chirality: an orientable surface is chiral when no automorphism reverses its orientation.
//! With a coherent orientation fixed, a start flag is positive when its corner order agrees with
//! its face's orientation. An automorphism maps each flag to one with the same code, reversing
//! the orientation iff it changes the flags' sign; so the surface is achiral iff the least code
//! over positive flags equals the least code over negative flags.

use crate::triangulation::{Triangulation, oriented_face};
use std::cmp::Ordering;

/// The canonical face list of a triangulation: vertices relabelled `0..n` by a least code's
/// walk, each face sorted increasingly, the faces sorted. Two triangulations are isomorphic
/// (mirror images included) iff their canonical forms are equal.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CanonicalForm {
    faces: Vec<[u32; 3]>,
}

impl CanonicalForm {
    /// The canonically labelled faces (vertices `0..n`).
    pub fn faces(&self) -> &[[u32; 3]] {
        &self.faces
    }

    /// The number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.faces
            .iter()
            .flatten()
            .map(|&v| v as usize + 1)
            .max()
            .unwrap_or(0)
    }

    /// The canonical face list as a triangulation.
    pub fn to_triangulation(&self) -> Triangulation {
        Triangulation::new(self.faces.clone())
            .expect("a canonical form relabels a valid triangulation")
    }
}

/// The walk's state, reused across start flags.
struct Walker<'a> {
    faces: &'a [[u32; 3]],
    across: Vec<[u32; 3]>,
    label: Vec<u32>,
    reached: Vec<bool>,
    queue: Vec<u32>,
    code: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl<'a> Walker<'a> {
    fn new(t: &'a Triangulation) -> Self {
        Self::from_parts(t.faces(), t.face_adjacency(), t.vertex_count())
    }

    fn from_parts(faces: &'a [[u32; 3]], across: Vec<[u32; 3]>, vertex_count: usize) -> Self {
        Self {
            faces,
            across,
            label: vec![NONE; vertex_count],
            reached: vec![false; faces.len()],
            queue: Vec::with_capacity(faces.len()),
            code: Vec::with_capacity(faces.len()),
        }
    }

    /// Walks from the flag (face `f0`, corners in the order `corners`), writing the code into
    /// `self.code`. With `best`, stops as soon as the code exceeds it (returns `Greater`);
    /// otherwise returns how the full code compares with `best` (`Less` when there is none).
    fn walk(&mut self, f0: usize, corners: [u32; 3], best: Option<&[u32]>) -> Ordering {
        self.label.fill(NONE);
        self.reached.fill(false);
        self.queue.clear();
        self.code.clear();
        for (i, &v) in corners.iter().enumerate() {
            self.label[v as usize] = i as u32;
        }
        let mut next = 3;
        self.reached[f0] = true;
        self.queue.push(f0 as u32);
        let mut order = if best.is_some() {
            Ordering::Equal
        } else {
            Ordering::Less
        };
        let mut head = 0;
        while head < self.queue.len() {
            let f = self.queue[head] as usize;
            head += 1;
            let face = self.faces[f];
            let mut by_label = [0usize, 1, 2];
            by_label.sort_unstable_by_key(|&i| self.label[face[i] as usize]);
            // Edges (l0,l1), (l0,l2), (l1,l2): opposite corners l2, l1, l0.
            for &corner in &[by_label[2], by_label[1], by_label[0]] {
                let g = self.across[f][corner] as usize;
                if self.reached[g] {
                    continue;
                }
                self.reached[g] = true;
                self.queue.push(g as u32);
                let (x, y) = (face[(corner + 1) % 3], face[(corner + 2) % 3]);
                let apex = *self.faces[g]
                    .iter()
                    .find(|&&z| z != x && z != y)
                    .expect("a face has a third corner");
                if self.label[apex as usize] == NONE {
                    self.label[apex as usize] = next;
                    next += 1;
                }
                let entry = self.label[apex as usize];
                if order == Ordering::Equal {
                    let b = best.map_or(NONE, |b| b[self.code.len()]);
                    order = entry.cmp(&b);
                    if order == Ordering::Greater {
                        return order;
                    }
                }
                self.code.push(entry);
            }
        }
        order
    }
}

/// The vertex invariant (degree, sorted degrees of the neighbours) of every vertex.
fn invariants(t: &Triangulation) -> Vec<(usize, Vec<usize>)> {
    let neighbours = t.neighbours();
    let degree: Vec<usize> = neighbours.iter().map(Vec::len).collect();
    neighbours
        .iter()
        .map(|list| {
            let mut around: Vec<usize> = list.iter().map(|&w| degree[w as usize]).collect();
            around.sort_unstable();
            (list.len(), around)
        })
        .collect()
}

/// The start class: the least-populated class of the invariant, ties to the largest invariant;
/// its invariant and members.
fn start_class(invariant: &[(usize, Vec<usize>)]) -> ((usize, Vec<usize>), Vec<u32>) {
    let mut classes: std::collections::BTreeMap<&(usize, Vec<usize>), Vec<u32>> =
        std::collections::BTreeMap::new();
    for (v, key) in invariant.iter().enumerate() {
        classes.entry(key).or_default().push(v as u32);
    }
    classes
        .into_iter()
        .rev()
        .min_by_key(|(_, members)| members.len())
        .map(|(key, members)| (key.clone(), members))
        .unwrap_or_default()
}

/// The vertices whose flags are the start flags, as a mask.
fn start_vertices(t: &Triangulation) -> Vec<bool> {
    let (_, members) = start_class(&invariants(t));
    let mut mask = vec![false; t.vertex_count()];
    for v in members {
        mask[v as usize] = true;
    }
    mask
}

/// The least code over the start flags accepted by `keep(face, corners)`, and its labelling.
fn least_code(
    t: &Triangulation,
    mut keep: impl FnMut(usize, [u32; 3]) -> bool,
) -> Option<(Vec<u32>, Vec<u32>)> {
    let starts = start_vertices(t);
    let mut walker = Walker::new(t);
    let mut best: Option<(Vec<u32>, Vec<u32>)> = None;
    for (f, face) in t.faces().iter().enumerate() {
        for (i, &a) in face.iter().enumerate() {
            if !starts[a as usize] {
                continue;
            }
            let (b, c) = (face[(i + 1) % 3], face[(i + 2) % 3]);
            for corners in [[a, b, c], [a, c, b]] {
                if !keep(f, corners) {
                    continue;
                }
                let order = walker.walk(f, corners, best.as_ref().map(|(code, _)| &code[..]));
                if order == Ordering::Less {
                    best = Some((walker.code.clone(), walker.label.clone()));
                }
            }
        }
    }
    best
}

/// Whether the flag (face `root`, corners in its stored order) has the least code among the
/// flags (a, b, c) accepted by `start(flag, other apex of ab)` (an isomorphism-invariant set of
/// flags holding the root): the canonical-root test of the census search, which keeps one
/// labelled copy per isomorphism class (all flags of an orbit of the automorphism group give the
/// same labelled triangulation, and the search reaches each labelled triangulation once).
/// `across[f][i]` is the face across the edge opposite corner i of face f.
pub(crate) fn is_least_root(
    faces: &[[u32; 3]],
    across: Vec<[u32; 3]>,
    vertex_count: usize,
    root: usize,
    start: impl Fn([u32; 3], u32) -> bool,
) -> bool {
    let mut walker = Walker::from_parts(faces, across, vertex_count);
    walker.walk(root, faces[root], None);
    let best = walker.code.clone();
    for (f, face) in faces.iter().enumerate() {
        for i in 0..3 {
            let a = face[i];
            let (b, c) = (face[(i + 1) % 3], face[(i + 2) % 3]);
            for (corners, opposite) in [([a, b, c], (i + 2) % 3), ([a, c, b], (i + 1) % 3)] {
                // The other apex of the edge a–corners[1]: the apex of the face across it.
                let g = walker.across[f][opposite] as usize;
                let other = *faces[g]
                    .iter()
                    .find(|&&z| z != corners[0] && z != corners[1])
                    .expect("a face has a third corner");
                if !start(corners, other) {
                    continue;
                }
                if walker.walk(f, corners, Some(&best)) == Ordering::Less {
                    return false;
                }
            }
        }
    }
    true
}

/// The canonical form of `t` (mirror images identified).
pub fn canonical_form(t: &Triangulation) -> CanonicalForm {
    let (_, label) = least_code(t, |_, _| true).expect("a triangulation has a start flag");
    relabelled(t, &label)
}

/// The faces of `t` under `label`, each sorted, the list sorted.
fn relabelled(t: &Triangulation, label: &[u32]) -> CanonicalForm {
    let mut faces: Vec<[u32; 3]> = t
        .faces()
        .iter()
        .map(|f| {
            let mut g = f.map(|v| label[v as usize]);
            g.sort_unstable();
            g
        })
        .collect();
    faces.sort_unstable();
    CanonicalForm { faces }
}

/// Whether `a` and `b` are isomorphic as simplicial complexes (a vertex bijection mapping faces
/// to faces; mirror images count as isomorphic).
pub fn isomorphic(a: &Triangulation, b: &Triangulation) -> bool {
    if a.vertex_count() != b.vertex_count() || a.face_count() != b.face_count() {
        return false;
    }
    let (invariant_a, invariant_b) = (invariants(a), invariants(b));
    let sorted = |v: &[(usize, Vec<usize>)]| {
        let mut v = v.to_vec();
        v.sort_unstable();
        v
    };
    if sorted(&invariant_a) != sorted(&invariant_b) {
        return false;
    }
    // One flag of a's start class against every flag of b at the vertices of that class: the
    // codes are equal for some b flag iff a and b are isomorphic (an isomorphism maps the flag
    // into the class and keeps its code; equal codes rebuild equal labelled face lists).
    let (key, members) = start_class(&invariant_a);
    let Some(&v) = members.first() else {
        return false;
    };
    let Some((f, face)) = a
        .faces()
        .iter()
        .enumerate()
        .find(|(_, face)| face.contains(&v))
    else {
        return false;
    };
    let i = face.iter().position(|&x| x == v).unwrap_or(0);
    let mut walker = Walker::new(a);
    walker.walk(f, [v, face[(i + 1) % 3], face[(i + 2) % 3]], None);
    let code = walker.code.clone();
    let mut walker = Walker::new(b);
    for (g, face) in b.faces().iter().enumerate() {
        for (j, &w) in face.iter().enumerate() {
            if invariant_b[w as usize] != key {
                continue;
            }
            let (x, y) = (face[(j + 1) % 3], face[(j + 2) % 3]);
            for corners in [[w, x, y], [w, y, x]] {
                if walker.walk(g, corners, Some(&code)) == Ordering::Equal {
                    return true;
                }
            }
        }
    }
    false
}

/// `Some(true)` when `t` is orientable and chiral (not isomorphic to its mirror image by an
/// orientation-preserving map: no automorphism reverses its orientation), `Some(false)` when
/// orientable and achiral, `None` when non-orientable (every map is then its own mirror image).
pub fn is_chiral(t: &Triangulation) -> Option<bool> {
    let flip = t.coherent_orientation()?;
    let positive = |f: usize, corners: [u32; 3]| {
        let face = oriented_face(t.faces()[f], flip[f]);
        let i = face.iter().position(|&v| v == corners[0]).unwrap_or(0);
        face[(i + 1) % 3] == corners[1]
    };
    let (plus, _) = least_code(t, positive)?;
    let (minus, _) = least_code(t, |f, c| !positive(f, c))?;
    Some(plus != minus)
}
