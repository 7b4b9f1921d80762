//! The libraries' typed errors as the Python exceptions of `surftopo._errors`.
//!
//! Every exception carries the library error's message (what the CLI prints after `error:`) and
//! the element it names as attributes (`face`, `edge`, `vertex`, `polygon`, `side`), plus `kind`,
//! the Rust variant's name. Errors are built as [`Failure`] while the GIL is released and turned
//! into exceptions once it is held again.

use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use surftopo_intrinsic::{
    DelaunayError, GeometryError, IntrinsicDelaunayError, IsometryError, PortalgonError,
};
use surftopo_io::IoError;
use surftopo_irreducible::IrreducibleError;
use surftopo_mesh::BuildError;
use surftopo_quad::QuadError;

/// Why a call failed, before it becomes a Python exception.
#[derive(Debug)]
pub enum Failure {
    /// The soup is not a triangulated surface, or not one the function takes (closed,
    /// connected, orientable).
    Build(BuildError),
    /// A face index outside `0..vertex_count` (negative or too large for the array's dtype).
    Index {
        /// Input face index.
        face: usize,
        /// The offending value.
        value: i64,
        /// Number of vertices.
        vertex_count: usize,
    },
    /// The algorithm needs a simplicial surface.
    Irreducible(IrreducibleError),
    /// The quadrangulation failed.
    Quad(QuadError),
    /// The lengths are unusable.
    Geometry(GeometryError),
    /// The Delaunay flips failed.
    Delaunay(DelaunayError),
    /// A portalgon is invalid.
    Portalgon(PortalgonError),
    /// The isometry test could not compare the surfaces.
    Isometry(IsometryError),
    /// `intrinsic_delaunay` by method failed.
    Intrinsic(IntrinsicDelaunayError),
    /// A mesh file could not be read or written.
    Io(IoError),
    /// Any other invalid argument (`ValueError`, exception class of `surftopo._errors`).
    Invalid(&'static str, String),
}

impl From<BuildError> for Failure {
    fn from(e: BuildError) -> Self {
        Failure::Build(e)
    }
}

/// The name of an enum variant from its `Debug` text (`BoundaryEdge { .. }` -> `BoundaryEdge`).
fn variant_name(debug: &impl std::fmt::Debug) -> String {
    let text = format!("{debug:?}");
    let end = text
        .find(|c: char| !c.is_alphanumeric() && c != '_')
        .unwrap_or(text.len());
    text[..end].to_string()
}

/// Attributes of a mesh build error: `face`, `edge` (input vertex indices), `vertex`.
fn build_fields(e: &BuildError, d: &Bound<'_, PyDict>) -> PyResult<()> {
    use BuildError as B;
    match e {
        B::IndexOutOfRange { face, index, .. } => {
            d.set_item("face", face)?;
            d.set_item("vertex", index)?;
        }
        B::RepeatedVertex { face, vertex } => {
            d.set_item("face", face)?;
            d.set_item("vertex", vertex)?;
        }
        B::DuplicateFace { face, .. }
        | B::Disconnected { face, .. }
        | B::NotTriangle { face, .. }
        | B::SideUnglued { face, .. }
        | B::SideGluedTwice { face, .. } => d.set_item("face", face)?,
        B::BoundaryEdge { edge, face }
        | B::NonManifoldEdge { edge, face, .. }
        | B::NonOrientable { edge, face } => {
            d.set_item("face", face)?;
            d.set_item("edge", (edge[0], edge[1]))?;
        }
        B::NonManifoldVertex { vertex, .. } | B::NonFinite { vertex, .. } => {
            d.set_item("vertex", vertex)?;
        }
        // Empty, TooLarge (and variants added later) name no element.
        _ => {}
    }
    Ok(())
}

/// Attributes of a length error: `edge` and `face` ids.
fn geometry_fields(e: &GeometryError, d: &Bound<'_, PyDict>) -> PyResult<()> {
    match e {
        GeometryError::NonFiniteLength { edge, .. }
        | GeometryError::NonPositiveLength { edge, .. } => d.set_item("edge", edge),
        GeometryError::TriangleInequality { face, .. } | GeometryError::ZeroArea { face, .. } => {
            d.set_item("face", face)
        }
        _ => Ok(()),
    }
}

/// Attributes of a portalgon error: `polygon` and `side`.
fn portalgon_fields(e: &PortalgonError, d: &Bound<'_, PyDict>) -> PyResult<()> {
    use PortalgonError as P;
    match e {
        P::Shape { polygon }
        | P::TooFewCorners { polygon, .. }
        | P::LengthsNotTriangle { polygon, .. }
        | P::TriangleInequality { polygon, .. }
        | P::NotCounterClockwise { polygon, .. }
        | P::NotSimple { polygon, .. }
        | P::NotTriangle { polygon, .. }
        | P::VertexLabels { polygon, .. }
        | P::NotAnArc { polygon, .. }
        | P::NotFlat { polygon, .. }
        | P::NoSuchPolygon(polygon) => d.set_item("polygon", polygon),
        P::NonFinite { polygon, index } => {
            d.set_item("polygon", polygon)?;
            d.set_item("side", index)
        }
        P::ZeroSide { polygon, side }
        | P::NoSuchSide { polygon, side }
        | P::MatchedTwice { polygon, side }
        | P::Unmatched { polygon, side }
        | P::CannotMerge { polygon, side } => {
            d.set_item("polygon", polygon)?;
            d.set_item("side", side)
        }
        P::UnequalSides {
            polygon_a, side_a, ..
        } => {
            d.set_item("polygon", polygon_a)?;
            d.set_item("side", side_a)
        }
        P::Gluing(b) => build_fields(b, d),
        P::Geometry(g) => geometry_fields(g, d),
        // Json, Io, Version, Empty, Invariant (and variants added later) name no element.
        _ => Ok(()),
    }
}

/// Which surface (0 or 1) an isometry error is about.
fn surface_of(e: &IsometryError) -> usize {
    match e {
        IsometryError::Delaunay { surface, .. }
        | IsometryError::Removal { surface, .. }
        | IsometryError::Portalgon { surface, .. } => *surface,
    }
}

/// Instantiates `surftopo._errors.<class>(message, **fields)`.
fn exception(py: Python<'_>, class: &str, message: String, fields: &Bound<'_, PyDict>) -> PyErr {
    let made = py
        .import("surftopo._errors")
        .and_then(|m| m.getattr(class))
        .and_then(|c| c.call((message,), Some(fields)));
    match made {
        Ok(value) => PyErr::from_value(value),
        Err(e) => e,
    }
}

impl Failure {
    /// The failure an error of `intrinsic_delaunay` stands for: its inner error, a numerical
    /// refusal of double precision (`NumericalBreakdownError`, as the CLI's exit 4), or invalid
    /// input.
    fn from_intrinsic(e: &IntrinsicDelaunayError) -> Failure {
        match e {
            IntrinsicDelaunayError::Flip(e) => Failure::Delaunay(e.clone()),
            IntrinsicDelaunayError::Geometry(e) => Failure::Geometry(e.clone()),
            IntrinsicDelaunayError::Portalgon(e) => Failure::Portalgon(e.clone()),
            e if e.is_numerical() => Failure::Invalid("NumericalBreakdownError", e.to_string()),
            e => invalid(e.to_string()),
        }
    }

