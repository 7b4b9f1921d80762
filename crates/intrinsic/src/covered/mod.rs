//! Intrinsic Delaunay on every compact surface: boundary loops, non-orientable pieces, several
//! components.
//!
//! A [`CoveredTriangulation`] is an intrinsic triangulation of a surface K held on the closed
//! oriented mesh D of its [`ClosedCover`] (ARCHITECTURE.md, "The surface model"), with one length
//! per edge of D. No new topology: flipping is [`crate::flip_to_delaunay`]'s algorithm on D with
//! two rules ([`CoverGluing`]):
//!
//! - **Boundary loops.** D closes each loop with a cone over an apex. The cone's triangles are
//!   *virtual*: an edge with an apex among the four vertices of its two faces (a boundary edge of
//!   K, or an apex edge) never flips, so the virtual triangles never change and the real ones
//!   stay real; the virtual triangles get any valid lengths (each apex edge as long as the
//!   longest edge of its loop) and never enter the Laplacian, the mass matrix or the Delaunay
//!   test. A boundary edge thus keeps its one half-cotangent: the natural (Neumann) boundary
//!   condition of libigl's `intrinsic_delaunay_cotmatrix` and geometry-central.
//! - **Non-orientable pieces.** D holds their orientable double cover; the deck map (each
//!   half-edge to its *mirror*) is an isometry, so an edge is non-Delaunay iff its mirror is, and
//!   the two flip together: D stays the double cover of a triangulation of K, which is K's
//!   Delaunay triangulation (Bobenko and Springborn's criterion is local, edge by edge). An edge
//!   whose two faces are each other's mirror (a triangle of K glued to itself with a reversal) is
//!   never flipped: its opposite angles are the base angles of an isosceles triangle, so it is
//!   Delaunay.
//!
//! Components are independent (flips are local). Matrices have one row per vertex of K, in the
//! input's numbering without unreferenced vertices (the cover's vertex classes), block-diagonal
//! over components. The alternative, half-edges with boundary half-edges and an orientation bit
//! per gluing, would give `flip`, rotation and every test new cases on the closed orientable hot
//! path; this module leaves that path's machine code as it was ([`crate::flip`]'s `Closed`).

pub(crate) mod isometry;

use crate::error::{DelaunayError, GeometryError, PortalgonError};
use crate::flip::stats::DelaunayStats;
use crate::flip::tessellation::{CellSurface, Tessellation, tessellate};
use crate::flip::{
    DelaunayOptions, FlipReport, Gluing, flip_glued, left_non_delaunay, product_bound,
};
use crate::formats::portalgon_json::{
    FORMAT_NAME, Number, ORIENTED_VERSION, PolygonDoc, PortalgonDoc, TwistedParts,
};
use crate::laplacian::assemble_laplacian;
use crate::sparse::SparseMatrix;
use crate::triangulation::convert::{
    TriangleGluing, check_glued_lengths, glued_length, gluing_error, label_vertices,
};
use crate::triangulation::{IntrinsicTriangulation, trig};
use surftopo_mesh::geometry::Point3;
use surftopo_mesh::{
    ClosedCover, CoveredSurface, EdgeId, FaceId, HalfedgeId, Lifting, Sheets, SurfaceMesh,
    TwistedGluing, VertexId,
};

/// An intrinsic triangulation of a compact surface on its closed cover (see the module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct CoveredTriangulation {
    /// The cover D with a length per edge (apex edges included).
    tri: IntrinsicTriangulation,
    /// The surface vertex each vertex of D stands for; apexes are `surface_vertices`.
    class: Vec<u32>,
    /// Vertices of K (the rows of the matrices).
    surface_vertices: usize,
    /// Mirror of each half-edge of a doubled piece, `INVALID` elsewhere; empty when none.
    mirror: Vec<HalfedgeId>,
    /// Per edge of D: an apex among the four vertices of its faces (a boundary or apex edge).
    frozen: Vec<bool>,
}

impl CoveredTriangulation {
    /// The intrinsic triangulation of a surface in space: the cover's topology, each edge as
    /// long as the segment between its ends' positions (`positions` by vertex class, as
    /// [`surftopo_mesh::CoveredSurface`] holds them), each apex edge as long as the longest
    /// boundary edge of its loop.
    ///
    /// # Errors
    /// [`GeometryError::NonFiniteLength`] (huge coordinates).
    pub fn from_cover(cover: &ClosedCover, positions: &[Point3]) -> Result<Self, GeometryError> {
        Self::from_cover_lengths(cover, |a, b| euclidean(positions, a, b))
    }

