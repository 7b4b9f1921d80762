"""surftopo: triangulations of closed surfaces, numpy in, numpy and scipy.sparse out.

Surfaces come as ``(V, F)``: float64 vertex positions of shape ``(n, 3)`` and integer triangles of
shape ``(m, 3)`` (int32 or int64, C or Fortran order; other integer dtypes and nested lists are
converted first). Faces may also be polygons, in any form :func:`read_mesh` returns them: an
``(m, k)`` array, an ``(m, k_max)`` array padded with trailing -1 (``polygons="padded"``; the
counts are not needed), or a list of 1-D sequences (``polygons="list"``); the functions that need
triangles (:func:`info`, :func:`irreducible`, :func:`quadrangulate`, :func:`laplacian`,
:func:`intrinsic_delaunay`, :func:`isometric`) cut them as the CLI does (ear clipping in each
polygon's plane, ``surftopo_mesh::triangulate_polygons``; errors name the polygon), and
:func:`quadrangulate` returns a quad-only input's own quads. Faces are reoriented to a consistent
orientation, unreferenced vertices are ignored (and get empty rows in matrices). Every vertex
index returned is an index into ``V`` (the input's vertex numbering is kept everywhere, as in the
CLI). The GIL is released while the libraries compute, and Ctrl-C raises
:class:`KeyboardInterrupt` within about 20 ms in every long call (the interrupted work, which
only the census can stop, ends in the background, its result dropped).

Invalid input raises a subclass of :class:`InvalidInputError` (a :class:`ValueError`) whose
message is the one the ``surftopo`` CLI prints and whose attributes name the element
(``face``, ``edge``, ``vertex``, ``polygon``, ``side``).
"""

from __future__ import annotations

import os
from typing import Any, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt
import scipy.sparse

from ._errors import (
    FlipLimitError as FlipLimitError,
    InternalError as InternalError,
    InvalidGeometryError as InvalidGeometryError,
    InvalidInputError as InvalidInputError,
    InvalidMeshError as InvalidMeshError,
    MeshFileError as MeshFileError,
    NotSimplicialError as NotSimplicialError,
    NumericalBreakdownError as NumericalBreakdownError,
    PortalgonError as PortalgonError,
    SurftopoError as SurftopoError,
)

__all__ = [
    "FlipLimitError",
    "InternalError",
    "IntrinsicTriangulation",
    "InvalidGeometryError",
    "InvalidInputError",
    "InvalidMeshError",
    "MeshFileError",
    "NotSimplicialError",
    "NumericalBreakdownError",
    "Portalgon",
    "PortalgonError",
    "SurftopoError",
    "annulus",
    "canonical_form",
    "cavity_box",
    "census",
    "disk",
    "flat_torus",
    "genus_surface",
    "icosphere",
    "info",
    "intrinsic_delaunay",
    "irreducible",
    "isometric",
    "isometry_verdict",
    "klein_bottle",
    "laplacian",
    "mobius_band",
    "non_orientable",
    "projective_plane",
    "quadrangulate",
    "read_mesh",
    "tetrahedron",
    "torus",
    "write_mesh",
]

__version__: str
"""The package's version (the surftopo workspace's, as ``surftopo --version`` prints it)."""

_Vertices = Union[npt.NDArray[np.float64], Sequence[Sequence[float]]]
"""Vertex positions, ``(n, 3)``; float64 arrays are read in place when C-contiguous."""
_Faces = Union[npt.NDArray[np.int32], npt.NDArray[np.int64], Sequence[Sequence[int]]]
"""Vertex indices: ``(m, 3)`` triangles, ``(m, k)`` polygons, the same padded with -1, or a list
of polygons (cut into triangles where triangles are needed)."""
_Surface = Union[Tuple[_Vertices, _Faces], "Portalgon", "IntrinsicTriangulation"]
"""A closed polyhedral surface: ``(V, F)``, a :class:`Portalgon` or an intrinsic triangulation."""

