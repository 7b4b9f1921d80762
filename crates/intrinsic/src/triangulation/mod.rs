//! Intrinsic triangulations: half-edge topology plus one length per edge.
//!
//! A triangular portalgon (Dubois, Section 2.1) whose surface is closed is stored as a
//! [`SurfaceMesh`] (loops and multi-edges allowed) and a `Vec<f64>` of edge lengths indexed by
//! [`EdgeId`]. The triangles are known up to isometry from their three lengths, which is all the
//! flip algorithm needs; [`IntrinsicTriangulation::layout_face`] places one in the plane when
//! coordinates are wanted (portalgon output).
//!
//! Conventions: side `i` of face `f` is `mesh.face_halfedges(f)[i]`, from corner `i` to corner
//! `i + 1`; the *corner* of a half-edge `h` is the corner at `origin(h)` in `face(h)`.

pub(crate) mod convert;
pub(crate) mod mollify;
pub(crate) mod quality;
pub(crate) mod trig;

use crate::error::{GeometryError, SoupError};
use crate::geometry::Tolerances;
use surftopo_mesh::geometry::{Point3, check_finite, edge_lengths};
use surftopo_mesh::{BuildReport, EdgeId, FaceId, HalfedgeId, SurfaceMesh, VertexId};
use trig::Quad;

/// An intrinsic triangulation of a closed surface: topology and edge lengths.
#[derive(Clone, Debug, PartialEq)]
pub struct IntrinsicTriangulation {
    mesh: SurfaceMesh,
    lengths: Vec<f64>,
}

impl IntrinsicTriangulation {
    /// Wraps a mesh and its edge lengths (indexed by edge id; entries of removed edges ignored).
    ///
    /// Checks only that there is one length per edge slot and that live lengths are finite; call
    /// [`Self::validate`] for positivity and the triangle inequalities (the Delaunay algorithm does,
    /// after mollifying if asked).
    ///
    /// # Errors
    /// [`GeometryError::LengthCount`], [`GeometryError::NonFiniteLength`].
    pub fn from_parts(mesh: SurfaceMesh, lengths: Vec<f64>) -> Result<Self, GeometryError> {
        if lengths.len() != mesh.edge_slots() {
            return Err(GeometryError::LengthCount {
                lengths: lengths.len(),
                edge_slots: mesh.edge_slots(),
            });
        }
        if let Some(e) = mesh.edges().find(|e| !lengths[e.idx()].is_finite()) {
            return Err(GeometryError::NonFiniteLength {
                edge: e.0,
                value: lengths[e.idx()],
            });
        }
        Ok(Self { mesh, lengths })
    }

    /// The intrinsic triangulation of a mesh in space: lengths are the 3D edge lengths.
    ///
    /// # Errors
    /// As [`Self::from_parts`] (non-finite lengths from huge coordinates).
    pub fn from_positions(mesh: SurfaceMesh, positions: &[Point3]) -> Result<Self, GeometryError> {
        let lengths = edge_lengths(&mesh, positions);
        Self::from_parts(mesh, lengths)
    }

    /// Builds the mesh of a triangle soup ([`surftopo_mesh::build()`]: closed, connected,
    /// orientable, no repeated vertex in a face) and takes its 3D edge lengths. Vertex ids follow
    /// [`BuildReport::vertex_old_to_new`]; face ids are the input face indices.
    ///
    /// # Errors
    /// [`SoupError::Build`] (naming the face, edge or vertex), [`SoupError::Geometry`].
    pub fn from_soup(
        positions: &[Point3],
        triangles: &[[u32; 3]],
    ) -> Result<(Self, BuildReport), SoupError> {
        check_finite(positions)?;
        let (mesh, report) = surftopo_mesh::build(positions.len(), triangles)?;
        let mut kept = vec![[0.0; 3]; mesh.vertex_slots()];
        for (old, new) in report.vertex_old_to_new.iter().enumerate() {
            if new.is_valid() {
                kept[new.idx()] = positions[old];
            }
        }
        Ok((Self::from_positions(mesh, &kept)?, report))
    }

    /// The topology.
    #[inline]
    pub fn mesh(&self) -> &SurfaceMesh {
        &self.mesh
    }
    /// The lengths, indexed by edge id.
    #[inline]
    pub fn lengths(&self) -> &[f64] {
        &self.lengths
    }
    /// Consumes the triangulation into its mesh and lengths.
    pub fn into_parts(self) -> (SurfaceMesh, Vec<f64>) {
        (self.mesh, self.lengths)
    }
    /// Mutable access to both parts, for edits that keep them consistent (crate only).
    pub(crate) fn parts_mut(&mut self) -> (&mut SurfaceMesh, &mut Vec<f64>) {
        (&mut self.mesh, &mut self.lengths)
    }

