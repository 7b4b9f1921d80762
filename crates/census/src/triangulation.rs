//! A triangulated closed surface as a face list: orientable or not, no orientation stored.
//!
//! The census works on small triangulations, and a non-orientable closed surface is just a list
//! of triangles, so this type holds only the faces (vertices `0..n`) and derives the rest. The
//! link condition on a closed surface needs no orientation: an edge uv is contractible iff u and
//! v have exactly two common neighbours (the apexes of its two faces) and the surface is not the
//! tetrahedron (Dey, Edelsbrunner, Guha and Nekhayev 1999; Lemma 3 of Schipper 1991, Theorem 3 of
//! Ramaswami–Siqueira).

use crate::error::CensusError;
use std::collections::HashMap;

/// A closed connected simplicial surface given by its triangles on the vertices `0..n`: every
/// edge lies in exactly two faces, every vertex link is one cycle, no two faces share their three
/// vertices. Built only by [`Triangulation::new`], which checks all of it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Triangulation {
    vertex_count: usize,
    faces: Vec<[u32; 3]>,
}

/// The sorted pair of an edge's endpoints.
pub(crate) fn edge_key(a: u32, b: u32) -> (u32, u32) {
    if a < b { (a, b) } else { (b, a) }
}

impl Triangulation {
    /// Checks that `faces` is a closed connected simplicial surface on the vertices `0..n` (n the
    /// largest index plus one, every index used) and wraps it. The error names the face, edge or
    /// vertex that fails.
    pub fn new(faces: Vec<[u32; 3]>) -> Result<Self, CensusError> {
        if faces.is_empty() {
            return Err(CensusError::Empty);
        }
        for (f, face) in faces.iter().enumerate() {
            for i in 0..3 {
                if face[i] == face[(i + 1) % 3] {
                    return Err(CensusError::DegenerateFace {
                        face: f,
                        vertex: face[i],
                    });
                }
            }
        }
        // The used vertices must be 0..n: found from the sorted distinct indices, so that a huge
        // index allocates nothing in proportion to it.
        let mut used: Vec<u32> = faces.iter().flatten().copied().collect();
        used.sort_unstable();
        used.dedup();
        if let Some(v) = used.iter().enumerate().position(|(i, &v)| v as usize != i) {
            return Err(CensusError::UnusedVertex { vertex: v as u32 });
        }
        let vertex_count = used.len();
        let mut seen: HashMap<[u32; 3], usize> = HashMap::with_capacity(faces.len());
        for (f, face) in faces.iter().enumerate() {
            let mut key = *face;
            key.sort_unstable();
            if let Some(&g) = seen.get(&key) {
                return Err(CensusError::DuplicateFace { faces: [g, f] });
            }
            seen.insert(key, f);
        }
        let mut edges: HashMap<(u32, u32), (usize, usize)> = HashMap::new();
        for (f, face) in faces.iter().enumerate() {
            for i in 0..3 {
                let entry = edges
                    .entry(edge_key(face[i], face[(i + 1) % 3]))
                    .or_insert((0, f));
                entry.0 += 1;
            }
        }
        let mut bad: Vec<_> = edges
            .iter()
            .filter(|(_, (count, _))| *count != 2)
            .map(|(&(a, b), &(count, face))| (face, a, b, count))
            .collect();
        bad.sort_unstable();
        if let Some(&(face, a, b, count)) = bad.first() {
            return Err(CensusError::EdgeFaceCount {
                edge: [a, b],
                faces: count,
                face,
            });
        }
        let triangulation = Self {
            vertex_count,
            faces,
        };
        let links = triangulation.links();
        for (v, link) in links.iter().enumerate() {
            let cycles = link_cycle_count(link);
            if cycles != 1 {
                return Err(CensusError::PinchedVertex {
                    vertex: v as u32,
                    cycles,
                });
            }
        }
        let neighbours = triangulation.neighbours();
        let mut reached = vec![false; vertex_count];
        let mut stack = vec![0u32];
        reached[0] = true;
        while let Some(v) = stack.pop() {
            for &w in &neighbours[v as usize] {
                if !reached[w as usize] {
                    reached[w as usize] = true;
                    stack.push(w);
                }
            }
        }
        if let Some(v) = reached.iter().position(|&r| !r) {
            return Err(CensusError::Disconnected { vertex: v as u32 });
        }
        Ok(triangulation)
    }