def read_mesh(
    path: Union[str, os.PathLike[str]],
    weld: bool = False,
    polygons: str = "auto",
    attributes: bool = False,
) -> tuple[Any, ...]:
    """Read a mesh file: OBJ, OFF, PLY or STL, optionally gzipped (``.gz``).

    Returns ``(V, F)``: float64 positions ``(n, 3)`` (every vertex of the file, in its order:
    vertices in no face included, so indices match the file's) and int64 faces as ``polygons``
    says:

    - ``"auto"``: an ``(m, k)`` array when every face has ``k`` sides (3 for triangles, 4 for
      quads), else a list of 1-D arrays, one per face;
    - ``"list"``: always that list;
    - ``"padded"``: an ``(m, k_max)`` array padded with ``-1``, followed by the side counts:
      ``(V, F, counts)``;
    - ``"triangles"``: an ``(m', 3)`` array, every polygon cut into triangles as the CLI's
      commands cut them (ear clipping in the polygon's plane, exact predicates: no degenerate
      triangle for a polygon simple in its plane), ready for :func:`laplacian`.

    ``attributes=True`` appends a dict of the per-vertex properties read beside the positions
    (name -> float64 ``(n,)``: ``u``, ``v`` for texture coordinates, ``nx``, ``ny``, ``nz``,
    colours, any PLY vertex property) and, for OBJ values given per face corner,
    ``corner_texcoords`` / ``corner_normals`` as ``(table, corners)``: the ``(e, width)`` float64
    table and each face corner's row (int64, ``-1`` for none), corners in face order.

    STL is always welded (its triangles share no vertices); ``weld=True`` also merges exactly
    equal positions in the other formats.

    Raises :class:`MeshFileError` naming the file and line (or byte offset), or :class:`OSError`
    (e.g. :class:`FileNotFoundError`).

    >>> import os, tempfile
    >>> path = os.path.join(tempfile.mkdtemp(), "sphere.obj")
    >>> surftopo.write_mesh(path, *surftopo.icosphere(2))
    >>> V, F = surftopo.read_mesh(path)
    >>> V.shape, F.shape
    ((162, 3), (320, 3))
    >>> prism = os.path.join(tempfile.mkdtemp(), "prism.obj")
    >>> with open(prism, "w") as f:
    ...     _ = f.write("v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nv 0 0 1\\nv 1 0 1\\nv 0 1 1\\n"
    ...                 "f 1 3 2\\nf 4 5 6\\nf 1 2 5 4\\nf 2 3 6 5\\nf 3 1 4 6\\n")
    >>> [len(f) for f in surftopo.read_mesh(prism)[1]]
    [3, 3, 4, 4, 4]
    >>> V, F, counts = surftopo.read_mesh(prism, polygons="padded")
    >>> F[0].tolist(), counts.tolist()
    ([0, 2, 1, -1], [3, 3, 4, 4, 4])
    >>> surftopo.read_mesh(prism, polygons="triangles")[1].shape
    (8, 3)
    """

def write_mesh(path: Union[str, os.PathLike[str]], vertices: _Vertices, faces: _Faces) -> None:
    """Write ``(V, F)`` to a mesh file, atomically (a failure leaves no half-written file).

    The format follows the extension: ``.obj``, ``.off``, ``.ply`` (binary little-endian),
    optionally ``.gz``. ``faces`` may be triangles ``(m, 3)``, quads ``(m, 4)`` (the ``Q`` of
    :func:`quadrangulate`) or any polygons (``(m, k)``, padded with -1, or a list, as
    :func:`read_mesh` returns them). Floats are written so that reading them back gives the same
    bits.
    """