    /// Length of an edge.
    #[inline(always)]
    pub fn length(&self, e: EdgeId) -> f64 {
        self.lengths[e.idx()]
    }
    /// Length of the edge of a half-edge.
    #[inline(always)]
    pub fn halfedge_length(&self, h: HalfedgeId) -> f64 {
        self.lengths[h.edge().idx()]
    }

    /// Side lengths of a face, side `i` being `face_halfedges(f)[i]`.
    #[inline]
    pub fn face_sides(&self, f: FaceId) -> [f64; 3] {
        self.mesh.face_halfedges(f).map(|h| self.halfedge_length(h))
    }

    /// The five lengths around the edge of `h` (see [`Quad`]), seen from `h = a -> b`.
    #[inline]
    pub(crate) fn quad(&self, h: HalfedgeId) -> Quad {
        let m = &self.mesh;
        let t = h.twin();
        Quad {
            ab: self.halfedge_length(h),
            bc: self.halfedge_length(m.next(h)),
            ca: self.halfedge_length(m.prev(h)),
            ad: self.halfedge_length(m.next(t)),
            db: self.halfedge_length(m.prev(t)),
        }
    }

    /// `tan²(θ/2)` of the angle θ opposite half-edge `h` in its face.
    #[inline]
    pub fn tan_half_sq_opposite(&self, h: HalfedgeId) -> f64 {
        let m = &self.mesh;
        trig::tan_half_sq(
            self.halfedge_length(h),
            self.halfedge_length(m.next(h)),
            self.halfedge_length(m.prev(h)),
        )
    }
    /// The angle opposite half-edge `h` in its face.
    #[inline]
    pub fn angle_opposite(&self, h: HalfedgeId) -> f64 {
        2.0 * self.tan_half_sq_opposite(h).sqrt().atan()
    }
    /// The cotangent of the angle opposite half-edge `h` in its face.
    #[inline]
    pub fn cot_opposite(&self, h: HalfedgeId) -> f64 {
        trig::cot_from_tan_half_sq(self.tan_half_sq_opposite(h))
    }
    /// The angle of the corner of `h` (at `origin(h)` in `face(h)`).
    #[inline]
    pub fn corner_angle(&self, h: HalfedgeId) -> f64 {
        self.angle_opposite(self.mesh.next(h))
    }

    /// `tan²` of the half angle opposite every half-edge (indexed by half-edge id, NaN for
    /// removed ones), one pass over the faces (Kahan's formulas, from the three lengths of each).
    pub fn halfedge_tan_half_sq(&self) -> Vec<f64> {
        let mut t2 = vec![f64::NAN; self.mesh.halfedge_slots()];
        for f in self.mesh.faces() {
            self.store_face_tan_half_sq(f, &mut t2);
        }
        t2
    }

    /// Stores the three half-angle tangents squared of face `f` into `t2` (by half-edge id);
    /// returns the smallest Kahan factor (positive iff the face is a valid triangle).
    #[inline]
    pub(crate) fn store_face_tan_half_sq(&self, f: FaceId, t2: &mut [f64]) -> f64 {
        let hs = self.mesh.face_halfedges(f);
        store_tan_half_sq(hs, hs.map(|h| self.halfedge_length(h)), t2)
    }

    /// Area of a face (Kahan's formula).
    #[inline]
    pub fn face_area(&self, f: FaceId) -> f64 {
        let [a, b, c] = self.face_sides(f);
        trig::area(a, b, c)
    }
    /// Total area.
    pub fn total_area(&self) -> f64 {
        self.mesh.faces().map(|f| self.face_area(f)).sum()
    }

    /// Angle sum around each vertex, indexed by vertex id (0 for removed vertices).
    pub fn angle_sums(&self) -> Vec<f64> {
        let mut sums = vec![0.0; self.mesh.vertex_slots()];
        for h in self.mesh.halfedges() {
            sums[self.mesh.origin(h).idx()] += self.corner_angle(h);
        }
        sums
    }
    /// Angle sum around one vertex.
    pub fn angle_sum(&self, v: VertexId) -> f64 {
        self.mesh.outgoing(v).map(|h| self.corner_angle(h)).sum()
    }

    /// The Delaunay product `tan²(γ/2) tan²(δ/2)` of an edge, γ and δ its opposite angles
    /// (from the half-angle tangents, no angle computed): above 1 iff `γ + δ > π`.
    #[inline]
    pub fn delaunay_product(&self, e: EdgeId) -> f64 {
        self.quad(e.halfedge()).delaunay_product()
    }

