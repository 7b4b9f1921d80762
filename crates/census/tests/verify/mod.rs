//! Independent checks of census outputs, written without the crate's code: a closed-surface
//! checker (edges in two faces, vertex links one cycle, connected, χ, orientability by
//! propagating face orientations), irreducibility by counting common neighbours, and an
//! isomorphism test by vertex backtracking (a second method beside the crate's flag-walk
//! canonical forms).

#![allow(dead_code)]

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};

/// What the checker finds of a closed surface.
#[derive(Debug, PartialEq, Eq)]
pub struct Surface {
    pub vertices: usize,
    pub euler_characteristic: i64,
    pub orientable: bool,
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// Checks that `faces` is a closed connected simplicial surface on 0..n; its χ and orientability.
pub fn closed_surface(faces: &[[u32; 3]]) -> Result<Surface, String> {
    let n = faces
        .iter()
        .flatten()
        .map(|&v| v as usize + 1)
        .max()
        .ok_or("no faces")?;
    let mut face_set = HashSet::new();
    let mut edge_faces: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (f, t) in faces.iter().enumerate() {
        let mut s = *t;
        s.sort();
        if s[0] == s[1] || s[1] == s[2] {
            return Err(format!("face {f} degenerate"));
        }
        if !face_set.insert(s) {
            return Err(format!("face {f} repeated"));
        }
        for i in 0..3 {
            edge_faces
                .entry(key(t[i], t[(i + 1) % 3]))
                .or_default()
                .push(f);
        }
    }
    for (e, fs) in &edge_faces {
        if fs.len() != 2 {
            return Err(format!("edge {e:?} in {} faces", fs.len()));
        }
    }
    // Links: the edges opposite each vertex form one cycle through all its neighbours.
    for v in 0..n as u32 {
        let link: Vec<(u32, u32)> = faces
            .iter()
            .filter(|t| t.contains(&v))
            .map(|t| {
                let o: Vec<u32> = t.iter().copied().filter(|&x| x != v).collect();
                (o[0], o[1])
            })
            .collect();
        if link.is_empty() {
            return Err(format!("vertex {v} unused"));
        }
        let mut adjacency: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
        for &(a, b) in &link {
            adjacency.entry(a).or_default().push(b);
            adjacency.entry(b).or_default().push(a);
        }
        if adjacency.values().any(|l| l.len() != 2) {
            return Err(format!("vertex {v}: link not a cycle"));
        }
        let start = *adjacency.keys().next().unwrap();
        let (mut prev, mut cur, mut steps) = (start, adjacency[&start][0], 1);
        while cur != start {
            let l = &adjacency[&cur];
            let next = if l[0] == prev { l[1] } else { l[0] };
            prev = cur;
            cur = next;
            steps += 1;
        }
        if steps != adjacency.len() {
            return Err(format!("vertex {v}: link is several cycles"));
        }
    }
    // Connected, by faces.
    let mut seen = vec![false; faces.len()];
    let mut stack = vec![0usize];
    seen[0] = true;
    let mut orientation: Vec<Option<[u32; 3]>> = vec![None; faces.len()];
    orientation[0] = Some(faces[0]);
    let mut orientable = true;
    while let Some(f) = stack.pop() {
        let o = orientation[f].unwrap();
        for i in 0..3 {
            let (a, b) = (o[i], o[(i + 1) % 3]);
            for &g in &edge_faces[&key(a, b)] {
                if g == f {
                    continue;
                }
                let t = faces[g];
                let c = *t.iter().find(|&&x| x != a && x != b).unwrap();
                let wanted = [b, a, c]; // traverses b -> a
                match orientation[g] {
                    None => {
                        orientation[g] = Some(wanted);
                        seen[g] = true;
                        stack.push(g);
                    }
                    Some(existing) => {
                        let same = (0..3).any(|r| {
                            existing[r] == wanted[0]
                                && existing[(r + 1) % 3] == wanted[1]
                                && existing[(r + 2) % 3] == wanted[2]
                        });
                        if !same {
                            orientable = false;
                        }
                    }
                }
            }
        }
    }
    if seen.iter().any(|s| !s) {
        return Err("disconnected".into());
    }
    let e = edge_faces.len() as i64;
    Ok(Surface {
        vertices: n,
        euler_characteristic: n as i64 - e + faces.len() as i64,
        orientable,
    })
}

/// Neighbour sets.
pub fn neighbours(faces: &[[u32; 3]]) -> Vec<BTreeSet<u32>> {
    let n = faces
        .iter()
        .flatten()
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0);
    let mut nb = vec![BTreeSet::new(); n];
    for t in faces {
        for i in 0..3 {
            for j in 0..3 {
                if i != j {
                    nb[t[i] as usize].insert(t[j]);
                }
            }
        }
    }
    nb
}

