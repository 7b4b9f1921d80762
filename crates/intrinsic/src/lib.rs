//! surftopo-intrinsic: portalgons and intrinsic Delaunay triangulations of closed polyhedral
//! surfaces.
//!
//! Paper: L. Dubois, "Computing the Intrinsic Delaunay Triangulation of a Closed Polyhedral
//! Surface", 2025, arXiv:2601.03954. Three algorithms compute the same Delaunay tessellation:
//! edge flipping (Bobenko & Springborn, the classical one the paper contrasts with its own), the
//! multi-source Voronoi wave of Appendix D (Proposition 3), and Dubois' Theorem 1 (Proposition 2's
//! reduction, then the wave), the last two in `f64` or exactly over the rationals. The design
//! notes of the Theorem 1 reconstruction, with what the paper leaves open and how we decided it,
//! are `docs/dubois.md` in the repository.
//!
//! The modules, from the ground up (a module imports only modules listed before it):
//! - [`geometry`]: the [`geometry::Scalar`] number types (`f64`, double-double, exact rationals)
//!   with the exact/rounded decisions as their methods, the tolerances of rounded arithmetic in
//!   one value ([`geometry::Tolerances`]), and plane geometry with exact-sign predicates;
//!   `error`: the typed errors;
//!   [`SparseMatrix`].
//! - `portalgon/` (Section 2.1): [`Portalgon`], its queries and elementary edits
//!   ([`Portalgon::cut`], [`Portalgon::shortcut`], [`Portalgon::merge`],
//!   [`Portalgon::delete_vertex`], [`Portalgon::glue`]), the edits of Sections 4.1–4.3
//!   ([`Portalgon::split_side`], [`Portalgon::vertex_info`], [`Portalgon::components`],
//!   [`Portalgon::splice`]) and Section 4.4's [`Regions`].
//! - `triangulation/`: [`IntrinsicTriangulation`], a closed triangular portalgon as half-edge
//!   topology ([`surftopo_mesh::SurfaceMesh`], loops and multi-edges allowed) plus edge lengths,
//!   from a mesh ([`IntrinsicTriangulation::from_soup`]) or a [`Portalgon`]; triangle formulas
//!   from side lengths (Kahan's), [`mollify()`], [`quality()`] (Section 2.2).
//! - `flip/`: [`flip_to_delaunay`] (a flip budget, robust half-angle tests), the needle test of
//!   `--method auto`, [`DelaunayStats`], [`delaunay_tessellation`] (co-circular triangles
//!   merged). `formats/`: portalgon JSON ([`PortalgonDoc`], `PORTALGON_FORMAT.md`), Matrix
//!   Market, numpy.
//! - [`voronoi`] (Appendix D): the wave and the dual of its Voronoi diagram.
//! - [`dubois`] (Sections 3, 4, 8; Theorem 1): ALGORITHM, tubes and bifaces, caps,
//!   [`dubois::delaunay_tessellation_dubois`]. `isometry/` (Appendix A, Corollary 2):
//!   [`isometric`], [`decide_isometry`]; on surfaces with boundary, non-orientable or in
//!   pieces, [`decide_isometry_on_cover`] (ours, `docs/isometry_every_surface.md`). `laplacian`: [`cotan_laplacian`] (positive
//!   semidefinite), [`lumped_mass`], [`intrinsic_delaunay_laplacian`] (flips and assembles in one
//!   call, libigl's `intrinsic_delaunay_cotmatrix`).
//! - `tufted/`: [`tufted_laplacian`], the Laplacian and mass matrix of any triangle soup
//!   (non-manifold, with fins, books, pinched vertices, duplicate faces) through the tufted
//!   cover of Sharp & Crane, "A Laplacian for Nonmanifold Triangle Meshes" (SGP 2020).
//! - `delaunay/`: [`intrinsic_delaunay`], the job by method (auto, flip, voronoi, dubois), with
//!   the rule of `auto` ([`choose_method`]). [`generators`]: `T_x` (Section 9), sheared
//!   tori, pillowcases, random isometric flips.
//!
//! ```
//! use surftopo_intrinsic::generators::flat_torus;
//! use surftopo_intrinsic::{
//!     DEFAULT_COCIRCULAR_TOLERANCE, DelaunayOptions, PortalgonDoc, TriangleStyle, cotan_laplacian,
//!     delaunay_tessellation, flip_to_delaunay,
//! };
//! // The flat torus T_10 of Section 9: one vertex, two triangles, three (loop) edges.
//! let mut tri = flat_torus(10.0, 1).unwrap();
//! let report = flip_to_delaunay(&mut tri, &DelaunayOptions::default()).unwrap();
//! assert_eq!((report.flips, report.non_delaunay_edges), (9, 0));
//! // Its Delaunay tessellation is the 1 x 2 rectangle with opposite sides glued.
//! let t = delaunay_tessellation(&tri, DEFAULT_COCIRCULAR_TOLERANCE);
//! assert_eq!((t.portalgon.polygon_count(), t.portalgon.side_count()), (1, 4));
//! // One vertex, only loops: the Laplacian is the 1 x 1 zero matrix.
//! assert_eq!(cotan_laplacian(&tri).get(0, 0), 0.0);
//! let json = PortalgonDoc::from_triangulation(&tri, TriangleStyle::Lengths).to_json().unwrap();
//! assert!(json.starts_with(r#"{"format":"surftopo-portalgon","version":1"#));
//! ```

