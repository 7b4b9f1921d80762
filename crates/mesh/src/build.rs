//! Building a [`SurfaceMesh`] from a triangle soup, with validation.
//!
//! The directed corner edges are paired after two counting sorts (by larger, then by smaller
//! vertex: O(n), no comparison sort); a walk around each vertex checks its fan, a union-find counts
//! components, and a breadth-first search over faces orients them when needed.
//! Every problem is collected ([`inspect`]); [`build`] fails on the first one.

use crate::error::BuildError;
use crate::ids::{FaceId, HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;
use crate::union_find::UnionFind;
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
    /// The problems found, counted by class (they sum to `problem_count`).
    pub counts: ProblemCounts,
}

/// The problems of an [`Inspection`] counted by class, one count per kind of [`BuildError`]
/// that [`inspect`] and the geometric checks ([`crate::geometry::problems`]) report. The field
/// names are the keys of `surftopo info --json` and, read with spaces for `_`, its text labels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ProblemCounts {
    /// Coordinates that are NaN or infinite, one per coordinate (a vertex `nan nan nan` counts
    /// three): [`BuildError::NonFinite`].
    pub non_finite_coordinates: usize,
    /// Faces of exactly zero area (collinear vertices): [`BuildError::ZeroArea`].
    pub zero_area_faces: usize,
    /// Faces repeating a vertex: [`BuildError::RepeatedVertex`].
    pub degenerate_faces: usize,
    /// Faces on the same vertices as an earlier face: [`BuildError::DuplicateFace`].
    pub duplicate_faces: usize,
    /// Edges in one face: [`BuildError::BoundaryEdge`].
    pub boundary_edges: usize,
    /// Edges in more than two faces: [`BuildError::NonManifoldEdge`].
    pub non_manifold_edges: usize,
    /// Vertices whose faces form several fans: [`BuildError::NonManifoldVertex`].
    pub non_manifold_vertices: usize,
    /// 1 when no consistent orientation exists ([`BuildError::NonOrientable`], reported once, at
    /// the first conflict found).
    pub non_orientable: usize,
    /// 1 when the faces form several connected components ([`BuildError::Disconnected`],
    /// reported once; [`Inspection::components`] says how many).
    pub disconnected: usize,
    /// Any other problem: a vertex index out of range, no face at all, more elements than
    /// `u32` ids address (none of which comes from a file: the readers refuse such files, and
    /// `surftopo info` with them).
    pub other_problems: usize,
}

impl ProblemCounts {
    /// Counts one problem in its class.
    pub fn add(&mut self, problem: &BuildError) {
        let count = match problem {
            BuildError::NonFinite { .. } => &mut self.non_finite_coordinates,
            BuildError::ZeroArea { .. } => &mut self.zero_area_faces,
            BuildError::RepeatedVertex { .. } => &mut self.degenerate_faces,
            BuildError::DuplicateFace { .. } => &mut self.duplicate_faces,
            BuildError::BoundaryEdge { .. } => &mut self.boundary_edges,
            BuildError::NonManifoldEdge { .. } => &mut self.non_manifold_edges,
            BuildError::NonManifoldVertex { .. } => &mut self.non_manifold_vertices,
            BuildError::NonOrientable { .. } => &mut self.non_orientable,
            BuildError::Disconnected { .. } => &mut self.disconnected,
            BuildError::IndexOutOfRange { .. }
            | BuildError::Empty
            | BuildError::TooLarge { .. }
            | BuildError::SideUnglued { .. }
            | BuildError::SideGluedTwice { .. }
            | BuildError::NotAsGiven { .. }
            | BuildError::NotTriangle { .. } => &mut self.other_problems,
        };
        *count += 1;
    }