def info(vertices: _Vertices, faces: _Faces, weld: bool = False) -> dict[str, Any]:
    """Counts, topology and every problem found, valid surface or not.

    The keys of ``surftopo info --json``: ``vertices``, ``edges``, ``faces``, ``genus`` (``None``
    unless the faces form one orientable surface), ``euler_characteristic``, ``components``,
    ``closed``, ``orientable``, ``boundary_loops``, ``boundary_edges``, ``simplicial``, ``valid``
    (no problem: a triangulated surface, boundary, non-orientable pieces and several components
    allowed), ``reoriented_faces``, ``unreferenced_vertices``, ``welded_vertices``, one count per
    problem class (``non_finite_coordinates``, ``zero_area_faces``, ``degenerate_faces``,
    ``duplicate_faces``, ``non_manifold_edges``, ``non_manifold_vertices``, ``other_problems``),
    ``problems_total``, ``problems_truncated``, ``problems`` (at most 100 messages, each naming
    the face, edge or vertex) and ``surfaces``: one dict per connected component with
    ``faces``, ``euler_characteristic``, ``orientable``, ``boundary_loops``, ``genus`` (``None``
    when non-orientable), ``crosscaps`` (``None`` when orientable), ``euler_genus`` and ``name``.
    ``weld=True`` first merges vertices with exactly equal positions.

    >>> V, F = surftopo.torus(24, 12)
    >>> d = surftopo.info(V, F)
    >>> d["genus"], d["valid"], d["faces"]
    (1, True, 576)
    >>> [s["name"] for s in surftopo.info(V, F[1:])["surfaces"]]
    ['genus 1 with 1 boundary loop']
    >>> surftopo.info(*surftopo.klein_bottle())["surfaces"][0]["crosscaps"]
    2
    """

def irreducible(
    vertices: _Vertices,
    faces: _Faces,
    algorithm: str = "rs",
    seed: int = 1,
    compact: bool = False,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], dict[str, Any]]:
    """An irreducible triangulation of the surface by topology-preserving edge contractions.

    Every edge of the result fails the link condition, so none can be contracted without changing
    the topology: the tetrahedron for genus 0, 7 to 10 vertices for the torus, 6 or 7 for the
    projective plane, a single triangle for a disk. Any compact surface is taken: boundary loops
    (the link condition of Dey et al. with the boundary coned over one vertex), non-orientable
    surfaces, several pieces (each reduced). ``algorithm`` is ``"rs"`` (Ramaswami–Siqueira,
    O(g² + gn)), ``"schipper"`` or ``"brute-force"`` (seeded by ``seed``; the CLI's default seed
    is also 1).

    Returns ``(V2, F2, stats)``: ``V2`` a copy of ``V`` (the input's vertex list: as the CLI's
    output, the numbering is kept) and ``F2`` the triangles as indices into it, on the surviving
    vertices; with ``compact=True`` (the CLI's ``--compact``) ``V2`` holds the surviving vertices
    only, in input order, and ``F2`` indexes them. ``stats``: the keys of
    ``surftopo irreducible --json`` (``algorithm``, ``input`` and ``output`` counts,
    ``link_tests``, ``edges_tested_more_than_once``, ``contractions``, ``seconds``, ``seed`` for
    brute force) plus ``vertex_indices``: the index into ``V`` of each surviving vertex (each row
    of ``V2`` with ``compact=True``).

    >>> V, F = surftopo.torus(24, 12)
    >>> V2, F2, stats = surftopo.irreducible(V, F)
    >>> {k: stats["output"][k] for k in ("vertices", "edges", "faces", "genus")}
    {'vertices': 7, 'edges': 21, 'faces': 14, 'genus': 1}
    >>> V2.shape == V.shape, sorted(set(F2.ravel().tolist())) == stats["vertex_indices"].tolist()
    (True, True)
    >>> V3, F3, _ = surftopo.irreducible(V, F, compact=True)
    >>> bool((V3 == V[stats["vertex_indices"]]).all()), bool((V3[F3] == V2[F2]).all())
    (True, True)
    >>> V2, F2, stats = surftopo.irreducible(*surftopo.klein_bottle())
    >>> stats["output"]["surfaces"][0]["name"], 8 <= len(stats["vertex_indices"]) <= 11
    ('Klein bottle', True)
    """

def census(
    surface: str, max_vertices: int | None = None
) -> list[npt.NDArray[np.int64]]:
    """Every irreducible triangulation of a closed surface, up to isomorphism.

    ``surface`` is ``"sphere"``, ``"torus"``, ``"projective-plane"``, ``"klein-bottle"``,
    ``"genus-G"`` or ``"nK"``. Each entry is an int64 ``(m, 3)`` face array on the vertices
    ``0..n`` in canonical labelling (see :func:`canonical_form`), sorted by vertex count; a
    triangulation and its mirror image are one entry. ``max_vertices`` cuts the search (the list
    is then complete up to that many vertices only); a surface with no vertex bound within reach
    (``"n3"``, ``"genus-2"`` and beyond) needs it, else :class:`InvalidInputError`. The method,
    its completeness argument and its sources: ``surftopo census --help`` and the README.

    >>> [len(F) for F in surftopo.census("projective-plane")]
    [10, 12]
    >>> len(surftopo.census("torus"))
    21
    """

