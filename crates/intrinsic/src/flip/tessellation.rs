//! The Delaunay tessellation of a Delaunay triangulation (Bobenko & Springborn 2007, Section 2
//! and Proposition 4; Dubois, Appendix C, Lemma 29).
//!
//! Every Delaunay triangulation with vertex set V refines the unique Delaunay tessellation of
//! (S, V): its faces are the convex polygons inscribed in the empty immersed disks, and a
//! Delaunay triangulation splits each of them along diagonals. A diagonal is exactly an edge whose
//! two triangles share their circumcircle — opposite angles summing to π, i.e. `tan(γ/2) tan(δ/2)
//! = 1` (see [`crate::triangulation::trig::Quad::delaunay_product`]). So the tessellation is obtained by deleting
//! the co-circular edges: triangles are merged across every edge with
//! `|√(tan²(γ/2) tan²(δ/2)) - 1| <= tolerance` ([`DEFAULT_COCIRCULAR_TOLERANCE`]).
//!
//! Decision where exact arithmetic leaves nothing to decide: merging follows a spanning forest of
//! the co-circular edges (edges in increasing id order, union-find over faces). In exact
//! arithmetic the co-circular edges of a Delaunay triangulation never close a cycle (each face of
//! the tessellation is a disk triangulated by diagonals), but with a tolerance a cycle could
//! appear; an edge that would close one is kept as a side (matched to another side of the same
//! polygon), so every polygon stays a disk and the output is always a valid portalgon.
//!
//! Each polygon is laid out in the plane by unfolding its triangles along the merged edges
//! (breadth-first from its smallest face id), and listed counter-clockwise starting from its
//! smallest side half-edge. Vertex labels are the dense vertex indices. O(n α(n)).
//!
//! The same code tessellates a surface with boundary, non-orientable or in pieces on its closed
//! cover ([`crate::CoveredTriangulation::tessellation`], through [`CellSurface`]): only interior
//! edges merge, each edge of the surface is decided once (on the first of its mirror pair), the
//! union-find runs over the surface's triangles, and each polygon is laid out on one lift (the
//! lift of a tree of triangles is a tree on one sheet), its sides glued to the lift its
//! neighbour was laid out on: reversed where that is the mirror copy.
//!
//! This is the Delaunay tessellation of (S, V) for V the triangulation's vertices; the paper's
//! canonical tessellation has V = the singular vertices (see [`crate::canonical_tessellation`],
//! which removes the flat ones first).

use crate::geometry::Tolerances;
use crate::portalgon::{Portalgon, SideId};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::dense_vertex_index;
use surftopo_mesh::{EdgeId, FaceId, HalfedgeId, UnionFind, VertexId};

/// [`Tolerances::cocircular`]'s default, the tolerance for co-circularity
/// (`|tan(γ/2) tan(δ/2) - 1| <= 1e-9`), as a constant for the callers that take one.
pub const DEFAULT_COCIRCULAR_TOLERANCE: f64 = Tolerances::DEFAULT.cocircular;

/// A Delaunay tessellation with its relation to the triangulation it came from; `P` holds the
/// polygons and their gluing: a [`Portalgon`] on a closed oriented surface, a
/// [`crate::PortalgonDoc`] (boundary sides unmatched, orientation-reversing gluings flagged) on
/// any surface ([`crate::CoveredTriangulation::tessellation`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Tessellation<P = Portalgon> {
    /// The polygons (dense ids) and their side matching; corners labelled with vertex indices.
    pub portalgon: P,
    /// The triangulation faces merged into polygon `k` are
    /// `faces[face_start[k] as usize..face_start[k + 1] as usize]`, increasing ids.
    pub faces: Vec<FaceId>,
    /// Offsets into [`Tessellation::faces`], one per polygon plus one.
    pub face_start: Vec<u32>,
    /// The triangulation half-edge of each side (indexed by side id).
    pub side_halfedge: Vec<HalfedgeId>,
    /// The edges deleted (merged across), increasing ids.
    pub merged_edges: Vec<EdgeId>,
    /// Co-circular edges kept as sides because merging across them would close a cycle (0 in
    /// exact arithmetic).
    pub cycle_edges: usize,
}

