//! Intrinsic Delaunay triangulations, their Laplacian and mass matrices as `scipy.sparse`
//! matrices, portalgons, and the isometry test.
//!
//! Matrix rows and columns are the input's vertex indices: `len(V)` rows for a mesh (an
//! unreferenced vertex gets an empty row and column), the dense vertex order for a portalgon.

use crate::arrays::{self, VertexArray, index_array, vector};
use crate::covered::Covered;
use crate::errors::{Failure, invalid};
use crate::interrupt::interruptible;
use crate::surface::{choose, input_index, json_to_python};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::time::Instant;
use surftopo_intrinsic::geometry::Rational;
use surftopo_intrinsic::{
    CoveredTriangulation, DEFAULT_COCIRCULAR_TOLERANCE, DEFAULT_LENGTH_TOLERANCE,
    DEFAULT_MOLLIFY_FACTOR, DEFAULT_TOLERANCE, DelaunayInput, DelaunayMethod, DelaunayOutputs,
    DelaunayRequest, DelaunayStats, FlipReport, IntrinsicTriangulation, IsometryDecision,
    IsometryOptions, PortalgonDoc, SparseMatrix, TriangleStyle, TuftedOptions, cotan_laplacian,
    delaunay_tessellation, lumped_mass,
};
use surftopo_mesh::{BuildReport, CoveredSurface};