def canonical_form(faces: _Faces) -> npt.NDArray[np.int64]:
    """The canonical form of a closed triangulated surface, orientable or not.

    ``faces`` is an ``(m, 3)`` integer array on the vertices ``0..n`` (every index used). The
    result, an int64 ``(m, 3)`` array with each row sorted and the rows sorted, is equal for two
    face lists exactly when they are isomorphic as simplicial complexes (mirror images included).
    A face list that is not a closed connected simplicial surface raises
    :class:`InvalidMeshError` naming the face, edge or vertex.

    >>> F = np.array([[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]])
    >>> surftopo.canonical_form(F[:, ::-1][[3, 1, 2, 0]]).tolist()
    [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
    """

def quadrangulate(
    vertices: _Vertices,
    faces: _Faces,
    algorithm: str = "ks",
    objective: str = "count",
    seed: int = 1,
    all_quads: bool = False,
) -> tuple[npt.NDArray[np.int64], dict[str, Any]]:
    """A quad mesh on the same vertices: a maximum pairing of the triangles, on any compact
    surface (boundary loops, non-orientable, several pieces), as ``surftopo quad``.

    Each quad ``[a, d, b, c]`` is the triangles ``(a, b, c)`` and ``(b, a, d)`` glued along their
    shared edge ``a-b``, its corners in the order of the first (on an orientable piece its
    consistent orientation; on a non-orientable one, the input's order of that triangle). A
    closed piece is paired entirely; a piece with boundary may leave triangles that no pairing
    can pair (an odd count, a triangle with three ears): as few as possible, proven by a
    Tutte–Berge certificate checked before the quads are built.
    ``algorithm``: ``"ks"`` (Karp–Sipser with local repairs, the fastest), ``"sg"`` (simple
    greedy) and ``"ps"`` (Pulli–Segal), both seeded by ``seed``, ``"lrs"`` (contraction and
    expansion; its quads pair triangles of a flipped triangulation; orientable pieces only),
    ``"ds"`` (Diks–Stanczyk). ``objective``: ``"count"`` (a maximum pairing, by ``algorithm``),
    ``"quality"`` (the maximum pairing of least total cost 1 − η, η being Remacle et al.'s quad
    quality, exact, its certificate verified; ``algorithm`` unused) or ``"quality-fast"`` (a
    cheaper approximation). ``all_quads``: turn each triangle left into a quad by one vertex added
    at the midpoint of a boundary edge (the fewest such vertices). Polygons are cut into triangles
    as the CLI cuts them; when every face is a quad, its own quads are returned (each as given or
    reversed to the piece's orientation; ``stats["objective"]`` is then ``"count"`` and
    ``algorithm`` and ``objective`` do not apply), as ``surftopo quad`` does.

    Returns ``(Q, stats)``: ``Q`` an int64 ``(k, 4)`` array of vertex indices, and the keys of
    ``surftopo quad --json`` (with ``cost``, ``optimality_gap``, ``quality``,
    ``unpaired_triangles``, ``deficiency_lower_bound``, ``added_vertices``, and ``components``
    when there are several pieces), plus ``triangles`` (the ``(t, 3)`` triangles left),
    ``added_positions`` (``(a, 3)``: the added vertices, numbered from ``len(V)``) and
    ``added_edges`` (``(a, 2)``: the boundary edge each is the midpoint of).

    >>> V, F = surftopo.torus(24, 12)
    >>> Q, stats = surftopo.quadrangulate(V, F)
    >>> Q.shape, stats["paired_percent"]
    ((288, 4), 100.0)
    >>> V, F = surftopo.disk(3)
    >>> Q, stats = surftopo.quadrangulate(V, F[:-1], all_quads=True)
    >>> Q.shape, stats["added_vertices"], stats["added_positions"].shape
    ((9, 4), 1, (1, 3))
    """