    /// `(key, count)` per class, in the order `surftopo info` prints them; the key is the
    /// field's name.
    pub fn entries(&self) -> [(&'static str, usize); 10] {
        [
            ("non_finite_coordinates", self.non_finite_coordinates),
            ("zero_area_faces", self.zero_area_faces),
            ("degenerate_faces", self.degenerate_faces),
            ("duplicate_faces", self.duplicate_faces),
            ("boundary_edges", self.boundary_edges),
            ("non_manifold_edges", self.non_manifold_edges),
            ("non_manifold_vertices", self.non_manifold_vertices),
            ("non_orientable", self.non_orientable),
            ("disconnected", self.disconnected),
            ("other_problems", self.other_problems),
        ]
    }

    /// The problems of the geometry (non-finite coordinates, zero-area faces); the others are
    /// of the combinatorics.
    pub fn geometric(&self) -> usize {
        self.non_finite_coordinates + self.zero_area_faces
    }

    /// All problems, every class.
    pub fn total(&self) -> usize {
        self.entries().iter().map(|&(_, n)| n).sum()
    }
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
    /// Whether no problem was found: the soup is a closed, connected, orientable surface that
    /// [`build()`] accepts.
    pub fn is_valid(&self) -> bool {
        self.problem_count == 0
    }
    /// Whether the combinatorics are those of a closed, connected, orientable surface: no
    /// problem but the geometric ones ([`ProblemCounts::geometric`]: non-finite coordinates,
    /// zero-area faces), which leave the topology defined.
    pub fn is_combinatorially_valid(&self) -> bool {
        self.problem_count == self.counts.geometric()
    }
    /// The genus `(2 - χ) / 2` when the combinatorics are valid
    /// ([`Self::is_combinatorially_valid`]), `None` otherwise.
    pub fn genus(&self) -> Option<i64> {
        self.is_combinatorially_valid()
            .then(|| (2 - self.euler_characteristic()) / 2)
    }
    /// Whether a problem makes the faces a non-simplicial complex: a face repeating a vertex, or
    /// two faces on the same three vertices.
    pub fn has_degenerate_faces(&self) -> bool {
        self.problems.iter().any(|p| {
            matches!(
                p,
                BuildError::RepeatedVertex { .. } | BuildError::DuplicateFace { .. }
            )
        })
    }
    /// Whether more problems were found than [`Self::problems`] lists (at most
    /// [`MAX_LISTED_PROBLEMS`]).
    pub fn is_truncated(&self) -> bool {
        self.problem_count > self.problems.len()
    }
    /// Counts problems found outside the soup's combinatorics (non-finite coordinates, zero-area
    /// faces: [`crate::geometry::problems`]) and lists them before the others, the list still
    /// cut at [`MAX_LISTED_PROBLEMS`].
    pub fn add_problems_first(&mut self, problems: impl IntoIterator<Item = BuildError>) {
        let later = std::mem::take(&mut self.problems);
        for e in problems {
            self.push(e);
        }
        let room = MAX_LISTED_PROBLEMS - self.problems.len();
        self.problems.extend(later.into_iter().take(room));
    }
    fn push(&mut self, e: BuildError) {
        self.problem_count += 1;
        self.counts.add(&e);
        if self.problems.len() < MAX_LISTED_PROBLEMS {
            self.problems.push(e);
        }
    }
}

/// Inspects a triangle soup without building anything: counts and every problem found.
pub fn inspect(vertex_count: usize, triangles: &[[u32; 3]]) -> Inspection {
    CornerPairing::run(vertex_count, triangles).inspection
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
    let mut p = CornerPairing::run(vertex_count, triangles);
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
        let again = CornerPairing::run(p.inspection.vertices, &oriented);
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
/// unreferenced vertices, so that vertex and face ids are the soup's as given.
///
/// # Errors
/// As [`build`]; [`BuildError::NotAsGiven`] if faces would need reorienting or vertices
/// dropping.
pub fn build_topology(
    vertex_count: usize,
    triangles: &[[u32; 3]],
) -> Result<SurfaceMesh, BuildError> {
    let (mesh, report) = build(vertex_count, triangles)?;
    if report.reoriented_faces > 0 || !report.dropped_vertices.is_empty() {
        return Err(BuildError::NotAsGiven {
            reoriented_faces: report.reoriented_faces,
            dropped_vertices: report.dropped_vertices.len(),
        });
    }
    Ok(mesh)
}

/// The pass that pairs the corners of a soup's triangles (each a directed edge) into the
/// half-edges of a mesh, with what it found on the way.
struct CornerPairing<'a> {
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

/// Step 1: the triangles in the ids of the referenced vertices, the faces whose indices are valid
/// (in range, no vertex repeated), and the vertex renumbering.
struct Indexed<'a> {
    /// Per face: whether its indices are valid.
    valid: Vec<bool>,
    /// Triangles in new vertex ids (`u32::MAX` for invalid faces), or the input as it is.
    remapped: Cow<'a, [[u32; 3]]>,
    old_to_new: Vec<VertexId>,
    new_to_old: Vec<u32>,
    /// The unreferenced input vertices.
    dropped: Vec<u32>,
}

impl Indexed<'_> {
    /// The valid faces with their index.
    fn live(&self) -> impl Iterator<Item = (usize, &[u32; 3])> {
        self.remapped
            .iter()
            .enumerate()
            .filter(|(_, t)| t[0] != u32::MAX)
    }