/// The `method=` names: every method of `surftopo_intrinsic::intrinsic_delaunay`.
fn methods() -> [(&'static str, DelaunayMethod); 4] {
    DelaunayMethod::ALL.map(|m| (m.name(), m))
}

/// An intrinsic triangulation and where its vertices go in the output matrices.
struct Located {
    tri: IntrinsicTriangulation,
    /// Output row of each vertex id (`u32::MAX` for a removed id).
    row_of: Vec<u32>,
    /// Number of output rows.
    rows: usize,
}

impl Located {
    /// The intrinsic triangulation of a mesh in space; rows are the input vertex indices.
    fn from_arrays(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> Result<Self, Failure> {
        let (tri, report) =
            IntrinsicTriangulation::from_soup(positions, triangles).map_err(|e| match e {
                surftopo_intrinsic::SoupError::Build(b) => Failure::Build(b),
                surftopo_intrinsic::SoupError::Geometry(g) => Failure::Geometry(g),
            })?;
        Ok(Self::built(tri, &report, positions.len()))
    }

    /// A triangulation built from `rows` input vertices with `report`: rows are the input
    /// vertex indices.
    fn built(tri: IntrinsicTriangulation, report: &BuildReport, rows: usize) -> Self {
        let mut row_of = input_index(report);
        row_of.resize(tri.mesh().vertex_slots(), u32::MAX);
        Self { tri, row_of, rows }
    }

    /// A triangulation without input vertices (a portalgon): rows in vertex id order.
    fn dense(tri: IntrinsicTriangulation) -> Self {
        let (row_of, rows) = (tri.matrix_rows(), tri.mesh().vertex_count());
        Self { tri, row_of, rows }
    }

    /// Runs `surftopo_intrinsic::intrinsic_delaunay` on the triangulation with `request`: the
    /// Delaunay triangulation with its rows (the wave's triangulation numbers the vertices by
    /// their dense index in the input) and the output.
    fn delaunay(
        self,
        request: &DelaunayRequest,
    ) -> Result<(Self, surftopo_intrinsic::DelaunayOutput), Failure> {
        let dense_rows = self.dense_rows();
        let input = DelaunayInput::Lengths(self.tri);
        let mut out =
            surftopo_intrinsic::intrinsic_delaunay(input, request).map_err(Failure::Intrinsic)?;
        let tri = out
            .triangulation
            .take()
            .expect("the triangulation is asked for");
        let row_of = if out.method == DelaunayMethod::Flip {
            self.row_of
        } else {
            let mut row_of = vec![u32::MAX; tri.mesh().vertex_slots()];
            for v in tri.mesh().vertices() {
                row_of[v.idx()] = dense_rows.get(v.idx()).copied().unwrap_or(u32::MAX);
            }
            row_of
        };
        let located = Self {
            tri,
            row_of,
            rows: self.rows,
        };
        Ok((located, out))
    }

    /// [`Self::delaunay`] in exact arithmetic on a portalgon given by exact corners: rows in the
    /// output's vertex order.
    fn exact_delaunay(
        p: surftopo_intrinsic::Portalgon<Rational>,
        request: &DelaunayRequest,
    ) -> Result<(Self, surftopo_intrinsic::DelaunayOutput), Failure> {
        let mut out = surftopo_intrinsic::intrinsic_delaunay(DelaunayInput::Exact(p), request)
            .map_err(Failure::Intrinsic)?;
        let tri = out
            .triangulation
            .take()
            .expect("the triangulation is asked for");
        Ok((Self::dense(tri), out))
    }

    /// Output row of each dense matrix index (the live vertices in id order).
    fn dense_rows(&self) -> Vec<u32> {
        self.tri
            .mesh()
            .vertices()
            .map(|v| self.row_of[v.idx()])
            .collect()
    }
}

/// The arrays of a `scipy.sparse.csr_matrix`: index arrays int32 when they fit (as scipy makes
/// them), else int64.
pub(crate) enum CsrIndices {
    /// `indices`, `indptr` as int32.
    Narrow(Vec<i32>, Vec<i32>),
    /// `indices`, `indptr` as int64.
    Wide(Vec<i64>, Vec<i64>),
}

/// A square CSR matrix ready for scipy (built without the GIL).
pub(crate) struct Csr {
    rows: usize,
    data: Vec<f64>,
    indices: CsrIndices,
}

impl Csr {
    /// `m` with its dense rows and columns moved to `rows_of_dense` (increasing, so rows stay
    /// sorted) in a `rows x rows` matrix.
    pub(crate) fn new(m: SparseMatrix, rows_of_dense: &[u32], rows: usize) -> Self {
        let mut indptr = vec![0usize; rows + 1];
        for (k, &r) in rows_of_dense.iter().enumerate() {
            indptr[r as usize + 1] = m.row_start[k + 1] - m.row_start[k];
        }
        for i in 0..rows {
            indptr[i + 1] += indptr[i];
        }
        let identity = rows == m.n;
        let indices = if rows <= i32::MAX as usize && indptr[rows] <= i32::MAX as usize {
            // Converted in place: `into_iter().map().collect()` reuses the `u32` buffer.
            let cols = if identity {
                m.cols.into_iter().map(|c| c as i32).collect()
            } else {
                m.cols
                    .into_iter()
                    .map(|c| rows_of_dense[c as usize] as i32)
                    .collect()
            };
            CsrIndices::Narrow(cols, indptr.iter().map(|&p| p as i32).collect())
        } else {
            let cols = m.cols.iter().map(|&c| i64::from(rows_of_dense[c as usize]));
            CsrIndices::Wide(cols.collect(), indptr.iter().map(|&p| p as i64).collect())
        };
        Self {
            rows,
            data: m.values,
            indices,
        }
    }

    /// The `scipy.sparse` matrix in `format`: `"csr"` (the arrays handed over without a copy)
    /// or `"csc"` (robust_laplacian's; the same matrix, converted by scipy).
    fn into_format<'py>(self, py: Python<'py>, format: Format) -> PyResult<Bound<'py, PyAny>> {
        let csr = self.into_scipy(py)?;
        match format {
            Format::Csr => Ok(csr),
            Format::Csc => csr.call_method0("tocsc"),
        }
    }

    /// The `scipy.sparse.csr_matrix` (the arrays are handed over without a copy).
    pub(crate) fn into_scipy(self, py: Python<'_>) -> PyResult<Bound<'_, PyAny>> {
        let data = vector(py, self.data);
        let (indices, indptr) = match self.indices {
            CsrIndices::Narrow(i, p) => (vector(py, i).into_any(), vector(py, p).into_any()),
            CsrIndices::Wide(i, p) => (vector(py, i).into_any(), vector(py, p).into_any()),
        };
        let kwargs = PyDict::new(py);
        kwargs.set_item("shape", (self.rows, self.rows))?;
        py.import("scipy.sparse")?
            .getattr("csr_matrix")?
            .call(((data, indices, indptr),), Some(&kwargs))
    }
}

/// The sparse format of the matrices returned.
#[derive(Clone, Copy)]
enum Format {
    Csr,
    Csc,
}

/// `format=` of [`laplacian`].
fn sparse_format(name: &str) -> Result<Format, Failure> {
    choose(
        "format",
        name,
        &[("csr", Format::Csr), ("csc", Format::Csc)],
    )
}

/// The CLI's refusal of matrices that are not representable (`inf` entries, a mass matrix of
/// zeros: coordinates of 1e200 or 1e-200), as an `InvalidGeometryError`.
fn check_matrices(l: &SparseMatrix, m: &SparseMatrix) -> Result<(), Failure> {
    let refuse =
        |what: &str, e: String| Failure::Invalid("InvalidGeometryError", format!("{what}: {e}"));
    l.check_representable(false)
        .map_err(|e| refuse("the cotan Laplacian", e))?;
    m.check_representable(true)
        .map_err(|e| refuse("the mass matrix", e))
}

/// The request of the Python arguments: `method=`, the flip limits, and the outputs.
fn request(
    method: &str,
    mollify: Option<f64>,
    max_flips: Option<u64>,
    outputs: DelaunayOutputs,
) -> Result<DelaunayRequest, Failure> {
    Ok(DelaunayRequest {
        method: choose("method", method, &methods())?,
        outputs,
        mollify,
        max_flips,
        ..DelaunayRequest::default()
    })
}

/// `exact=True` on a surface not given by exact corners.
fn not_exact() -> Failure {
    invalid(
        "exact=True needs a Portalgon given by exact corners (a mesh's lengths are square roots)",
    )
}

/// The exact portalgon of `surface` for `exact=True`: a [`Portalgon`] given by exact corners
/// (a mesh's lengths are square roots).
fn exact_portalgon(
    surface: &Bound<'_, PyAny>,
    faces: Option<&Bound<'_, PyAny>>,
) -> Result<surftopo_intrinsic::Portalgon<Rational>, Failure> {
    if faces.is_some() {
        return Err(not_exact());
    }
    let p = surface.cast::<Portalgon>().map_err(|_| not_exact())?;
    let p = p
        .get()
        .doc
        .to_portalgon_in::<Rational>(0.0)
        .map_err(Failure::Portalgon)?;
    p.check_closed().map_err(Failure::Portalgon)?;
    Ok(p)
}

/// A closed polyhedral surface given by flat polygons glued along their sides (a portalgon,
/// `crates/intrinsic/PORTALGON_FORMAT.md`): its JSON document.
#[pyclass(frozen, module = "surftopo", name = "Portalgon")]
pub struct Portalgon {
    doc: PortalgonDoc,
    /// Why doubles cannot hold the document's exact corners (it is valid exactly): the error
    /// every double-precision use gives.
    exact_only: Option<surftopo_intrinsic::PortalgonError>,
}

#[pymethods]
impl Portalgon {
    /// Parses and validates a portalgon JSON text (exact corners valid exactly are kept even
    /// where doubles cannot hold them, for `exact=True`).
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str) -> PyResult<Self> {
        let doc =
            PortalgonDoc::from_json(text).map_err(|e| Failure::Portalgon(e).into_pyerr(py))?;
        if doc.needs_cover() {
            // Triangles with free sides, reversed gluings (version 2) or several pieces.
            Covered::from_doc(&doc).map_err(|f| f.into_pyerr(py))?;
            return Ok(Self {
                doc,
                exact_only: None,
            });
        }
        // Exact corners that doubles cannot hold (a side of 10^30 + 1 rounds to a zero side)
        // are kept when they are valid exactly: `exact=True` computes on them, the
        // double-precision methods refuse them with this error.
        let exact_only = doc.to_portalgon(DEFAULT_LENGTH_TOLERANCE).err();
        if let Some(e) = &exact_only {
            let exact_ok = doc
                .to_portalgon_in::<Rational>(0.0)
                .is_ok_and(|p| p.check_closed().is_ok());
            if !exact_ok {
                return Err(Failure::Portalgon(e.clone()).into_pyerr(py));
            }
        }
        Ok(Self { doc, exact_only })
    }

    /// The JSON text (compact, one line).
    fn to_json(&self, py: Python<'_>) -> PyResult<String> {
        self.doc
            .to_json()
            .map_err(|e| Failure::Portalgon(e).into_pyerr(py))
    }

    /// Number of polygons.
    #[getter]
    fn polygon_count(&self) -> usize {
        self.doc.polygons.len()
    }

    /// Number of polygon sides (twice the number of glued pairs on a closed surface).
    #[getter]
    fn side_count(&self) -> usize {
        self.doc
            .polygons
            .iter()
            .map(|p| match (&p.corners, &p.lengths) {
                (Some(c), _) => c.len(),
                (None, Some(l)) => l.len(),
                (None, None) => 0,
            })
            .sum()
    }

    /// Number of glued side pairs.
    #[getter]
    fn matched_pairs(&self) -> usize {
        self.doc.matching.len()
    }

    /// Total area (of the polygons: the gluing, orientation-reversing or not, plays no part).
    #[getter]
    fn area(&self, py: Python<'_>) -> PyResult<f64> {
        let polygons = PortalgonDoc {
            matching: Vec::new(),
            reversed: Vec::new(),
            ..self.doc.clone()
        };
        polygons
            .to_portalgon(DEFAULT_LENGTH_TOLERANCE)
            .map(|p| p.area())
            .map_err(|e| Failure::Portalgon(e).into_pyerr(py))
    }

    fn __repr__(&self) -> String {
        format!(
            "Portalgon({} polygons, {} sides)",
            self.polygon_count(),
            self.side_count()
        )
    }
}

