"""Why robust_laplacian differs from libigl (and from surftopo's natural boundary condition) on
open meshes: its tufted cover glues each face to its mirror image along the boundary, so a
boundary edge becomes an interior edge whose two opposite angles are the one angle γ facing it in
its face; the cover's intrinsic Delaunay triangulation flips it when 2γ > π. libigl and surftopo
never flip a boundary edge. Tested here: with no obtuse angle facing the boundary the two
Laplacians are the same; with one they differ, and the tufted one is the Laplacian of the surface
doubled along its boundary (built explicitly, flipped by the closed-surface path), folded back."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse

import surftopo


def _fan(widest_degrees):
    """A flat fan of six triangles around vertex 0 (interior), the first with angle
    ``widest_degrees`` at vertex 0 (facing its boundary edge), the others sharing the rest."""
    rest = (360.0 - widest_degrees) / 5
    angles = np.radians(np.concatenate([[0.0], widest_degrees + rest * np.arange(5)]))
    radii = 1.0 + 0.1 * np.arange(6)
    ring = np.column_stack([radii * np.cos(angles), radii * np.sin(angles), np.zeros(6)])
    V = np.vstack([[0.0, 0.0, 0.0], ring])
    F = np.array([[0, 1 + k, 1 + (k + 1) % 6] for k in range(6)])
    return V, F


def boundary_edges(V, F):
    """The number of boundary edges (in one face) and of those facing an obtuse angle in their
    face (also the benchmark's column)."""
    sides = np.vstack([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
    opposite = np.concatenate([F[:, 2], F[:, 0], F[:, 1]])
    _, which, count = np.unique(np.sort(sides, axis=1), axis=0, return_inverse=True,
                                return_counts=True)
    boundary = count[which.ravel()] == 1
    a, b, o = (V[x] for x in (sides[boundary, 0], sides[boundary, 1], opposite[boundary]))
    return int(boundary.sum()), int((np.einsum("ij,ij->i", a - o, b - o) < 0).sum())


def _facing_obtuse(V, F):
    return boundary_edges(V, F)[1]


def _doubled_and_folded(V, F):
    """The Laplacian of the surface glued to its mirror image along its boundary (interior
    vertices copied, boundary vertices shared; a closed surface, flipped by surftopo's closed
    path), folded back onto V with the tufted cover's factor 1/2."""
    n = len(V)
    sides = np.sort(np.vstack([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, count = np.unique(sides, axis=0, return_counts=True)
    copy = np.arange(n) + n
    copy[np.unique(unique[count == 1])] = np.unique(unique[count == 1])
    L, _ = surftopo.laplacian(np.vstack([V, V]), np.vstack([F, copy[F][:, ::-1]]), tufted=False)
    fold = scipy.sparse.vstack([scipy.sparse.identity(n), scipy.sparse.identity(n)]).tocsr()
    return 0.5 * (fold.T @ L @ fold)


def _relative(A, B):
    return abs(A - B).max() / abs(A).max()


def _holed_icosphere():
    """An icosphere with the stars of three far-apart vertices removed: near-equilateral
    triangles, so every angle facing the boundary is acute."""
    V, F = surftopo.icosphere(3)
    centres = [0, 5, 9]
    return V, F[~np.isin(F, centres).any(axis=1)]


@pytest.mark.parametrize(
    "mesh, doubled",
    [
        (lambda: _fan(80.0), True),
        (lambda: _fan(89.0), True),
        # The grid's corner triangles have three boundary vertices: doubled, they would be a
        # face and its reverse, which the closed path refuses.
        (lambda: surftopo.disk(6), False),
        (lambda: surftopo.annulus(24, 3), True),
        (_holed_icosphere, True),
    ],
)
def test_with_no_obtuse_angle_facing_the_boundary_tufted_equals_natural(mesh, doubled):
    V, F = mesh()
    assert _facing_obtuse(V, F) == 0
    natural, _ = surftopo.laplacian(V, F)
    tufted, _ = surftopo.laplacian(V, F, tufted=True, mollify_factor=0.0)
    assert _relative(natural, tufted) < 1e-12
    if doubled:
        assert _relative(tufted, _doubled_and_folded(V, F)) < 1e-12


@pytest.mark.parametrize("widest", [95.0, 120.0, 150.0])
def test_a_boundary_edge_facing_an_obtuse_angle_is_flipped_in_the_tufted_cover(widest):
    V, F = _fan(widest)
    assert _facing_obtuse(V, F) == 1
    natural, _ = surftopo.laplacian(V, F)
    tufted, _ = surftopo.laplacian(V, F, tufted=True, mollify_factor=0.0)
    # The natural condition keeps edge (1, 2): its weight is cot(widest) / 2 < 0.
    assert natural[1, 2] == pytest.approx(-0.5 / np.tan(np.radians(widest)), rel=1e-12)
    assert natural[1, 2] > 0  # a negative cotan weight: the boundary edge is not Delaunay
    # The cover flips it: the tufted Laplacian is the doubled surface's, folded.
    assert _relative(natural, tufted) > 1e-2
    assert _relative(tufted, _doubled_and_folded(V, F)) < 1e-12
    assert tufted[1, 2] <= 0


def test_robust_laplacian_is_the_tufted_cover_on_open_meshes():
    robust_laplacian = pytest.importorskip("robust_laplacian")
    for V, F in (_fan(80.0), _fan(120.0), _holed_icosphere()):
        tufted, _ = surftopo.laplacian(V, F, tufted=True, mollify_factor=0.0)
        theirs = robust_laplacian.mesh_laplacian(V, F, mollify_factor=0.0)[0]
        # robust_laplacian puts a 1 on the diagonal of an unreferenced vertex (the holes').
        used = np.unique(F)
        assert _relative(tufted[used][:, used], theirs.tocsr()[used][:, used]) < 1e-12
        natural, _ = surftopo.laplacian(V, F)
        assert (_relative(natural[used][:, used], theirs.tocsr()[used][:, used]) > 1e-2) == (
            _facing_obtuse(V, F) > 0
        )