    /// The intrinsic triangulation of K with each edge as long as `length(a, b)` says for its
    /// ends' vertices of K (an abstract metric: a flat strip glued into an annulus or a Möbius
    /// band, say); apex edges as [`Self::from_cover`] makes them.
    ///
    /// # Errors
    /// [`GeometryError::NonFiniteLength`] when a length is not finite.
    pub fn from_cover_lengths(
        cover: &ClosedCover,
        length: impl Fn(u32, u32) -> f64,
    ) -> Result<Self, GeometryError> {
        let sheets = &cover.sheets;
        let mesh = &cover.mesh;
        Self::from_cover_edge_lengths(cover, |e| {
            let [a, b] = mesh.edge_vertices(e);
            length(sheets.class(a), sheets.class(b))
        })
    }

    /// The intrinsic triangulation of K with each edge of D without an apex end as long as
    /// `length(e)` says (edges of K given by a gluing, loops and multi-edges included: the
    /// same length for an edge and its mirror); apex edges as [`Self::from_cover`] makes them.
    ///
    /// # Errors
    /// [`GeometryError::NonFiniteLength`] when a length is not finite.
    pub fn from_cover_edge_lengths(
        cover: &ClosedCover,
        length: impl Fn(EdgeId) -> f64,
    ) -> Result<Self, GeometryError> {
        let parts = CoverParts::new(&cover.mesh, &cover.sheets, length);
        parts.with_mesh(cover.mesh.clone())
    }

    /// [`Self::from_cover`] of a surface in space, taking its cover's mesh instead of copying
    /// it (the same triangulation).
    ///
    /// # Errors
    /// As [`Self::from_cover`].
    pub fn from_surface(surface: CoveredSurface) -> Result<Self, GeometryError> {
        let CoveredSurface { cover, positions } = surface;
        let ClosedCover { mesh, sheets } = cover;
        let parts = CoverParts::new(&mesh, &sheets, |e| {
            let [a, b] = mesh.edge_vertices(e).map(|v| sheets.class(v));
            euclidean(&positions, a, b)
        });
        parts.with_mesh(mesh)
    }

    /// The surface a portalgon file describes, glued in any way (format version 2:
    /// orientation-reversing gluings, free sides as boundary, several pieces; polygons of more
    /// than three sides cut into triangles first, `PortalgonDoc::cut_into_triangles`, errors
    /// naming the file's polygon): its cover
    /// built from the gluing itself ([`ClosedCover::from_twisted_gluing`]: loops, multi-edges
    /// and triangles glued to themselves are allowed, as no vertex numbering describes them).
    /// Triangle `p` of K is polygon `p`; K's vertices are the labels when the file gives them
    /// (else numbered in order of first corner), so [`Self::to_doc`]'s file reads back with the
    /// same vertices (the rows of the matrices). Each edge is as long as its glued sides (their
    /// mean; they must agree within `tolerance`, relative), a boundary edge as its side.
    /// Triangle inequalities are checked later ([`IntrinsicTriangulation::validate`] on
    /// [`Self::cover`]).
    ///
    /// # Errors
    /// [`PortalgonError::NotTriangle`], [`PortalgonError::NoSuchSide`],
    /// [`PortalgonError::MatchedTwice`], [`PortalgonError::UnequalSides`],
    /// [`PortalgonError::VertexLabels`] (labels that disagree with the gluing), the lengths'
    /// errors ([`PortalgonError::NonFinite`], ...), each naming the polygon and side.
    pub fn from_doc(doc: &PortalgonDoc, tolerance: f64) -> Result<Self, PortalgonError> {
        let cut;
        let (doc, polygon_index) = if doc.polygons.iter().all(PolygonDoc::is_triangle) {
            (doc, (0..doc.polygons.len()).collect())
        } else {
            let (triangles, polygon_of) = doc.cut_into_triangles(tolerance)?;
            cut = triangles;
            (&cut, polygon_of)
        };
        let TwistedParts {
            sides,
            pairs,
            reversed,
            labels,
        } = doc.twisted_parts()?;
        let g = TriangleGluing {
            sides: &sides,
            pairs: &pairs,
            labels: labels.as_deref(),
            polygon_index: &polygon_index,
            tolerance,
        };
        check_glued_lengths(&g)?;
        let gluing = TwistedGluing {
            face_count: sides.len(),
            pairs: &pairs,
            reversed: &reversed,
        };
        let fail = |e| gluing_error(&g, e);
        let (classes, vertex_count) = gluing.corner_vertices().map_err(fail)?;
        let corner_labels: Vec<u32> = match &labels {
            Some(labels) => {
                let label_of = label_vertices(&g, labels, |c| classes[c] as usize, vertex_count)?;
                classes.iter().map(|&v| label_of[v as usize]).collect()
            }
            None => classes,
        };
        let twisted = ClosedCover::from_twisted_gluing(&gluing, &corner_labels, vertex_count)
            .map_err(fail)?;
        // The length of each side of K: a glued pair's common length, a free side's own.
        let mut side_length: Vec<f64> = sides.iter().flatten().copied().collect();
        for &(s, t) in &pairs {
            let l = glued_length(g.side_length(s), g.side_length(t));
            side_length[3 * s.face as usize + s.side as usize] = l;
            side_length[3 * t.face as usize + t.side as usize] = l;
        }
        let n = sides.len();
        let on_k = |h: HalfedgeId| {
            let s = twisted.side_of_halfedge[h.idx()];
            ((s.face as usize) < n).then(|| side_length[3 * s.face as usize + s.side as usize])
        };
        let tri = Self::from_cover_edge_lengths(&twisted.cover, |e| {
            let h = e.halfedge();
            on_k(h).or_else(|| on_k(h.twin())).unwrap_or(0.0)
        })?;
        Ok(tri)
    }