impl Portalgon {
    /// The intrinsic triangulation of a triangular portalgon.
    fn triangulation(&self) -> Result<IntrinsicTriangulation, Failure> {
        if let Some(e) = &self.exact_only {
            // Valid exactly, not in doubles: a numerical failure of double precision, as the
            // CLI's exit 4.
            return Err(Failure::Invalid(
                "NumericalBreakdownError",
                format!(
                    "{e} (its exact corners are valid: use exact=True with method='voronoi' or 'dubois')"
                ),
            ));
        }
        self.doc
            .to_triangulation(DEFAULT_LENGTH_TOLERANCE)
            .map_err(Failure::Portalgon)
    }
}

/// An intrinsic Delaunay triangulation: its topology, edge lengths and the matrices.
#[pyclass(frozen, module = "surftopo", name = "IntrinsicTriangulation")]
pub struct Intrinsic {
    held: Held,
    stats: DelaunayStats,
}

/// The triangulation an [`Intrinsic`] holds.
enum Held {
    /// A closed orientable surface (every method).
    Closed(Located),
    /// A surface with boundary, non-orientable or in pieces, on its closed cover (flipping).
    Covered(Covered),
    /// Any triangle soup through its tufted cover (Sharp & Crane 2020): the cover flipped, its
    /// vertices' rows the input vertices they cover, and the folded matrices.
    Tufted {
        located: Located,
        laplacian: SparseMatrix,
        mass: SparseMatrix,
    },
}

impl Held {
    /// A mesh in space, built once ([`CoveredSurface::from_triangles`]): a closed orientable
    /// surface in one piece as itself (every method), any other surface (boundary,
    /// non-orientable, in pieces) on its closed cover. The build errors are
    /// `surftopo_mesh::build`'s (the first problem the soup has).
    fn from_arrays(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> Result<Self, Failure> {
        let (surface, report) = CoveredSurface::from_triangles(positions.to_vec(), triangles)?;
        if report.surfaces.len() == 1 && surface.cover.is_plain() {
            let plain = surface
                .into_plain()
                .expect("a plain cover is a closed surface");
            let tri = IntrinsicTriangulation::from_positions(plain.mesh, &plain.positions)
                .map_err(Failure::Geometry)?;
            return Ok(Held::Closed(Located::built(tri, &report, positions.len())));
        }
        Covered::from_surface(surface, &report, positions.len()).map(Held::Covered)
    }

    /// The intrinsic triangulation of a closed oriented surface held: the surface's, or the
    /// tufted cover's.
    fn located(&self) -> Option<&Located> {
        match self {
            Held::Closed(located) | Held::Tufted { located, .. } => Some(located),
            Held::Covered(_) => None,
        }
    }

    /// The refusal of what the tufted cover does not give (as `delaunay --tufted` refuses `-o`
    /// and `--tessellation`).
    fn refuse_tufted(&self, what: &str) -> Result<(), Failure> {
        match self {
            Held::Tufted { .. } => Err(invalid(format!(
                "{what}: the tufted cover gives the Laplacian, the mass matrix and the cover's \
                 triangulation (faces, edges, lengths), not a triangulation or tessellation of \
                 the mesh"
            ))),
            _ => Ok(()),
        }
    }
}

#[pymethods]
impl Intrinsic {
    /// The cotan Laplacian (positive semidefinite), `scipy.sparse.csr_matrix`.
    fn laplacian<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let m = py.detach(|| match &self.held {
            Held::Closed(located) => Csr::new(
                cotan_laplacian(&located.tri),
                &located.dense_rows(),
                located.rows,
            ),
            Held::Covered(covered) => {
                Csr::new(covered.tri.laplacian(), &covered.rows, covered.count)
            }
            Held::Tufted {
                located, laplacian, ..
            } => input_rows(laplacian, located.rows),
        });
        m.into_scipy(py)
    }

