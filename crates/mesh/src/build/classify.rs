//! The classification of each connected component of a triangulated surface: a compact connected
//! surface is determined by its orientability, its Euler characteristic χ and its number b of
//! boundary loops (the classification theorem). Orientable of genus g: χ = 2 − 2g − b;
//! non-orientable with k crosscaps: χ = 2 − k − b; the Euler genus is h = 2g or k.

use super::pairing::CornerPairing;
use crate::union_find::UnionFind;

/// One connected component of a triangulated surface, classified.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SurfaceKind {
    /// Its faces.
    pub faces: usize,
    /// Its edges.
    pub edges: usize,
    /// Its vertices.
    pub vertices: usize,
    /// χ = V − E + F.
    pub euler_characteristic: i64,
    /// Whether it has a consistent orientation.
    pub orientable: bool,
    /// Its boundary loops b (cycles of edges in one face).
    pub boundary_loops: usize,
    /// g with χ = 2 − 2g − b, when orientable.
    pub genus: Option<u64>,
    /// k with χ = 2 − k − b, when non-orientable.
    pub crosscaps: Option<u64>,
    /// h: 2g or k.
    pub euler_genus: u64,
}

impl SurfaceKind {
    /// The surface of the given orientability, Euler characteristic and boundary loops (the
    /// numbers must be those of a surface: `2 − χ − b` even and non-negative when orientable,
    /// positive when not; otherwise the genus saturates at 0).
    pub fn new(
        faces: usize,
        edges: usize,
        vertices: usize,
        orientable: bool,
        boundary_loops: usize,
    ) -> Self {
        let euler_characteristic = vertices as i64 - edges as i64 + faces as i64;
        let euler_genus = (2 - euler_characteristic - boundary_loops as i64).max(0) as u64;
        SurfaceKind {
            faces,
            edges,
            vertices,
            euler_characteristic,
            orientable,
            boundary_loops,
            genus: orientable.then_some(euler_genus / 2),
            crosscaps: (!orientable).then_some(euler_genus),
            euler_genus,
        }
    }

    /// Whether it has no boundary.
    pub fn is_closed(&self) -> bool {
        self.boundary_loops == 0
    }

    /// Its name: sphere, torus, genus-g surface, projective plane, Klein bottle, N_k, disk,
    /// annulus, Möbius band, or in general "genus g with b boundary loops" / "N_k with b boundary
    /// loops".
    pub fn name(&self) -> String {
        let b = self.boundary_loops;
        let loops = |b: usize| format!("{b} boundary loop{}", if b == 1 { "" } else { "s" });
        match (self.genus, self.crosscaps, b) {
            (Some(0), _, 0) => "sphere".into(),
            (Some(1), _, 0) => "torus".into(),
            (Some(g), _, 0) => format!("genus-{g} surface"),
            (Some(0), _, 1) => "disk".into(),
            (Some(0), _, 2) => "annulus".into(),
            (Some(g), _, b) => format!("genus {g} with {}", loops(b)),
            (_, Some(1), 0) => "projective plane".into(),
            (_, Some(2), 0) => "Klein bottle".into(),
            (_, Some(k), 0) => format!("N_{k}"),
            (_, Some(1), 1) => "Möbius band".into(),
            (_, Some(k), b) => format!("N_{k} with {}", loops(b)),
            (None, None, _) => unreachable!("a surface is orientable or not"),
        }
    }
}

/// The classification of each connected component, in the order of their first face, of a soup
/// that forms a surface ([`CornerPairing::is_surface`]). A breadth-first search over the faces
/// through the edges in two faces finds the components and, by propagating a sign that flips
/// across an edge both faces run the same way, their orientability; the boundary loops are the
/// components of the graph of boundary edges (a cycle each: every boundary vertex of a surface
/// has two boundary edges). O(n).
pub(crate) fn classify(p: &CornerPairing) -> Vec<SurfaceKind> {
    let ins = &p.inspection;
    if ins.boundary_edges == 0 && ins.orientable && ins.components == 1 {
        // One closed orientable piece: its counts are the whole's.
        let (faces, vertices) = (p.remapped.len(), p.new_to_old.len());
        return vec![SurfaceKind::new(faces, 3 * faces / 2, vertices, true, 0)];
    }
    components(p).1
}

/// The component of each face (numbered in order of their first face) and the classification
/// of each component, as [`classify`].
pub(crate) fn components(p: &CornerPairing) -> (Vec<u32>, Vec<SurfaceKind>) {
    if p.inspection.components == 1 {
        one_piece(p)
    } else {
        search(p)
    }
}

