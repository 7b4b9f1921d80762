//! Building the [`ClosedCover`] of triangles glued side to side, some gluings reversing
//! orientation and some sides free: the one construction behind both a triangle soup
//! ([`ClosedCover::from_triangles`], whose gluing is read from its vertex numbers) and an
//! intrinsic triangulation given by its gluing (a portalgon file of version 2, whose loops and
//! multi-edges no vertex numbering describes).
//!
//! The surface K: triangle `f` has corners `3f + i` and sides `(f, i)` from corner `i` to
//! corner `i + 1`; a *plain* gluing joins two sides running in opposite directions (start of
//! one to end of the other), a *reversed* gluing two sides running the same way (start to
//! start); a side in no pair is a boundary side. The cover D is built in three steps:
//!
//! 1. **Orientation.** A walk over the gluings gives each triangle a sign (the same across a
//!    plain gluing, the other across a reversed one); a component where two walks disagree is
//!    non-orientable. An orientable component keeps its majority orientation (ties: the
//!    orientation of its first triangle), the others their triangles as given.
//! 2. **Cones.** Each boundary side gets a cone triangle `(b, a, apex)` glued to it; the cones
//!    of consecutive sides of a boundary loop are glued along their apex sides, found by
//!    rotating around the vertex they share (a boundary vertex's corners form one fan, whose two
//!    ends are boundary sides). One apex per loop.
//! 3. **Sheets.** Each triangle (cones included) of an orientable component appears once, in
//!    the component's orientation; each triangle of a non-orientable component twice, as given
//!    (its first lift) and reversed (its mirror copy, corners `[0, 2, 1]`). A plain gluing joins
//!    copies of the same sense, a reversed one copies of opposite senses: the orientable double
//!    cover. [`SurfaceMesh::from_gluing_pieces`] glues the copies into D.
//!
//! Ids follow the soup construction's (see the [module documentation](super)): K's vertices
//! keep their labels (the lift at a vertex's first corner, in face order), the apexes follow
//! (in the order of their loop's first boundary side, in the first lifts' face and side
//! order), then the second lifts (in label order); K's faces keep their ids, the cones follow,
//! then the mirror copies. Edge `k` of D is its `k`-th glued pair of sides.

use super::{ClosedCover, Sheets};
use crate::compact::Renumbering;
use crate::error::BuildError;
use crate::gluing::Side;
use crate::ids::{EdgeId, FaceId, VertexId};
use crate::topology::SurfaceMesh;
use crate::union_find::UnionFind;

/// Triangles glued side to side (see the [module documentation](self)).
#[derive(Clone, Copy, Debug)]
pub struct TwistedGluing<'a> {
    /// The number of triangles.
    pub face_count: usize,
    /// The glued pairs of sides.
    pub pairs: &'a [(Side, Side)],
    /// Per pair, whether its two sides run the same way (an orientation-reversing gluing);
    /// empty when none does.
    pub reversed: &'a [bool],
}

/// The cover of a [`TwistedGluing`] with, per half-edge of D, the side of the closed gluing it
/// lies on: `face < face_count` a side of K, else a side of cone `face - face_count`.
#[derive(Clone, Debug)]
pub struct TwistedCover {
    /// The cover.
    pub cover: ClosedCover,
    /// The side of each half-edge of D (by half-edge id).
    pub side_of_halfedge: Vec<Side>,
}

/// The side of the copy of a triangle of sense `reversed` that side `i` of the triangle is:
/// a reversed copy has corners `[0, 2, 1]`, so side `i` is its side `2 - i`.
#[inline]
fn copy_side(reversed: bool, i: usize) -> usize {
    if reversed { 2 - i } else { i }
}

/// The corner of a triangle at corner `k` of its copy of sense `reversed`.
#[inline]
fn copy_corner(reversed: bool, k: usize) -> usize {
    if reversed { [0, 2, 1][k] } else { k }
}