    /// The lumped (barycentric) mass matrix, diagonal, `scipy.sparse.csr_matrix`.
    fn mass<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        match &self.held {
            Held::Closed(located) => Csr::new(
                lumped_mass(&located.tri),
                &located.dense_rows(),
                located.rows,
            ),
            Held::Covered(covered) => Csr::new(covered.tri.mass(), &covered.rows, covered.count),
            Held::Tufted { located, mass, .. } => input_rows(mass, located.rows),
        }
        .into_scipy(py)
    }

    /// The Delaunay tessellation (co-circular triangles merged) as a [`Portalgon`];
    /// `cocircular_tolerance` `None` is the library's default. On a surface with boundary its
    /// boundary sides are unmatched; on a non-orientable one its orientation-reversing gluings
    /// are flagged (format version 2).
    #[pyo3(signature = (cocircular_tolerance = None))]
    fn tessellation(
        &self,
        py: Python<'_>,
        cocircular_tolerance: Option<f64>,
    ) -> PyResult<Portalgon> {
        let tolerance = cocircular_tolerance.unwrap_or(DEFAULT_COCIRCULAR_TOLERANCE);
        self.held
            .refuse_tufted("tessellation()")
            .map_err(|f| f.into_pyerr(py))?;
        let doc = py.detach(|| match &self.held {
            Held::Covered(covered) => covered.tri.tessellation(tolerance).portalgon,
            held => {
                let located = held.located().expect("a closed surface");
                let t = delaunay_tessellation(&located.tri, tolerance);
                PortalgonDoc::from_portalgon(&t.portalgon)
            }
        });
        Ok(Portalgon {
            doc,
            exact_only: None,
        })
    }

    /// The triangulation as portalgon JSON (triangles by their side lengths), as
    /// `surftopo delaunay -o OUT.json` writes it.
    fn to_json(&self, py: Python<'_>) -> PyResult<String> {
        self.doc()
            .and_then(|doc| doc.to_json().map_err(Failure::Portalgon))
            .map_err(|f| f.into_pyerr(py))
    }

    /// The triangulation as a [`Portalgon`].
    fn to_portalgon(&self, py: Python<'_>) -> PyResult<Portalgon> {
        let doc = self.doc().map_err(|f| f.into_pyerr(py))?;
        Ok(Portalgon {
            doc,
            exact_only: None,
        })
    }

    /// The faces `(m, 3)` as output vertex indices, corner `i` to corner `i + 1` being side `i`.
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        match (&self.held, self.held.located()) {
            (Held::Covered(covered), _) => index_array(py, &covered.face_rows()).into_any(),
            (_, Some(located)) => {
                let mesh = located.tri.mesh();
                located.vertex_rows(py, mesh.faces().map(|f| mesh.face_vertices(f)))
            }
            _ => unreachable!("every other surface is closed"),
        }
    }

    /// The edges `(E, 2)` as output vertex indices (a loop has both ends equal).
    #[getter]
    fn edges<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        match (&self.held, self.held.located()) {
            (Held::Covered(covered), _) => index_array(py, &covered.edge_rows()).into_any(),
            (_, Some(located)) => {
                let mesh = located.tri.mesh();
                located.vertex_rows(py, mesh.edges().map(|e| mesh.edge_vertices(e)))
            }
            _ => unreachable!("every other surface is closed"),
        }
    }

    /// The edge of each face side `(m, 3)`: side `i` of face `f` is edge `face_edges[f, i]`.
    #[getter]
    fn face_edges<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let rows: Vec<[u32; 3]> = match (&self.held, self.held.located()) {
            (Held::Covered(covered), _) => covered.face_edges(),
            (_, Some(located)) => {
                let mesh = located.tri.mesh();
                let (_, dense_edge) = edge_ranks(&located.tri);
                mesh.faces()
                    .map(|f| mesh.face_halfedges(f).map(|h| dense_edge[h.edge().idx()]))
                    .collect()
            }
            _ => unreachable!("every other surface is closed"),
        };
        index_array(py, &rows).into_any()
    }

    /// The intrinsic length of each edge `(E,)`, in the order of `edges`.
    #[getter]
    fn edge_lengths<'py>(&self, py: Python<'py>) -> Bound<'py, PyAny> {
        let lengths = match (&self.held, self.held.located()) {
            (Held::Covered(covered), _) => covered.edge_lengths(),
            (_, Some(located)) => {
                let (live, _) = edge_ranks(&located.tri);
                let lengths = located.tri.lengths();
                live.iter().map(|&e| lengths[e]).collect::<Vec<f64>>()
            }
            _ => unreachable!("every other surface is closed"),
        };
        vector(py, lengths).into_any()
    }

    /// The number of flips made.
    #[getter]
    fn flips(&self) -> u64 {
        self.stats.flips
    }

    /// The figures `surftopo delaunay --json` prints.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let text = serde_json::to_string(&self.stats)
            .map_err(|e| invalid(e.to_string()).into_pyerr(py))?;
        json_to_python(py, &text)
    }

    /// Number of rows of the matrices (input vertices, or the portalgon's vertices).
    #[getter]
    fn vertex_count(&self) -> usize {
        match (&self.held, self.held.located()) {
            (Held::Covered(covered), _) => covered.count,
            (_, Some(located)) => located.rows,
            _ => unreachable!("every other surface is closed"),
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "IntrinsicTriangulation({} vertices, {} edges, {} faces, {} flips)",
            self.stats.vertices, self.stats.edges, self.stats.faces, self.stats.flips
        )
    }
}

impl Intrinsic {
    /// The triangulation's portalgon document (triangles by lengths): what `surftopo delaunay
    /// -o` writes.
    fn doc(&self) -> Result<PortalgonDoc, Failure> {
        self.held.refuse_tufted("the triangulation")?;
        Ok(match (&self.held, self.held.located()) {
            (Held::Covered(covered), _) => covered.tri.to_doc(),
            (_, Some(located)) => {
                PortalgonDoc::from_triangulation(&located.tri, TriangleStyle::Lengths)
            }
            _ => unreachable!("every other surface is closed"),
        })
    }
}

/// A matrix with one row per input vertex as CSR.
fn input_rows(m: &SparseMatrix, rows: usize) -> Csr {
    let identity: Vec<u32> = (0..rows as u32).collect();
    Csr::new(m.clone(), &identity, rows)
}