impl<P> Tessellation<P> {
    /// The triangulation faces merged into polygon `k`.
    pub fn faces_of(&self, k: usize) -> &[FaceId] {
        &self.faces[self.face_start[k] as usize..self.face_start[k + 1] as usize]
    }

    /// The same tessellation with its polygons in another form.
    pub(crate) fn with_polygons<Q>(self, make: impl FnOnce(P) -> Q) -> Tessellation<Q> {
        Tessellation {
            portalgon: make(self.portalgon),
            faces: self.faces,
            face_start: self.face_start,
            side_halfedge: self.side_halfedge,
            merged_edges: self.merged_edges,
            cycle_edges: self.cycle_edges,
        }
    }
}

/// The polygons of a tessellation before they become a portalgon: sides numbered polygon after
/// polygon, each polygon's corners (counter-clockwise) and vertex labels by side.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Cells {
    /// The corner at the start of each side.
    pub corners: Vec<[f64; 2]>,
    /// The vertex label of each corner.
    pub labels: Vec<u32>,
    /// The first side of each polygon, and the side count at the end.
    pub side_start: Vec<u32>,
    /// Glued sides `(s, t, reversed)`, `s < t`, in increasing `s`: `reversed` when the two run
    /// the same way on the surface (an orientation-reversing gluing). Sides in no pair are
    /// boundary.
    pub gluings: Vec<(u32, u32, bool)>,
}

impl Cells {
    /// The sides of polygon `k`.
    pub(crate) fn sides(&self, k: usize) -> std::ops::Range<usize> {
        self.side_start[k] as usize..self.side_start[k + 1] as usize
    }
}

/// What the tessellation asks of the surface beyond the triangulation: a closed oriented surface
/// is the mesh itself ([`Closed`]); a surface with boundary or non-orientable is held on its
/// closed cover ([`crate::CoveredTriangulation`]).
pub(crate) trait CellSurface {
    /// The triangle of the surface a face of the mesh stands for (the first of its lifts);
    /// `None` for a face that is not on the surface (a virtual cone face).
    fn surface_face(&self, f: FaceId) -> Option<FaceId>;
    /// The edge of the surface an edge of the mesh stands for (the first of its lifts).
    fn surface_edge(&self, e: EdgeId) -> EdgeId;
    /// The label of a vertex in the output.
    fn label(&self, v: VertexId) -> u32;
    /// The other lift of a half-edge, running the other way on the other sheet.
    fn mirror(&self, h: HalfedgeId) -> Option<HalfedgeId>;
}

/// A closed oriented surface: the mesh itself, labels the dense vertex indices.
struct Closed(Vec<u32>);

impl CellSurface for Closed {
    #[inline(always)]
    fn surface_face(&self, f: FaceId) -> Option<FaceId> {
        Some(f)
    }
    #[inline(always)]
    fn surface_edge(&self, e: EdgeId) -> EdgeId {
        e
    }
    #[inline(always)]
    fn label(&self, v: VertexId) -> u32 {
        self.0[v.idx()]
    }
    #[inline(always)]
    fn mirror(&self, _: HalfedgeId) -> Option<HalfedgeId> {
        None
    }
}

/// Whether the edge's two triangles are co-circular within `tolerance` (and distinct).
pub fn is_cocircular(tri: &IntrinsicTriangulation, e: EdgeId, tolerance: f64) -> bool {
    let h = e.halfedge();
    let mesh = tri.mesh();
    mesh.face(h) != mesh.face(h.twin())
        && cocircular_product(tri.quad(h).delaunay_product(), tolerance)
}

/// `|√product - 1| <= tolerance`.
#[inline]
fn cocircular_product(product: f64, tolerance: f64) -> bool {
    (product.sqrt() - 1.0).abs() <= tolerance
}

