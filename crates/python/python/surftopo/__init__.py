"""surftopo: triangulated surfaces, numpy in, numpy and scipy.sparse out.

Irreducible triangulations (of any compact surface: boundary loops, non-orientable, several
pieces), quadrangulations and intrinsic Delaunay triangulations (with their cotan Laplacian and
mass matrix; closed, connected, orientable meshes), computed by the surftopo Rust libraries with
the GIL released. See ``help(surftopo.laplacian)`` and the type stubs
for every function; invalid input raises a subclass of :class:`InvalidInputError` (a
:class:`ValueError`) that names the face, edge or vertex.

>>> import surftopo
>>> V, F = surftopo.icosphere(2)
>>> L, M = surftopo.laplacian(V, F)
>>> L.shape
(162, 162)
"""

from . import _errors, _native
from ._errors import *  # noqa: F403 (the exception classes, listed in _errors.__all__)
from ._native import *  # noqa: F403 (the functions and classes; the type stubs list them)
from ._native import __version__  # the package's version (the workspace's)

__all__ = [name for name in dir(_native) if not name.startswith("_")] + _errors.__all__