impl Located {
    /// Rows of vertex ids as an int64 array of output vertex indices.
    fn vertex_rows<'py, const K: usize>(
        &self,
        py: Python<'py>,
        rows: impl Iterator<Item = [surftopo_mesh::VertexId; K]>,
    ) -> Bound<'py, PyAny> {
        let rows: Vec<[u32; K]> = rows.map(|r| r.map(|v| self.row_of[v.idx()])).collect();
        index_array(py, &rows).into_any()
    }
}

/// The live edge ids in order, and the rank of each edge id among them.
fn edge_ranks(tri: &IntrinsicTriangulation) -> (Vec<usize>, Vec<u32>) {
    let mesh = tri.mesh();
    let live: Vec<usize> = mesh.edges().map(|e| e.idx()).collect();
    let mut rank = vec![u32::MAX; mesh.edge_slots()];
    for (k, &e) in live.iter().enumerate() {
        rank[e] = k as u32;
    }
    (live, rank)
}

/// A surface argument: `(V, F)` arrays, or a portalgon, or an intrinsic triangulation.
fn located_surface(
    py: Python<'_>,
    surface: &Bound<'_, PyAny>,
    faces: Option<&Bound<'_, PyAny>>,
) -> PyResult<Located> {
    if let Some(faces) = faces {
        let vertices = VertexArray::extract(surface)?;
        let faces = arrays::any_faces(faces, vertices.len())?;
        let positions = vertices.positions();
        return py
            .detach(|| {
                let cut = faces.triangulated(&positions);
                Located::from_arrays(&positions, &cut.triangles).map_err(|f| cut.on_faces(f))
            })
            .map_err(|f| f.into_pyerr(py));
    }
    if let Ok(p) = surface.cast::<Portalgon>() {
        let tri = p.get().triangulation().map_err(|f| f.into_pyerr(py))?;
        return Ok(Located::dense(tri));
    }
    if let Ok(t) = surface.cast::<Intrinsic>() {
        return match &t.get().held {
            Held::Closed(located) => Ok(Located {
                tri: located.tri.clone(),
                row_of: located.row_of.clone(),
                rows: located.rows,
            }),
            Held::Covered(_) | Held::Tufted { .. } => Err(invalid(
                "this IntrinsicTriangulation has boundary, is non-orientable, in pieces or a \
                 tufted cover: a closed orientable surface is needed here",
            )
            .into_pyerr(py)),
        };
    }
    if let Ok(pair) = surface.cast::<PyTuple>()
        && pair.len() == 2
    {
        return located_surface(py, &pair.get_item(0)?, Some(&pair.get_item(1)?));
    }
    Err(
        invalid("a surface is (V, F) arrays, a Portalgon or an IntrinsicTriangulation")
            .into_pyerr(py),
    )
}

/// A surface argument that is not one closed orientable piece and is held on its cover: a
/// [`Portalgon`] of triangles with free sides, reversed gluings or several pieces, or such an
/// [`Intrinsic`]; `None` for anything else.
fn covered_surface(py: Python<'_>, surface: &Bound<'_, PyAny>) -> PyResult<Option<Covered>> {
    if let Ok(p) = surface.cast::<Portalgon>()
        && p.get().doc.needs_cover()
    {
        return Covered::from_doc(&p.get().doc)
            .map(Some)
            .map_err(|f| f.into_pyerr(py));
    }
    if let Ok(t) = surface.cast::<Intrinsic>()
        && let Held::Covered(covered) = &t.get().held
    {
        return Ok(Some(Covered {
            tri: covered.tri.clone(),
            rows: covered.rows.clone(),
            count: covered.count,
        }));
    }
    Ok(None)
}

/// A surface argument of any kind: one closed orientable piece as [`Located`], any other on
/// its cover (arrays of a mesh with boundary, non-orientable or in pieces too).
fn any_surface(py: Python<'_>, surface: &Bound<'_, PyAny>) -> PyResult<Result<Located, Covered>> {
    if let Some(covered) = covered_surface(py, surface)? {
        return Ok(Err(covered));
    }
    let arrays = if let Ok(pair) = surface.cast::<PyTuple>()
        && pair.len() == 2
        && surface.cast::<Portalgon>().is_err()
    {
        Some((pair.get_item(0)?, pair.get_item(1)?))
    } else {
        None
    };
    let Some((vertices, faces)) = arrays else {
        return located_surface(py, surface, None).map(Ok);
    };
    let vertices = VertexArray::extract(&vertices)?;
    let faces = arrays::any_faces(&faces, vertices.len())?;
    let positions = vertices.positions().into_owned();
    py.detach(|| {
        let cut = faces.triangulated(&positions);
        match Held::from_arrays(&positions, &cut.triangles) {
            Ok(Held::Closed(located)) => Ok(Ok(located)),
            Ok(Held::Covered(covered)) => Ok(Err(covered)),
            Ok(Held::Tufted { .. }) => unreachable!("from_arrays never takes the tufted cover"),
            Err(f) => Err(cut.on_faces(f)),
        }
    })
    .map_err(|f| f.into_pyerr(py))
}

/// What `intrinsic_delaunay` starts from: a surface to run the request on, or the tufted cover
/// already flipped (with its figures, and whether it was taken because the soup is not a
/// manifold).
enum Start {
    Run(Held),
    Tufted(Held, DelaunayStats, bool),
}