    /// Whether an edge is locally Delaunay up to `tolerance`: `tan(γ/2) tan(δ/2) <= 1 + tolerance`
    /// (equivalently γ + δ <= π up to about `tolerance` radians).
    #[inline]
    pub fn is_delaunay_edge(&self, e: EdgeId, tolerance: f64) -> bool {
        let bound = (1.0 + tolerance) * (1.0 + tolerance);
        self.delaunay_product(e) <= bound
    }

    /// Number of live edges that are not locally Delaunay up to `tolerance`.
    pub fn non_delaunay_edges(&self, tolerance: f64) -> usize {
        self.mesh
            .edges()
            .filter(|&e| !self.is_delaunay_edge(e, tolerance))
            .count()
    }

    /// Checks every live edge length is positive and every face satisfies the strict triangle
    /// inequality (Kahan's ordered factors, so the sign of the test is exact for exact lengths).
    ///
    /// # Errors
    /// [`GeometryError::NonPositiveLength`], [`GeometryError::TriangleInequality`] or
    /// [`GeometryError::ZeroArea`], naming the first offending edge or face.
    pub fn validate(&self) -> Result<(), GeometryError> {
        for e in self.mesh.edges() {
            let value = self.length(e);
            if !value.is_finite() {
                return Err(GeometryError::NonFiniteLength { edge: e.0, value });
            }
            if value <= 0.0 {
                return Err(GeometryError::NonPositiveLength { edge: e.0, value });
            }
        }
        for f in self.mesh.faces() {
            check_triangle(f, self.face_sides(f))?;
        }
        Ok(())
    }

    /// Places face `f` in the plane: corner 0 at the origin, corner 1 on the positive x axis,
    /// counter-clockwise. Corner `i` is the origin of `face_halfedges(f)[i]`.
    pub fn layout_face(&self, f: FaceId) -> [[f64; 2]; 3] {
        let [l0, l1, l2] = self.face_sides(f);
        [[0.0, 0.0], [l0, 0.0], trig::third_corner(l0, l1, l2)]
    }

    /// Lays out in the plane the region of face `f0` whose faces are joined by the `merged`
    /// edges, breadth first: `f0` as [`Self::layout_face`] places it, then each face across a
    /// merged edge of a face laid out, unless the face it stands for (`key(face)`: itself, or the
    /// surface triangle a lift of a cover stands for) is `placed` already; that one is marked
    /// placed and unfolded across the edge. The position of the origin of each half-edge of the
    /// region's faces, in its face's placement, goes to `pos`; `queue` ends holding the region's
    /// faces in the order they were laid out. The caller marks `f0`'s own key placed.
    pub(crate) fn lay_out_region(
        &self,
        f0: FaceId,
        merged: &[bool],
        placed: &mut [bool],
        key: impl Fn(FaceId) -> FaceId,
        pos: &mut [[f64; 2]],
        queue: &mut Vec<FaceId>,
    ) {
        let mesh = &self.mesh;
        for (h, c) in mesh
            .face_halfedges(f0)
            .into_iter()
            .zip(self.layout_face(f0))
        {
            pos[h.idx()] = c;
        }
        queue.clear();
        queue.push(f0);
        let mut head = 0;
        while head < queue.len() {
            let f = queue[head];
            head += 1;
            for h in mesh.face_halfedges(f) {
                if !merged[h.edge().idx()] {
                    continue;
                }
                let g = mesh.face(h.twin());
                let k = key(g);
                if !placed[k.idx()] {
                    placed[k.idx()] = true;
                    self.unfold_across(h, pos);
                    queue.push(g);
                }
            }
        }
    }

    /// Places the face across half-edge `h` (of a face placed in `pos`) in the plane of `h`'s
    /// face: its twin runs from the end of `h` to its start, the third corner to its left.
    fn unfold_across(&self, h: HalfedgeId, pos: &mut [[f64; 2]]) {
        let mesh = &self.mesh;
        let t = h.twin();
        let from = pos[mesh.next(h).idx()];
        let to = pos[h.idx()];
        let [along, across] = trig::third_corner(
            self.halfedge_length(t),
            self.halfedge_length(mesh.next(t)),
            self.halfedge_length(mesh.prev(t)),
        );
        let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
        let scale = dx.hypot(dy);
        let (cos, sin) = (dx / scale, dy / scale);
        pos[t.idx()] = from;
        pos[mesh.next(t).idx()] = to;
        pos[mesh.prev(t).idx()] = [
            from[0] + along * cos - across * sin,
            from[1] + along * sin + across * cos,
        ];
    }

    /// Flips the edge intrinsically if its two faces differ, the quad they form is strictly
    /// convex, both new triangles, with the rounded new length, satisfy the strict triangle
    /// inequality (so the result is always a valid triangulation) and their areas add up to the
    /// quad's within [`Tolerances::flip_area`] (so rounding on needle-like quads cannot change the
    /// metric: the result stays isometric to double precision); returns whether it flipped.
    pub fn flip_if_convex(&mut self, e: EdgeId) -> bool {
        self.flip_if_convex_with_margin(e, 1.0)
    }