    /// The name of the innermost library error's variant (`BoundaryEdge`, `MaxFlips`, ...).
    fn kind(&self) -> Option<String> {
        Some(match self {
            Failure::Build(e) => variant_name(e),
            Failure::Index { .. } => "IndexOutOfRange".to_string(),
            Failure::Irreducible(e) => variant_name(e),
            Failure::Quad(QuadError::NotSimplicial(e)) => variant_name(e),
            Failure::Quad(e) => variant_name(e),
            Failure::Geometry(e) | Failure::Delaunay(DelaunayError::Geometry(e)) => variant_name(e),
            Failure::Delaunay(e) => variant_name(e),
            Failure::Portalgon(e) => variant_name(e),
            Failure::Isometry(IsometryError::Delaunay { source, .. }) => {
                return Failure::Delaunay(source.clone()).kind();
            }
            Failure::Isometry(IsometryError::Removal { source, .. }) => variant_name(source),
            Failure::Isometry(IsometryError::Portalgon { source, .. }) => variant_name(source),
            Failure::Io(e) => variant_name(e),
            Failure::Intrinsic(e) => return Failure::from_intrinsic(e).kind(),
            Failure::Invalid(..) => return None,
        })
    }

    /// The exception class (in `surftopo._errors`); fills in the attributes but `kind`.
    fn class(&self, d: &Bound<'_, PyDict>) -> PyResult<&'static str> {
        Ok(match self {
            Failure::Build(e) => {
                build_fields(e, d)?;
                "InvalidMeshError"
            }
            Failure::Index { face, value, .. } => {
                d.set_item("face", face)?;
                d.set_item("vertex", value)?;
                "InvalidMeshError"
            }
            Failure::Irreducible(e) => {
                match e {
                    IrreducibleError::Loop { edge, vertex } => {
                        d.set_item("edge", edge.0)?;
                        d.set_item("vertex", vertex.0)?;
                    }
                    IrreducibleError::MultiEdge { edges, .. } => d.set_item("edge", edges[0].0)?,
                    IrreducibleError::DuplicateFace { faces } => d.set_item("face", faces[1].0)?,
                    _ => {}
                }
                "NotSimplicialError"
            }
            Failure::Quad(e) => match e {
                QuadError::NotSimplicial(inner) => {
                    return Failure::Irreducible(inner.clone()).class(d);
                }
                QuadError::Internal(_) => "InternalError",
                QuadError::Unsupported(_) | QuadError::QualityTooLarge(_) => "InvalidInputError",
                _ => "InvalidMeshError",
            },
            Failure::Geometry(e) => {
                geometry_fields(e, d)?;
                "InvalidGeometryError"
            }
            Failure::Delaunay(e) => match e {
                DelaunayError::Geometry(g) => return Failure::Geometry(g.clone()).class(d),
                DelaunayError::MaxFlips { flips, pending } => {
                    d.set_item("flips", flips)?;
                    d.set_item("pending", pending)?;
                    "FlipLimitError"
                }
                DelaunayError::NumericalBreakdown { edge, .. } => {
                    d.set_item("edge", edge)?;
                    "NumericalBreakdownError"
                }
                _ => "InvalidInputError",
            },
            Failure::Portalgon(e) => {
                portalgon_fields(e, d)?;
                "PortalgonError"
            }
            Failure::Isometry(e) => {
                d.set_item("surface", surface_of(e))?;
                match e {
                    IsometryError::Delaunay { source, .. } => {
                        Failure::Delaunay(source.clone()).class(d)?
                    }
                    IsometryError::Removal { .. } => "InvalidGeometryError",
                    IsometryError::Portalgon { source, .. } => {
                        Failure::Portalgon(source.clone()).class(d)?
                    }
                }
            }
            Failure::Io(_) => "MeshFileError",
            Failure::Intrinsic(e) => return Failure::from_intrinsic(e).class(d),
            Failure::Invalid(class, _) => class,
        })
    }

    /// The Python exception. A failure of the operating system (a missing file, no permission)
    /// is an `OSError` subclass as Python's own `open` raises it (`FileNotFoundError`, ...).
    pub fn into_pyerr(self, py: Python<'_>) -> PyErr {
        if let Failure::Io(IoError::Io { source, .. }) = &self {
            let message = self.to_string();
            return match source.raw_os_error() {
                Some(errno) => PyOSError::new_err((errno, message)),
                None => PyOSError::new_err(message),
            };
        }
        let fields = PyDict::new(py);
        let kind = fields.set_item("kind", self.kind());
        match kind.and_then(|()| self.class(&fields)) {
            Ok(class) => exception(py, class, self.to_string(), &fields),
            Err(e) => e,
        }
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::Build(e) => {
                // Surfaces the called function does not take yet, though they are surfaces.
                let unsupported = match e {
                    BuildError::BoundaryEdge { .. } => Some("surfaces with boundary are"),
                    BuildError::NonOrientable { .. } => Some("non-orientable surfaces are"),
                    BuildError::Disconnected { .. } => Some("several pieces are"),
                    _ => None,
                };
                if let Some(what) = unsupported {
                    write!(
                        f,
                        "{what} not supported yet here (info classifies them, irreducible takes \
                         them): "
                    )?;
                }
                e.fmt(f)
            }
            Failure::Index {
                face,
                value,
                vertex_count,
            } => write!(
                f,
                "face {face}: vertex index {value} out of range ({vertex_count} vertices)"
            ),
            Failure::Irreducible(e) => e.fmt(f),
            Failure::Quad(e) => e.fmt(f),
            Failure::Geometry(e) => e.fmt(f),
            Failure::Delaunay(e) => e.fmt(f),
            Failure::Portalgon(e) => e.fmt(f),
            Failure::Isometry(e) => e.fmt(f),
            Failure::Io(e) => e.fmt(f),
            Failure::Intrinsic(e) => e.fmt(f),
            Failure::Invalid(_, message) => f.write_str(message),
        }
    }
}

impl From<Failure> for PyErr {
    fn from(failure: Failure) -> Self {
        Python::attach(|py| failure.into_pyerr(py))
    }
}

/// A `ValueError` subclass `InvalidInputError` with `message`.
pub fn invalid(message: impl Into<String>) -> Failure {
    Failure::Invalid("InvalidInputError", message.into())
}
