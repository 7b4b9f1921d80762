//! The tufted cover of a triangle soup (Sharp & Crane 2020, Section 4.2): every face gets two
//! sides, and around every edge the face-sides are glued in the cyclic order of the faces around
//! the edge in space, which makes a closed oriented surface.
//!
//! Cover face `2f` is input face `f` as given (its *front*), `2f + 1` the same triangle reversed
//! (its *back*: corners `v0, v2, v1`, so front side `i` is back side `2 - i`). Around an edge,
//! directed as the side of its first face (the lowest index) runs (`d`), a face-side runs
//! *along* `d` or *against* it; the front and back of a face run opposite ways. The faces of the edge are
//! sorted clockwise around `d` (by decreasing angle of their third vertex in a right-handed
//! frame `(b0, b1, d)`), then the side of face `i` running against `d` is glued to the side of
//! face `i + 1` running along `d`, cyclically: each gluing pairs opposite directions, so the
//! cover is oriented, and each face-side is glued once on each edge, so it is closed.
//!
//! The paper lets the order be any (its Section 4.2: every order gives a valid cover); the
//! geometric one is the paper's and geometry-central's (`buildIntrinsicTuftedCover`, which
//! `robust_laplacian` runs), so the cover is the same surface as theirs. Faces at the same angle
//! (duplicate faces, or third vertices on one half-plane) are ordered as geometry-central lists
//! an edge's halfedges before its sort, which keeps that order for up to 16 faces (an insertion
//! sort): the first face, then the others in decreasing face index. The order of equal angles
//! matters: it changes the cover's topology, and then its Laplacian. Reversing
//! `d` reverses the cyclic order and swaps along and against, which gives the same gluing when
//! no two faces are at the same angle; with ties it does not (the order of the tied faces is not
//! reversed), so `d` is geometry-central's too (its edge's first halfedge). One face on an edge (a fin) glues its front to its back; two faces need
//! no sort (a cyclic order of two is unique).
//!
//! Vertices of the cover are the orbits of corners ([`SurfaceMesh::from_gluing_pieces`]): a
//! pinched input vertex, or any vertex whose faces make several fans on the cover, has one cover
//! vertex per fan, each mapped back to the input vertex.

use surftopo_mesh::geometry::{Point3, distance};
use surftopo_mesh::{BuildError, Side, SurfaceMesh};

/// The tufted cover's topology, its edge lengths, and the input vertex of each cover vertex.
pub(crate) struct Cover {
    /// The closed oriented cover (possibly in several pieces).
    pub mesh: SurfaceMesh,
    /// Length of each cover edge: the 3D length of its input edge.
    pub lengths: Vec<f64>,
    /// Input vertex of each cover vertex.
    pub input_vertex: Vec<u32>,
    /// Distinct input edges (for the mollification's mean).
    pub input_edges: usize,
    /// Sum of the input edges' lengths.
    pub input_length_sum: f64,
    /// Input edges with one face (fins).
    pub fin_edges: usize,
    /// Input edges with three faces or more (books).
    pub book_edges: usize,
}

/// Side `i` of cover face `face`.
fn side(face: usize, i: usize) -> Side {
    Side {
        face: face as u32,
        side: i as u8,
    }
}