def laplacian(
    vertices: _Vertices,
    faces: _Faces,
    method: str = "flip",
    exact: bool = False,
    mollify: float | None = None,
    max_flips: int | None = None,
    format: str = "csr",
    tufted: bool | None = None,
    mollify_factor: float | None = None,
) -> tuple[Any, Any]:
    """The cotan Laplacian ``L`` and the lumped mass matrix ``M`` of the intrinsic Delaunay
    triangulation, as ``robust_laplacian.mesh_laplacian`` returns them.

    ``tufted=True`` takes any triangle soup (non-manifold edges and vertices, fins, duplicate
    faces, several pieces) through the tufted cover of Sharp and Crane ("A Laplacian for
    Nonmanifold Triangle Meshes", 2020): every face gets two sides glued around each edge in the
    faces' order in space, the lengths are mollified (``mollify_factor``, default ``1e-5`` of the
    mean edge length, as robust_laplacian's), the cover is flipped to intrinsic Delaunay, and its
    matrices are folded onto the input vertices with the factor 1/2. ``tufted=None`` (the
    default) does so, with a :class:`UserWarning`, when the soup is not a manifold (a
    non-manifold edge or vertex, a duplicate face); ``tufted=False`` refuses such soups. On a
    closed manifold both give the same ``L``. An unreferenced vertex has a zero row and mass
    (robust_laplacian puts 1 on its diagonal). On a manifold, ``mollify_factor`` is ``mollify``.

    Sign convention: ``L`` is **positive semidefinite** (positive diagonal, off-diagonal
    ``-w_ij`` with ``w_ij >= 0``), symmetric, with rows summing to zero; libigl's ``cotmatrix``
    is ``-L``. ``M`` is diagonal: a third of the incident triangle areas. Both are
    ``len(V) x len(V)`` (a vertex in no face gets an empty row and column), in ``format``:
    ``"csr"`` (``scipy.sparse.csr_matrix``, the default) or ``"csc"`` (``csc_matrix``, as
    robust_laplacian returns them). Degenerate input (a zero-length edge, a flat triangle) raises
    :class:`InvalidGeometryError` unless ``mollify`` (epsilon relative to the mean edge length)
    asks for intrinsic mollification; ``max_flips`` bounds the flips (:class:`FlipLimitError`).
    Matrices beyond double precision's range (areas that overflow or underflow: coordinates of
    1e200 or 1e-200) raise :class:`InvalidGeometryError`, as the CLI refuses them. ``method``
    computes the Delaunay triangulation as in :func:`intrinsic_delaunay` (every method gives the
    same ``L``); ``exact=True`` raises :class:`InvalidInputError`: a mesh's lengths are square
    roots (use a :class:`Portalgon` given by exact corners with :func:`intrinsic_delaunay`).

    Any manifold mesh is taken: boundary loops (boundary edges are never flipped and keep their
    one half-cotangent: the natural Neumann boundary condition, libigl's
    ``intrinsic_delaunay_cotmatrix``), non-orientable pieces and several pieces (``L`` is then
    block-diagonal, one zero mode per piece), by flipping; ``method="voronoi"`` or ``"dubois"``
    raise :class:`SurftopoError` on them (Dubois' methods treat closed orientable surfaces).

    >>> V, F = surftopo.icosphere(2)
    >>> L, M = surftopo.laplacian(V, F)
    >>> L.shape, bool(abs(L.sum(axis=1)).max() < 1e-12)
    ((162, 162), True)
    >>> round(float(M.sum()), 4)  # the area of the polyhedron
    12.3291
    >>> L, M = surftopo.laplacian(*surftopo.mobius_band(12, 3))
    >>> round(float(M.sum()), 4), bool(abs(L.sum(axis=1)).max() < 1e-12)
    (3.6806, True)
    >>> book = [[0, 1, 2], [1, 0, 3], [0, 1, 4]]  # three triangles on one edge
    >>> W = [[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0], [0.5, 0, 1]]
    >>> L, M = surftopo.laplacian(W, book, tufted=True)
    >>> L.shape, round(float(M.sum()), 4)  # the area of the three triangles
    ((5, 5), 1.5)
    """