impl TwistedGluing<'_> {
    fn is_reversed(&self, k: usize) -> bool {
        self.reversed.get(k).copied().unwrap_or(false)
    }

    /// Per side `3f + i`: the side glued to it and whether the gluing reverses orientation.
    ///
    /// # Errors
    /// [`BuildError::Empty`], [`BuildError::TooLarge`], [`BuildError::SideGluedTwice`] (a side
    /// out of range, glued twice or to itself).
    fn mates(&self) -> Result<Vec<Option<(u32, bool)>>, BuildError> {
        if self.face_count == 0 {
            return Err(BuildError::Empty);
        }
        if 6 * self.face_count >= u32::MAX as usize / 2 {
            return Err(BuildError::TooLarge { what: "faces" });
        }
        let mut mate = vec![None; 3 * self.face_count];
        for (k, &(s, t)) in self.pairs.iter().enumerate() {
            for side in [s, t] {
                let bad = side.face as usize >= self.face_count || side.side > 2;
                if bad || s == t || mate[index(side)].is_some() {
                    return Err(BuildError::SideGluedTwice {
                        face: side.face as usize,
                        side: side.side as usize,
                    });
                }
                let other = if side == s { t } else { s };
                mate[index(side)] = Some((index(other) as u32, self.is_reversed(k)));
            }
        }
        Ok(mate)
    }

    /// The vertex of each corner (`3f + i`) as the gluing identifies corners, numbered in order
    /// of first corner, and the vertex count. A plain gluing of sides `(f, i)` and `(g, j)`
    /// identifies corner `i` of f with corner `j + 1` of g and `i + 1` with `j`; a reversed one
    /// `i` with `j` and `i + 1` with `j + 1`. O(n α(n)).
    ///
    /// # Errors
    /// As the pairs are checked: [`BuildError::Empty`], [`BuildError::SideGluedTwice`].
    pub fn corner_vertices(&self) -> Result<(Vec<u32>, usize), BuildError> {
        let mate = self.mates()?;
        let mut sets = UnionFind::new(3 * self.face_count);
        for (s, m) in mate.iter().enumerate() {
            if let Some((t, reversed)) = *m {
                let (s, t) = (s as u32, t);
                let (s1, t1) = (next_in_face(s), next_in_face(t));
                if reversed {
                    sets.union(s, t);
                    sets.union(s1, t1);
                } else {
                    sets.union(s, t1);
                    sets.union(s1, t);
                }
            }
        }
        let mut id = vec![u32::MAX; 3 * self.face_count];
        let mut count = 0u32;
        let vertex = (0..3 * self.face_count as u32)
            .map(|c| {
                let r = sets.find(c) as usize;
                if id[r] == u32::MAX {
                    id[r] = count;
                    count += 1;
                }
                id[r]
            })
            .collect();
        Ok((vertex, count as usize))
    }
}

/// Side (or corner) `3f + i` as an index.
#[inline]
fn index(s: Side) -> usize {
    3 * s.face as usize + s.side as usize
}

/// The next side (corner) of the same triangle.
#[inline]
fn next_in_face(c: u32) -> u32 {
    c - c % 3 + (c % 3 + 1) % 3
}

fn side(c: usize) -> Side {
    Side {
        face: (c / 3) as u32,
        side: (c % 3) as u8,
    }
}

/// Step 1: per triangle, whether its first lift is reversed; per triangle, whether its
/// component is doubled (non-orientable).
fn orient(face_count: usize, mate: &[Option<(u32, bool)>]) -> (Vec<bool>, Vec<bool>) {
    let mut sign = vec![false; face_count];
    let mut seen = vec![false; face_count];
    let mut doubled = vec![false; face_count];
    let mut queue = Vec::new();
    for start in 0..face_count {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        queue.clear();
        queue.push(start);
        let (mut head, mut orientable) = (0, true);
        while head < queue.len() {
            let f = queue[head];
            head += 1;
            for i in 0..3 {
                let Some((t, reversed)) = mate[3 * f + i] else {
                    continue;
                };
                let g = t as usize / 3;
                let want = sign[f] ^ reversed;
                if !seen[g] {
                    seen[g] = true;
                    sign[g] = want;
                    queue.push(g);
                } else if sign[g] != want {
                    orientable = false;
                }
            }
        }
        if !orientable {
            for &f in &queue {
                doubled[f] = true;
                sign[f] = false;
            }
        } else if 2 * queue.iter().filter(|&&f| sign[f]).count() > queue.len() {
            for &f in &queue {
                sign[f] = !sign[f];
            }
        }
    }
    (sign, doubled)
}

