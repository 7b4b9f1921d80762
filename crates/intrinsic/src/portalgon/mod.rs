//! Portalgons (Dubois, Section 2.1): polygons in the plane with a partial matching of sides.
//!
//! - [`core`]: the structure, its queries, its validation, and the elementary edits (cut, merge,
//!   glue, delete a vertex, sub-portalgons);
//! - [`edits`]: the edits of Dubois' Sections 4.1–4.3 and Appendix B (split a side, vertex
//!   degrees and weakness, components, splice);
//! - [`Regions`]: the partition into regions with one active region (Section 4.4).

mod core;
mod edits;

pub(crate) use self::core::points_inside;
pub use self::core::{
    DEFAULT_LENGTH_TOLERANCE, Point2, PolygonId, Portalgon, Regions, SHORTCUT_MIN_SINE, SideId,
    check_polygon, signed_area,
};
pub use edits::{Component, EditError, VertexInfo};