    /// A closed orientable surface as its own cover (no apex, no mirror, vertex ids as the
    /// vertices of K), so that it can be compared with a surface of any kind.
    pub fn from_closed(tri: IntrinsicTriangulation) -> Self {
        let mesh = tri.mesh();
        let class = (0..mesh.vertex_slots())
            .map(|v| {
                if mesh.is_vertex_live(VertexId::new(v)) {
                    v as u32
                } else {
                    u32::MAX
                }
            })
            .collect();
        let (surface_vertices, frozen) = (mesh.vertex_slots(), vec![false; mesh.edge_slots()]);
        Self {
            tri,
            class,
            surface_vertices,
            mirror: Vec::new(),
            frozen,
        }
    }

    /// The cover D with its lengths (virtual triangles included).
    pub fn cover(&self) -> &IntrinsicTriangulation {
        &self.tri
    }

    /// The number of vertices of K: the rows of [`Self::laplacian`] and [`Self::mass`].
    pub fn surface_vertex_count(&self) -> usize {
        self.surface_vertices
    }

    /// The vertex of K a vertex of D stands for (`surface_vertex_count()` for an apex).
    pub fn class(&self, v: VertexId) -> u32 {
        self.class[v.idx()]
    }

    /// Whether a vertex of D is an apex (not a vertex of K).
    pub fn is_apex(&self, v: VertexId) -> bool {
        self.class[v.idx()] as usize == self.surface_vertices
    }

    /// The mirror of a half-edge of a doubled piece.
    pub fn mirror(&self, h: HalfedgeId) -> Option<HalfedgeId> {
        self.mirror.get(h.idx()).copied().filter(|m| m.is_valid())
    }

    /// Whether a face of D is a triangle of K: not a cone face (virtual), and the first (smaller
    /// id) of its mirror pair on a doubled piece.
    pub fn is_surface_face(&self, f: FaceId) -> bool {
        let mesh = self.tri.mesh();
        let h = mesh.face_halfedge(f);
        self.is_real_face(f) && self.mirror(h).is_none_or(|m| f <= mesh.face(m))
    }

    /// Whether a face of D is real (no apex corner), mirror copies included.
    fn is_real_face(&self, f: FaceId) -> bool {
        let mesh = self.tri.mesh();
        mesh.face_vertices(f).iter().all(|&v| !self.is_apex(v))
    }

    /// Whether an edge of D is an edge of K: no apex end, and the first of its mirror pair.
    pub fn is_surface_edge(&self, e: EdgeId) -> bool {
        let mesh = self.tri.mesh();
        let [a, b] = mesh.edge_vertices(e);
        !self.is_apex(a)
            && !self.is_apex(b)
            && self.mirror(e.halfedge()).is_none_or(|m| e <= m.edge())
    }