/// The tufted cover of `triangles` over `positions` (indices checked by the caller, no repeated
/// vertex in a face). O(F log d), d the largest number of faces on an edge.
///
/// # Errors
/// [`BuildError::TooLarge`] beyond `u32` ids (from the gluing).
pub(crate) fn tufted_cover(
    positions: &[Point3],
    triangles: &[[u32; 3]],
) -> Result<Cover, BuildError> {
    let n = positions.len();
    let sides = 3 * triangles.len();
    if sides >= u32::MAX as usize / 4 {
        return Err(BuildError::TooLarge { what: "faces" });
    }
    let ends = |s: usize| {
        let t = &triangles[s / 3];
        (t[s % 3], t[(s % 3 + 1) % 3])
    };
    // Face sides bucketed by their smaller end (a counting sort), each bucket then sorted by the
    // larger end and the side, as the integers `hi << 32 | s`: each edge's sides become a run.
    let mut start = vec![0u32; n + 1];
    for t in triangles {
        for i in 0..3 {
            start[t[i].min(t[(i + 1) % 3]) as usize + 1] += 1;
        }
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut by_edge = vec![0u64; sides];
    let mut fill = start[..n].to_vec();
    for (f, t) in triangles.iter().enumerate() {
        for i in 0..3 {
            let (u, w) = (t[i], t[(i + 1) % 3]);
            let lo = u.min(w) as usize;
            by_edge[fill[lo] as usize] = u64::from(u.max(w)) << 32 | (3 * f + i) as u64;
            fill[lo] += 1;
        }
    }
    drop(fill);
    let side_of = |key: u64| key as u32;
    let hi_of = |key: u64| (key >> 32) as u32;
    // Glue each run.
    let mut pairs: Vec<(Side, Side)> = Vec::with_capacity(sides);
    let mut lengths: Vec<f64> = Vec::with_capacity(sides);
    let (mut input_edges, mut input_length_sum) = (0usize, 0.0f64);
    let (mut fin_edges, mut book_edges) = (0usize, 0usize);
    let mut ring: Vec<(f64, u32)> = Vec::new();
    let mut run: Vec<u32> = Vec::new();
    for lo in 0..n {
        let bucket = &mut by_edge[start[lo] as usize..start[lo + 1] as usize];
        bucket.sort_unstable();
        let mut k = 0;
        while k < bucket.len() {
            let hi = hi_of(bucket[k]);
            let mut end = k + 1;
            while end < bucket.len() && hi_of(bucket[end]) == hi {
                end += 1;
            }
            run.clear();
            run.extend(bucket[k..end].iter().map(|&key| side_of(key)));
            k = end;
            let first = run[0];
            let (u, w) = ends(first as usize);
            let lo = lo as u32;
            let length = distance(positions[lo as usize], positions[hi as usize]);
            input_edges += 1;
            input_length_sum += length;
            // d runs as the first face's side (u -> w). The side of face-side s's face that runs
            // along d and the one against it.
            let along_against = |s: u32| {
                let (f, i) = (s as usize / 3, s as usize % 3);
                let (front, back) = (side(2 * f, i), side(2 * f + 1, 2 - i));
                if ends(s as usize).0 == u {
                    (front, back)
                } else {
                    (back, front)
                }
            };
            ring.clear();
            if run.len() >= 3 {
                book_edges += 1;
                let angle = frame_angle(positions, u, w);
                // The faces in geometry-central's order of an edge's halfedges (the first face,
                // then the others from the last), then a stable sort clockwise around d
                // (decreasing angle): faces at the same angle keep that order.
                let order = run[..1].iter().chain(run[1..].iter().rev());
                ring.extend(order.map(|&s| {
                    let t = &triangles[s as usize / 3];
                    (angle(t[(s as usize % 3 + 2) % 3]), s)
                }));
                ring.sort_by(|a, b| b.0.total_cmp(&a.0));
            } else {
                fin_edges += usize::from(run.len() == 1);
                ring.extend(run.iter().map(|&s| (0.0, s)));
            }
            for j in 0..ring.len() {
                let against = along_against(ring[j].1).1;
                let along = along_against(ring[(j + 1) % ring.len()].1).0;
                pairs.push((against, along));
                lengths.push(length);
            }
        }
    }
    let (mesh, corner_vertex) = SurfaceMesh::from_gluing_pieces(2 * triangles.len(), &pairs)?;
    let mut input_vertex = vec![u32::MAX; mesh.vertex_slots()];
    for (c, v) in corner_vertex.iter().enumerate() {
        let (face, i) = (c / 3, c % 3);
        let t = &triangles[face / 2];
        // The back's corners are v0, v2, v1.
        let corner = if face % 2 == 0 { i } else { [0, 2, 1][i] };
        input_vertex[v.idx()] = t[corner];
    }
    Ok(Cover {
        mesh,
        lengths,
        input_vertex,
        input_edges,
        input_length_sum,
        fin_edges,
        book_edges,
    })
}

/// The angle around `d = p[tip] - p[tail]` of a point's offset from `p[tail]`, in a right-handed
/// frame `(b0, b1, d)` (counter-clockwise seen from the tip of `d`).
fn frame_angle(positions: &[Point3], tail: u32, tip: u32) -> impl Fn(u32) -> f64 + '_ {
    let p = positions[tail as usize];
    let d = sub(positions[tip as usize], p);
    // A helper axis not parallel to d, then b0 ⟂ d and b1 = d × b0 (so b0 × b1 points along d).
    let helper = if d[0].abs() <= d[1].abs().max(d[2].abs()) {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let b0 = cross(helper, d);
    let b1 = cross(d, b0);
    move |v: u32| {
        let o = sub(positions[v as usize], p);
        dot(b1, o).atan2(dot(b0, o))
    }
}

fn sub(a: Point3, b: Point3) -> Point3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: Point3, b: Point3) -> Point3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: Point3, b: Point3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
