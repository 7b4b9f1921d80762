//! Typed errors. Every variant names the offending element: an edge or face id of the intrinsic
//! triangulation (equal to the input face index for meshes and to the polygon index for portalgon
//! files), or a polygon and side index of a portalgon.

use thiserror::Error;

/// A problem with the edge lengths of an intrinsic triangulation.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum GeometryError {
    /// The length vector does not match the mesh.
    #[error("{lengths} edge lengths given, the mesh has {edge_slots} edge slots")]
    LengthCount {
        /// Lengths given.
        lengths: usize,
        /// `mesh.edge_slots()`.
        edge_slots: usize,
    },
    /// A length is NaN or infinite.
    #[error("edge {edge}: length {value} is not finite")]
    NonFiniteLength {
        /// Edge id.
        edge: u32,
        /// The length.
        value: f64,
    },
    /// A length is zero or negative.
    #[error("edge {edge}: length {value} is not positive (degenerate edge)")]
    NonPositiveLength {
        /// Edge id.
        edge: u32,
        /// The length.
        value: f64,
    },
    /// The three sides of a face violate the triangle inequality.
    #[error("face {face}: sides {sides:?} violate the triangle inequality")]
    TriangleInequality {
        /// Face id.
        face: u32,
        /// Its side lengths, side i from corner i to corner i + 1.
        sides: [f64; 3],
    },
    /// The three sides of a face make a zero-area (flat) triangle.
    #[error("face {face}: sides {sides:?} make a zero-area triangle")]
    ZeroArea {
        /// Face id.
        face: u32,
        /// Its side lengths.
        sides: [f64; 3],
    },
}

/// Why the intrinsic Delaunay flip algorithm stopped without a result.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum DelaunayError {
    /// The input lengths are unusable (and mollification was not asked for).
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// More flips were needed than allowed.
    #[error(
        "stopped after {flips} flips (the limit): {pending} edges still to check; raise max_flips"
    )]
    MaxFlips {
        /// The limit, reached.
        flips: u64,
        /// Edges still in the work queue.
        pending: usize,
    },
    /// A flip produced a length that is not a positive finite number, or a triangle that breaks
    /// the triangle inequality: double precision is exhausted (e.g. the flat torus T_x for huge x).
    #[error(
        "numerical breakdown at flip {flips}: edge {edge} would get length {length} \
         (sides of its new triangles no longer form triangles)"
    )]
    NumericalBreakdown {
        /// The edge being flipped.
        edge: u32,
        /// Flips done before.
        flips: u64,
        /// The computed length.
        length: f64,
    },
    /// The mollification parameter is not a finite positive number.
    #[error(
        "mollification epsilon {0:?} must be positive and at most 1 (relative to the mean edge length)"
    )]
    InvalidMollify(f64),
    /// The tolerance is not a finite non-negative number.
    #[error("Delaunay tolerance {0} must be finite and non-negative")]
    InvalidTolerance(f64),
}