    /// Whether an edge of D lies on a boundary loop of K (one real face, one virtual).
    pub fn is_boundary_edge(&self, e: EdgeId) -> bool {
        let mesh = self.tri.mesh();
        let h = e.halfedge();
        self.is_real_face(mesh.face(h)) != self.is_real_face(mesh.face(h.twin()))
    }

    /// The edge of K an edge of D stands for: itself, or the first of its mirror pair.
    pub fn surface_edge(&self, e: EdgeId) -> EdgeId {
        self.mirror(e.halfedge()).map_or(e, |m| e.min(m.edge()))
    }

    /// The edges of K (see [`Self::is_surface_edge`]).
    pub fn surface_edges(&self) -> impl Iterator<Item = EdgeId> + '_ {
        self.tri.mesh().edges().filter(|&e| self.is_surface_edge(e))
    }

    /// The triangles of K (see [`Self::is_surface_face`]).
    pub fn surface_faces(&self) -> impl Iterator<Item = FaceId> + '_ {
        self.tri.mesh().faces().filter(|&f| self.is_surface_face(f))
    }

    /// Whether the edge of K through `e` may flip: interior (no apex among its quad's vertices)
    /// and its two faces not each other's mirror.
    pub fn may_flip(&self, e: EdgeId) -> bool {
        CoverGluing::may_flip_in(&self.frozen, &self.mirror, self.tri.mesh(), e)
    }

    /// Flips every interior edge of K whose opposite angles sum to more than π (up to the
    /// tolerance) until none is left: [`crate::flip_to_delaunay`] on the cover under the rules
    /// of the module doc. Boundary edges are never flipped. The report counts the flips of K
    /// (a mirror pair is one flip) and the non-Delaunay interior edges of D left.
    ///
    /// # Errors
    /// As [`crate::flip_to_delaunay`].
    pub fn flip_to_delaunay(
        &mut self,
        options: &DelaunayOptions,
    ) -> Result<FlipReport, DelaunayError> {
        self.flip_keeping_tan_half_sq(options)
            .map(|(report, _)| report)
    }

    /// [`Self::flip_to_delaunay`], also returning the half-angle cache flipping keeps: `tan²(θ/2)`
    /// of the angle opposite every half-edge of D (by half-edge id), equal bit for bit to
    /// [`IntrinsicTriangulation::halfedge_tan_half_sq`] of the result.
    pub(crate) fn flip_keeping_tan_half_sq(
        &mut self,
        options: &DelaunayOptions,
    ) -> Result<(FlipReport, Vec<f64>), DelaunayError> {
        let mut gluing = CoverGluing {
            frozen: &self.frozen,
            mirror: &mut self.mirror,
        };
        let (mut report, t2) = flip_glued(&mut self.tri, options, false, &mut gluing)?
            .expect("flipping without the needle test always finishes");
        if !self.mirror.is_empty() {
            // Each non-Delaunay edge of a doubled piece was counted on both lifts.
            let bound = product_bound(options.tolerance);
            let mesh = self.tri.mesh();
            report.non_delaunay_edges = mesh
                .edges()
                .filter(|&e| self.is_surface_edge(e) && self.may_flip(e))
                .filter(|&e| left_non_delaunay(mesh, &t2, bound, e))
                .count();
        }
        Ok((report, t2))
    }

    /// Re-triangulates K isometrically by up to `count` random intrinsic flips, as
    /// [`crate::generators::random_flips`] does on a closed surface: edges of D drawn uniformly
    /// (seeded), an interior edge of K flipped when its quad is convex with margin and keeps its
    /// area, its mirror edge with it (the same new length). Boundary edges never flip. At most
    /// `20 · count` draws. Returns the number of flips of K made. Same seed, same result.
    pub fn random_flips(&mut self, count: u64, seed: u64) -> u64 {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        let slots = self.tri.mesh().edge_slots();
        let mut flips = 0;
        for _ in 0..count.saturating_mul(20) {
            if flips == count || slots == 0 {
                break;
            }
            let e = EdgeId::new(rng.random_range(0..slots));
            if !self.tri.mesh().is_edge_live(e) || !self.may_flip(e) {
                continue;
            }
            let h = e.halfedge();
            let partner = self.mirror(h).map(HalfedgeId::twin);
            if !self.tri.flip_if_convex_with_margin(e, 0.9) {
                continue;
            }
            if let Some(p) = partner {
                self.tri.apply_flip(p.edge(), self.tri.length(e));
                let mut gluing = CoverGluing {
                    frozen: &self.frozen,
                    mirror: &mut self.mirror,
                };
                gluing.flipped(self.tri.mesh(), h, p);
            }
            flips += 1;
        }
        flips
    }

    /// The cotan weight `w_e` of every edge of D (by edge id): half the cotangent of each
    /// opposite angle in a real triangle; 0 on apex edges. A boundary edge gets its one
    /// half-cotangent (the natural boundary condition).
    pub fn cotan_weights(&self) -> Vec<f64> {
        self.weights_from_tan_half_sq(&self.tri.halfedge_tan_half_sq())
    }

    /// [`Self::cotan_weights`] from the half-angle tangents squared `t2` of D (by half-edge id).
    /// Edge e's half-edges are `2e` and `2e + 1`: one pass over all of them (it vectorises, as
    /// [`crate::cotan_laplacian`]'s), then the frozen edges again, the only ones a virtual
    /// triangle can touch (a cone face has an apex corner, so each of its edges has an apex
    /// in its quad), summing their real triangles' halves alone. The sums are those of a pass
    /// over the real faces (two terms at most, and `0.5 x + 0.5 y = 0.5 (x + y)` exactly).
    fn weights_from_tan_half_sq(&self, t2: &[f64]) -> Vec<f64> {
        let mesh = self.tri.mesh();
        let half_cot = |h: HalfedgeId| 0.5 * trig::cot_from_tan_half_sq(t2[h.idx()]);
        let mut w: Vec<f64> = t2
            .chunks_exact(2)
            .map(|t| 0.5 * (trig::cot_from_tan_half_sq(t[0]) + trig::cot_from_tan_half_sq(t[1])))
            .collect();
        for (e, &frozen) in self.frozen.iter().enumerate() {
            let e = EdgeId::new(e);
            if !mesh.is_edge_live(e) {
                w[e.idx()] = 0.0;
            } else if frozen {
                let h = e.halfedge();
                w[e.idx()] = [h, h.twin()]
                    .into_iter()
                    .filter(|&g| self.is_real_face(mesh.face(g)))
                    .map(half_cot)
                    .sum();
            }
        }
        w
    }

    /// The lumped mass of K's vertices: a third of each triangle of K's area per corner, in
    /// face id order (one pass over D's faces, cone faces and mirror copies skipped).
    fn lumped_mass(&self) -> Vec<f64> {
        let mesh = self.tri.mesh();
        let mut mass = vec![0.0; self.surface_vertices];
        for f in mesh.faces() {
            let halfedges = mesh.face_halfedges(f);
            let rows = halfedges.map(|h| self.class[mesh.origin(h).idx()] as usize);
            if rows.contains(&self.surface_vertices) {
                continue; // a cone face (virtual)
            }
            if self.mirror(halfedges[0]).is_none_or(|m| f <= mesh.face(m)) {
                let [a, b, c] = halfedges.map(|h| self.tri.halfedge_length(h));
                let third = trig::area(a, b, c) / 3.0;
                for r in rows {
                    mass[r] += third;
                }
            }
        }
        mass
    }

    /// The cotan Laplacian of K (positive semidefinite, as [`crate::cotan_laplacian`]): one row
    /// per vertex of K, each edge of K once (a mirror pair is one edge).
    pub fn laplacian(&self) -> SparseMatrix {
        self.laplacian_from_tan_half_sq(&self.tri.halfedge_tan_half_sq())
    }

    /// [`Self::laplacian`] from the half-angle tangents squared `t2` of D (by half-edge id), as
    /// [`Self::flip_keeping_tan_half_sq`] returns them.
    pub(crate) fn laplacian_from_tan_half_sq(&self, t2: &[f64]) -> SparseMatrix {
        self.assemble(&self.weights_from_tan_half_sq(t2))
    }

    /// The Laplacian of K from the cotan weights of D's edges (by edge id).
    fn assemble(&self, weights: &[f64]) -> SparseMatrix {
        let mesh = self.tri.mesh();
        let class = &self.class;
        let entries: Vec<(usize, usize, f64)> = self
            .surface_edges()
            .map(|e| {
                let [a, b] = mesh.edge_vertices(e).map(|v| class[v.idx()] as usize);
                (a, b, weights[e.idx()])
            })
            .collect();
        assemble_laplacian(self.surface_vertices, || entries.iter().copied())
    }

    /// The lumped (barycentric) mass matrix of K: a third of each triangle's area per corner.
    pub fn mass(&self) -> SparseMatrix {
        SparseMatrix::diagonal(self.lumped_mass())
    }
}