/// The Delaunay tessellation of a Delaunay triangulation (see the module doc). The input is not
/// checked to be Delaunay: run [`crate::flip_to_delaunay`] first; an edge that is not Delaunay
/// simply stays a side.
pub fn delaunay_tessellation(tri: &IntrinsicTriangulation, tolerance: f64) -> Tessellation {
    let (dense, _) = dense_vertex_index(tri);
    tessellate(tri, tolerance, &Closed(dense)).with_polygons(|cells| {
        let mut portalgon = Portalgon::new();
        let mut side_ids: Vec<SideId> = Vec::with_capacity(cells.corners.len());
        for k in 0..cells.side_start.len() - 1 {
            let sides = cells.sides(k);
            let count = sides.len();
            let p =
                portalgon.push_polygon(&cells.corners[sides.clone()], Some(&cells.labels[sides]));
            side_ids.extend((0..count).map(|i| portalgon.side(p, i)));
        }
        for &(s, t, _) in &cells.gluings {
            portalgon.set_mates(side_ids[s as usize], side_ids[t as usize]);
        }
        portalgon
    })
}

/// The tessellation of the surface `surface` says `tri` is (see the module doc): co-circular
/// interior edges of the surface merged along a spanning forest over its triangles, each polygon
/// laid out on one lift.
pub(crate) fn tessellate<C: CellSurface>(
    tri: &IntrinsicTriangulation,
    tolerance: f64,
    surface: &C,
) -> Tessellation<Cells> {
    let merge = merge_cocircular(tri, tolerance, surface);
    let layout = lay_out_regions(tri, surface, &merge.merged);
    let (cells, side_halfedge) = walk_sides(tri, surface, &merge.merged, &layout);
    Tessellation {
        portalgon: cells,
        faces: layout.faces,
        face_start: layout.face_start,
        side_halfedge,
        merged_edges: merge.merged_edges,
        cycle_edges: merge.cycle_edges,
    }
}

/// The co-circular interior edges merged by [`merge_cocircular`].
struct Merge {
    /// Per edge slot: merged (both lifts of a surface edge alike).
    merged: Vec<bool>,
    /// The merged edges, first lifts, in the order merged.
    merged_edges: Vec<EdgeId>,
    /// Co-circular edges left unmerged because they would close a cycle.
    cycle_edges: usize,
}

/// Merges co-circular interior edges of the surface along a spanning forest over its triangles
/// (an edge whose two triangles are already one region is left, counted in `cycle_edges`).
fn merge_cocircular<C: CellSurface>(
    tri: &IntrinsicTriangulation,
    tolerance: f64,
    surface: &C,
) -> Merge {
    let mesh = tri.mesh();
    let mut regions = UnionFind::new(mesh.face_slots());
    let mut merged = vec![false; mesh.edge_slots()];
    let mut merged_edges = Vec::new();
    let mut cycle_edges = 0usize;
    let t2 = tri.halfedge_tan_half_sq();
    for e in mesh.edges() {
        if surface.surface_edge(e) != e {
            continue;
        }
        let h = e.halfedge();
        let faces = [h, h.twin()].map(|g| surface.surface_face(mesh.face(g)));
        let [Some(f), Some(g)] = faces else {
            continue; // a boundary or apex edge
        };
        if f == g || !cocircular_product(t2[h.idx()] * t2[h.twin().idx()], tolerance) {
            continue;
        }
        let (a, b) = (regions.find(f.0), regions.find(g.0));
        if a == b {
            cycle_edges += 1;
            continue;
        }
        regions.union(a, b);
        merged[e.idx()] = true;
        merged_edges.push(e);
    }
    // The other lift of a merged edge is merged too.
    for e in mesh.edges() {
        let first = surface.surface_edge(e);
        if first != e {
            merged[e.idx()] = merged[first.idx()];
        }
    }
    Merge {
        merged,
        merged_edges,
        cycle_edges,
    }
}

/// Each region laid out on one lift by [`lay_out_regions`].
struct Layout {
    /// Per half-edge: the position of its origin in the placement of its face.
    pos: Vec<[f64; 2]>,
    /// The surface triangles of each region, sorted, region `r` at
    /// `faces[face_start[r]..face_start[r + 1]]`.
    faces: Vec<FaceId>,
    face_start: Vec<u32>,
    /// The faces of the lift each region was laid out on, region `r` at
    /// `lifts[lift_start[r]..lift_start[r + 1]]`.
    lifts: Vec<FaceId>,
    lift_start: Vec<usize>,
}