/// The surface argument of `intrinsic_delaunay`: a closed orientable one as [`Located`], a
/// mesh with boundary, non-orientable or in pieces (or such an [`Intrinsic`]) on its cover, a
/// soup through its tufted cover as `tufted` says (as `laplacian` takes them), when `method`
/// flips.
fn delaunay_surface(
    py: Python<'_>,
    surface: &Bound<'_, PyAny>,
    faces: Option<&Bound<'_, PyAny>>,
    tufted: &Tufted,
    method: DelaunayMethod,
) -> PyResult<Start> {
    if let Some(faces) = faces {
        let vertices = VertexArray::extract(surface)?;
        let faces = arrays::any_faces(faces, vertices.len())?;
        let positions = vertices.positions().into_owned();
        let tufted = *tufted;
        return interruptible(py, move |_| {
            let cut = faces.triangulated(&positions);
            let triangles = &cut.triangles;
            let run_tufted = |automatic| {
                let start = Instant::now();
                let t = crate::tufted::tufted(&positions, triangles, &tufted.options)?;
                let report = FlipReport {
                    flips: t.report.flips,
                    mollify_delta: Some(t.report.mollify_delta),
                    non_delaunay_edges: t.cover.non_delaunay_edges(DEFAULT_TOLERANCE),
                };
                let stats = DelaunayStats::new(&t.cover, &report, start.elapsed().as_secs_f64());
                let mut row_of = t.cover_input_vertex;
                row_of.resize(t.cover.mesh().vertex_slots(), u32::MAX);
                let located = Located {
                    tri: t.cover,
                    row_of,
                    rows: positions.len(),
                };
                let held = Held::Tufted {
                    located,
                    laplacian: t.laplacian,
                    mass: t.mass,
                };
                Ok::<_, Failure>(Start::Tufted(held, stats, automatic))
            };
            if tufted.asked == Some(true) {
                return run_tufted(false);
            }
            match Held::from_arrays(&positions, triangles) {
                Err(f) if tufted.asked.is_none() && crate::tufted::is_non_manifold(&f) => {
                    match method {
                        DelaunayMethod::Auto | DelaunayMethod::Flip => run_tufted(true),
                        _ => Err(invalid(format!(
                            "method={:?}: the mesh is not a manifold ({f}); its tufted cover \
                             is flipped: method='flip' only",
                            method.name()
                        ))),
                    }
                }
                held => held.map(Start::Run).map_err(|f| cut.on_faces(f)),
            }
        })?
        .map_err(|f| f.into_pyerr(py));
    }
    if let Some(covered) = covered_surface(py, surface)? {
        return Ok(Start::Run(Held::Covered(covered)));
    }
    if let Ok(pair) = surface.cast::<PyTuple>()
        && pair.len() == 2
    {
        let (vertices, faces) = (pair.get_item(0)?, pair.get_item(1)?);
        return delaunay_surface(py, &vertices, Some(&faces), tufted, method);
    }
    located_surface(py, surface, None).map(|l| Start::Run(Held::Closed(l)))
}

/// The intrinsic Delaunay triangulation of a polyhedral surface by `method` (`"flip"`,
/// `"voronoi"`, `"dubois"` or `"auto"`, as `surftopo delaunay --method`); `exact=True` computes
/// exactly (voronoi, dubois, auto) on a [`Portalgon`] given by exact corners. A mesh with
/// boundary, non-orientable or in pieces is flipped on its closed cover (the wave and Theorem 1
/// refused, naming flip, as the CLI does); `tufted=` and `mollify_factor=` as in [`laplacian`].
#[pyfunction]
#[pyo3(signature = (vertices, faces = None, method = "flip", exact = false, mollify = None, max_flips = None, tufted = None, mollify_factor = None))]
#[allow(clippy::too_many_arguments)] // the Python keyword arguments
pub fn intrinsic_delaunay(
    py: Python<'_>,
    vertices: &Bound<'_, PyAny>,
    faces: Option<&Bound<'_, PyAny>>,
    method: &str,
    exact: bool,
    mollify: Option<f64>,
    max_flips: Option<u64>,
    tufted: Option<bool>,
    mollify_factor: Option<f64>,
) -> PyResult<Intrinsic> {
    let outputs = DelaunayOutputs {
        triangulation: true,
        figures: true,
        ..DelaunayOutputs::default()
    };
    let tufted = tufted_arguments(method, mollify, mollify_factor, tufted, max_flips)
        .map_err(|f| f.into_pyerr(py))?;
    let request = request(method, mollify.or(mollify_factor), max_flips, outputs)
        .map_err(|f| f.into_pyerr(py))?;
    let (held, out) = if exact {
        if tufted.asked == Some(true) {
            return Err(not_exact().into_pyerr(py));
        }
        let p = exact_portalgon(vertices, faces).map_err(|f| f.into_pyerr(py))?;
        interruptible(py, move |_| Located::exact_delaunay(p, &request))?
            .map(|(located, out)| (Held::Closed(located), out))
    } else {
        match delaunay_surface(py, vertices, faces, &tufted, request.method)? {
            Start::Tufted(held, stats, automatic) => {
                if automatic {
                    warn_tufted(py)?;
                }
                return Ok(Intrinsic { held, stats });
            }
            Start::Run(Held::Covered(covered)) => {
                interruptible(py, move |_| covered.delaunay(&request))?
                    .map(|(covered, out)| (Held::Covered(covered), out))
            }
            Start::Run(held) => {
                let located = match held {
                    Held::Closed(located) => located,
                    _ => unreachable!("a surface to run is closed or covered"),
                };
                interruptible(py, move |_| located.delaunay(&request))?
                    .map(|(located, out)| (Held::Closed(located), out))
            }
        }
    }
    .map_err(|f| f.into_pyerr(py))?;
    let stats = out.stats.expect("the figures are asked for");
    Ok(Intrinsic { held, stats })
}

/// The warning of a soup taken through the tufted cover because it is not a manifold.
fn warn_tufted(py: Python<'_>) -> PyResult<()> {
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    PyErr::warn(
        py,
        &category,
        c"the mesh is not a manifold: its Laplacian and mass matrix are the tufted cover's (Sharp & Crane 2020); pass tufted=True to ask for them, tufted=False to refuse such input",
        1,
    )
}

