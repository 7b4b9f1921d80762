//! The corner pairing: a triangle soup's corners (directed edges) paired into half-edges, with
//! every problem and fact found on the way (steps 1 to 6 below).

use super::Inspection;
use crate::error::BuildError;
use crate::ids::{HalfedgeId, VertexId};
use crate::topology::SurfaceMesh;
use crate::union_find::UnionFind;
use std::borrow::Cow;

/// The pass that pairs the corners of a soup's triangles (each a directed edge) into the
/// half-edges of a mesh, with what it found on the way.
pub(crate) struct CornerPairing<'a> {
    pub(crate) inspection: Inspection,
    /// Triangles in new vertex ids (faces with bad indices are kept with `u32::MAX`); the input
    /// itself when nothing needed renumbering.
    pub(crate) remapped: Cow<'a, [[u32; 3]]>,
    /// Per face: whether its indices are valid.
    pub(crate) valid: Vec<bool>,
    pub(crate) old_to_new: Vec<VertexId>,
    pub(crate) new_to_old: Vec<u32>,
    pub(crate) dropped: Vec<u32>,
    /// The corners paired by edge.
    pub(crate) edges: EdgePairs,
    /// Whether each face is reversed by the orientation (the majority orientation of each
    /// orientable component).
    pub(crate) flip: Vec<bool>,
    /// What keeps the faces from being one closed oriented surface although they form a surface,
    /// each reported once in order of discovery: the first boundary edge, the components, the
    /// first orientation conflict.
    refusals: Vec<BuildError>,
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
pub(crate) struct EdgePairs {
    /// Half-edge id of each corner (`INVALID` for the corners of edges not in two faces).
    pub(crate) corner_halfedge: Vec<HalfedgeId>,
    /// Corner of each half-edge.
    pub(crate) halfedge_corner: Vec<u32>,
    /// Per edge in two faces: whether its two corners run the same way (an orientation conflict
    /// between the faces).
    pub(crate) same_direction: Vec<bool>,
    /// `around[c]`: the corner after `c` around its vertex when the orientation is consistent
    /// (the next corner, in its face, after the twin of corner `c`'s half-edge).
    around: Vec<u32>,
    /// The vertices joined along the edges.
    vertex_sets: UnionFind,
    /// Consecutive corners of the edges in more than two faces (their faces are joined too).
    other_joins: Vec<(u32, u32)>,
    /// Per vertex, whether it is on an edge in more than two faces (empty when there is none).
    on_non_manifold_edge: Vec<bool>,
}

impl<'a> CornerPairing<'a> {
    pub(crate) fn run(vertex_count: usize, triangles: &'a [[u32; 3]]) -> Self {
        let mut ins = Inspection {
            faces: triangles.len(),
            orientable: true,
            ..Inspection::default()
        };
        let mut refusals = Vec::new();
        let refused = |ins: Inspection, refusals| CornerPairing {
            inspection: ins,
            remapped: Cow::Borrowed(&[]),
            valid: Vec::new(),
            old_to_new: Vec::new(),
            new_to_old: Vec::new(),
            dropped: Vec::new(),
            edges: EdgePairs::empty(),
            flip: Vec::new(),
            refusals,
        };
        if triangles.is_empty() {
            ins.push(BuildError::Empty);
            return refused(ins, refusals);
        }
        if triangles.len().saturating_mul(3) >= (u32::MAX >> 1) as usize
            || vertex_count >= u32::MAX as usize
        {
            ins.push(BuildError::TooLarge {
                what: "faces or vertices",
            });
            return refused(ins, refusals);
        }
        // Between the steps, a stop asked for ends the work (`crate::stop`).
        let indexed = check_indices(vertex_count, triangles, &mut ins);
        crate::stop::check();
        let sorted = sort_corners(&indexed);
        crate::stop::check();
        let mut edges = pair_edges(&indexed, sorted, &mut ins, &mut refusals);
        crate::stop::check();
        let all_valid = indexed.valid.iter().all(|&ok| ok);
        let consistent = !edges.same_direction.iter().any(|&same| same);
        if all_valid {
            check_fans(&indexed, &edges, consistent, &mut ins);
        }
        crate::stop::check();
        count_components(&indexed, &mut edges, all_valid, &mut ins, &mut refusals);
        crate::stop::check();
        let flip = orient(&indexed, &edges, consistent, &mut ins, &mut refusals);
        crate::stop::check();
        CornerPairing {
            inspection: ins,
            remapped: indexed.remapped,
            valid: indexed.valid,
            old_to_new: indexed.old_to_new,
            new_to_old: indexed.new_to_old,
            dropped: indexed.dropped,
            edges,
            flip,
            refusals,
        }
    }

