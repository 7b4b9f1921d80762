//! surftopo-census: every irreducible triangulation of a closed surface, up to isomorphism, and
//! canonical forms of triangulated closed surfaces, orientable or not.
//!
//! The census is the future work that Ramaswami and Siqueira name in Section 6 of "A fast
//! algorithm for computing irreducible triangulations of closed surfaces in E^d" (the list of all
//! irreducible triangulations of a surface); their Section 1 lists what is known: the sphere has
//! one (the tetrahedron), the projective plane two (Barnette 1982), the torus 21 (Lawrencenko
//! 1987), the Klein bottle 29 (Lawrencenko and Negami 1997, Sulanke 2006). Sulanke's generator
//! (T. Sulanke, "Generating irreducible triangulations of surfaces", arXiv:math/0606687) adds
//! handles, crosscaps and crosshandles to triangulations of surfaces of smaller Euler genus; it is
//! not public. This crate's method is another one (see [`search`]): a search that completes the
//! vertex links in order, as Lutz's and Sulanke–Lutz's lexicographic enumeration of triangulated
//! surfaces does (T. Sulanke and F. H. Lutz, "Isomorphism-free lexicographic enumeration of
//! triangulated surfaces and 3-manifolds", European J. Combin. 30, 2009), pruned by
//! irreducibility (an edge is contractible iff its ends have exactly two common neighbours:
//! Ramaswami–Siqueira's Theorem 3, Section 2) and cut at a proven or published largest vertex
//! count (Joret and Wood, "Irreducible triangulations are small", JCTB 100, 2010: at most 13h − 4
//! vertices), with isomorph rejection by canonical forms ([`canonical_form`]).
//!
//! The triangulations here are plain face lists ([`Triangulation`]): the census needs surfaces
//! of any orientability, and the link condition on a closed surface needs no orientation.

mod canonical;
mod error;
mod format;
mod random;
pub mod search;
mod surface;
mod triangulation;

pub use canonical::{CanonicalForm, canonical_form, is_chiral, isomorphic};
pub use error::CensusError;
pub use format::{parse_lutz, parse_lutz_line, to_lutz, to_lutz_line};
pub use random::{random_reduction, random_retriangulation};
pub use search::{Census, CensusOptions, Job, JobResult, Progress, VertexCountFigures, census};
pub use surface::{BoundSource, SurfaceKind, VertexRange};
pub use triangulation::Triangulation;