/// The distance between the positions of vertex classes `a` and `b`.
fn euclidean(positions: &[Point3], a: u32, b: u32) -> f64 {
    let [p, q] = [a, b].map(|v| positions[v as usize]);
    ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt()
}

/// A [`CoveredTriangulation`] but its mesh: what [`CoveredTriangulation::from_cover_edge_lengths`]
/// reads off the cover.
struct CoverParts {
    lengths: Vec<f64>,
    class: Vec<u32>,
    surface_vertices: usize,
    mirror: Vec<HalfedgeId>,
    frozen: Vec<bool>,
}

impl CoverParts {
    /// Each edge of D without an apex end as long as `length(e)` says, each apex edge as long
    /// as the longest boundary edge of its loop; classes, mirrors and frozen edges from the
    /// cover.
    fn new(mesh: &SurfaceMesh, sheets: &Sheets, length: impl Fn(EdgeId) -> f64) -> Self {
        let surface_vertices = sheets
            .apex_class()
            .map_or(sheets.class_count(), |a| a as usize);
        let class: Vec<u32> = (0..mesh.vertex_slots())
            .map(|v| {
                let v = VertexId::new(v);
                if mesh.is_vertex_live(v) {
                    sheets.class(v)
                } else {
                    u32::MAX
                }
            })
            .collect();
        let is_apex = |v: VertexId| class[v.idx()] as usize == surface_vertices;
        let mut lengths = vec![0.0; mesh.edge_slots()];
        for e in mesh.edges() {
            let [a, b] = mesh.edge_vertices(e);
            if !is_apex(a) && !is_apex(b) {
                lengths[e.idx()] = length(e);
            }
        }
        // Each apex edge as long as the longest boundary edge of its loop: every cone triangle
        // (boundary edge ab, apex edges L, L) is then valid, ab ≤ L < 2L.
        let mut longest = vec![0.0f64; mesh.vertex_slots()];
        for h in mesh.halfedges() {
            let apex = mesh.origin(h);
            if is_apex(apex) {
                let l = &mut longest[apex.idx()];
                *l = l.max(lengths[mesh.next(h).edge().idx()]);
            }
        }
        // An edge is frozen when its quad (the corners of its two faces) has an apex: when it
        // is a side of a face with an apex corner (a cone face), marked from the apexes' side.
        let mut frozen = vec![false; mesh.edge_slots()];
        for h in mesh.halfedges() {
            if is_apex(mesh.origin(h)) {
                lengths[h.edge().idx()] = longest[mesh.origin(h).idx()];
                for g in mesh.face_halfedges(mesh.face(h)) {
                    frozen[g.edge().idx()] = true;
                }
            }
        }
        let mirror = if sheets.doubled() {
            (0..mesh.halfedge_slots())
                .map(|h| {
                    sheets
                        .mirror(HalfedgeId::new(h))
                        .unwrap_or(HalfedgeId::INVALID)
                })
                .collect()
        } else {
            Vec::new()
        };
        Self {
            lengths,
            class,
            surface_vertices,
            mirror,
            frozen,
        }
    }