/// A problem with a portalgon: its polygons, its side matching, or its JSON text.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum PortalgonError {
    /// The text is not valid JSON for the format.
    #[error("portalgon JSON: {0}")]
    Json(String),
    /// Reading or writing failed.
    #[error("portalgon I/O: {0}")]
    Io(String),
    /// The `format`/`version` fields name another format.
    #[error(
        "unsupported format {format:?} version {version} (expected \"surftopo-portalgon\" version 1 or 2)"
    )]
    Version {
        /// The `format` field.
        format: String,
        /// The `version` field.
        version: u32,
    },
    /// The portalgon has no polygon.
    #[error("empty portalgon: no polygons")]
    Empty,
    /// An orientation-reversing gluing (a non-orientable surface) where an oriented portalgon is
    /// needed: portalgons and intrinsic triangulations read from files are oriented.
    #[error(
        "polygon {polygon}, side {side}: its gluing reverses orientation (a non-orientable \
         surface), and portalgons read from files are oriented (delaunay takes non-orientable \
         surfaces as mesh files)"
    )]
    ReversedGluing {
        /// The polygon.
        polygon: usize,
        /// The side.
        side: usize,
    },
    /// A polygon gives neither or both of `corners` and `lengths`.
    #[error("polygon {polygon}: give exactly one of \"corners\" and \"lengths\"")]
    Shape {
        /// Polygon index.
        polygon: usize,
    },
    /// A polygon has fewer than three corners.
    #[error("polygon {polygon}: {corners} corners, at least 3 are needed")]
    TooFewCorners {
        /// Polygon index.
        polygon: usize,
        /// Corners given.
        corners: usize,
    },
    /// `lengths` was given for a polygon that is not a triangle.
    #[error("polygon {polygon}: \"lengths\" describes triangles only ({count} lengths given)")]
    LengthsNotTriangle {
        /// Polygon index.
        polygon: usize,
        /// Number of lengths given.
        count: usize,
    },
    /// Exact mode needs corners, but a polygon is given by its lengths (square roots in general).
    #[error(
        "polygon {polygon} is given by \"lengths\": exact arithmetic needs every polygon given by \
         its corners"
    )]
    LengthsNotExact {
        /// Polygon index.
        polygon: usize,
    },
    /// A coordinate or length is NaN or infinite.
    #[error("polygon {polygon}: corner or side {index} is not finite")]
    NonFinite {
        /// Polygon index.
        polygon: usize,
        /// Corner (or side) index.
        index: usize,
    },
    /// A triangle side length given in the file is negative.
    #[error("polygon {polygon}: \"lengths\"[{side}] = {value} is negative")]
    NegativeLength {
        /// Polygon index.
        polygon: usize,
        /// Side index.
        side: usize,
        /// The length given.
        value: f64,
    },
    /// A parameter of a generator is out of its range.
    #[error("parameter {name} = {value}: {requirement}")]
    InvalidParameter {
        /// The parameter's name.
        name: &'static str,
        /// Its value, as given.
        value: String,
        /// What it must satisfy.
        requirement: String,
    },
    /// A side has zero length.
    #[error("polygon {polygon}: side {side} has zero length")]
    ZeroSide {
        /// Polygon index.
        polygon: usize,
        /// Side index (from corner `side` to corner `side + 1`).
        side: usize,
    },
    /// A triangle given by lengths violates the strict triangle inequality.
    #[error("polygon {polygon}: side lengths {lengths:?} violate the strict triangle inequality")]
    TriangleInequality {
        /// Polygon index.
        polygon: usize,
        /// The lengths.
        lengths: [f64; 3],
    },
    /// A polygon is not counter-clockwise (signed area not positive).
    #[error(
        "polygon {polygon}: signed area {area} is not positive (corners must run counter-clockwise)"
    )]
    NotCounterClockwise {
        /// Polygon index.
        polygon: usize,
        /// Its signed area.
        area: f64,
    },
    /// A polygon given by exact corners that double precision cannot hold: what doubles hold
    /// of it (rounded lengths or corners) has not its exact area
    /// ([`crate::geometry::Tolerances::exact_rounding`]); valid exactly, so exact arithmetic
    /// computes on it.
    #[error(
        "polygon {polygon}: double precision cannot hold its exact corners (area {exact_area:e} \
         exactly, {rounded_area:e} once rounded to doubles): compute in exact arithmetic"
    )]
    BeyondDoubles {
        /// Polygon index.
        polygon: usize,
        /// Its exact area (rounded for the message).
        exact_area: f64,
        /// The area of what doubles hold of it (NaN or 0 when that is not a valid polygon).
        rounded_area: f64,
    },
    /// Two sides of a polygon intersect: the polygon is not simple.
    #[error("polygon {polygon}: sides {a} and {b} intersect (not a simple polygon)")]
    NotSimple {
        /// Polygon index.
        polygon: usize,
        /// One side.
        a: usize,
        /// The other side.
        b: usize,
    },
    /// A matching or an edit names a side that does not exist.
    #[error("side {side} of polygon {polygon} does not exist")]
    NoSuchSide {
        /// Polygon index.
        polygon: usize,
        /// Side index.
        side: usize,
    },
    /// A polygon id is not live.
    #[error("polygon {0} does not exist")]
    NoSuchPolygon(usize),
    /// A side is matched twice, or to itself.
    #[error("side {side} of polygon {polygon} is matched twice or to itself")]
    MatchedTwice {
        /// Polygon index.
        polygon: usize,
        /// Side index.
        side: usize,
    },
    /// Two matched sides differ in length beyond the tolerance.
    #[error(
        "sides ({polygon_a}, {side_a}) and ({polygon_b}, {side_b}) are matched but their lengths \
         {length_a} and {length_b} differ by more than {tolerance} relative"
    )]
    UnequalSides {
        /// First polygon.
        polygon_a: usize,
        /// First side.
        side_a: usize,
        /// Second polygon.
        polygon_b: usize,
        /// Second side.
        side_b: usize,
        /// First length.
        length_a: f64,
        /// Second length.
        length_b: f64,
        /// The relative tolerance used.
        tolerance: f64,
    },
    /// A side is unmatched where a closed surface is required.
    #[error("side {side} of polygon {polygon} is unmatched: the surface is not closed")]
    Unmatched {
        /// Polygon index.
        polygon: usize,
        /// Side index.
        side: usize,
    },
    /// A triangle is required.
    #[error("polygon {polygon} has {sides} sides, a triangle is needed")]
    NotTriangle {
        /// Polygon index.
        polygon: usize,
        /// Its number of sides.
        sides: usize,
    },
    /// A polygon's vertex labels do not match its corners, or contradict the gluing.
    #[error("polygon {polygon}: vertex labels {detail}")]
    VertexLabels {
        /// Polygon index.
        polygon: usize,
        /// What is wrong.
        detail: String,
    },
    /// The segment between two corners is not a vertex-to-vertex arc inside the polygon.
    #[error("polygon {polygon}: corners {i} and {j} are not joined by an arc inside the polygon")]
    NotAnArc {
        /// Polygon index.
        polygon: usize,
        /// First corner.
        i: usize,
        /// Second corner.
        j: usize,
    },
    /// Merging across a side needs it matched to a side of another polygon.
    #[error("side {side} of polygon {polygon} is not matched to a side of another polygon")]
    CannotMerge {
        /// Polygon index.
        polygon: usize,
        /// Side index.
        side: usize,
    },
    /// Deleting a vertex needs a total angle of 2π around it: the star did not close up.
    #[error(
        "polygon {polygon}: the corners around the deleted vertex do not meet (gap {gap}): not \
         a flat interior vertex"
    )]
    NotFlat {
        /// Polygon index.
        polygon: usize,
        /// Distance between the two corners that should coincide.
        gap: f64,
    },
    /// The portalgon's internal structure is inconsistent ([`crate::Portalgon::check_invariants`]).
    #[error("portalgon invariant broken: {0}")]
    Invariant(String),
    /// The side gluing does not make a closed connected surface.
    #[error("gluing: {0}")]
    Gluing(#[from] surftopo_mesh::BuildError),
    /// The lengths of the triangles are unusable.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
}

