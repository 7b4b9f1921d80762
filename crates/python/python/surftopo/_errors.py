"""The exceptions surftopo raises.

Invalid input raises a subclass of :class:`InvalidInputError`, itself a :class:`ValueError`; the
message is the one the ``surftopo`` command line prints after ``error:`` (without the file name
when the input came as arrays), and the attributes name the element: ``face`` (an input face
index), ``edge`` (two input vertex indices for mesh errors, an edge id for the intrinsic
triangulation's), ``vertex``, ``polygon`` and ``side`` (portalgons). An attribute that does not
apply is ``None``; ``kind`` is the name of the Rust error variant (``"BoundaryEdge"``, ...).
"""

from __future__ import annotations


class SurftopoError(Exception):
    """Base class of every error surftopo raises."""

    kind: str | None = None

    def __init__(self, message: str, **fields: object) -> None:
        super().__init__(message)
        self.message = message
        for name, value in fields.items():
            setattr(self, name, value)


class InvalidInputError(SurftopoError, ValueError):
    """The input is not what the function accepts (the CLI's exit code 2)."""


class InvalidMeshError(InvalidInputError):
    """The triangles are not a closed, connected, orientable surface, or an index is out of range.

    ``face`` is the input face index, ``edge`` a pair of input vertex indices, ``vertex`` an input
    vertex index (``None`` when they do not apply).
    """

    face: int | None = None
    edge: tuple[int, int] | int | None = None
    vertex: int | None = None


class NotSimplicialError(InvalidMeshError):
    """The algorithm needs a simplicial surface (no loop, multi-edge or doubled triangle).

    Elements are the mesh's ids: ``vertex`` and ``face`` equal the input indices unless the input
    has unreferenced vertices; ``edge`` is an edge id.
    """


class InvalidGeometryError(InvalidInputError):
    """Unusable lengths: a zero or non-finite edge, a flat triangle, a violated triangle inequality.

    ``edge`` is an edge id and ``face`` a face id of the intrinsic triangulation (the input face
    index for meshes). ``mollify=`` accepts degenerate input.
    """

    face: int | None = None
    edge: int | None = None


class FlipLimitError(InvalidInputError):
    """The Delaunay flips exceeded ``max_flips`` (``flips`` done, ``pending`` edges still queued)."""

    flips: int | None = None
    pending: int | None = None


class PortalgonError(InvalidInputError):
    """A portalgon (its JSON text, a polygon, the side matching) is invalid.

    ``polygon`` and ``side`` index the polygon list and a polygon's sides.
    """

    polygon: int | None = None
    side: int | None = None


class MeshFileError(InvalidInputError):
    """A mesh file cannot be read or written: bad syntax, unsupported extension, bad index.

    The message names the file and the line (text formats) or byte offset (binary formats).
    Operating-system failures (a missing file, no permission) raise :class:`OSError` instead.
    """

    path: str | None = None


class NumericalBreakdownError(SurftopoError, ArithmeticError):
    """Double precision could not finish: the Delaunay flips no longer give valid triangles
    (``edge``), or the Voronoi wave's traced edges do not close up (``method="voronoi"`` or
    ``"dubois"`` without ``exact``)."""

    edge: int | None = None


class InternalError(SurftopoError, RuntimeError):
    """A broken invariant: a bug in surftopo, reported instead of a wrong result."""


__all__ = [
    "SurftopoError",
    "InvalidInputError",
    "InvalidMeshError",
    "NotSimplicialError",
    "InvalidGeometryError",
    "FlipLimitError",
    "PortalgonError",
    "MeshFileError",
    "NumericalBreakdownError",
    "InternalError",
]