    /// The triangulation on `mesh` (the cover's).
    fn with_mesh(self, mesh: SurfaceMesh) -> Result<CoveredTriangulation, GeometryError> {
        Ok(CoveredTriangulation {
            tri: IntrinsicTriangulation::from_parts(mesh, self.lengths)?,
            class: self.class,
            surface_vertices: self.surface_vertices,
            mirror: self.mirror,
            frozen: self.frozen,
        })
    }
}

impl CoveredTriangulation {
    /// The figures of a run that made `report` in `seconds`: the surface's own vertices, edges,
    /// faces, loops and multi-edges (not the cover's).
    pub fn stats(&self, report: &FlipReport, seconds: f64) -> DelaunayStats {
        let mesh = self.tri.mesh();
        let pairs: Vec<(u32, u32)> = self
            .surface_edges()
            .map(|e| {
                let [a, b] = mesh.edge_vertices(e).map(|v| self.class(v));
                (a.min(b), a.max(b))
            })
            .collect();
        let faces = self.surface_faces().count();
        let counts = [self.surface_vertex_count(), pairs.len(), faces];
        DelaunayStats::from_pairs(counts, pairs, report, seconds)
    }
}

impl CoveredTriangulation {
    /// The portalgon document of K: its triangles by lengths (in face id order, vertex labels
    /// the surface's vertices, sides in the order of the first lift's half-edges), each interior
    /// edge one pair, reversed (version 2) where the two sides run the same way on the surface —
    /// where its other side lies on the mirror copy of a doubled piece; boundary edges are
    /// unmatched sides.
    pub fn to_doc(&self) -> PortalgonDoc {
        let mesh = self.tri.mesh();
        let faces: Vec<FaceId> = self.surface_faces().collect();
        let mut rank = vec![u32::MAX; mesh.face_slots()];
        for (k, &f) in faces.iter().enumerate() {
            rank[f.idx()] = k as u32;
        }
        let side = |h: HalfedgeId| {
            let f = mesh.face(h);
            let i = mesh.face_halfedges(f).iter().position(|&g| g == h);
            [rank[f.idx()] as usize, i.expect("a half-edge of its face")]
        };
        let polygons = faces
            .iter()
            .map(|&f| PolygonDoc {
                corners: None,
                lengths: Some(self.tri.face_sides(f).map(Number::Double).to_vec()),
                vertices: Some(mesh.face_vertices(f).map(|v| self.class(v)).to_vec()),
            })
            .collect();
        let (mut matching, mut reversed) = (Vec::new(), Vec::new());
        for &f in &faces {
            for h in mesh.face_halfedges(f) {
                let t = h.twin();
                if !self.is_real_face(mesh.face(t)) {
                    continue;
                }
                // The other side on the surface: t itself, or its mirror (same direction as h).
                let (other, flip) = if rank[mesh.face(t).idx()] != u32::MAX {
                    (t, false)
                } else {
                    (self.mirror(t).expect("a mirror copy has a mirror"), true)
                };
                let (a, b) = (side(h), side(other));
                if a < b {
                    matching.push([a, b]);
                    reversed.push(flip);
                }
            }
        }
        glued_doc(polygons, matching, reversed)
    }
}