    /// As [`Self::flip_if_convex`], requiring the quad's angles at both ends of the edge to satisfy
    /// `tan(α₁/2) tan(α₂/2) < bound` (`bound = 1` is plain strict convexity; smaller bounds keep
    /// the new triangles away from degeneracy).
    pub fn flip_if_convex_with_margin(&mut self, e: EdgeId, bound: f64) -> bool {
        if !self.mesh.can_flip(e) {
            return false;
        }
        let q = self.quad(e.halfedge());
        let b2 = bound * bound;
        if !(q.convexity_at_a() < b2 && q.convexity_at_b() < b2) {
            return false;
        }
        let length = q.flipped_length();
        // Both new triangles must satisfy the strict triangle inequality as rounded, or the flip
        // would leave an invalid triangulation (needles: a convex quad, a rounded diagonal).
        if !(trig::is_triangle(length, q.ca, q.ad) && trig::is_triangle(length, q.db, q.bc)) {
            return false;
        }
        if !keeps_area(&q, length) {
            return false;
        }
        self.apply_flip(e, length);
        true
    }

    /// Flips `e` in the mesh and sets its new length (crate-internal; the caller checked
    /// `can_flip` and computed the length from [`Quad::flipped_length`]).
    #[inline]
    pub(crate) fn apply_flip(&mut self, e: EdgeId, length: f64) {
        self.mesh
            .flip(e)
            .expect("caller checked that the edge is flippable");
        self.lengths[e.idx()] = length;
    }
}

impl IntrinsicTriangulation {
    /// Per vertex slot, its row (and column) in the matrices of this crate ([`crate::cotan_laplacian`],
    /// [`crate::lumped_mass`], [`crate::intrinsic_delaunay_laplacian`]): the live vertices in increasing id
    /// order, `u32::MAX` for removed ids. There are [`surftopo_mesh::SurfaceMesh::vertex_count`]
    /// rows.
    pub fn matrix_rows(&self) -> Vec<u32> {
        dense_vertex_index(self).0
    }
}

/// Dense index of each live vertex (increasing id order), `u32::MAX` for removed ids, and the
/// number of live vertices.
pub(crate) fn dense_vertex_index(tri: &IntrinsicTriangulation) -> (Vec<u32>, usize) {
    let mesh = tri.mesh();
    let mut index = vec![u32::MAX; mesh.vertex_slots()];
    let mut n = 0usize;
    for v in mesh.vertices() {
        index[v.idx()] = n as u32;
        n += 1;
    }
    (index, n)
}

/// Whether flipping the quad's diagonal to `length` keeps its area within
/// [`Tolerances::flip_area`] (Kahan's areas of the two old and the two new triangles): on
/// needle-like quads the rounded new diagonal can change the area by far more than rounding of
/// the area itself (errors grow with the squared aspect ratio), and repeated flips would drift
/// away from the surface.
fn keeps_area(q: &Quad, length: f64) -> bool {
    let before = trig::area(q.ab, q.bc, q.ca) + trig::area(q.ab, q.ad, q.db);
    let after = trig::area(length, q.ca, q.ad) + trig::area(length, q.db, q.bc);
    (after - before).abs() <= Tolerances::DEFAULT.flip_area * before
}

/// Stores the half-angle tangents squared of the triangle with sides `lengths` into `t2`, entry
/// `i` at `halfedges[i]` (the angle opposite side `i`); returns the smallest Kahan factor
/// (positive iff the triangle inequality holds strictly). The values do not depend on the order
/// of the sides (see [`trig::excesses`]).
#[inline]
pub(crate) fn store_tan_half_sq(
    halfedges: [HalfedgeId; 3],
    lengths: [f64; 3],
    t2: &mut [f64],
) -> f64 {
    let (values, smallest) = trig::tan_half_sq_all(lengths);
    for (h, v) in halfedges.into_iter().zip(values) {
        t2[h.idx()] = v;
    }
    smallest
}

/// Checks the strict triangle inequality of one face.
pub(crate) fn check_triangle(f: FaceId, sides: [f64; 3]) -> Result<(), GeometryError> {
    let [a, b, c] = sides;
    let [p, ea, eb, ec] = trig::excesses(a, b, c);
    let smallest = ea.min(eb).min(ec);
    if p.is_nan() || p <= 0.0 || smallest.is_nan() || smallest < 0.0 {
        return Err(GeometryError::TriangleInequality { face: f.0, sides });
    }
    if smallest == 0.0 {
        return Err(GeometryError::ZeroArea { face: f.0, sides });
    }
    Ok(())
}