/// Lays out each region on one lift, breadth first across merged edges from its first face.
fn lay_out_regions<C: CellSurface>(
    tri: &IntrinsicTriangulation,
    surface: &C,
    merged: &[bool],
) -> Layout {
    let mesh = tri.mesh();
    let nf = mesh.face_slots();
    // `placed` by surface triangle, the lift's faces in `lifts`.
    let mut pos = vec![[f64::NAN; 2]; mesh.halfedge_slots()];
    let mut placed = vec![false; nf];
    let mut faces: Vec<FaceId> = Vec::with_capacity(mesh.face_count());
    let mut face_start: Vec<u32> = vec![0];
    let mut lifts: Vec<FaceId> = Vec::with_capacity(mesh.face_count());
    let mut lift_start: Vec<usize> = vec![0];
    let mut queue: Vec<FaceId> = Vec::new();
    for f0 in mesh.faces() {
        if surface.surface_face(f0) != Some(f0) || placed[f0.idx()] {
            continue;
        }
        placed[f0.idx()] = true;
        let key = |g| surface.surface_face(g).expect("a merged edge is interior");
        tri.lay_out_region(f0, merged, &mut placed, key, &mut pos, &mut queue);
        lifts.extend_from_slice(&queue);
        lift_start.push(lifts.len());
        let region = faces.len();
        faces.extend(
            queue
                .iter()
                .map(|&f| surface.surface_face(f).expect("real")),
        );
        faces[region..].sort_unstable();
        face_start.push(faces.len() as u32);
    }
    Layout {
        pos,
        faces,
        face_start,
        lifts,
        lift_start,
    }
}

/// The polygons: the boundary walk of each region on its lift (the sides, from the least
/// unmerged half-edge), then each side glued to the side across its edge. Returns the cells and
/// the half-edge of each side.
fn walk_sides<C: CellSurface>(
    tri: &IntrinsicTriangulation,
    surface: &C,
    merged: &[bool],
    layout: &Layout,
) -> (Cells, Vec<HalfedgeId>) {
    let mesh = tri.mesh();
    let (pos, lifts) = (&layout.pos, &layout.lifts);
    let mut side_of = vec![u32::MAX; mesh.halfedge_slots()];
    let mut side_halfedge = Vec::with_capacity(mesh.halfedge_slots());
    let mut cells = Cells {
        side_start: vec![0],
        ..Cells::default()
    };
    for region in layout.lift_start.windows(2) {
        let region = &lifts[region[0]..region[1]];
        let start = region
            .iter()
            .flat_map(|&f| mesh.face_halfedges(f))
            .filter(|h| !merged[h.edge().idx()])
            .min()
            .expect("a region has a side");
        let first_side = side_halfedge.len();
        let mut h = start;
        loop {
            side_of[h.idx()] = side_halfedge.len() as u32;
            side_halfedge.push(h);
            cells.corners.push(pos[h.idx()]);
            cells.labels.push(surface.label(mesh.origin(h)));
            let mut g = mesh.next(h);
            while merged[g.edge().idx()] {
                g = mesh.next(g.twin());
            }
            if g == start {
                break;
            }
            h = g;
        }
        debug_assert_eq!(side_halfedge.len() - first_side, region.len() + 2);
        cells.side_start.push(side_halfedge.len() as u32);
    }
    // Each side is glued to the side across its edge on the lift that was laid out: its twin,
    // or (on the other sheet) its twin's mirror, which runs the same way.
    for (s, &h) in side_halfedge.iter().enumerate() {
        let t = h.twin();
        if surface.surface_face(mesh.face(t)).is_none() {
            continue; // a boundary side
        }
        let (other, reversed) = match side_of[t.idx()] {
            u32::MAX => {
                let m = surface.mirror(t).expect("the other lift was laid out");
                (side_of[m.idx()], true)
            }
            other => (other, false),
        };
        debug_assert_ne!(other, u32::MAX);
        if (s as u32) < other {
            cells.gluings.push((s as u32, other, reversed));
        }
    }
    (cells, side_halfedge)
}