/// `tufted=` and `mollify_factor=` of [`laplacian`] and [`intrinsic_delaunay`], checked
/// against the other arguments.
fn tufted_arguments(
    method: &str,
    mollify: Option<f64>,
    mollify_factor: Option<f64>,
    tufted: Option<bool>,
    max_flips: Option<u64>,
) -> Result<Tufted, Failure> {
    if mollify.is_some() && mollify_factor.is_some() {
        return Err(invalid("give mollify or mollify_factor, not both"));
    }
    if tufted == Some(true) && (method != "flip" || mollify.is_some()) {
        return Err(invalid(
            "tufted=True flips the tufted cover: method='flip' only, its mollification is mollify_factor",
        ));
    }
    if tufted == Some(false) && mollify_factor.is_some() {
        return Err(invalid(
            "mollify_factor applies to the tufted Laplacian (tufted=True or None)",
        ));
    }
    Ok(Tufted {
        asked: tufted,
        options: TuftedOptions {
            mollify_factor: mollify_factor.unwrap_or(DEFAULT_MOLLIFY_FACTOR),
            max_flips,
        },
    })
}

/// Which Laplacian `laplacian` computes: `tufted=` as given (`None`: the tufted one when the
/// soup is not a manifold, with a warning).
#[derive(Clone, Copy)]
struct Tufted {
    asked: Option<bool>,
    options: TuftedOptions,
}

/// `laplacian` and the seconds of the library calls alone (soup to matrices, their intermediate
/// results freed), for the benchmark.
fn laplacian_and_seconds<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    request: &DelaunayRequest,
    format: &str,
    tufted: Tufted,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>, f64)> {
    let format = sparse_format(format).map_err(|f| f.into_pyerr(py))?;
    let vertices = VertexArray::extract(vertices)?;
    let faces = arrays::any_faces(faces, vertices.len())?;
    let positions = vertices.positions().into_owned();
    let request = *request;
    let computed = interruptible(py, move |_| {
        let start = Instant::now();
        let cut = faces.triangulated(&positions);
        let matrices = library_matrices(&positions, &cut.triangles, &request, tufted)
            .map_err(|f| cut.on_faces(f))?;
        let seconds = start.elapsed().as_secs_f64();
        if !matrices.tufted {
            check_matrices(&matrices.laplacian, &matrices.mass)?;
        }
        let (rows, n) = (&matrices.rows, matrices.rows_out);
        let csr = (
            Csr::new(matrices.laplacian, rows, n),
            Csr::new(matrices.mass, rows, n),
        );
        let automatic = matrices.tufted && tufted.asked.is_none();
        Ok::<_, Failure>((csr, seconds, automatic))
    })?;
    let ((l, m), seconds, automatic) = computed.map_err(|f| f.into_pyerr(py))?;
    if automatic {
        warn_tufted(py)?;
    }
    Ok((
        l.into_format(py, format)?,
        m.into_format(py, format)?,
        seconds,
    ))
}

/// The matrices of `laplacian` as the libraries return them.
struct Matrices {
    laplacian: SparseMatrix,
    mass: SparseMatrix,
    /// Output row of each matrix row (increasing).
    rows: Vec<u32>,
    /// Number of output rows.
    rows_out: usize,
    /// Whether they are the tufted cover's.
    tufted: bool,
}

/// The library calls of `laplacian` (call without the GIL): the closed surface's matrices, or a
/// surface with boundary, non-orientable or in pieces ([`covered_matrices`]), or the tufted
/// cover's as `tufted` says. The intermediate results are freed on return.
fn library_matrices(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    request: &DelaunayRequest,
    tufted: Tufted,
) -> Result<Matrices, Failure> {
    let tufted_matrices = || {
        let (laplacian, mass) =
            crate::tufted::tufted_matrices(positions, triangles, &tufted.options)?;
        Ok(Matrices {
            laplacian,
            mass,
            rows: (0..positions.len() as u32).collect(),
            rows_out: positions.len(),
            tufted: true,
        })
    };
    if tufted.asked == Some(true) {
        return tufted_matrices();
    }
    let located = match Held::from_arrays(positions, triangles) {
        Err(f) if tufted.asked.is_none() && crate::tufted::is_non_manifold(&f) => {
            return tufted_matrices();
        }
        Ok(Held::Covered(covered)) => return covered_matrices(covered, request),
        Ok(Held::Closed(located)) => located,
        Ok(Held::Tufted { .. }) => unreachable!("a mesh is built closed or covered"),
        Err(f) => return Err(f),
    };
    let (located, out) = located.delaunay(request)?;
    let matrix = |m: Option<SparseMatrix>| m.expect("the matrices are asked for");
    Ok(Matrices {
        laplacian: matrix(out.laplacian),
        mass: matrix(out.mass),
        rows: located.dense_rows(),
        rows_out: located.rows,
        tufted: false,
    })
}

/// The Laplacian and mass matrices of a surface with boundary, non-orientable or in pieces
/// (`surftopo_intrinsic::CoveredTriangulation`: flipping; the natural boundary condition), rows
/// the input's vertex indices.
fn covered_matrices(covered: Covered, request: &DelaunayRequest) -> Result<Matrices, Failure> {
    let request = DelaunayRequest {
        outputs: DelaunayOutputs {
            triangulation: false,
            ..request.outputs
        },
        ..*request
    };
    let out = surftopo_intrinsic::intrinsic_delaunay(DelaunayInput::Covered(covered.tri), &request)
        .map_err(Failure::Intrinsic)?;
    let matrix = |m: Option<SparseMatrix>| m.expect("the matrices are asked for");
    Ok(Matrices {
        laplacian: matrix(out.laplacian),
        mass: matrix(out.mass),
        rows: covered.rows,
        rows_out: covered.count,
        tufted: false,
    })
}

/// The request of `laplacian`: the triangulation and both matrices.
fn laplacian_request(
    method: &str,
    mollify: Option<f64>,
    max_flips: Option<u64>,
) -> Result<DelaunayRequest, Failure> {
    let outputs = DelaunayOutputs {
        triangulation: true,
        laplacian: true,
        mass: true,
        ..DelaunayOutputs::default()
    };
    request(method, mollify, max_flips, outputs)
}