    /// Wraps faces the census search built: a closed connected simplicial surface on `0..n` by
    /// construction (the search's tests), so the checks of [`Self::new`] are left out in release
    /// builds and asserted in debug builds.
    pub(crate) fn from_search(vertex_count: usize, faces: Vec<[u32; 3]>) -> Self {
        debug_assert!(Self::new(faces.clone()).is_ok());
        Self {
            vertex_count,
            faces,
        }
    }

    /// The faces, as given.
    pub fn faces(&self) -> &[[u32; 3]] {
        &self.faces
    }

    /// The faces, consuming the triangulation.
    pub fn into_faces(self) -> Vec<[u32; 3]> {
        self.faces
    }

    /// n: the vertices are `0..n`.
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// E = 3F/2.
    pub fn edge_count(&self) -> usize {
        3 * self.faces.len() / 2
    }

    /// F.
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// χ = V − E + F.
    pub fn euler_characteristic(&self) -> i64 {
        self.vertex_count as i64 - self.edge_count() as i64 + self.face_count() as i64
    }

    /// Whether the faces can be oriented coherently (each edge traversed in opposite directions
    /// by its two faces): propagation from face 0 across edges; a conflict means non-orientable.
    pub fn is_orientable(&self) -> bool {
        self.coherent_orientation().is_some()
    }

    /// A coherent orientation (`flip[f]`: reverse face f) when the surface is orientable.
    pub(crate) fn coherent_orientation(&self) -> Option<Vec<bool>> {
        let across = self.face_adjacency();
        let mut flip: Vec<Option<bool>> = vec![None; self.faces.len()];
        flip[0] = Some(false);
        let mut stack = vec![0usize];
        while let Some(f) = stack.pop() {
            let oriented = oriented_face(self.faces[f], flip[f] == Some(true));
            for i in 0..3 {
                let (a, b) = (oriented[i], oriented[(i + 1) % 3]);
                let corner = (0..3)
                    .find(|&j| self.faces[f][j] != a && self.faces[f][j] != b)
                    .unwrap_or(0);
                let g = across[f][corner] as usize;
                // g must traverse the edge b -> a.
                let face_g = self.faces[g];
                let forward = (0..3).any(|j| face_g[j] == b && face_g[(j + 1) % 3] == a);
                let needed = !forward;
                match flip[g] {
                    None => {
                        flip[g] = Some(needed);
                        stack.push(g);
                    }
                    Some(x) if x != needed => return None,
                    Some(_) => {}
                }
            }
        }
        Some(flip.into_iter().map(|x| x == Some(true)).collect())
    }

    /// The Euler genus: 2 − χ (2g for an orientable surface of genus g, k for k crosscaps).
    pub fn euler_genus(&self) -> u32 {
        (2 - self.euler_characteristic()) as u32
    }

    /// The sorted neighbours of every vertex.
    pub fn neighbours(&self) -> Vec<Vec<u32>> {
        let mut neighbours = vec![Vec::new(); self.vertex_count];
        for face in &self.faces {
            for i in 0..3 {
                neighbours[face[i] as usize].push(face[(i + 1) % 3]);
                neighbours[face[i] as usize].push(face[(i + 2) % 3]);
            }
        }
        for list in &mut neighbours {
            list.sort_unstable();
            list.dedup();
        }
        neighbours
    }

    /// The degree of every vertex.
    pub fn degrees(&self) -> Vec<usize> {
        self.neighbours().iter().map(Vec::len).collect()
    }

    /// For every vertex, the edges of its link (the opposite side of each incident face).
    fn links(&self) -> Vec<Vec<(u32, u32)>> {
        let mut links = vec![Vec::new(); self.vertex_count];
        for face in &self.faces {
            for i in 0..3 {
                links[face[i] as usize].push((face[(i + 1) % 3], face[(i + 2) % 3]));
            }
        }
        links
    }