    fn vertex_count(&self) -> usize {
        self.new_to_old.len()
    }
}

/// Step 2: every corner as `(larger endpoint, corner << 1 | forward, opposite vertex)`, bucketed
/// by its smaller endpoint and sorted within buckets by larger endpoint then corner.
struct SortedCorners {
    /// Per vertex `v`, where its bucket starts in `sorted` (`nv + 1` entries).
    bucket_start: Vec<u32>,
    sorted: Vec<(u32, u32, u32)>,
}

/// Step 3: the corners grouped by edge, the pairs of an edge in two faces made half-edges.
struct EdgePairs {
    /// Half-edge id of each corner (`INVALID` for the corners of edges not in two faces).
    corner_halfedge: Vec<HalfedgeId>,
    /// Corner of each half-edge.
    halfedge_corner: Vec<u32>,
    /// Per edge in two faces: whether its two corners run the same way (an orientation conflict
    /// between the faces).
    same_direction: Vec<bool>,
    /// `around[c]`: the corner after `c` around its vertex when the orientation is consistent
    /// (the next corner, in its face, after the twin of corner `c`'s half-edge).
    around: Vec<u32>,
    /// The vertices joined along the edges.
    vertex_sets: UnionFind,
    /// Consecutive corners of the edges in more than two faces (their faces are joined too).
    other_joins: Vec<(u32, u32)>,
}