mod covered;
mod delaunay;
pub mod dubois;
mod error;
mod flip;
mod formats;
pub mod generators;
pub mod geometry;
mod isometry;
mod laplacian;
mod portalgon;
mod sparse;
mod triangulation;
mod tufted;
pub mod voronoi;

pub use covered::CoveredTriangulation;
pub use covered::isometry::{decide_isometry_on_cover, piece_tessellations};
pub use delaunay::choice::{
    DUBOIS_TAKES_CONE_POINTS, choose_method, choose_method_for_triangulation, largest_aspect_ratio,
};
pub use delaunay::{
    AnyPortalgon, DelaunayInput, DelaunayMethod, DelaunayOutput, DelaunayOutputs, DelaunayRequest,
    IntrinsicDelaunayError, RequestError, WaveFigures, intrinsic_delaunay,
    intrinsic_delaunay_reporting,
};
pub use dubois::biface::{Biface, BifaceError, BifaceKind, GoodBiface, good_biface_of_ladder};
pub use dubois::tube::{
    LEMMA_28_MAX_DEGREE, Tube, TubeError, TubeReport, TubeRoute, biface_portalgon,
};
pub use error::{
    DelaunayError, GeometryError, IsometryError, PortalgonError, RemovalError, SoupError,
    TuftedError,
};
pub use flip::needle::AUTO_ASPECT_LIMIT;
pub use flip::stats::{DelaunayStats, delaunay_with_stats};
pub use flip::tessellation::{
    DEFAULT_COCIRCULAR_TOLERANCE, Tessellation, delaunay_tessellation, is_cocircular,
};
pub use flip::{
    DEFAULT_TOLERANCE, DelaunayOptions, FlipReport, default_max_flips, flip_to_delaunay,
    flip_to_delaunay_unless_needle,
};
pub use formats::matrix_market::{MatrixStorage, read_matrix_market, write_matrix_market};
pub use formats::numpy::{write_npy, write_npz};
pub use formats::portalgon_json::{
    FORMAT_NAME, FORMAT_VERSION, Number, ORIENTED_VERSION, PolygonDoc, PortalgonDoc, TriangleStyle,
};
pub use isometry::decision::{IsometryDecision, decide_isometry};
pub use isometry::flat_torus_lattice::flat_torus_invariants;
pub use isometry::flat_vertices::{RemovalReport, remove_flat_vertices};
pub use isometry::twisted::{MapDifference, MapMatch, TwistedMap, compare_twisted};
pub use isometry::{
    IsometryOptions, Mismatch, MismatchKind, Outcome, canonical_tessellation,
    compare_tessellations, isometric,
};
pub use laplacian::{cotan_laplacian, cotan_weights, intrinsic_delaunay_laplacian, lumped_mass};
pub use portalgon::{
    Component, DEFAULT_LENGTH_TOLERANCE, EditError, Point2, PolygonId, Portalgon, Regions, SideId,
    VertexInfo, check_polygon, signed_area,
};
pub use sparse::SparseMatrix;
pub use triangulation::IntrinsicTriangulation;
pub use triangulation::mollify::{MAX_MOLLIFY, mollify};
pub use triangulation::quality::{
    DEFAULT_ANGLE_TOLERANCE, Quality, flat_vertices, is_singular, quality,
};
pub use tufted::{
    DEFAULT_MOLLIFY_FACTOR, TuftedLaplacian, TuftedOptions, TuftedReport, tufted_laplacian,
};