/// Why flat vertices could not all be removed.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum RemovalError {
    /// The input lengths are unusable.
    #[error(transparent)]
    Geometry(#[from] GeometryError),
    /// The Delaunay flips run between removal passes failed.
    #[error(transparent)]
    Delaunay(#[from] DelaunayError),
    /// No flip brings the flat vertex down to degree 3 without loops (e.g. it is the base of a
    /// loop edge that cannot be flipped away).
    #[error("flat vertex {vertex} (degree {degree}) cannot be removed by flips")]
    Stuck {
        /// Vertex id.
        vertex: u32,
        /// Its degree when stuck.
        degree: usize,
    },
}

/// Why two surfaces could not be compared.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum IsometryError {
    /// The Delaunay flip algorithm failed on one input.
    #[error("surface {surface}: {source}")]
    Delaunay {
        /// 0 for the first surface, 1 for the second.
        surface: usize,
        /// The failure.
        source: DelaunayError,
    },
    /// Removing the flat vertices failed on one input.
    #[error("surface {surface}: {source}")]
    Removal {
        /// 0 for the first surface, 1 for the second.
        surface: usize,
        /// The failure.
        source: RemovalError,
    },
    /// A tessellation to compare is not closed.
    #[error("surface {surface}: {source}")]
    Portalgon {
        /// 0 for the first surface, 1 for the second.
        surface: usize,
        /// The failure.
        source: PortalgonError,
    },
}

/// Why a triangle soup with positions could not become an intrinsic triangulation.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum SoupError {
    /// The soup is not a closed connected orientable manifold (or has bad coordinates).
    #[error(transparent)]
    Build(#[from] surftopo_mesh::BuildError),
    /// An edge length is not finite (coordinates too large).
    #[error(transparent)]
    Geometry(#[from] GeometryError),
}

/// Why [`crate::tufted_laplacian`] refused a soup or stopped.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum TuftedError {
    /// No face, an index out of range, a face repeating a vertex, a non-finite coordinate, more
    /// elements than `u32` ids address (naming the input face or vertex).
    #[error(transparent)]
    Input(#[from] surftopo_mesh::BuildError),
    /// The mollification factor is not a number in `[0, MAX_MOLLIFY]`.
    #[error(
        "mollify factor {0:?} must be at least 0 (no mollification) and at most 1 (relative to the mean edge length)"
    )]
    InvalidMollifyFactor(f64),
    /// An input face is degenerate after mollification (a zero-area triangle, with no
    /// mollification or with every point at one place); the face is the input face index.
    #[error("{0} (give a positive mollify factor)")]
    Degenerate(GeometryError),
    /// Flipping the cover to Delaunay failed (its flip budget, double precision).
    #[error(transparent)]
    Flip(#[from] DelaunayError),
}