/// The cones of step 2: cone k is triangle `face_count + k`, corners `(b, a, apex)` for the
/// side from a to b of K (as given) under it: its side 0 glued plainly to that side, side 1
/// from a to the apex, side 2 from the apex to b.
struct Cones {
    /// The side of K under each cone (`3f + i`).
    sides: Vec<u32>,
    /// The pairs gluing the cones to K and to each other.
    pairs: Vec<(Side, Side)>,
    /// Per pair, whether it reverses orientation.
    reversed: Vec<bool>,
}

/// Step 2: the cone of each boundary side, in the first lifts' face and side order.
fn cones(
    face_count: usize,
    mate: &[Option<(u32, bool)>],
    sign: &[bool],
) -> Result<Cones, BuildError> {
    let mut cone_of = vec![u32::MAX; 3 * face_count];
    let mut cone = Vec::new();
    for (f, &sense) in sign.iter().enumerate().take(face_count) {
        for k in 0..3 {
            let s = 3 * f + copy_side(sense, k);
            if mate[s].is_none() {
                cone_of[s] = cone.len() as u32;
                cone.push(s as u32);
            }
        }
    }
    let cone_side = |k: u32, i: u8| Side {
        face: face_count as u32 + k,
        side: i,
    };
    let mut pairs = Vec::with_capacity(2 * cone.len());
    let mut reversed = Vec::with_capacity(2 * cone.len());
    for (k, &s) in cone.iter().enumerate() {
        pairs.push((cone_side(k as u32, 0), side(s as usize)));
        reversed.push(false);
    }
    // Cone k's side 1 lies at the start of its side of K, side 2 at the end; each apex side is
    // glued once, to the apex side of the cone at the other end of the vertex's fan.
    let mut glued = vec![false; 3 * cone.len()];
    for (k, &s) in cone.iter().enumerate() {
        for at_start in [false, true] {
            let (x, x_reversed) = around_fan(mate, s, at_start).ok_or_else(|| {
                let s = side(s as usize);
                BuildError::SideUnglued {
                    face: s.face as usize,
                    side: s.side as usize,
                }
            })?;
            let other = cone_of[x as usize];
            let mine = 3 * k + if at_start { 1 } else { 2 };
            let theirs = 3 * other as usize + if x_reversed { 2 } else { 1 };
            if glued[mine] || glued[theirs] {
                continue;
            }
            glued[mine] = true;
            glued[theirs] = true;
            pairs.push((
                cone_side(k as u32, (mine % 3) as u8),
                cone_side(other, (theirs % 3) as u8),
            ));
            reversed.push(at_start != x_reversed);
        }
    }
    Ok(Cones {
        sides: cone,
        pairs,
        reversed,
    })
}

/// The boundary side at the other end of a boundary vertex's fan: rotates around the end of
/// boundary side `s` (its start when `at_start`), in the sense of the copy of s's triangle in
/// which s enters that vertex (reversed when `at_start`), crossing each glued side into the
/// copy of the next triangle (of the other sense across a reversed gluing), until a boundary
/// side leaves the vertex. Returns it and whether its copy is reversed (then it enters the
/// vertex as given). `None` after more steps than sides (not a gluing of a surface).
fn around_fan(mate: &[Option<(u32, bool)>], s: u32, at_start: bool) -> Option<(u32, bool)> {
    let (mut entering, mut reversed) = (s, at_start);
    for _ in 0..=mate.len() {
        let leaving = if reversed {
            entering - entering % 3 + (entering % 3 + 2) % 3
        } else {
            next_in_face(entering)
        };
        match mate[leaving as usize] {
            None => return Some((leaving, reversed)),
            Some((t, r)) => {
                entering = t;
                reversed ^= r;
            }
        }
    }
    None
}

