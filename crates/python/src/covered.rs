//! Surfaces with boundary, non-orientable or in pieces, on their closed cover
//! (`surftopo_intrinsic::CoveredTriangulation`): what `intrinsic_delaunay` and `laplacian` take
//! beside closed orientable meshes.

use crate::errors::Failure;
use crate::surface::input_index;
use surftopo_intrinsic::{CoveredTriangulation, DelaunayInput, DelaunayOutput, DelaunayRequest};
use surftopo_mesh::{BuildReport, CoveredSurface, EdgeId};

/// A surface K on its closed cover and where its vertices go in the output matrices.
pub(crate) struct Covered {
    /// K's intrinsic triangulation.
    pub tri: CoveredTriangulation,
    /// Output row of each vertex of K (the matrices' dense rows), increasing.
    pub rows: Vec<u32>,
    /// Number of output rows (the input's vertices, referenced or not).
    pub count: usize,
}

impl Covered {
    /// The intrinsic triangulation of a mesh in space of any surface kind, built from `count`
    /// input vertices ([`CoveredSurface::from_triangles`] and its report); rows are the input
    /// vertex indices.
    pub fn from_surface(
        surface: CoveredSurface,
        report: &BuildReport,
        count: usize,
    ) -> Result<Self, Failure> {
        let tri = CoveredTriangulation::from_surface(surface).map_err(Failure::Geometry)?;
        Ok(Self {
            tri,
            rows: input_index(report),
            count,
        })
    }

    /// The surface of a portalgon file of triangles with free sides, orientation-reversing
    /// gluings or several pieces ([`CoveredTriangulation::from_doc`]); rows are its labels.
    pub fn from_doc(doc: &surftopo_intrinsic::PortalgonDoc) -> Result<Self, Failure> {
        let tri = CoveredTriangulation::from_doc(doc, surftopo_intrinsic::DEFAULT_LENGTH_TOLERANCE)
            .map_err(Failure::Portalgon)?;
        let count = tri.surface_vertex_count();
        Ok(Self {
            tri,
            rows: (0..count as u32).collect(),
            count,
        })
    }

    /// Runs `surftopo_intrinsic::intrinsic_delaunay` with `request` (which asks for the
    /// triangulation): the flipped surface and the output.
    pub fn delaunay(self, request: &DelaunayRequest) -> Result<(Self, DelaunayOutput), Failure> {
        let input = DelaunayInput::Covered(self.tri);
        let mut out =
            surftopo_intrinsic::intrinsic_delaunay(input, request).map_err(Failure::Intrinsic)?;
        let tri = out.covered.take().expect("the triangulation is asked for");
        let flipped = Self {
            tri,
            rows: self.rows,
            count: self.count,
        };
        Ok((flipped, out))
    }

    /// The output row of each corner of K's triangles, corner `i` to corner `i + 1` being side
    /// `i` (in the first lift's orientation).
    pub fn face_rows(&self) -> Vec<[u32; 3]> {
        let mesh = self.tri.cover().mesh();
        self.tri
            .surface_faces()
            .map(|f| mesh.face_vertices(f).map(|v| self.row(v)))
            .collect()
    }

    /// The output rows of the ends of K's edges.
    pub fn edge_rows(&self) -> Vec<[u32; 2]> {
        let mesh = self.tri.cover().mesh();
        self.tri
            .surface_edges()
            .map(|e| mesh.edge_vertices(e).map(|v| self.row(v)))
            .collect()
    }

    /// The edge (rank among K's edges) of each side of K's triangles.
    pub fn face_edges(&self) -> Vec<[u32; 3]> {
        let mesh = self.tri.cover().mesh();
        let mut rank = vec![u32::MAX; mesh.edge_slots()];
        for (k, e) in self.tri.surface_edges().enumerate() {
            rank[e.idx()] = k as u32;
        }
        self.tri
            .surface_faces()
            .map(|f| {
                mesh.face_halfedges(f)
                    .map(|h| rank[self.tri.surface_edge(h.edge()).idx()])
            })
            .collect()
    }

    /// The length of each of K's edges, in the order of [`Self::edge_rows`].
    pub fn edge_lengths(&self) -> Vec<f64> {
        let cover = self.tri.cover();
        let lengths: Vec<EdgeId> = self.tri.surface_edges().collect();
        lengths.iter().map(|&e| cover.length(e)).collect()
    }

    /// The output row of a vertex of the cover.
    fn row(&self, v: surftopo_mesh::VertexId) -> u32 {
        self.rows[self.tri.class(v) as usize]
    }
}