def intrinsic_delaunay(
    vertices: Union[_Vertices, Portalgon, IntrinsicTriangulation],
    faces: _Faces | None = None,
    method: str = "flip",
    exact: bool = False,
    mollify: float | None = None,
    max_flips: int | None = None,
    tufted: bool | None = None,
    mollify_factor: float | None = None,
) -> IntrinsicTriangulation:
    """The intrinsic Delaunay triangulation of a polyhedral surface.

    The surface is ``(V, F)``, or a triangular :class:`Portalgon` (``faces`` omitted), or an
    :class:`IntrinsicTriangulation`. ``method``, as ``surftopo delaunay --method``: ``"flip"``
    (Bobenko–Springborn edge flipping with robust half-angle formulas; loops and multi-edges may
    appear), ``"voronoi"`` (Dubois' multi-source Voronoi wave and its dual: the tessellation cut
    into triangles), ``"dubois"`` (Dubois' Theorem 1: the reduction, then the wave; for
    needles), or ``"auto"`` (flipping unless a triangle's aspect ratio exceeds 1e5, then
    ``"dubois"`` on a flat surface). ``exact=True`` computes in exact rational arithmetic
    (``"voronoi"``, ``"dubois"``, ``"auto"``) on a :class:`Portalgon` given by exact corners;
    anything else raises :class:`InvalidInputError`. Where double precision cannot finish the
    wave, :class:`NumericalBreakdownError`. ``mollify`` and ``max_flips`` (flipping only) as in
    :func:`laplacian`.

    Takes what :func:`laplacian` takes. A mesh with boundary loops, non-orientable pieces or
    several pieces is flipped on its closed cover (boundary edges never flipped, a
    non-orientable piece on its double cover, each piece on its own); ``"auto"`` takes
    ``"flip"`` there and ``"voronoi"`` and ``"dubois"`` raise :class:`SurftopoError` naming flip
    (Dubois treats closed surfaces). The triangulation's faces, edges and lengths are the
    surface's (one face per input triangle's place, boundary edges in one face); its Laplacian
    has the natural boundary condition; :meth:`IntrinsicTriangulation.tessellation` keeps the
    boundary edges as unmatched sides and flags the gluings that reverse orientation. A soup
    that is not a manifold goes through the tufted cover as in :func:`laplacian` (``tufted``,
    ``mollify_factor``; a :class:`UserWarning` when ``tufted=None`` takes it): the result is the
    cover flipped (``faces``: every input face twice, as input vertex indices), its
    ``laplacian()`` and ``mass()`` folded with 1/2; ``tessellation()``, ``to_json()`` and
    ``to_portalgon()`` raise :class:`InvalidInputError` (as ``delaunay --tufted`` refuses ``-o``
    and ``--tessellation``).

    >>> t = surftopo.intrinsic_delaunay(surftopo.flat_torus(10.0))
    >>> t.flips  # Section 9 of the paper: T_x needs x - 1 flips
    9
    >>> t.tessellation()
    Portalgon(1 polygons, 4 sides)
    >>> surftopo.intrinsic_delaunay(*surftopo.disk(3)).tessellation()  # nine unit squares
    Portalgon(9 polygons, 36 sides)
    """

def isometric(a: _Surface, b: _Surface, allow_reflection: bool = True) -> bool:
    """Whether two compact polyhedral surfaces are isometric.

    Closed orientable surfaces: their canonical Delaunay tessellations are compared (Corollary 2
    of the intrinsic-Delaunay paper; flat vertices removed first). Any other kind (boundary
    loops, non-orientable, several pieces; a :class:`Portalgon` of version 2 too) as ``surftopo
    isometric`` compares it: pieces, boundary lengths and tessellations with twisted gluings
    (``docs/isometry_every_surface.md``). True only for the verdict ``"isometric"``
    (:func:`isometry_verdict` tells the others apart). Mirror images count as isometric unless
    ``allow_reflection=False``. Each surface is ``(V, F)``, a :class:`Portalgon` or an
    :class:`IntrinsicTriangulation`.

    >>> V, F = surftopo.torus(12, 6)
    >>> surftopo.isometric((V, F), (V + 1.0, F)), surftopo.isometric((V, F), (2 * V, F))
    (True, False)
    """