impl<'a> CornerPairing<'a> {
    fn run(vertex_count: usize, triangles: &'a [[u32; 3]]) -> Self {
        let mut ins = Inspection {
            faces: triangles.len(),
            orientable: true,
            ..Inspection::default()
        };
        let mut p = CornerPairing {
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
        let indexed = check_indices(vertex_count, triangles, &mut ins);
        let sorted = sort_corners(&indexed);
        let mut edges = pair_edges(&indexed, sorted, &mut ins);
        let all_paired = indexed.valid.iter().all(|&ok| ok)
            && ins.boundary_edges == 0
            && ins.non_manifold_edges == 0;
        let consistent = !edges.same_direction.iter().any(|&same| same);
        if all_paired {
            check_fans(&indexed, &edges, consistent, &mut ins);
        }
        count_components(&indexed, &mut edges, all_paired, &mut ins);
        let flip = orient(&indexed, &edges, consistent, &mut ins);
        p.inspection = ins;
        p.remapped = indexed.remapped;
        p.old_to_new = indexed.old_to_new;
        p.new_to_old = indexed.new_to_old;
        p.dropped = indexed.dropped;
        p.corner_halfedge = edges.corner_halfedge;
        p.halfedge_corner = edges.halfedge_corner;
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

/// Step 1: indices in range and no repeated vertex (else the face is invalid and reported); the
/// referenced vertices, renumbered densely in input order.
fn check_indices<'a>(
    vertex_count: usize,
    triangles: &'a [[u32; 3]],
    ins: &mut Inspection,
) -> Indexed<'a> {
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
    let mut dropped = Vec::new();
    for (i, &u) in used.iter().enumerate() {
        if u {
            old_to_new[i] = VertexId::new(new_to_old.len());
            new_to_old.push(i as u32);
        } else {
            dropped.push(i as u32);
        }
    }
    drop(used);
    ins.vertices = new_to_old.len();
    ins.dropped_vertices = dropped.len();
    let identity = dropped.is_empty() && valid.iter().all(|&ok| ok);
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
    Indexed {
        valid,
        remapped,
        old_to_new,
        new_to_old,
        dropped,
    }
}

/// Step 2: the corners sorted by (smaller endpoint, larger endpoint, corner) without
/// comparisons: a counting sort by the larger endpoint, then a stable one by the smaller.
fn sort_corners(indexed: &Indexed) -> SortedCorners {
    let nv = indexed.vertex_count();
    let mut bucket_start = vec![0u32; nv + 1];
    let mut by_hi_start = vec![0u32; nv + 1];
    for (_, t) in indexed.live() {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            bucket_start[a.min(b) as usize + 1] += 1;
            by_hi_start[a.max(b) as usize + 1] += 1;
        }
    }
    for v in 0..nv {
        bucket_start[v + 1] += bucket_start[v];
        by_hi_start[v + 1] += by_hi_start[v];
    }
    // (smaller endpoint, corner << 1 | forward, opposite vertex), by larger endpoint.
    let mut by_hi = vec![(0u32, 0u32, 0u32); by_hi_start[nv] as usize];
    let mut fill = by_hi_start.clone();
    for (f, t) in indexed.live() {
        for i in 0..3 {
            let (a, b, opposite) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
            let hi = a.max(b) as usize;
            let corner = ((3 * f + i) as u32) << 1 | u32::from(a < b);
            by_hi[fill[hi] as usize] = (a.min(b), corner, opposite);
            fill[hi] += 1;
        }
    }
    // (larger endpoint, corner << 1 | forward, opposite vertex), bucketed by the smaller
    // endpoint and sorted within buckets: grouping then reads nothing at random.
    let mut sorted = vec![(0u32, 0u32, 0u32); bucket_start[nv] as usize];
    fill.copy_from_slice(&bucket_start);
    for hi in 0..nv {
        let range = by_hi_start[hi] as usize..by_hi_start[hi + 1] as usize;
        for &(lo, corner, opposite) in &by_hi[range] {
            sorted[fill[lo as usize] as usize] = (hi as u32, corner, opposite);
            fill[lo as usize] += 1;
        }
    }
    SortedCorners {
        bucket_start,
        sorted,
    }
}