    /// Whether the faces form a surface (compact 2-manifold, possibly with boundary, possibly
    /// non-orientable or in pieces): every face valid, no non-manifold edge or vertex.
    pub(crate) fn is_surface(&self) -> bool {
        let ins = &self.inspection;
        !self.valid.is_empty()
            && self.valid.iter().all(|&ok| ok)
            && ins.non_manifold_edges == 0
            && ins.non_manifold_vertices == 0
    }

    /// The first problem, else the first refusal of a closed oriented mesh (components allowed
    /// when `components` is set).
    pub(crate) fn first_refusal(&self, components: bool) -> Option<BuildError> {
        let refusals = self
            .refusals
            .iter()
            .filter(|e| !(components && matches!(e, BuildError::Disconnected { .. })));
        self.inspection
            .problems
            .iter()
            .chain(refusals)
            .next()
            .cloned()
    }

    /// The triangles in new vertex ids, each reversed when [`Self::flip`] says so.
    pub(crate) fn oriented_triangles(&self) -> Vec<[u32; 3]> {
        let mut oriented = self.remapped.to_vec();
        for (t, &flip) in oriented.iter_mut().zip(&self.flip) {
            if flip {
                t.swap(1, 2);
            }
        }
        oriented
    }

    /// The half-edge arrays (requires no problems, no refusal but components, and no
    /// reorientation).
    pub(crate) fn into_mesh(self) -> SurfaceMesh {
        let corner_halfedge = &self.edges.corner_halfedge;
        let remapped = &self.remapped;
        SurfaceMesh::from_sides(
            remapped.len(),
            self.new_to_old.len(),
            |f, i| corner_halfedge[3 * f + i],
            |f, i| VertexId(remapped[f][i]),
        )
    }

    /// The vertex (new id) at corner `c`.
    #[inline]
    pub(crate) fn corner_vertex(&self, c: u32) -> u32 {
        self.remapped[(c / 3) as usize][(c % 3) as usize]
    }
}

impl EdgePairs {
    fn empty() -> Self {
        EdgePairs {
            corner_halfedge: Vec::new(),
            halfedge_corner: Vec::new(),
            same_direction: Vec::new(),
            around: Vec::new(),
            vertex_sets: UnionFind::new(0),
            other_joins: Vec::new(),
            on_non_manifold_edge: Vec::new(),
        }
    }

    /// The corner of the other face on corner `c`'s edge, `None` when the edge is not in two
    /// faces.
    #[inline]
    pub(crate) fn across(&self, c: u32) -> Option<u32> {
        let h = self.corner_halfedge[c as usize];
        h.is_valid().then(|| self.halfedge_corner[h.twin().idx()])
    }