def isometry_verdict(a: _Surface, b: _Surface) -> tuple[str, str]:
    """The verdict of ``surftopo isometric`` (default method) and its reason, on any surfaces.

    The verdict is ``"isometric"``, ``"not isometric"`` (a proof: an invariant or the
    tessellations differ), ``"undecidable in double precision"`` or ``"undecided"`` (a flat
    vertex on a surface with boundary or without orientation), as the CLI prints it.

    >>> V, F = surftopo.mobius_band(9, 3)
    >>> surftopo.isometry_verdict((V, F), (V + 1.0, F))[0], surftopo.isometry_verdict((V, F), (2 * V, F))[0]
    ('isometric', 'not isometric')
    """

@final
class IntrinsicTriangulation:
    """An intrinsic Delaunay triangulation (made by :func:`intrinsic_delaunay`).

    Vertex indices are those of the input ``V`` (the dense vertex order for a portalgon). Loops
    (an edge from a vertex to itself) and multi-edges are allowed.

    >>> t = surftopo.intrinsic_delaunay(*surftopo.icosphere(1))
    >>> t.faces.shape, t.edges.shape, t.edge_lengths.shape
    ((80, 3), (120, 2), (120,))
    """

    def laplacian(self) -> scipy.sparse.csr_matrix:
        """The cotan Laplacian, positive semidefinite (see :func:`laplacian`)."""
    def mass(self) -> scipy.sparse.csr_matrix:
        """The lumped (barycentric) mass matrix, diagonal."""
    def tessellation(self, cocircular_tolerance: float | None = None) -> Portalgon:
        """The Delaunay tessellation: co-circular triangles merged into polygons (unique).

        Two triangles are co-circular when ``|tan(γ/2) tan(δ/2) - 1|`` is at most
        ``cocircular_tolerance`` (``None``: the library's default, 1e-9). Never merged across a
        boundary edge: boundary edges are unmatched sides. On a non-orientable surface each
        polygon is laid out on one sheet of the double cover and a gluing whose two sides run
        the same way is flagged ``true`` (portalgon JSON version 2; ``json.loads`` reads it;
        :meth:`Portalgon.from_json` reads tessellations of closed orientable surfaces only).
        """
    def to_json(self) -> str:
        """Portalgon JSON, triangles by side lengths: what ``surftopo delaunay -o`` writes."""
    def to_portalgon(self) -> Portalgon:
        """The triangulation as a :class:`Portalgon`."""
    @property
    def faces(self) -> npt.NDArray[np.int64]:
        """``(m, 3)`` vertex indices; side ``i`` runs from corner ``i`` to corner ``i + 1``."""
    @property
    def edges(self) -> npt.NDArray[np.int64]:
        """``(E, 2)`` vertex indices of each edge (both equal for a loop)."""
    @property
    def face_edges(self) -> npt.NDArray[np.int64]:
        """``(m, 3)``: side ``i`` of face ``f`` is edge ``face_edges[f, i]``."""
    @property
    def edge_lengths(self) -> npt.NDArray[np.float64]:
        """``(E,)`` intrinsic length of each edge, in the order of :attr:`edges`."""
    @property
    def flips(self) -> int:
        """The number of flips made."""
    @property
    def stats(self) -> dict[str, Any]:
        """The keys of ``surftopo delaunay --json``: ``vertices``, ``edges``, ``faces``,
        ``flips``, ``non_delaunay_edges``, ``seconds``, ``mollify_delta``, ``loops``,
        ``multi_edges``."""
    @property
    def vertex_count(self) -> int:
        """Rows of the matrices: ``len(V)``, or the portalgon's vertex count."""

