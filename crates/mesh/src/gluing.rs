//! Building a surface by gluing triangles side to side: loops and multi-edges allowed.
//!
//! This is how intrinsic triangulations (triangular portalgons) are given: triangles and a
//! matching of their sides, the vertices being whatever the gluing identifies (the flat torus
//! T_x of the intrinsic-Delaunay paper has one vertex, two triangles and three edges).

use crate::error::BuildError;
use crate::ids::{FaceId, HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;

/// A side of a triangle: side `i` of face `f` runs from its corner `i` to corner `i + 1 (mod 3)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Side {
    /// The face.
    pub face: u32,
    /// 0, 1 or 2.
    pub side: u8,
}

impl Side {
    fn index(self) -> usize {
        3 * self.face as usize + self.side as usize
    }
}

impl SurfaceMesh {
    /// Glues `face_count` counter-clockwise triangles along the given pairs of sides (each side in
    /// exactly one pair; the two sides of a pair run in opposite directions, which keeps the
    /// surface oriented). Edge `k` is the `k`-th pair: half-edge `2k` is its first side and `2k + 1`
    /// its second. Face `f` stores the half-edge of its side 0.
    ///
    /// Returns the mesh and the vertex of each corner (`corner_vertex[3 f + i]`); vertices are
    /// numbered in order of first corner.
    ///
    /// # Errors
    /// [`BuildError::Empty`], [`BuildError::SideUnglued`], [`BuildError::SideGluedTwice`] (also for
    /// out-of-range faces), [`BuildError::Disconnected`]. (Gluing triangles side to side always
    /// gives a surface: every vertex is one fan by construction.)
    pub fn from_gluing(
        face_count: usize,
        pairs: &[(Side, Side)],
    ) -> Result<(SurfaceMesh, Vec<VertexId>), BuildError> {
        Self::glue(face_count, pairs, true)
    }

    /// [`Self::from_gluing`] allowing several connected pieces (each a closed oriented surface).
    ///
    /// # Errors
    /// As [`Self::from_gluing`], without [`BuildError::Disconnected`].
    pub fn from_gluing_pieces(
        face_count: usize,
        pairs: &[(Side, Side)],
    ) -> Result<(SurfaceMesh, Vec<VertexId>), BuildError> {
        Self::glue(face_count, pairs, false)
    }

    /// The closed mesh of `face_count` triangles whose side `i` of face `f` (from corner `i` to
    /// corner `i + 1`) is half-edge `halfedge(f, i)`, leaving vertex `vertex(f, i)` (below
    /// `vertex_count`): each half-edge's tables from its side, each face's half-edge its side
    /// 0's, each vertex's half-edge its last corner's (in face and corner order). The caller
    /// pairs the sides (half-edges `2e`, `2e + 1` glued) and numbers the vertices.
    #[inline]
    pub(crate) fn from_sides(
        face_count: usize,
        vertex_count: usize,
        halfedge: impl Fn(usize, usize) -> HalfedgeId,
        vertex: impl Fn(usize, usize) -> VertexId,
    ) -> SurfaceMesh {
        let sides = 3 * face_count;
        let mut next = vec![HalfedgeId::INVALID; sides];
        let mut origin = vec![VertexId::INVALID; sides];
        let mut face = vec![FaceId::INVALID; sides];
        let mut vertex_halfedge = vec![HalfedgeId::INVALID; vertex_count];
        let mut face_halfedge = vec![HalfedgeId::INVALID; face_count];
        for (f, first) in face_halfedge.iter_mut().enumerate() {
            for i in 0..3 {
                let (h, v) = (halfedge(f, i), vertex(f, i));
                next[h.idx()] = halfedge(f, (i + 1) % 3);
                origin[h.idx()] = v;
                face[h.idx()] = FaceId::new(f);
                vertex_halfedge[v.idx()] = h;
            }
            *first = halfedge(f, 0);
        }
        SurfaceMesh {
            next,
            origin,
            face,
            vertex_halfedge,
            face_halfedge,
            live_vertices: vertex_count,
            live_edges: sides / 2,
            live_faces: face_count,
        }
    }

    /// The gluing of [`Self::from_gluing`]; refuses several pieces when `connected`.
    fn glue(
        face_count: usize,
        pairs: &[(Side, Side)],
        connected: bool,
    ) -> Result<(SurfaceMesh, Vec<VertexId>), BuildError> {
        if face_count == 0 {
            return Err(BuildError::Empty);
        }
        if 3 * face_count >= u32::MAX as usize / 2 {
            return Err(BuildError::TooLarge { what: "faces" });
        }
        let sides = 3 * face_count;
        let mut halfedge_of_side = vec![HalfedgeId::INVALID; sides];
        for (k, &(s, t)) in pairs.iter().enumerate() {
            for (j, side) in [s, t].into_iter().enumerate() {
                let bad = side.face as usize >= face_count || side.side > 2;
                if bad || s == t || halfedge_of_side[side.index()].is_valid() {
                    return Err(BuildError::SideGluedTwice {
                        face: side.face as usize,
                        side: side.side as usize,
                    });
                }
                halfedge_of_side[side.index()] = HalfedgeId::new(2 * k + j);
            }
        }
        if let Some(i) = halfedge_of_side.iter().position(|h| !h.is_valid()) {
            return Err(BuildError::SideUnglued {
                face: i / 3,
                side: i % 3,
            });
        }
        // The side glued to each side.
        let glued_to = {
            let mut v = vec![0u32; sides];
            for &(s, t) in pairs {
                v[s.index()] = t.index() as u32;
                v[t.index()] = s.index() as u32;
            }
            v
        };
        // Corner c = 3f + i is the start of side c. The side glued to side c starts where c ends.
        let glued = |c: usize| glued_to[c] as usize;
        // Vertices: orbits of corners under "rotate": corner c -> the corner after the side glued
        // to the side entering c. Each orbit is one fan; orbits are the vertices.
        let prev_side = |c: usize| c - c % 3 + (c % 3 + 2) % 3;
        let mut corner_vertex = vec![VertexId::INVALID; sides];
        let mut vertex_count = 0usize;
        for start in 0..sides {
            if corner_vertex[start].is_valid() {
                continue;
            }
            let v = VertexId::new(vertex_count);
            vertex_count += 1;
            let mut c = start;
            loop {
                corner_vertex[c] = v;
                // The side entering c is prev_side(c); its glued partner leaves corner c's vertex.
                c = glued(prev_side(c));
                if c == start {
                    break;
                }
            }
        }
        let mesh = Self::from_sides(
            face_count,
            vertex_count,
            |f, i| halfedge_of_side[3 * f + i],
            |f, i| corner_vertex[3 * f + i],
        );
        if !connected {
            return Ok((mesh, corner_vertex));
        }
        // Connectedness over faces.
        let mut component = vec![u32::MAX; face_count];
        let mut components = 0u32;
        let mut first_outside = None;
        for root in 0..face_count {
            if component[root] != u32::MAX {
                continue;
            }
            if components == 1 {
                first_outside = Some(root);
            }
            component[root] = components;
            let mut stack = vec![root];
            while let Some(f) = stack.pop() {
                for h in mesh.face_halfedges(FaceId::new(f)) {
                    let g = mesh.face(h.twin()).idx();
                    if component[g] == u32::MAX {
                        component[g] = components;
                        stack.push(g);
                    }
                }
            }
            components += 1;
        }
        if let Some(face) = first_outside {
            return Err(BuildError::Disconnected {
                components: components as usize,
                face,
            });
        }
        Ok((mesh, corner_vertex))
    }
}
