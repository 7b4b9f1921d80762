//! Building a [`SurfaceMesh`] from a triangle soup, with validation.
//!
//! One pass pairs the directed corner edges by a counting sort on their smaller vertex (O(n), no
//! global sort), then a breadth-first search over faces orients them and counts components.
//! Every problem is collected ([`inspect`]); [`build`] fails on the first one.

use crate::error::BuildError;
use crate::ids::{FaceId, HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;
use std::borrow::Cow;

/// At most this many problems are listed by [`inspect`] (counts are always complete).
pub const MAX_LISTED_PROBLEMS: usize = 100;

/// What building a mesh changed about its input.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BuildReport {
    /// Faces whose orientation was reversed to make the orientation consistent.
    pub reoriented_faces: usize,
    /// Input vertices that no face uses; they were dropped.
    pub dropped_vertices: Vec<u32>,
    /// Input vertex index -> mesh vertex id (`INVALID` for dropped vertices).
    pub vertex_old_to_new: Vec<VertexId>,
}

/// Everything [`inspect`] finds out about a triangle soup, valid or not.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Inspection {
    /// Referenced vertices.
    pub vertices: usize,
    /// Distinct undirected edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Connected components (faces joined through shared edges).
    pub components: usize,
    /// Edges in exactly one face.
    pub boundary_edges: usize,
    /// Edges in more than two faces.
    pub non_manifold_edges: usize,
    /// Vertices whose faces form more than one fan (only checked when edges are manifold).
    pub non_manifold_vertices: usize,
    /// Whether a consistent orientation exists (over the manifold part).
    pub orientable: bool,
    /// Faces that would be reversed to orient the surface consistently.
    pub reoriented_faces: usize,
    /// Unreferenced vertices.
    pub dropped_vertices: usize,
    /// The problems found, at most [`MAX_LISTED_PROBLEMS`], in input order of discovery.
    pub problems: Vec<BuildError>,
    /// Total number of problems found.
    pub problem_count: usize,
}

impl Inspection {
    /// Whether every edge has exactly two faces.
    pub fn is_closed(&self) -> bool {
        self.boundary_edges == 0 && self.non_manifold_edges == 0
    }
    /// Euler characteristic `V - E + F`.
    pub fn euler_characteristic(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.faces as i64
    }
    fn push(&mut self, e: BuildError) {
        self.problem_count += 1;
        if self.problems.len() < MAX_LISTED_PROBLEMS {
            self.problems.push(e);
        }
    }
}

/// Inspects a triangle soup without building anything: counts and every problem found.
pub fn inspect(vertex_count: usize, triangles: &[[u32; 3]]) -> Inspection {
    Pairing::run(vertex_count, triangles).inspection
}

