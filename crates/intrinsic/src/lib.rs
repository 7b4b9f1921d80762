//! surftopo-intrinsic: portalgons and intrinsic Delaunay triangulations.
//!
//! Paper: L. Dubois, "Computing the Intrinsic Delaunay Triangulation of a Closed Polyhedral
//! Surface", 2025, arXiv:2601.03954 — Sections 1–2 (portalgons, aspect ratio), Section 9 (the flat torus T_x),
//! Appendix A (Corollary 2, the isometry test), Appendix C (the Delaunay tessellation of Bobenko &
//! Springborn). This crate holds the portalgon model and the classical edge-flip algorithm the
//! paper contrasts with its own; the paper's algorithm (Sections 3–8) builds on [`Portalgon`]'s
//! edits: [`Portalgon::cut`] and [`Portalgon::shortcut`] (INSERTEDGES),
//! [`Portalgon::delete_vertex`] (DELETEVERTICES), [`Portalgon::merge`], [`Portalgon::glue`] /
//! [`Portalgon::unglue`], [`Portalgon::sub_portalgon`] and [`Regions`] (Section 4.4's active and
//! inactive regions), [`Portalgon::split_side`] (INSERTVERTICES), [`Portalgon::vertex_info`]
//! (weak and strong vertices, Section 4.2), [`Portalgon::components`] and [`Portalgon::splice`].
//! Section 3 and Appendix B: [`Biface`] with the good-biface kernel [`Biface::make_good`] (Lemma 25
//! by closed forms), and tubes with Proposition 4 ([`Portalgon::good_biface_of_tube`],
//! [`TubeRoute`]). [`voronoi`] is Proposition 3's second route to the Delaunay tessellation, the
//! multi-source wave of Appendix D and the dual of its Voronoi diagram, in `f64` or exactly over the
//! rationals ([`geometry`]). Section 4: the routines and ALGORITHM on flat closed surfaces in [`dubois`]
//! ([`dubois::reduce`]). Not here yet: Section 8's caps and Theorem 1's driver.
//!
//! - [`IntrinsicTriangulation`]: a closed triangular portalgon as half-edge topology
//!   ([`surftopo_mesh::SurfaceMesh`], loops and multi-edges allowed) plus edge lengths; from a mesh
//!   and positions ([`IntrinsicTriangulation::from_soup`]), from a [`Portalgon`], or from JSON
//!   ([`PortalgonDoc`], format in `PORTALGON_FORMAT.md`).
//! - [`flip_to_delaunay`]: Bobenko–Springborn edge flipping with robust half-angle formulas
//!   (Kahan's, from side lengths alone), a flip budget and optional [`mollify()`]; [`DelaunayStats`] for reports.
//! - [`delaunay_tessellation`]: co-circular triangles merged into the unique Delaunay tessellation;
//!   [`voronoi::voronoi_delaunay`] computes it by the wave instead (exactly with rational corners).
//! - [`cotan_laplacian`], [`lumped_mass`], [`cotan_weights`] and a Matrix Market writer
//!   ([`write_matrix_market`]). Convention: the Laplacian is positive semidefinite.
//!   [`intrinsic_delaunay_laplacian`] flips and assembles in one call (libigl's
//!   `intrinsic_delaunay_cotmatrix`), reusing the flips' half-angle tangents.
//! - [`quality()`]: aspect ratio, local aspect ratio, singular vertices (Section 2.2).
//! - [`isometric`]: Corollary 2's test on canonical tessellations ([`remove_flat_vertices`] first).
//! - [`generators`]: T_x ([`generators::flat_torus`]), sheared tori, random isometric flips.
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

mod biface;
mod convert;
mod delaunay;
pub mod dubois;
mod error;
mod flat;
pub mod flat_torus_lattice;
mod format;
pub mod generators;
pub mod geometry;
mod isometry;
mod isometry_decision;
mod laplacian;
mod matrix_market;
pub mod method_choice;
mod mollify;
mod numpy;
mod portalgon;
mod portalgon_edits;
mod quality;
mod stats;
mod tessellation;
mod text_blocks;
mod triangulation;
mod trig;
mod tube;
pub mod voronoi;

pub use biface::{Biface, BifaceError, BifaceKind, GoodBiface, good_biface_of_ladder};
pub use delaunay::{
    DEFAULT_TOLERANCE, DelaunayOptions, FlipReport, default_max_flips, flip_to_delaunay,
    flip_to_delaunay_unless_needle,
};
pub use error::{
    DelaunayError, GeometryError, IsometryError, PortalgonError, RemovalError, SoupError,
};
pub use flat::{RemovalReport, remove_flat_vertices};
pub use format::{FORMAT_NAME, FORMAT_VERSION, Number, PolygonDoc, PortalgonDoc, TriangleStyle};
pub use isometry::{
    ISOMETRY_COCIRCULAR_TOLERANCE, ISOMETRY_LENGTH_TOLERANCE, IsometryOptions, Mismatch,
    MismatchKind, Outcome, canonical_tessellation, compare_tessellations, isometric,
};
pub use isometry_decision::{AREA_CERTIFICATE, IsometryDecision, decide_isometry};
pub use laplacian::{
    SparseMatrix, cotan_laplacian, cotan_weights, intrinsic_delaunay_laplacian, lumped_mass,
};
pub use matrix_market::{MatrixStorage, read_matrix_market, write_matrix_market};
pub use mollify::{MAX_MOLLIFY, mollify};
pub use numpy::{write_npy, write_npz};
pub use portalgon::{
    DEFAULT_LENGTH_TOLERANCE, Point2, PolygonId, Portalgon, Regions, SHORTCUT_MIN_SINE, SideId,
    check_polygon, signed_area,
};
pub use portalgon_edits::{Component, EditError, VertexInfo};
pub use quality::{DEFAULT_ANGLE_TOLERANCE, Quality, flat_vertices, is_singular, quality};
pub use stats::{DelaunayStats, delaunay_with_stats, delaunay_with_stats_unless_needle};
pub use tessellation::{
    DEFAULT_COCIRCULAR_TOLERANCE, Tessellation, delaunay_tessellation, is_cocircular,
};
pub use triangulation::{FLIP_AREA_TOLERANCE, IntrinsicTriangulation};
pub use tube::{LEMMA_28_MAX_DEGREE, Tube, TubeError, TubeReport, TubeRoute, biface_portalgon};