/// Step 3: groups the corners by edge and makes the two corners of an edge in two faces a
/// half-edge pair; reports boundary and non-manifold edges and repeated faces. A bucket holds a
/// few corners (about twice the vertex degree): sorted by (larger endpoint, corner), which
/// numbers the edges in (smaller, larger) order.
fn pair_edges(indexed: &Indexed, corners: SortedCorners, ins: &mut Inspection) -> EdgePairs {
    let (remapped, new_to_old) = (&indexed.remapped, &indexed.new_to_old);
    let (nv, nf) = (indexed.vertex_count(), remapped.len());
    let SortedCorners {
        bucket_start,
        sorted,
    } = corners;
    // Two faces sharing an edge and its opposite vertex are the same face; reported once, at
    // the smallest edge of the face.
    let is_smallest_edge = |c: u32, lo: u32, hi: u32| {
        let t = &remapped[(c / 3) as usize];
        let smallest = (0..3)
            .map(|i| (t[i].min(t[(i + 1) % 3]), t[i].max(t[(i + 1) % 3])))
            .min();
        smallest == Some((lo, hi))
    };
    let mut pairs = EdgePairs {
        corner_halfedge: vec![HalfedgeId::INVALID; 3 * nf],
        halfedge_corner: Vec::with_capacity(3 * nf),
        same_direction: Vec::with_capacity(3 * nf / 2),
        around: vec![u32::MAX; 3 * nf],
        vertex_sets: UnionFind::new(nv),
        other_joins: Vec::new(),
    };
    for v in 0..nv {
        let bucket = &sorted[bucket_start[v] as usize..bucket_start[v + 1] as usize];
        let mut v_root = pairs.vertex_sets.find(v as u32);
        let mut i = 0;
        while i < bucket.len() {
            let hi = bucket[i].0;
            let mut j = i + 1;
            while j < bucket.len() && bucket[j].0 == hi {
                j += 1;
            }
            // (larger endpoint, corner << 1 | forward, opposite vertex) of each face on this edge.
            let group = &bucket[i..j];
            let corner = |k: usize| group[k].1 >> 1;
            ins.edges += 1;
            v_root = pairs.vertex_sets.union(v_root, hi);
            if group.len() > 2 {
                pairs
                    .other_joins
                    .extend((1..group.len()).map(|k| (corner(k - 1), corner(k))));
            }
            // A repeated face shares this edge and its opposite vertex with an earlier one.
            for k in 1..group.len() {
                let first = group[..k].iter().find(|g| g.2 == group[k].2);
                if let Some(&(_, c1, _)) =
                    first.filter(|_| is_smallest_edge(corner(k), v as u32, hi))
                {
                    ins.push(BuildError::DuplicateFace {
                        face: (corner(k) / 3) as usize,
                        duplicate_of: (c1 >> 1) as usize / 3,
                    });
                }
            }
            let edge = || [new_to_old[v], new_to_old[hi as usize]];
            let face = (corner(0) / 3) as usize;
            match group.len() {
                1 => {
                    ins.boundary_edges += 1;
                    ins.push(BuildError::BoundaryEdge { edge: edge(), face });
                }
                2 => {
                    let (c1, c2) = (corner(0), corner(1));
                    let h = pairs.halfedge_corner.len();
                    pairs.corner_halfedge[c1 as usize] = HalfedgeId::new(h);
                    pairs.corner_halfedge[c2 as usize] = HalfedgeId::new(h + 1);
                    pairs.around[c1 as usize] = next_corner(c2);
                    pairs.around[c2 as usize] = next_corner(c1);
                    pairs.halfedge_corner.push(c1);
                    pairs.halfedge_corner.push(c2);
                    pairs.same_direction.push(group[0].1 & 1 == group[1].1 & 1);
                }
                _ => {
                    ins.non_manifold_edges += 1;
                    ins.push(BuildError::NonManifoldEdge {
                        edge: edge(),
                        face_count: group.len(),
                        face,
                    });
                }
            }
            i = j;
        }
    }
    pairs
}

/// Step 4, when every edge is in two faces: the fan around each vertex must hold all its corners
/// (the walk ignores orientation).
fn check_fans(indexed: &Indexed, edges: &EdgePairs, consistent: bool, ins: &mut Inspection) {
    let (remapped, nv) = (&indexed.remapped, indexed.vertex_count());
    // Corner count and one corner of each vertex.
    let mut corners = vec![0u32; nv];
    let mut start_corner = vec![u32::MAX; nv];
    for (c, &v) in remapped.iter().flatten().enumerate() {
        corners[v as usize] += 1;
        start_corner[v as usize] = c as u32;
    }
    // The corner after `leave` around vertex v. In general the two corners of a face that
    // touch v are `leave` itself (leaving v) and the previous corner (entering v): the walk
    // enters a face through one and leaves through the other, whatever the faces'
    // orientations; with a consistent orientation that is `around`.
    let step = |leave: u32, v: u32| {
        if consistent {
            return edges.around[leave as usize];
        }
        let h = edges.corner_halfedge[leave as usize];
        let entered = edges.halfedge_corner[h.twin().idx()];
        // `entered` is one of the two corners at v in the next face; leave by the other.
        if remapped[(entered / 3) as usize][(entered % 3) as usize] == v {
            prev_corner(entered)
        } else {
            next_corner(entered)
        }
    };
    for v in 0..nv {
        let start = start_corner[v];
        let (mut leave, mut steps) = (start, 0u32);
        loop {
            steps += 1;
            leave = step(leave, v as u32);
            if leave / 3 == start / 3 || steps > corners[v] {
                break;
            }
        }
        if steps != corners[v] {
            ins.non_manifold_vertices += 1;
            ins.push(BuildError::NonManifoldVertex {
                vertex: indexed.new_to_old[v],
                faces: corners[v] as usize,
                first_fan: steps as usize,
            });
        }
    }
}