/// Builds a closed, connected, orientable surface from a triangle soup.
///
/// Unreferenced vertices are dropped (see [`BuildReport::vertex_old_to_new`]); faces are reoriented
/// to agree with the majority orientation when needed. Face ids equal input face indices.
///
/// # Errors
/// The first problem found, naming the input face, vertex or edge (see [`BuildError`]).
pub fn build(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> Result<(SurfaceMesh, BuildReport), BuildError> {
    let mut p = Pairing::run(vertex_count, triangles);
    if let Some(e) = p.inspection.problems.first() {
        return Err(e.clone());
    }
    let mut report = BuildReport {
        reoriented_faces: p.inspection.reoriented_faces,
        dropped_vertices: std::mem::take(&mut p.dropped),
        vertex_old_to_new: std::mem::take(&mut p.old_to_new),
    };
    let mesh = if report.reoriented_faces > 0 {
        let mut oriented = std::mem::take(&mut p.remapped).into_owned();
        for (t, &flip) in oriented.iter_mut().zip(&p.flip) {
            if flip {
                t.swap(1, 2);
            }
        }
        let again = Pairing::run(p.inspection.vertices, &oriented);
        debug_assert_eq!(again.inspection.reoriented_faces, 0);
        if let Some(e) = again.inspection.problems.first() {
            return Err(e.clone());
        }
        again.into_mesh()
    } else {
        p.into_mesh()
    };
    report.reoriented_faces = report.reoriented_faces.min(triangles.len());
    Ok((mesh, report))
}

/// Builds the topology of a soup that is known to be valid and consistently oriented, with no
/// unreferenced vertices (used by generators).
///
/// # Errors
/// As [`build`]; additionally fails if faces would need reorienting or vertices dropping.
pub fn build_topology(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> Result<SurfaceMesh, BuildError> {
    let (mesh, report) = build(vertex_count, triangles)?;
    if report.reoriented_faces > 0 || !report.dropped_vertices.is_empty() {
        return Err(BuildError::NonOrientable {
            edge: [0, 0],
            face: 0,
        });
    }
    Ok(mesh)
}

/// Internal state of the pairing pass.
struct Pairing<'a> {
    inspection: Inspection,
    /// Triangles in new vertex ids (faces with bad indices are kept with `u32::MAX`); the input
    /// itself when nothing needed renumbering.
    remapped: Cow<'a, [[u32; 3]]>,
    old_to_new: Vec<VertexId>,
    new_to_old: Vec<u32>,
    dropped: Vec<u32>,
    /// Half-edge id of each corner (corner `3f + i` is the directed edge `t[i] -> t[i+1]`).
    corner_halfedge: Vec<HalfedgeId>,
    /// Corner of each half-edge.
    halfedge_corner: Vec<u32>,
    /// Whether each face is reversed by the orientation.
    flip: Vec<bool>,
}

impl<'a> Pairing<'a> {
    fn run(vertex_count: usize, triangles: &'a [[u32; 3]]) -> Self {
        let mut ins = Inspection {
            faces: triangles.len(),
            orientable: true,
            ..Inspection::default()
        };
        let mut p = Pairing {
            inspection: Inspection::default(),
            remapped: Cow::Borrowed(&[]),
            old_to_new: Vec::new(),
            new_to_old: Vec::new(),
            dropped: Vec::new(),
            corner_halfedge: Vec::new(),
            halfedge_corner: Vec::new(),
            flip: Vec::new(),
        };
        if triangles.is_empty() {
            ins.push(BuildError::Empty);
            p.inspection = ins;
            return p;
        }
        if triangles.len().saturating_mul(3) >= (u32::MAX >> 1) as usize
            || vertex_count >= u32::MAX as usize
        {
            ins.push(BuildError::TooLarge {
                what: "faces or vertices",
            });
            p.inspection = ins;
            return p;
        }
        // 1. Indices in range, no repeated vertex; referenced vertices.
        let mut valid = vec![true; triangles.len()];
        let mut used = vec![false; vertex_count];
        for (f, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= vertex_count) {
                ins.push(BuildError::IndexOutOfRange {
                    face: f,
                    index,
                    vertex_count,
                });
                valid[f] = false;
                continue;
            }
            if t[0] == t[1] || t[0] == t[2] || t[1] == t[2] {
                let vertex = if t[0] == t[1] || t[0] == t[2] {
                    t[0]
                } else {
                    t[1]
                };
                ins.push(BuildError::RepeatedVertex { face: f, vertex });
                valid[f] = false;
                continue;
            }
            for &i in t {
                used[i as usize] = true;
            }
        }
        let mut old_to_new = vec![VertexId::INVALID; vertex_count];
        let mut new_to_old = Vec::with_capacity(vertex_count);
        for (i, &u) in used.iter().enumerate() {
            if u {
                old_to_new[i] = VertexId::new(new_to_old.len());
                new_to_old.push(i as u32);
            } else {
                p.dropped.push(i as u32);
            }
        }
        drop(used);
        let nv = new_to_old.len();
        ins.vertices = nv;
        ins.dropped_vertices = p.dropped.len();
        let identity = p.dropped.is_empty() && valid.iter().all(|&ok| ok);
        let remapped: Cow<'a, [[u32; 3]]> = if identity {
            Cow::Borrowed(triangles)
        } else {
            triangles
                .iter()
                .zip(&valid)
                .map(|(t, &ok)| {
                    if ok {
                        t.map(|i| old_to_new[i as usize].0)
                    } else {
                        [u32::MAX; 3]
                    }
                })
                .collect()
        };

        // 2. Counting sort of corners by their smaller endpoint.
        let nf = triangles.len();
        let mut bucket_start = vec![0u32; nv + 1];
        for t in remapped.iter().filter(|t| t[0] != u32::MAX) {
            for i in 0..3 {
                let lo = t[i].min(t[(i + 1) % 3]);
                bucket_start[lo as usize + 1] += 1;
            }
        }
        for v in 0..nv {
            bucket_start[v + 1] += bucket_start[v];
        }
        let mut fill = bucket_start.clone();
        // (larger endpoint, corner << 1 | forward, opposite vertex), bucketed by the smaller endpoint:
        // grouping then reads nothing at random.
        let mut sorted = vec![(0u32, 0u32, 0u32); bucket_start[nv] as usize];
        for (f, t) in remapped
            .iter()
            .enumerate()
            .filter(|(_, t)| t[0] != u32::MAX)
        {
            for i in 0..3 {
                let (a, b, opposite) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
                let lo = a.min(b);
                let corner = ((3 * f + i) as u32) << 1 | u32::from(a < b);
                sorted[fill[lo as usize] as usize] = (a.max(b), corner, opposite);
                fill[lo as usize] += 1;
            }
        }
        drop(fill);
        // Two faces sharing an edge and its opposite vertex are the same face; reported once, at
        // the smallest edge of the face.
        let is_smallest_edge = |c: u32, lo: u32, hi: u32| {
            let t = &remapped[(c / 3) as usize];
            let smallest = (0..3)
                .map(|i| (t[i].min(t[(i + 1) % 3]), t[i].max(t[(i + 1) % 3])))
                .min();
            smallest == Some((lo, hi))
        };

        // 3. Group corners by edge; assign half-edge pairs to edges in two faces.
        let mut corner_halfedge = vec![HalfedgeId::INVALID; 3 * nf];
        let mut halfedge_corner: Vec<u32> = Vec::with_capacity(3 * nf);
        let mut same_direction: Vec<bool> = Vec::with_capacity(3 * nf / 2);
        let mut uf = UnionFind::new(nf);
        let mut group: Vec<(u32, bool, u32)> = Vec::new();
        for v in 0..nv {
            let bucket = &mut sorted[bucket_start[v] as usize..bucket_start[v + 1] as usize];
            bucket.sort_unstable();
            let mut i = 0;
            while i < bucket.len() {
                let hi = bucket[i].0;
                let mut j = i + 1;
                while j < bucket.len() && bucket[j].0 == hi {
                    j += 1;
                }
                // (corner, forward, opposite vertex) of each face on this edge.
                group.clear();
                group.extend(
                    bucket[i..j]
                        .iter()
                        .map(|&(_, c, opposite)| (c >> 1, c & 1 == 1, opposite)),
                );
                ins.edges += 1;
                let edge = [new_to_old[v], new_to_old[hi as usize]];
                for w in group.windows(2) {
                    uf.union(w[0].0 / 3, w[1].0 / 3);
                }
                // A repeated face shares this edge and its opposite vertex with an earlier one.
                for (k, &(c2, _, opposite)) in group.iter().enumerate().skip(1) {
                    let first = group[..k].iter().find(|g| g.2 == opposite);
                    if let Some(&(c1, _, _)) = first.filter(|_| is_smallest_edge(c2, v as u32, hi))
                    {
                        ins.push(BuildError::DuplicateFace {
                            face: (c2 / 3) as usize,
                            duplicate_of: (c1 / 3) as usize,
                        });
                    }
                }
                let face = (group[0].0 / 3) as usize;
                match group[..] {
                    [_] => {
                        ins.boundary_edges += 1;
                        ins.push(BuildError::BoundaryEdge { edge, face });
                    }
                    [(c1, forward1, _), (c2, forward2, _)] => {
                        let h = halfedge_corner.len();
                        corner_halfedge[c1 as usize] = HalfedgeId::new(h);
                        corner_halfedge[c2 as usize] = HalfedgeId::new(h + 1);
                        halfedge_corner.push(c1);
                        halfedge_corner.push(c2);
                        same_direction.push(forward1 == forward2);
                    }
                    _ => {
                        ins.non_manifold_edges += 1;
                        ins.push(BuildError::NonManifoldEdge {
                            edge,
                            face_count: group.len(),
                            face,
                        });
                    }
                }
                i = j;
            }
        }
        drop(sorted);
        drop(bucket_start);

        // 4. Vertex manifoldness: the fan around each vertex must hold all its corners (checked
        //    when every edge has two faces; the walk ignores orientation).
        let all_paired =
            valid.iter().all(|&ok| ok) && ins.boundary_edges == 0 && ins.non_manifold_edges == 0;
        let consistent = !same_direction.iter().any(|&same| same);
        if all_paired {
            let mut corners = vec![0u32; nv];
            for t in remapped.iter() {
                for &v in t {
                    corners[v as usize] += 1;
                }
            }
            let mut start_corner = vec![u32::MAX; nv];
            for (c, &v) in remapped.iter().flatten().enumerate() {
                start_corner[v as usize] = c as u32;
            }
            // The two corners of a face that touch the vertex at corner c: c itself (leaving it)
            // and the previous corner (entering it). The walk enters a face through one and
            // leaves through the other, whatever the faces' orientations.
            let prev_corner = |c: u32| c - c % 3 + (c % 3 + 2) % 3;
            for v in 0..nv {
                let start = start_corner[v];
                let (mut leave, mut steps) = (start, 0u32);
                loop {
                    steps += 1;
                    let h = corner_halfedge[leave as usize];
                    let entered = halfedge_corner[h.twin().idx()];
                    // `entered` is one of the two corners at v in the next face; leave by the other.
                    // (With a consistent orientation, `entered` always ends at v.)
                    let starts_at_v = !consistent
                        && remapped[(entered / 3) as usize][(entered % 3) as usize] == v as u32;
                    leave = if starts_at_v {
                        prev_corner(entered)
                    } else {
                        entered - entered % 3 + (entered % 3 + 1) % 3
                    };
                    if leave / 3 == start / 3 || steps > corners[v] {
                        break;
                    }
                }
                if steps != corners[v] {
                    ins.non_manifold_vertices += 1;
                    ins.push(BuildError::NonManifoldVertex {
                        vertex: new_to_old[v],
                        faces: corners[v] as usize,
                        first_fan: steps as usize,
                    });
                }
            }
        }

        // 5. Components (over all shared edges).
        let first_valid = valid.iter().position(|&ok| ok);
        if let Some(f0) = first_valid {
            let root0 = uf.find(f0 as u32);
            let mut roots = 0usize;
            let mut outside = None;
            for f in (0..nf).filter(|&f| valid[f]) {
                let r = uf.find(f as u32);
                if r == f as u32 {
                    roots += 1;
                }
                if outside.is_none() && r != root0 {
                    outside = Some(f);
                }
            }
            ins.components = roots;
            if let Some(face) = outside {
                ins.push(BuildError::Disconnected {
                    components: roots,
                    face,
                });
            }
        }

        // 6. Orientation by breadth-first search across manifold edges.
        // Skipped when every edge already joins opposite directions (the usual case).
        let mut flip = vec![false; nf];
        let mut seen = vec![consistent; nf];
        let mut queue: Vec<u32> = Vec::new();
        for start in 0..nf {
            if seen[start] || !valid[start] {
                continue;
            }
            seen[start] = true;
            queue.clear();
            queue.push(start as u32);
            let mut head = 0;
            let mut component_faces = Vec::new();
            while head < queue.len() {
                let f = queue[head] as usize;
                head += 1;
                component_faces.push(f);
                for i in 0..3 {
                    let h = corner_halfedge[3 * f + i];
                    if !h.is_valid() {
                        continue;
                    }
                    let other_corner = halfedge_corner[h.twin().idx()];
                    let g = (other_corner / 3) as usize;
                    let want = flip[f] ^ same_direction[h.edge().idx()];
                    if !seen[g] {
                        seen[g] = true;
                        flip[g] = want;
                        queue.push(g as u32);
                    } else if flip[g] != want && ins.orientable {
                        ins.orientable = false;
                        let t = &remapped[f];
                        ins.push(BuildError::NonOrientable {
                            edge: [
                                new_to_old[t[i] as usize],
                                new_to_old[t[(i + 1) % 3] as usize],
                            ],
                            face: g,
                        });
                    }
                }
            }
            // Keep the majority orientation of each component.
            let flipped = component_faces.iter().filter(|&&f| flip[f]).count();
            if 2 * flipped > component_faces.len() {
                for &f in &component_faces {
                    flip[f] = !flip[f];
                }
            }
        }
        if ins.orientable {
            ins.reoriented_faces = flip.iter().filter(|&&b| b).count();
        }

        p.inspection = ins;
        p.remapped = remapped;
        p.old_to_new = old_to_new;
        p.new_to_old = new_to_old;
        p.corner_halfedge = corner_halfedge;
        p.halfedge_corner = halfedge_corner;
        p.flip = flip;
        p
    }

    /// The half-edge arrays (requires no problems and no reorientation).
    fn into_mesh(self) -> SurfaceMesh {
        let nh = self.halfedge_corner.len();
        let nf = self.remapped.len();
        let nv = self.new_to_old.len();
        let mut next = vec![HalfedgeId::INVALID; nh];
        let mut origin = vec![VertexId::INVALID; nh];
        let mut face = vec![FaceId::INVALID; nh];
        let mut vertex_halfedge = vec![HalfedgeId::INVALID; nv];
        let mut face_halfedge = vec![HalfedgeId::INVALID; nf];
        for (f, t) in self.remapped.iter().enumerate() {
            for i in 0..3 {
                let h = self.corner_halfedge[3 * f + i];
                next[h.idx()] = self.corner_halfedge[3 * f + (i + 1) % 3];
                origin[h.idx()] = VertexId(t[i]);
                face[h.idx()] = FaceId::new(f);
                vertex_halfedge[t[i] as usize] = h;
            }
            face_halfedge[f] = self.corner_halfedge[3 * f];
        }
        SurfaceMesh {
            next,
            origin,
            face,
            vertex_halfedge,
            face_halfedge,
            live_vertices: nv,
            live_edges: nh / 2,
            live_faces: nf,
        }
    }
}

/// Union-find with path halving.
struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n as u32).collect(),
        }
    }
    fn find(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let gp = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = gp;
            x = gp;
        }
        x
    }
    fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            let (lo, hi) = (ra.min(rb), ra.max(rb));
            self.parent[hi as usize] = lo;
        }
    }
}
