//! Conversions between [`IntrinsicTriangulation`] (topology + lengths) and [`Portalgon`]
//! (polygons in the plane + side matching), through `SurfaceMesh::from_gluing`.
//!
//! Numbering, both ways: the `k`-th live face is the `k`-th polygon and its side `i` is the face's
//! half-edge `face_halfedges(f)[i]`; edge `k` of a triangulation built from a gluing is its `k`-th
//! matched pair (pairs listed by increasing first side); vertex labels are the dense vertex
//! indices (the Laplacian's row numbers), and a triangulation built from a labelled portalgon gets
//! exactly those vertex ids back.

use crate::error::PortalgonError;
use crate::geometry::Scalar;
use crate::portalgon::{Portalgon, SideId, signed_area};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::dense_vertex_index;
use surftopo_mesh::{EdgeId, FaceId, Renumbering, Side, SurfaceMesh, VertexId};

/// Triangles glued side to side, as read from a file or a portalgon.
pub(crate) struct TriangleGluing<'a> {
    /// Side lengths of each triangle (side i from corner i to corner i + 1).
    pub sides: &'a [[f64; 3]],
    /// The matched pairs of sides.
    pub pairs: &'a [(Side, Side)],
    /// Vertex label of each corner, if known.
    pub labels: Option<&'a [[u32; 3]]>,
    /// Input polygon index of each triangle, for error messages.
    pub polygon_index: &'a [usize],
    /// Relative tolerance on matched lengths.
    pub tolerance: f64,
}

/// Builds the triangulation of a gluing: lengths of matched sides must agree within the tolerance
/// (the edge gets their mean), the gluing must close up into a connected surface, and labels (if
/// any) must give one label per vertex, a permutation of `0..V`. Triangle inequalities are *not*
/// checked here (degenerate input may still be mollified): see [`IntrinsicTriangulation::validate`].
pub(crate) fn triangulation_from_gluing(
    g: &TriangleGluing<'_>,
) -> Result<IntrinsicTriangulation, PortalgonError> {
    check_glued_lengths(g)?;
    let (mut mesh, corner_vertex) =
        SurfaceMesh::from_gluing(g.sides.len(), g.pairs).map_err(|e| match e {
            surftopo_mesh::BuildError::SideUnglued { face, side } => PortalgonError::Unmatched {
                polygon: g.polygon_index[face],
                side,
            },
            other => gluing_error(g, other),
        })?;
    let lengths: Vec<f64> = g
        .pairs
        .iter()
        .map(|&(s, t)| glued_length(g.side_length(s), g.side_length(t)))
        .collect();
    if let Some(labels) = g.labels {
        let label_of = label_vertices(g, labels, |c| corner_vertex[c].idx(), mesh.vertex_count())?;
        let map = Renumbering {
            vertices: label_of.into_iter().map(VertexId).collect(),
            edges: (0..mesh.edge_slots()).map(EdgeId::new).collect(),
            faces: (0..mesh.face_slots()).map(FaceId::new).collect(),
        };
        mesh.renumber(&map);
    }
    Ok(IntrinsicTriangulation::from_parts(mesh, lengths)?)
}

impl TriangleGluing<'_> {
    /// The length of a side.
    pub(crate) fn side_length(&self, s: Side) -> f64 {
        self.sides[s.face as usize][s.side as usize]
    }
}

/// The length of the edge two glued sides make: their common value, or their mean.
pub(crate) fn glued_length(a: f64, b: f64) -> f64 {
    if a == b { a } else { 0.5 * (a + b) }
}

/// A gluing's structural error in the file's terms.
pub(crate) fn gluing_error(g: &TriangleGluing<'_>, e: surftopo_mesh::BuildError) -> PortalgonError {
    match e {
        surftopo_mesh::BuildError::SideGluedTwice { face, side } => PortalgonError::MatchedTwice {
            polygon: g.polygon_index.get(face).copied().unwrap_or(face),
            side,
        },
        other => PortalgonError::Gluing(other),
    }
}

/// Checks that glued sides have equal lengths within the tolerance (relative).
///
/// # Errors
/// [`PortalgonError::UnequalSides`], naming both sides.
pub(crate) fn check_glued_lengths(g: &TriangleGluing<'_>) -> Result<(), PortalgonError> {
    for &(s, t) in g.pairs {
        let bad = |x: Side| x.face as usize >= g.sides.len() || x.side > 2;
        if bad(s) || bad(t) {
            continue; // the gluing names it
        }
        let (la, lb) = (g.side_length(s), g.side_length(t));
        if (la - lb).abs() > g.tolerance * la.max(lb) {
            return Err(PortalgonError::UnequalSides {
                polygon_a: g.polygon_index[s.face as usize],
                side_a: s.side as usize,
                polygon_b: g.polygon_index[t.face as usize],
                side_b: t.side as usize,
                length_a: la,
                length_b: lb,
                tolerance: g.tolerance,
            });
        }
    }
    Ok(())
}