@final
class Portalgon:
    """A closed polyhedral surface as flat polygons glued along their sides.

    The JSON format is ``crates/intrinsic/PORTALGON_FORMAT.md`` of the repository (what
    ``surftopo generate flat-torus`` and ``surftopo delaunay`` write).

    >>> p = surftopo.flat_torus(3.0)
    >>> q = surftopo.Portalgon.from_json(p.to_json())
    >>> q.polygon_count, q.matched_pairs, round(q.area, 12)
    (2, 3, 2.0)
    """

    @staticmethod
    def from_json(text: str) -> Portalgon:
        """Parse and validate a portalgon JSON text (:class:`PortalgonError` otherwise).

        Exact corners (strings such as ``"1/3"`` or ``"1e100"``) that are valid exactly are
        kept even where doubles cannot hold them: ``intrinsic_delaunay(..., exact=True)``
        computes on them; the double-precision methods refuse them with
        :class:`NumericalBreakdownError` naming ``exact=True`` (the rounding's error: a triangle
        whose rounded lengths or corners have not its exact area, ``T_x`` for ``x = 10**30``).

        Version 2 is read: a file of triangles with unmatched sides (boundary), gluings flagged
        ``true`` (orientation-reversing) or several pieces, as ``surftopo delaunay -o`` writes
        it for such a mesh, is a surface for :func:`intrinsic_delaunay` and :func:`isometric`.
        """
    def to_json(self) -> str:
        """The JSON text (compact)."""
    @property
    def polygon_count(self) -> int:
        """Number of polygons."""
    @property
    def side_count(self) -> int:
        """Number of polygon sides."""
    @property
    def matched_pairs(self) -> int:
        """Number of glued side pairs."""
    @property
    def area(self) -> float:
        """Total area."""

def tetrahedron() -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The boundary of a tetrahedron (4 vertices, genus 0), as ``(V, F)``."""

def icosphere(subdivisions: int = 3) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """An icosahedron refined ``subdivisions`` times by 1-to-4 splits (``20 * 4**s``
    triangles), on the unit sphere.

    >>> V, F = surftopo.icosphere(2)
    >>> V.shape, F.shape
    ((162, 3), (320, 3))
    """

def torus(m: int = 24, n: int = 12) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """A torus of revolution as an ``m x n`` grid (``2 m n`` triangles, genus 1), ``m, n >= 3``."""

def genus_surface(
    genus: int = 2, size: int = 2
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """A closed surface of genus ``genus``: a slab with square through-holes; ``size`` scales
    the resolution.

    >>> V, F = surftopo.genus_surface(3, 1)
    >>> surftopo.info(V, F)["genus"]
    3
    """

def cavity_box(
    cavities: int = 3844, holes: int = 0, triangles: int = 100000
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The papers' brick with ``cavities`` square cavities and ``holes`` through-holes (genus
    ``holes``), refined to about ``triangles`` triangles."""

def disk(n: int = 8) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The unit square as an ``n x n`` grid: a disk (``2 n^2`` triangles), ``n >= 1``."""

def annulus(m: int = 24, n: int = 4) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """An open cylinder: an annulus as an ``m x n`` grid (``2 m n`` triangles), ``m >= 3``,
    ``n >= 1``."""

def mobius_band(m: int = 24, n: int = 4) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """A Möbius band as an ``m x n`` grid glued with a half twist (``2 m n`` triangles),
    ``m >= 5``, ``n >= 1``.

    >>> surftopo.info(*surftopo.mobius_band())["surfaces"][0]["name"]
    'Möbius band'
    """

def projective_plane() -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The 6-vertex projective plane (10 triangles, every two vertices adjacent)."""

def klein_bottle(m: int = 24, n: int = 12) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """A Klein bottle as an ``m x n`` grid on the figure-8 immersion (``2 m n`` triangles),
    ``m, n >= 3``."""

def non_orientable(crosscaps: int = 3) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]:
    """The non-orientable surface N_k with ``crosscaps`` crosscaps: a connected sum of 6-vertex
    projective planes (``8k + 2`` triangles).

    >>> surftopo.info(*surftopo.non_orientable(3))["surfaces"][0]["name"]
    'N_3'
    """

def flat_torus(x: float, m: int = 1) -> Portalgon:
    """The flat torus T_x of the intrinsic-Delaunay paper (Section 9): one vertex, two
    triangles (0,0), (1,0), (x,2); refined ``m x m`` when ``m > 1``."""