    /// Whether the two faces on corner `c`'s edge (which must be in two faces) run it the same
    /// way.
    #[inline]
    pub(crate) fn same_direction_at(&self, c: u32) -> bool {
        self.same_direction[self.corner_halfedge[c as usize].edge().idx()]
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
fn pair_edges(
    indexed: &Indexed,
    corners: SortedCorners,
    ins: &mut Inspection,
    refusals: &mut Vec<BuildError>,
) -> EdgePairs {
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
        on_non_manifold_edge: Vec::new(),
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
                    if ins.boundary_edges == 0 {
                        refusals.push(BuildError::BoundaryEdge { edge: edge(), face });
                    }
                    ins.boundary_edges += 1;
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
                    if pairs.on_non_manifold_edge.is_empty() {
                        pairs.on_non_manifold_edge = vec![false; nv];
                    }
                    pairs.on_non_manifold_edge[v] = true;
                    pairs.on_non_manifold_edge[hi as usize] = true;
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

/// Step 4, when every face is valid: the faces around each vertex must form one fan, closed
/// (a cycle) or open (a path between two boundary edges); the walk ignores orientation and stops
/// at edges not in two faces. Vertices on edges in more than three faces are left to those
/// edges' reports.
fn check_fans(indexed: &Indexed, edges: &EdgePairs, consistent: bool, ins: &mut Inspection) {
    let (remapped, nv) = (&indexed.remapped, indexed.vertex_count());
    // Corner count and one corner of each vertex.
    let mut corners = vec![0u32; nv];
    let mut start_corner = vec![u32::MAX; nv];
    for (c, &v) in remapped.iter().flatten().enumerate() {
        corners[v as usize] += 1;
        start_corner[v as usize] = c as u32;
    }
    let closed = ins.boundary_edges == 0 && ins.non_manifold_edges == 0;
    // The corner whose edge the walk around vertex v crosses after crossing `leave`'s edge, or
    // `None` at an edge not in two faces. The two edges of a face at v are those of its corner
    // at v (leaving v) and of the previous corner (entering v): the walk enters a face through
    // one and leaves through the other, whatever the faces' orientations; with a consistent
    // orientation, `forward` (leaving by a corner at v) that is `around` (`u32::MAX` at an edge
    // not in two faces).
    let step = |leave: u32, v: u32, forward: bool| -> Option<u32> {
        if consistent && closed {
            return Some(edges.around[leave as usize]);
        }
        if consistent && forward {
            let c = edges.around[leave as usize];
            return (c != u32::MAX).then_some(c);
        }
        let entered = edges.across(leave)?;
        // `entered` is one of the two corners at v in the next face; leave by the other.
        Some(
            if remapped[(entered / 3) as usize][(entered % 3) as usize] == v {
                prev_corner(entered)
            } else {
                next_corner(entered)
            },
        )
    };
    for v in 0..nv {
        if edges.on_non_manifold_edge.get(v).copied().unwrap_or(false) {
            continue;
        }
        let start = start_corner[v];
        let (mut leave, mut steps, mut open) = (start, 1u32, false);
        loop {
            match step(leave, v as u32, true) {
                None => {
                    open = true;
                    break;
                }
                Some(c) if c / 3 == start / 3 => break,
                Some(c) => leave = c,
            }
            steps += 1;
            if steps > corners[v] {
                break;
            }
        }
        if open {
            // The other way from the start face, through its edge entering v.
            leave = prev_corner(start);
            while steps <= corners[v] {
                match step(leave, v as u32, false) {
                    Some(c) if c / 3 != start / 3 => leave = c,
                    _ => break,
                }
                steps += 1;
            }
        }
        if steps != corners[v] {
            ins.non_manifold_vertices += 1;
            ins.push(BuildError::NonManifoldVertex {
                vertex: indexed.new_to_old[v],
                faces: corners[v] as usize,
                first_fan: steps.min(corners[v]) as usize,
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
    all_valid: bool,
    ins: &mut Inspection,
    refusals: &mut Vec<BuildError>,
) {
    let (remapped, valid) = (&indexed.remapped, &indexed.valid);
    let (nv, nf) = (indexed.vertex_count(), remapped.len());
    let Some(f0) = valid.iter().position(|&ok| ok) else {
        return;
    };
    let by_vertex = all_valid && ins.non_manifold_edges == 0 && ins.non_manifold_vertices == 0;
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
        refusals.push(BuildError::Disconnected {
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
    refusals: &mut Vec<BuildError>,
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
                    refusals.push(BuildError::NonOrientable {
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
pub(crate) fn next_corner(c: u32) -> u32 {
    c - c % 3 + (c % 3 + 1) % 3
}

/// The previous corner in the same face.
#[inline]
pub(crate) fn prev_corner(c: u32) -> u32 {
    c - c % 3 + (c % 3 + 2) % 3
}