/// The document of polygons glued by `matching`, `reversed` per pair (kept only when some pair
/// reverses orientation).
fn glued_doc(
    polygons: Vec<PolygonDoc>,
    matching: Vec<[[usize; 2]; 2]>,
    mut reversed: Vec<bool>,
) -> PortalgonDoc {
    if !reversed.contains(&true) {
        reversed.clear();
    }
    PortalgonDoc {
        format: FORMAT_NAME.to_string(),
        version: ORIENTED_VERSION,
        comment: None,
        polygons,
        matching,
        reversed,
    }
}

impl CoveredTriangulation {
    /// The Delaunay tessellation of K (run [`Self::flip_to_delaunay`] first): the triangles of
    /// K merged across every interior edge whose two triangles are co-circular, decided as
    /// [`crate::delaunay_tessellation`] decides it on a closed surface (`|√(tan²(γ/2)
    /// tan²(δ/2)) - 1| <= tolerance`, a spanning forest over K's triangles), once per edge of K;
    /// never across a boundary edge. Each polygon is laid out on one lift in D, so its corners
    /// run counter-clockwise in that lift's orientation.
    ///
    /// The document (portalgon JSON, version 2 when some gluing reverses orientation): polygons
    /// by `corners` with `vertices` (the surface's vertices), a pair per interior side, flagged
    /// `true` where its two sides run the same way (the neighbour was laid out on the other
    /// sheet: on a non-orientable piece, no choice of lifts avoids it), boundary sides
    /// unmatched. The faces are K's triangles (the first lift's face ids), the merged edges K's
    /// edges (first lifts), the side half-edges those of the lifts laid out.
    ///
    /// Uniqueness: on a closed surface the Delaunay tessellation is unique (Bobenko and
    /// Springborn, Proposition 4). With boundary, every triangulation of K with these vertices
    /// has the boundary edges (the boundary is the union of the segments between consecutive
    /// boundary vertices), so the tessellation is the constrained one: each cell is the set of
    /// triangles whose circumdisks, developed across interior edges only, coincide; flipping
    /// reaches a triangulation whose interior edges are all Delaunay, in which the developed
    /// circumdisk of a triangle is empty of vertices it sees (the planar argument of Lee and
    /// Lin's constrained Delaunay triangulation, local across interior edges), and these disks
    /// depend on the metric and the vertices alone, so the cells do not depend on the flips
    /// that led there (see README, "The Delaunay tessellation on every surface").
    pub fn tessellation(&self, tolerance: f64) -> Tessellation<PortalgonDoc> {
        tessellate(&self.tri, tolerance, self).with_polygons(|cells| {
            let polygon_of = |s: u32| {
                let k = cells.side_start.partition_point(|&start| start <= s) - 1;
                [k, (s - cells.side_start[k]) as usize]
            };
            let polygons = (0..cells.side_start.len() - 1)
                .map(|k| {
                    let sides = cells.sides(k);
                    PolygonDoc {
                        corners: Some(
                            cells.corners[sides.clone()]
                                .iter()
                                .map(|c| c.map(Number::Double))
                                .collect(),
                        ),
                        lengths: None,
                        vertices: Some(cells.labels[sides].to_vec()),
                    }
                })
                .collect();
            let matching = cells
                .gluings
                .iter()
                .map(|&(s, t, _)| [polygon_of(s), polygon_of(t)])
                .collect();
            let reversed = cells.gluings.iter().map(|g| g.2).collect();
            glued_doc(polygons, matching, reversed)
        })
    }
}