/// The labels of the closed gluing's corners ([`ClosedCover::from_twisted_gluing`]): K's
/// `labels` for its `n` triangles, then a cone `(b, a, apex)` over each boundary side `a -> b`
/// of `cone` takes b's and a's labels and its loop's apex label (`vertex_count` + the loop's
/// rank; the cones of one boundary loop are glued to each other by `cone_pairs`). Returns the
/// labels and the number of apexes.
fn closed_labels(
    n: usize,
    cone: &[u32],
    cone_pairs: &[(Side, Side)],
    labels: &[u32],
    vertex_count: usize,
) -> (Vec<u32>, u32) {
    let mut loops = UnionFind::new(cone.len());
    for &(s, t) in cone_pairs {
        if s.face as usize >= n && t.face as usize >= n {
            loops.union(s.face - n as u32, t.face - n as u32);
        }
    }
    let mut apex_of_root = vec![u32::MAX; cone.len()];
    let mut apexes = 0u32;
    let mut label = labels.to_vec();
    for (k, &s) in cone.iter().enumerate() {
        let root = loops.find(k as u32) as usize;
        if apex_of_root[root] == u32::MAX {
            apex_of_root[root] = vertex_count as u32 + apexes;
            apexes += 1;
        }
        let (a, b) = (labels[s as usize], labels[next_in_face(s) as usize]);
        label.extend([b, a, apex_of_root[root]]);
    }
    (label, apexes)
}

/// The vertex ids of the cover ([`ClosedCover::from_twisted_gluing`]), from the vertex of each
/// corner (`corner_vertex`) and its class (`corner_class`, `0..classes`): the lift at each
/// class's first corner (first lifts in face order) keeps the class; the other lifts follow, in
/// class order. Returns the new id of each of the `slots` vertices and the class of each new
/// id; `None` when that does not number the vertices `0..slots` (labels that are no bijection
/// of the gluing's vertices).
fn lift_ids(
    corner_vertex: &[VertexId],
    slots: usize,
    classes: usize,
    corner_class: impl Fn(usize) -> u32,
) -> Option<(Vec<VertexId>, Vec<u32>)> {
    let mut first = vec![VertexId::INVALID; classes];
    let mut class = vec![u32::MAX; slots];
    for (c, &v) in corner_vertex.iter().enumerate() {
        let k = corner_class(c);
        class[v.idx()] = k;
        if !first[k as usize].is_valid() {
            first[k as usize] = v;
        }
    }
    let mut second = vec![u32::MAX; classes];
    let mut next_id = classes as u32;
    let mut has_second = vec![false; classes];
    for (v, &k) in class.iter().enumerate() {
        if first[k as usize] != VertexId::new(v) {
            has_second[k as usize] = true;
        }
    }
    for k in 0..classes {
        if has_second[k] {
            second[k] = next_id;
            next_id += 1;
        }
    }
    let vertices: Vec<VertexId> = (0..slots)
        .map(|v| {
            let k = class[v] as usize;
            VertexId(if first[k] == VertexId::new(v) {
                k as u32
            } else {
                second[k]
            })
        })
        .collect();
    if next_id as usize != slots {
        return None;
    }
    let mut sheet_class: Vec<u32> = (0..next_id).collect();
    for k in 0..classes {
        if has_second[k] {
            sheet_class[second[k] as usize] = k as u32;
        }
    }
    Some((vertices, sheet_class))
}

