//! Portalgons (Dubois, Section 2.1): polygons in the plane with a partial matching of sides.
//!
//! A [`Portalgon`] is a collection of counter-clockwise polygons, each given by its corners in its
//! own copy of the plane (the paper's real-RAM *representation*: displacing a polygon gives
//! another representation of the same portalgon), with a partial matching of equally long sides.
//! Gluing matched sides, respecting the polygons' orientations, gives the surface `S(T)`;
//! unmatched sides are its boundary (e.g. the boundary of a *sub-portalgon*, Section 2.1, or of a
//! *region*, Section 4.4). Side `i` of a polygon runs from its corner `i` to corner `i + 1`.
//!
//! Ids are stable: sides ([`SideId`]) and polygons ([`PolygonId`]) keep their ids through the
//! elementary edits the paper's algorithm is made of, and removed ones become tombstones:
//! - [`Portalgon::cut`]: cut a polygon along a vertex-to-vertex arc, the two new sides matched to
//!   each other (INSERTEDGES, Section 4.1; [`Portalgon::shortcut`] finds the arc it inserts, and
//!   [`Portalgon::triangulate_by_shortcuts`] is INSERTEDGES on one polygon);
//! - [`Portalgon::merge`]: the inverse, gluing two polygons along a matched pair of sides after
//!   displacing one rigidly (Section 2.3's elementary operation);
//! - [`Portalgon::delete_vertex`]: DELETEVERTICES' step (Section 4.2), merging the polygons around
//!   a weak flat vertex into one and closing the slit left at it;
//! - [`Portalgon::glue`] / [`Portalgon::unglue`]: change the matching (cutting the surface, as in
//!   Appendix B's proof of Lemma 25, or closing it up);
//! - [`Portalgon::sub_portalgon`]: the sub-portalgon of a set of polygons, and [`Regions`], the
//!   partition into regions with one active region of Section 4.4.
//!
//! The corners are in a [`Scalar`] `S` (`Portalgon<S = f64>`): `f64`, or exact rationals
//! ([`crate::geometry::Rational`]), where every edit is exact — [`Portalgon::merge`] displaces by
//! footnote 2's motion ([`Motion::gluing`]: no square root in exact mode; in `f64` normalised to
//! a rotation, so that rounding in short sides does not scale what is moved) and lengths are
//! compared squared ([`Portalgon::side_length2`]). The plane geometry is [`crate::geometry`]'s; its predicates have
//! exact signs in both modes.
//!
//! What is checked: [`Portalgon::add_polygon`] validates a polygon (at least three finite corners,
//! no zero side, counter-clockwise, simple); [`Portalgon::glue`] requires equal lengths, exactly
//! in exact mode and up to a relative tolerance in `f64` (`|a - b| <= tolerance · max(a, b)`,
//! [`DEFAULT_LENGTH_TOLERANCE`]). [`Portalgon::check_invariants`] checks the whole structure (tests
//! call it after every edit).
//! [`Portalgon::merge`] does not check that the merged polygon is simple (merging all polygons
//! around a vertex whose angle exceeds 2π overlaps itself in the plane), nor does it need to.
//!
//! The module's files: [`core`] (the structure, its queries and validation, the elementary edits
//! above), [`edits`] (the edits of Sections 4.1–4.3 and Appendix B: [`Portalgon::split_side`],
//! [`Portalgon::vertex_info`], [`Portalgon::components`], [`Portalgon::splice`]) and [`regions`]
//! ([`Regions`]).

mod core;
mod edits;
mod regions;

pub(crate) use self::core::points_inside;
pub use self::core::{
    DEFAULT_LENGTH_TOLERANCE, Point2, PolygonId, Portalgon, SideId, check_polygon, signed_area,
};
pub use edits::{Component, EditError, VertexInfo};
pub use regions::Regions;