/// K as [`tessellate`] sees it: K's triangles and edges are the first lifts, cone faces are
/// not on it, labels are the vertex classes.
impl CellSurface for CoveredTriangulation {
    fn surface_face(&self, f: FaceId) -> Option<FaceId> {
        if !self.is_real_face(f) {
            return None;
        }
        let mesh = self.tri.mesh();
        Some(
            self.mirror(mesh.face_halfedge(f))
                .map_or(f, |m| f.min(mesh.face(m))),
        )
    }

    fn surface_edge(&self, e: EdgeId) -> EdgeId {
        CoveredTriangulation::surface_edge(self, e)
    }

    fn label(&self, v: VertexId) -> u32 {
        self.class(v)
    }

    fn mirror(&self, h: HalfedgeId) -> Option<HalfedgeId> {
        CoveredTriangulation::mirror(self, h)
    }
}

/// The flip rules of a cover (see the module doc).
struct CoverGluing<'a> {
    frozen: &'a [bool],
    mirror: &'a mut Vec<HalfedgeId>,
}

impl CoverGluing<'_> {
    fn may_flip_in(frozen: &[bool], mirror: &[HalfedgeId], mesh: &SurfaceMesh, e: EdgeId) -> bool {
        if frozen[e.idx()] {
            return false;
        }
        let h = e.halfedge();
        match mirror.get(h.idx()) {
            Some(m) if m.is_valid() => mesh.face(h.twin()) != mesh.face(*m),
            _ => true,
        }
    }
}

impl Gluing for CoverGluing<'_> {
    fn may_flip(&self, mesh: &SurfaceMesh, e: EdgeId) -> bool {
        Self::may_flip_in(self.frozen, self.mirror, mesh, e)
    }

    /// The mirror edge, seen from `twin(mirror(h))`: it runs between the mirror lifts of h's
    /// ends with the mirror of h's left face on its left.
    fn partner(&self, h: HalfedgeId) -> Option<HalfedgeId> {
        let m = *self.mirror.get(h.idx())?;
        m.is_valid().then(|| m.twin())
    }

    /// Repairs the mirrors of the two flipped edges. The mirror copy of a face runs the other
    /// way, so `next(mirror(x)) = mirror(prev(x))`; after the flips `prev(next(h)) = h` and the
    /// sides keep their ids and mirrors, hence `mirror(h) = next(mirror(next(h)))`.
    fn flipped(&mut self, mesh: &SurfaceMesh, h: HalfedgeId, p: HalfedgeId) {
        for g in [h, h.twin()] {
            let m = mesh.next(self.mirror[mesh.next(g).idx()]);
            debug_assert_eq!(m.edge(), p.edge());
            self.mirror[g.idx()] = m;
            self.mirror[m.idx()] = g;
        }
    }
}