/// Step 5: components, faces joined through shared edges. On a clean surface (every edge in two
/// faces, every vertex one fan) two faces are joined iff their vertices are joined along edges,
/// so the (smaller) vertex sets answer; otherwise sets over the faces, joined by the half-edge
/// pairs and by the edges in more than two faces.
fn count_components(
    indexed: &Indexed,
    edges: &mut EdgePairs,
    all_paired: bool,
    ins: &mut Inspection,
) {
    let (remapped, valid) = (&indexed.remapped, &indexed.valid);
    let (nv, nf) = (indexed.vertex_count(), remapped.len());
    let Some(f0) = valid.iter().position(|&ok| ok) else {
        return;
    };
    let by_vertex = all_paired && ins.non_manifold_vertices == 0;
    let mut face_sets;
    let sets = if by_vertex {
        &mut edges.vertex_sets
    } else {
        face_sets = UnionFind::new(nf);
        let pairs = edges.halfedge_corner.chunks_exact(2).map(|p| (p[0], p[1]));
        for (c1, c2) in pairs.chain(edges.other_joins.iter().copied()) {
            face_sets.union(c1 / 3, c2 / 3);
        }
        &mut face_sets
    };
    // The set element of a face, and the elements.
    let node = |f: usize| if by_vertex { remapped[f][0] } else { f as u32 };
    let nodes = if by_vertex { nv } else { nf };
    let roots = (0..nodes as u32)
        .filter(|&x| (by_vertex || valid[x as usize]) && sets.find(x) == x)
        .count();
    let root0 = sets.find(node(f0));
    let outside = (f0..nf).find(|&f| valid[f] && sets.find(node(f)) != root0);
    ins.components = roots;
    if let Some(face) = outside {
        ins.push(BuildError::Disconnected {
            components: roots,
            face,
        });
    }
}

/// Step 6: the orientation, by breadth-first search across the half-edge pairs, keeping the
/// majority orientation of each component; skipped when every edge already joins opposite
/// directions (the usual case). Returns per face whether it is reversed.
fn orient(
    indexed: &Indexed,
    edges: &EdgePairs,
    consistent: bool,
    ins: &mut Inspection,
) -> Vec<bool> {
    let (remapped, valid, new_to_old) = (&indexed.remapped, &indexed.valid, &indexed.new_to_old);
    let nf = remapped.len();
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
                let h = edges.corner_halfedge[3 * f + i];
                if !h.is_valid() {
                    continue;
                }
                let other_corner = edges.halfedge_corner[h.twin().idx()];
                let g = (other_corner / 3) as usize;
                let want = flip[f] ^ edges.same_direction[h.edge().idx()];
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
    flip
}

/// The next corner in the same face (corner `3f + i` is at vertex `t[i]`).
#[inline]
fn next_corner(c: u32) -> u32 {
    c - c % 3 + (c % 3 + 1) % 3
}

/// The previous corner in the same face.
#[inline]
fn prev_corner(c: u32) -> u32 {
    c - c % 3 + (c % 3 + 2) % 3
}