    /// `across[f][i]`: the face sharing with f the edge opposite its corner i.
    pub(crate) fn face_adjacency(&self) -> Vec<[u32; 3]> {
        if self.vertex_count <= 128 {
            return self.face_adjacency_dense();
        }
        let mut first: HashMap<(u32, u32), u32> = HashMap::with_capacity(self.faces.len() * 2);
        let mut across = vec![[u32::MAX; 3]; self.faces.len()];
        for (f, face) in self.faces.iter().enumerate() {
            for i in 0..3 {
                let key = edge_key(face[(i + 1) % 3], face[(i + 2) % 3]);
                if let Some(&g) = first.get(&key) {
                    across[f][i] = g;
                    let other = self.faces[g as usize];
                    let j = (0..3)
                        .find(|&j| !(key.0 == other[j] || key.1 == other[j]))
                        .unwrap_or(0);
                    across[g as usize][j] = f as u32;
                } else {
                    first.insert(key, f as u32);
                }
            }
        }
        across
    }

    /// [`Self::face_adjacency`] through an n × n table (small triangulations).
    fn face_adjacency_dense(&self) -> Vec<[u32; 3]> {
        let n = self.vertex_count;
        let mut face_of = vec![[u32::MAX; 2]; n * n];
        for (f, face) in self.faces.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = edge_key(face[(i + 1) % 3], face[(i + 2) % 3]);
                let slot = &mut face_of[a as usize * n + b as usize];
                if slot[0] == u32::MAX {
                    slot[0] = f as u32;
                } else {
                    slot[1] = f as u32;
                }
            }
        }
        self.faces
            .iter()
            .enumerate()
            .map(|(f, face)| {
                [0, 1, 2].map(|i| {
                    let (a, b) = edge_key(face[(i + 1) % 3], face[(i + 2) % 3]);
                    let [g, h] = face_of[a as usize * n + b as usize];
                    if g == f as u32 { h } else { g }
                })
            })
            .collect()
    }

    /// The edges (sorted pairs, each once) that satisfy the link condition: their ends have
    /// exactly two common neighbours, and the surface is not the tetrahedron.
    pub fn contractible_edges(&self) -> Vec<[u32; 2]> {
        if self.vertex_count == 4 {
            return Vec::new(); // the tetrahedron: every contraction leaves a non-surface
        }
        let neighbours = self.neighbours();
        let mut edges = Vec::new();
        for (u, list) in neighbours.iter().enumerate() {
            for &v in list {
                if (u as u32) < v && common_count(list, &neighbours[v as usize]) == 2 {
                    edges.push([u as u32, v]);
                }
            }
        }
        edges
    }

    /// Whether no edge satisfies the link condition.
    pub fn is_irreducible(&self) -> bool {
        self.contractible_edges().is_empty()
    }

    /// Contracts the edge uv into u (v disappears, the largest vertex takes v's index so that
    /// the vertices stay `0..n−1`). `None` when uv is not an edge satisfying the link condition.
    pub fn contract(&self, u: u32, v: u32) -> Option<Self> {
        if !self.contractible_edges().contains(&[u.min(v), u.max(v)]) {
            return None;
        }
        let last = (self.vertex_count - 1) as u32;
        let rename = |x: u32| {
            let x = if x == v { u } else { x };
            if x == last { v } else { x }
        };
        let faces = self
            .faces
            .iter()
            .filter(|f| !(f.contains(&u) && f.contains(&v)))
            .map(|f| f.map(rename))
            .collect();
        Self::new(faces).ok()
    }

    /// Splits vertex v along the path a–v–b (a, b two distinct neighbours of v): a new vertex w
    /// (index n) takes the faces of v on one side of the path, and the faces a v w, b w v join
    /// them, so that contracting vw gives back this triangulation. The side taken is the run of
    /// faces around v from a towards b that starts with the face `first` (a face of v containing
    /// a). `None` when a = b, a or b is not a neighbour, or the result would not be simplicial.
    pub fn split_vertex(&self, v: u32, a: u32, b: u32, first: usize) -> Option<Self> {
        if a == b || !self.faces.get(first)?.contains(&v) || !self.faces[first].contains(&a) {
            return None;
        }
        let w = self.vertex_count as u32;
        // Walk around v from a through `first` until b, moving those faces to w.
        let mut faces = self.faces.clone();
        let mut current = first;
        let mut from = a;
        let mut steps = 0;
        loop {
            let face = self.faces[current];
            let next_vertex = *face.iter().find(|&&x| x != v && x != from)?;
            faces[current] = face.map(|x| if x == v { w } else { x });
            if next_vertex == b {
                break;
            }
            // The other face on edge v-next_vertex.
            current = (0..self.faces.len()).find(|&g| {
                g != current && self.faces[g].contains(&v) && self.faces[g].contains(&next_vertex)
            })?;
            from = next_vertex;
            steps += 1;
            if steps > self.faces.len() {
                return None;
            }
        }
        faces.push([a, v, w]);
        faces.push([b, w, v]);
        Self::new(faces).ok()
    }

    /// Flips the edge uv (its two faces u v x, v u y become x y u, y x v). `None` when uv is not
    /// an edge, or xy is already an edge (the result would not be simplicial), or a vertex of
    /// degree 3 would be left with degree 2.
    pub fn flip(&self, u: u32, v: u32) -> Option<Self> {
        let two: Vec<usize> = (0..self.faces.len())
            .filter(|&f| self.faces[f].contains(&u) && self.faces[f].contains(&v))
            .collect();
        if two.len() != 2 {
            return None;
        }
        let apex = |f: usize| {
            *self.faces[f]
                .iter()
                .find(|&&z| z != u && z != v)
                .unwrap_or(&u)
        };
        let (x, y) = (apex(two[0]), apex(two[1]));
        if self.neighbours()[x as usize].contains(&y) {
            return None;
        }
        let mut faces: Vec<[u32; 3]> = self
            .faces
            .iter()
            .enumerate()
            .filter(|(f, _)| !two.contains(f))
            .map(|(_, &f)| f)
            .collect();
        faces.push([x, y, u]);
        faces.push([y, x, v]);
        Self::new(faces).ok()
    }
}