/// Irreducible: the tetrahedron, or every edge's ends have more than two common neighbours
/// (an edge of a closed surface always has its two apexes in common; exactly two means the link
/// condition holds and the edge contracts).
pub fn is_irreducible(faces: &[[u32; 3]]) -> bool {
    let nb = neighbours(faces);
    if nb.len() == 4 {
        return true;
    }
    for (u, set) in nb.iter().enumerate() {
        for &v in set {
            if nb[v as usize].intersection(set).count() == 2 && (u as u32) < v {
                return false;
            }
        }
    }
    true
}

/// Whether a vertex bijection maps the faces of `a` onto those of `b`: backtracking over vertex
/// images in breadth-first order of `a`, degrees and adjacency to mapped vertices checked.
pub fn isomorphic_by_backtracking(a: &[[u32; 3]], b: &[[u32; 3]]) -> bool {
    let (na, nb) = (neighbours(a), neighbours(b));
    if na.len() != nb.len() || a.len() != b.len() {
        return false;
    }
    let faces_b: HashSet<[u32; 3]> = b
        .iter()
        .map(|t| {
            let mut s = *t;
            s.sort();
            s
        })
        .collect();
    // Breadth-first order of a's vertices from vertex 0.
    let mut order = vec![0u32];
    let mut placed = vec![false; na.len()];
    placed[0] = true;
    let mut i = 0;
    while i < order.len() {
        for &w in &na[order[i] as usize] {
            if !placed[w as usize] {
                placed[w as usize] = true;
                order.push(w);
            }
        }
        i += 1;
    }
    let mut search = Backtrack {
        image: vec![u32::MAX; na.len()],
        used: vec![false; nb.len()],
        order,
        na,
        nb,
        faces_a: a,
        faces_b,
    };
    search.extend(0)
}

/// The state of [`isomorphic_by_backtracking`].
struct Backtrack<'a> {
    order: Vec<u32>,
    na: Vec<BTreeSet<u32>>,
    nb: Vec<BTreeSet<u32>>,
    image: Vec<u32>,
    used: Vec<bool>,
    faces_a: &'a [[u32; 3]],
    faces_b: HashSet<[u32; 3]>,
}

impl Backtrack<'_> {
    fn extend(&mut self, k: usize) -> bool {
        if k == self.order.len() {
            return self.faces_a.iter().all(|t| {
                let mut s = t.map(|v| self.image[v as usize]);
                s.sort();
                self.faces_b.contains(&s)
            });
        }
        let v = self.order[k] as usize;
        for w in 0..self.nb.len() {
            if self.used[w] || self.nb[w].len() != self.na[v].len() {
                continue;
            }
            let consistent = self.order[..k]
                .iter()
                .all(|&x| self.na[v].contains(&x) == self.nb[w].contains(&self.image[x as usize]));
            if !consistent {
                continue;
            }
            self.image[v] = w as u32;
            self.used[w] = true;
            if self.extend(k + 1) {
                return true;
            }
            self.image[v] = u32::MAX;
            self.used[w] = false;
        }
        false
    }
}

/// A key that isomorphic triangulations share (vertex count, sorted degrees), to compare only
/// within buckets.
pub fn bucket(faces: &[[u32; 3]]) -> (usize, Vec<usize>) {
    let nb = neighbours(faces);
    let mut d: Vec<usize> = nb.iter().map(BTreeSet::len).collect();
    d.sort();
    (nb.len(), d)
}

/// Checks a census list: every entry a closed surface with the given χ and orientability,
/// irreducible, and no two isomorphic (backtracking test within degree buckets).
pub fn check_census(list: &[Vec<[u32; 3]>], chi: i64, orientable: bool) {
    let mut buckets: HashMap<(usize, Vec<usize>), Vec<usize>> = HashMap::new();
    for (i, faces) in list.iter().enumerate() {
        let s = closed_surface(faces).unwrap_or_else(|e| panic!("entry {i}: {e}"));
        assert_eq!(s.euler_characteristic, chi, "entry {i}: χ");
        assert_eq!(s.orientable, orientable, "entry {i}: orientability");
        assert!(is_irreducible(faces), "entry {i} has a contractible edge");
        buckets.entry(bucket(faces)).or_default().push(i);
    }
    for members in buckets.values() {
        for (x, &i) in members.iter().enumerate() {
            for &j in &members[x + 1..] {
                assert!(
                    !isomorphic_by_backtracking(&list[i], &list[j]),
                    "entries {i} and {j} are isomorphic"
                );
            }
        }
    }
}