/// [`components`] of a surface in one piece (as the pairing counted them): its counts are the
/// whole's, its orientability the pairing's, its boundary loops those of all the boundary
/// edges; no search over the faces.
fn one_piece(p: &CornerPairing) -> (Vec<u32>, Vec<SurfaceKind>) {
    let (nf, nv, ins) = (p.remapped.len(), p.new_to_old.len(), &p.inspection);
    let mut loops = Loops {
        sets: UnionFind::new(nv),
        on_boundary: vec![false; nv],
    };
    let mut boundary_vertices = Vec::new();
    for c in (0..3 * nf as u32).filter(|&c| p.edges.across(c).is_none()) {
        loops.add_edge(p, c, &mut boundary_vertices);
    }
    let boundary_loops = loops.count(&boundary_vertices);
    let kind = SurfaceKind::new(nf, ins.edges, nv, ins.orientable, boundary_loops);
    (vec![0; nf], vec![kind])
}

/// [`components`] by a breadth-first search over the faces (see [`classify`]).
fn search(p: &CornerPairing) -> (Vec<u32>, Vec<SurfaceKind>) {
    let nf = p.remapped.len();
    let nv = p.new_to_old.len();
    let edges = &p.edges;
    let mut loops = Loops {
        sets: UnionFind::new(nv),
        on_boundary: vec![false; nv],
    };
    const NONE: u32 = u32::MAX;
    let mut component = vec![NONE; nf];
    let mut sign = vec![false; nf];
    let mut vertex_component = vec![NONE; nv];
    let mut kinds = Vec::new();
    let mut queue = Vec::new();
    for start in 0..nf {
        if component[start] != NONE {
            continue;
        }
        let id = kinds.len() as u32;
        let (mut faces, mut edge_count, mut vertices, mut orientable) = (0, 0, 0, true);
        let mut boundary_vertices = Vec::new();
        component[start] = id;
        queue.clear();
        queue.push(start);
        while let Some(f) = queue.pop() {
            faces += 1;
            for i in 0..3 {
                let c = (3 * f + i) as u32;
                let v = p.corner_vertex(c) as usize;
                if vertex_component[v] == NONE {
                    vertex_component[v] = id;
                    vertices += 1;
                }
                let Some(other) = edges.across(c) else {
                    // A boundary edge (the soup is a surface: no edge in three faces).
                    edge_count += 1;
                    loops.add_edge(p, c, &mut boundary_vertices);
                    continue;
                };
                if c < other {
                    edge_count += 1;
                }
                let g = (other / 3) as usize;
                let want = sign[f] ^ edges.same_direction_at(c);
                if component[g] == NONE {
                    component[g] = id;
                    sign[g] = want;
                    queue.push(g);
                } else if sign[g] != want {
                    orientable = false;
                }
            }
        }
        let boundary_loops = loops.count(&boundary_vertices);
        kinds.push(SurfaceKind::new(
            faces,
            edge_count,
            vertices,
            orientable,
            boundary_loops,
        ));
    }
    (component, kinds)
}

/// The boundary loops of a surface: its boundary vertices joined along boundary edges.
struct Loops {
    sets: UnionFind,
    on_boundary: Vec<bool>,
}

impl Loops {
    /// The boundary edge at corner `c`: its ends join one loop; each end not seen yet is added
    /// to `listed`.
    fn add_edge(&mut self, p: &CornerPairing, c: u32, listed: &mut Vec<u32>) {
        let v = p.corner_vertex(c);
        let w = p.corner_vertex(super::pairing::next_corner(c));
        self.sets.union(v, w);
        for x in [v, w] {
            if !self.on_boundary[x as usize] {
                self.on_boundary[x as usize] = true;
                listed.push(x);
            }
        }
    }

    /// The number of loops through the vertices `listed`.
    fn count(&mut self, listed: &[u32]) -> usize {
        listed.iter().filter(|&&x| self.sets.find(x) == x).count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generators::{
        annulus, cut_holes, disk, icosphere, klein_bottle, mobius_band, torus,
    };
    use crate::{CoveredSurface, Lifting};

    /// The triangles of K as a soup (classes as vertex ids).
    fn soup(s: &CoveredSurface) -> (usize, Vec<[u32; 3]>) {
        (s.cover.sheets.class_count(), s.cover.surface_triangles())
    }

    #[test]
    fn one_piece_counts_what_the_search_finds() {
        let sphere: CoveredSurface = icosphere(2).into();
        let surfaces = [
            disk(5),
            annulus(7, 3),
            mobius_band(9, 3),
            klein_bottle(6, 4),
            cut_holes(&sphere, 3, 5).0,
            cut_holes(&torus(8, 5).into(), 2, 1).0,
            sphere,
        ];
        for s in &surfaces {
            let (nv, triangles) = soup(s);
            let p = CornerPairing::run(nv, &triangles);
            assert!(p.is_surface() && p.inspection.components == 1);
            let (fast, searched) = (one_piece(&p), search(&p));
            assert_eq!(fast, searched, "{}", searched.1[0].name());
        }
    }
}