impl ClosedCover {
    /// The cover of the surface K of a [`TwistedGluing`] (see the [module
    /// documentation](self)), K's vertex at corner `3f + i` being `labels[3f + i]`: the
    /// vertices of [`TwistedGluing::corner_vertices`] under a bijection onto
    /// `0..vertex_count` (the caller checks it; a soup's vertex ids are such labels once
    /// the soup is a manifold). O(n α(n)).
    ///
    /// # Errors
    /// As [`TwistedGluing::corner_vertices`].
    pub fn from_twisted_gluing(
        gluing: &TwistedGluing<'_>,
        labels: &[u32],
        vertex_count: usize,
    ) -> Result<TwistedCover, BuildError> {
        let n = gluing.face_count;
        let mate = gluing.mates()?;
        let (mut sign, mut doubled) = orient(n, &mate);
        let Cones {
            sides: cone,
            pairs: cone_pairs,
            reversed: cone_reversed,
        } = cones(n, &mate, &sign)?;
        // The closed gluing: K's pairs, then the cones'.
        let pairs: Vec<(Side, Side)> = gluing.pairs.iter().chain(&cone_pairs).copied().collect();
        let reversed: Vec<bool> = (0..gluing.pairs.len())
            .map(|k| gluing.is_reversed(k))
            .chain(cone_reversed)
            .collect();
        let total = n + cone.len();
        for &s in &cone {
            let f = s as usize / 3;
            sign.push(sign[f]);
            doubled.push(doubled[f]);
        }
        let (label, apexes) = closed_labels(n, &cone, &cone_pairs, labels, vertex_count);
        let classes = vertex_count + apexes as usize;
        // Step 3: the copies, first lifts then mirror copies.
        let mut mirror_face = vec![u32::MAX; total];
        let mut faces = total as u32;
        for f in 0..total {
            if doubled[f] {
                mirror_face[f] = faces;
                faces += 1;
            }
        }
        let copy_face = |f: usize, reversed: bool| {
            if reversed == sign[f] {
                f as u32
            } else {
                mirror_face[f]
            }
        };
        let mut copy_sense = vec![false; faces as usize];
        let mut copy_of = vec![0u32; faces as usize];
        for f in 0..total {
            copy_sense[f] = sign[f];
            copy_of[f] = f as u32;
            if doubled[f] {
                copy_sense[mirror_face[f] as usize] = !sign[f];
                copy_of[mirror_face[f] as usize] = f as u32;
            }
        }
        let mut d_pairs = Vec::with_capacity(2 * pairs.len());
        let mut side_of_halfedge = Vec::with_capacity(4 * pairs.len());
        for (k, &(s, t)) in pairs.iter().enumerate() {
            let f = s.face as usize;
            let senses = [Some(sign[f]), doubled[f].then_some(!sign[f])];
            for sense in senses.into_iter().flatten() {
                let other = sense ^ reversed[k];
                let copy = |x: Side, sense: bool| Side {
                    face: copy_face(x.face as usize, sense),
                    side: copy_side(sense, x.side as usize) as u8,
                };
                d_pairs.push((copy(s, sense), copy(t, other)));
                side_of_halfedge.extend([s, t]);
            }
        }
        let (mut mesh, corner_vertex) = SurfaceMesh::from_gluing_pieces(faces as usize, &d_pairs)?;
        // Vertex ids: the lift at each class's first corner (first lifts in face order) keeps
        // the class; the other lifts follow, in class order.
        let corner_class = |c: usize| {
            let f = c / 3;
            let original = copy_of[f] as usize;
            label[3 * original + copy_corner(copy_sense[f], c % 3)]
        };
        let slots = mesh.vertex_slots();
        let Some((vertices, mut sheet_class)) =
            lift_ids(&corner_vertex, slots, classes, corner_class)
        else {
            // Labels that are no bijection of the gluing's vertices (a caller's error).
            return Err(BuildError::NotAsGiven {
                reoriented_faces: 0,
                dropped_vertices: 0,
            });
        };
        let map = Renumbering {
            edges: (0..mesh.edge_slots()).map(EdgeId::new).collect(),
            faces: (0..mesh.face_slots()).map(FaceId::new).collect(),
            vertices,
        };
        mesh.renumber(&map);
        for c in sheet_class
            .iter_mut()
            .filter(|c| **c as usize >= vertex_count)
        {
            *c = vertex_count as u32;
        }
        let lift = (0..vertex_count as u32)
            .chain((apexes > 0).then_some(vertex_count as u32))
            .map(VertexId)
            .collect();
        let mut sheets = Sheets {
            class: sheet_class,
            lift,
            mirror: Vec::new(),
            apex: (apexes > 0).then_some(vertex_count as u32),
        };
        // Mirrors: side k of a first lift and side 2 - k of its mirror copy. Face f of D stores
        // the half-edge of its side 0.
        for f in (0..total).filter(|&f| doubled[f]) {
            let m = FaceId(mirror_face[f]);
            let theirs = mesh.face_halfedges(m);
            for (k, h) in mesh.face_halfedges(FaceId::new(f)).into_iter().enumerate() {
                sheets.set_mirror(h, theirs[2 - k]);
            }
        }
        Ok(TwistedCover {
            cover: ClosedCover { mesh, sheets },
            side_of_halfedge,
        })
    }
}