/// The face with its vertices in the given or reversed order.
pub(crate) fn oriented_face(face: [u32; 3], reverse: bool) -> [u32; 3] {
    if reverse {
        [face[0], face[2], face[1]]
    } else {
        face
    }
}

/// The number of common entries of two sorted lists.
pub(crate) fn common_count(a: &[u32], b: &[u32]) -> usize {
    let (mut i, mut j, mut count) = (0, 0, 0);
    while i < a.len() && j < b.len() {
        match a[i].cmp(&b[j]) {
            std::cmp::Ordering::Less => i += 1,
            std::cmp::Ordering::Greater => j += 1,
            std::cmp::Ordering::Equal => {
                count += 1;
                i += 1;
                j += 1;
            }
        }
    }
    count
}

/// The number of cycles of a link given by its edges, every link vertex of degree 2 (which holds
/// once every edge lies in two faces).
fn link_cycle_count(link: &[(u32, u32)]) -> usize {
    let mut adjacency: HashMap<u32, Vec<u32>> = HashMap::new();
    for &(a, b) in link {
        adjacency.entry(a).or_default().push(b);
        adjacency.entry(b).or_default().push(a);
    }
    let mut seen: HashMap<u32, bool> = adjacency.keys().map(|&k| (k, false)).collect();
    let mut cycles = 0;
    let mut keys: Vec<u32> = adjacency.keys().copied().collect();
    keys.sort_unstable();
    for start in keys {
        if seen[&start] {
            continue;
        }
        cycles += 1;
        let mut stack = vec![start];
        seen.insert(start, true);
        while let Some(x) = stack.pop() {
            for &y in &adjacency[&x] {
                if !seen[&y] {
                    seen.insert(y, true);
                    stack.push(y);
                }
            }
        }
    }
    cycles
}