/// Checks that the corners' labels name the gluing's vertices (`vertex_of(c)` for corner
/// `3f + i`, `0..vertex_count`) one to one, and returns the label of each vertex.
///
/// # Errors
/// [`PortalgonError::VertexLabels`], naming the polygon: a label out of range, two vertices
/// under one label, or one vertex under two.
pub(crate) fn label_vertices(
    g: &TriangleGluing<'_>,
    labels: &[[u32; 3]],
    vertex_of: impl Fn(usize) -> usize,
    vertex_count: usize,
) -> Result<Vec<u32>, PortalgonError> {
    let mut label_of = vec![u32::MAX; vertex_count];
    let mut vertex_of_label = vec![u32::MAX; vertex_count];
    for c in 0..3 * labels.len() {
        let (f, i, v) = (c / 3, c % 3, vertex_of(c));
        let l = labels[f][i];
        let polygon = g.polygon_index[f];
        if l as usize >= vertex_count {
            return Err(PortalgonError::VertexLabels {
                polygon,
                detail: format!("label {l} out of range: the gluing has {vertex_count} vertices"),
            });
        }
        if label_of[v] == u32::MAX {
            if vertex_of_label[l as usize] != u32::MAX {
                return Err(PortalgonError::VertexLabels {
                    polygon,
                    detail: format!("label {l} names two different vertices of the gluing"),
                });
            }
            label_of[v] = l;
            vertex_of_label[l as usize] = v as u32;
        } else if label_of[v] != l {
            return Err(PortalgonError::VertexLabels {
                polygon,
                detail: format!(
                    "corner {i} is labelled {l} but the gluing makes it vertex {}",
                    label_of[v]
                ),
            });
        }
    }
    Ok(label_of)
}

impl IntrinsicTriangulation {
    /// The triangulation of a closed triangular portalgon: side lengths from the corner
    /// coordinates, matched lengths equal within `tolerance` (relative; the edge gets their mean),
    /// vertex ids from the labels when every corner is labelled. Face `k` is the `k`-th live
    /// polygon.
    ///
    /// # Errors
    /// [`PortalgonError::Empty`], [`PortalgonError::NotTriangle`], [`PortalgonError::Unmatched`],
    /// [`PortalgonError::UnequalSides`], [`PortalgonError::VertexLabels`],
    /// [`PortalgonError::Gluing`] (not connected).
    pub fn from_portalgon<S: Scalar>(
        p: &Portalgon<S>,
        tolerance: f64,
    ) -> Result<Self, PortalgonError> {
        let polygons: Vec<_> = p.polygons().collect();
        if polygons.is_empty() {
            return Err(PortalgonError::Empty);
        }
        let mut rank = vec![u32::MAX; p.polygon_slots()];
        let mut sides = Vec::with_capacity(polygons.len());
        let mut labels = Vec::with_capacity(polygons.len());
        let mut all_labelled = true;
        for (k, &q) in polygons.iter().enumerate() {
            let s = p.polygon_sides(q);
            if s.len() != 3 {
                return Err(PortalgonError::NotTriangle {
                    polygon: q.idx(),
                    sides: s.len(),
                });
            }
            rank[q.idx()] = k as u32;
            sides.push([0, 1, 2].map(|i| p.side_length(s[i])));
            let l = [0, 1, 2].map(|i| p.vertex_label(s[i]));
            all_labelled &= l.iter().all(Option::is_some);
            labels.push(l.map(|x| x.unwrap_or(u32::MAX)));
        }
        let as_side = |s: SideId| Side {
            face: rank[p.owner(s).idx()],
            side: p.side_index(s) as u8,
        };
        let mut pairs = Vec::with_capacity(p.side_count() / 2);
        for s in p.sides() {
            match p.mate(s) {
                None => {
                    return Err(PortalgonError::Unmatched {
                        polygon: p.owner(s).idx(),
                        side: p.side_index(s),
                    });
                }
                Some(t) if s < t => pairs.push((as_side(s), as_side(t))),
                Some(_) => {}
            }
        }
        let polygon_index: Vec<usize> = polygons.iter().map(|q| q.idx()).collect();
        triangulation_from_gluing(&TriangleGluing {
            sides: &sides,
            pairs: &pairs,
            labels: all_labelled.then_some(&labels[..]),
            polygon_index: &polygon_index,
            tolerance,
        })
    }

    /// The triangular portalgon of this triangulation: each live face laid out in its own plane
    /// ([`IntrinsicTriangulation::layout_face`]), sides matched along edges, corners labelled with
    /// dense vertex indices. Returns it with the side of each half-edge (indexed by half-edge id).
    pub fn to_portalgon(&self) -> (Portalgon, Vec<SideId>) {
        let mesh = self.mesh();
        let (dense, _) = dense_vertex_index(self);
        let mut p = Portalgon::new();
        let mut side_of = vec![SideId::INVALID; mesh.halfedge_slots()];
        for f in mesh.faces() {
            let hs = mesh.face_halfedges(f);
            let labels = hs.map(|h| dense[mesh.origin(h).idx()]);
            let q = p.push_polygon(&self.layout_face(f), Some(&labels));
            for (i, h) in hs.into_iter().enumerate() {
                side_of[h.idx()] = p.side(q, i);
            }
        }
        for e in mesh.edges() {
            let h = e.halfedge();
            p.set_mates(side_of[h.idx()], side_of[h.twin().idx()]);
        }
        (p, side_of)
    }
}

/// Whether a triangle given by corners runs clockwise (negative signed area).
pub(crate) fn is_clockwise(corners: &[[f64; 2]]) -> bool {
    signed_area(corners) < 0.0
}
