"""surftopo: triangulations of closed surfaces, numpy in, numpy and scipy.sparse out.

Irreducible triangulations, quadrangulations and intrinsic Delaunay triangulations (with their
cotan Laplacian and mass matrix) of closed, connected, orientable triangle meshes, computed by the
surftopo Rust libraries with the GIL released. See ``help(surftopo.laplacian)`` and the type stubs
for every function; invalid input raises a subclass of :class:`InvalidInputError` (a
:class:`ValueError`) that names the face, edge or vertex.

>>> import surftopo
>>> V, F = surftopo.icosphere(2)
>>> L, M = surftopo.laplacian(V, F)
>>> L.shape
(162, 162)
"""

from ._errors import (
    FlipLimitError,
    InternalError,
    InvalidGeometryError,
    InvalidInputError,
    InvalidMeshError,
    MeshFileError,
    NotSimplicialError,
    NumericalBreakdownError,
    PortalgonError,
    SurftopoError,
)
from ._native import (
    IntrinsicTriangulation,
    Portalgon,
    cavity_box,
    flat_torus,
    genus_surface,
    icosphere,
    info,
    intrinsic_delaunay,
    irreducible,
    isometric,
    laplacian,
    quadrangulate,
    read_mesh,
    tetrahedron,
    torus,
    write_mesh,
)

__all__ = [
    "read_mesh",
    "write_mesh",
    "info",
    "irreducible",
    "quadrangulate",
    "intrinsic_delaunay",
    "laplacian",
    "isometric",
    "IntrinsicTriangulation",
    "Portalgon",
    "tetrahedron",
    "icosphere",
    "torus",
    "genus_surface",
    "cavity_box",
    "flat_torus",
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