/// The cotan Laplacian `L` (positive semidefinite) and the lumped mass matrix `M` of the intrinsic
/// Delaunay triangulation of `(V, F)` by `method`, as `robust_laplacian.mesh_laplacian` returns
/// them, in `format` (`"csr"` or `"csc"`), refused as the CLI refuses them when not
/// representable. `exact=True` is refused: a mesh's lengths are square roots. `tufted=True` (or
/// `None` on a soup that is not a manifold: a non-manifold edge or vertex, a duplicate face, with
/// a warning) gives the tufted cover's (Sharp & Crane 2020) with `mollify_factor` (default 1e-5,
/// as robust_laplacian's); on a manifold, `mollify_factor` is `mollify`.
#[pyfunction]
#[pyo3(signature = (vertices, faces, method = "flip", exact = false, mollify = None, max_flips = None, format = "csr", tufted = None, mollify_factor = None))]
#[allow(clippy::too_many_arguments)] // the Python keyword arguments
pub fn laplacian<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    method: &str,
    exact: bool,
    mollify: Option<f64>,
    max_flips: Option<u64>,
    format: &str,
    tufted: Option<bool>,
    mollify_factor: Option<f64>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let tufted = tufted_arguments(method, mollify, mollify_factor, tufted, max_flips)
        .map_err(|f| f.into_pyerr(py))?;
    let request = laplacian_request(method, mollify.or(mollify_factor), max_flips)
        .map_err(|f| f.into_pyerr(py))?;
    if exact {
        return Err(not_exact().into_pyerr(py));
    }
    laplacian_and_seconds(py, vertices, faces, &request, format, tufted).map(|(l, m, _)| (l, m))
}

/// [`laplacian`] with the default options (`tufted` as given), also returning the seconds spent
/// in the library calls (the benchmark's reference for the Python overhead).
#[pyfunction]
#[pyo3(signature = (vertices, faces, tufted = None))]
pub fn _laplacian_timed<'py>(
    py: Python<'py>,
    vertices: &Bound<'py, PyAny>,
    faces: &Bound<'py, PyAny>,
    tufted: Option<bool>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>, f64)> {
    let request = laplacian_request("flip", None, None).map_err(|f| f.into_pyerr(py))?;
    let tufted = Tufted {
        asked: tufted,
        options: TuftedOptions::default(),
    };
    laplacian_and_seconds(py, vertices, faces, &request, "csr", tufted)
}

/// Whether two compact polyhedral surfaces are isometric: closed orientable ones by Corollary 2
/// of the intrinsic-Delaunay paper (equal canonical Delaunay tessellations), any other kind
/// (boundary loops, non-orientable, several pieces) on their covers as `surftopo isometric`
/// decides it (`docs/isometry_every_surface.md`). True only for the verdict "isometric".
#[pyfunction]
#[pyo3(signature = (a, b, allow_reflection = true))]
pub fn isometric(
    py: Python<'_>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    allow_reflection: bool,
) -> PyResult<bool> {
    let options = IsometryOptions {
        allow_reflection,
        ..IsometryOptions::default()
    };
    match (any_surface(py, a)?, any_surface(py, b)?) {
        (Ok(first), Ok(second)) => {
            let (first, second) = (first.tri, second.tri);
            interruptible(py, move |_| {
                surftopo_intrinsic::isometric(first, second, &options)
            })?
            .map(|outcome| outcome.is_isometric())
            .map_err(|e| Failure::Isometry(e).into_pyerr(py))
        }
        (first, second) => {
            decide_on_cover(py, first, second, options).map(|decision| decision.is_isometric())
        }
    }
}

/// The verdict of `surftopo isometric` (its default method) on two surfaces of any kind, and
/// its reason: `"isometric"`, `"not isometric"` (a proof), `"undecidable in double precision"`
/// or `"undecided"` (a flat vertex on a surface with boundary or without orientation).
#[pyfunction]
pub fn isometry_verdict(
    py: Python<'_>,
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
) -> PyResult<(&'static str, String)> {
    let options = IsometryOptions::default();
    let decision = match (any_surface(py, a)?, any_surface(py, b)?) {
        (Ok(first), Ok(second)) => {
            let (first, second) = (first.tri, second.tri);
            interruptible(py, move |_| {
                surftopo_intrinsic::decide_isometry(&first, &second, &options)
            })?
            .map_err(|e| Failure::Isometry(e).into_pyerr(py))?
        }
        (first, second) => decide_on_cover(py, first, second, options)?,
    };
    let verdict = match &decision {
        IsometryDecision::Isometric(_) => "isometric",
        IsometryDecision::NotIsometric(_) => "not isometric",
        IsometryDecision::Undecidable(_) => "undecidable in double precision",
        IsometryDecision::Undecided(_) => "undecided",
    };
    Ok((verdict, decision.to_string()))
}

/// `decide_isometry_on_cover` on two surfaces, a closed orientable one as its own cover.
fn decide_on_cover(
    py: Python<'_>,
    first: Result<Located, Covered>,
    second: Result<Located, Covered>,
    options: IsometryOptions,
) -> PyResult<IsometryDecision> {
    let cover = |s: Result<Located, Covered>| match s {
        Ok(located) => CoveredTriangulation::from_closed(located.tri),
        Err(covered) => covered.tri,
    };
    let (first, second) = (cover(first), cover(second));
    interruptible(py, move |_| {
        surftopo_intrinsic::decide_isometry_on_cover(&first, &second, &options)
    })?
    .map_err(|e| Failure::Isometry(e).into_pyerr(py))
}

/// The flat torus T_x of the intrinsic-Delaunay paper (Section 9): one vertex, two triangles
/// (0,0), (1,0), (x,2); refined `m x m` when `m > 1`. A [`Portalgon`].
#[pyfunction]
#[pyo3(signature = (x, m = 1))]
pub fn flat_torus(py: Python<'_>, x: f64, m: u32) -> PyResult<Portalgon> {
    let tri = surftopo_intrinsic::generators::flat_torus(x, m)
        .map_err(|e| Failure::Portalgon(e).into_pyerr(py))?;
    Ok(Portalgon {
        doc: PortalgonDoc::from_triangulation(&tri, TriangleStyle::Lengths),
        exact_only: None,
    })
}
