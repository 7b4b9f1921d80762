"""The Laplacian on surfaces with boundary, non-orientable surfaces and files of several pieces:
against libigl's intrinsic_delaunay_cotmatrix on open manifold meshes (the natural boundary
condition: a boundary edge keeps its one half-cotangent), and by structure on every kind."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse

import surftopo
from verify import laplacian_spectrum, triangle_areas


def jitter(V, amount, seed):
    rng = np.random.default_rng(seed)
    return V + amount * rng.uniform(-0.5, 0.5, V.shape)


def cut_holes(V, F, holes, seed):
    """Removes the faces around `holes` vertices chosen at random, far from each other and from
    the boundary; unreferenced vertices stay (they get empty rows)."""
    rng = np.random.default_rng(seed)
    n = len(V)
    neighbours = [set() for _ in range(n)]
    for a, b, c in F:
        neighbours[a] |= {b, c}
        neighbours[b] |= {a, c}
        neighbours[c] |= {a, b}
    edges = np.sort(np.vstack([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    blocked = np.zeros(n, bool)
    blocked[unique[counts == 1].ravel()] = True

    def block(v, depth):
        frontier = {v}
        for _ in range(depth):
            frontier |= {w for u in frontier for w in neighbours[u]}
        blocked[list(frontier)] = True

    for v in np.flatnonzero(blocked).tolist():
        block(v, 2)
    removed = []
    for v in rng.permutation(n):
        if len(removed) == holes:
            break
        if not blocked[v]:
            removed.append(v)
            block(v, 3)
    keep = ~np.isin(F, removed).any(axis=1)
    return V, F[keep]


def open_meshes():
    sphere = surftopo.icosphere(3)
    torus = surftopo.torus(30, 12)
    return {
        "disk": (jitter(surftopo.disk(12)[0], 0.03, 1), surftopo.disk(12)[1]),
        "annulus": (jitter(surftopo.annulus(24, 6)[0], 0.05, 2), surftopo.annulus(24, 6)[1]),
        "sphere with holes": cut_holes(jitter(sphere[0], 0.02, 3), sphere[1], 6, 4),
        "torus with holes": cut_holes(torus[0], torus[1], 4, 5),
    }


def check_structure(L, M, V, F, components):
    n = len(V)
    assert isinstance(L, scipy.sparse.csr_matrix) and L.shape == M.shape == (n, n)
    dense, eigenvalues, scale = laplacian_spectrum(L)
    # One zero mode (the constants) per component; unreferenced vertices add empty rows.
    empty = int((np.abs(dense).sum(axis=1) == 0).sum())
    zero = int((np.abs(eigenvalues) <= 1e-9 * scale).sum())
    assert zero == components + empty
    assert M.diagonal().sum() == pytest.approx(triangle_areas(V, F).sum(), rel=1e-12)


@pytest.mark.parametrize("name", list(open_meshes()))
def test_open_meshes_match_libigl(name):
    igl = pytest.importorskip("igl", reason="libigl is not installed: cross-check skipped")
    V, F = open_meshes()[name]
    assert not surftopo.info(V, F)["closed"]
    L, M = surftopo.laplacian(V, F)
    check_structure(L, M, V, F, 1)
    # libigl's cotmatrix is negative semidefinite: the opposite sign.
    Li, _, _ = igl.intrinsic_delaunay_cotmatrix(V, F)
    assert abs(L + Li).max() <= 1e-12 * abs(L).max()


def test_holes_cut_from_a_shared_mesh_match_libigl(shared_meshes):
    igl = pytest.importorskip("igl", reason="libigl is not installed: cross-check skipped")
    V, F = surftopo.read_mesh(shared_meshes / "hand_4054.obj.gz")
    V, F = cut_holes(V, F, 8, 6)
    assert surftopo.info(V, F)["boundary_loops"] == 8
    L, _ = surftopo.laplacian(V, F)
    Li, _, _ = igl.intrinsic_delaunay_cotmatrix(V, F)
    assert abs(L + Li).max() <= 1e-12 * abs(L).max()


NON_ORIENTABLE = {
    "mobius band": lambda: surftopo.mobius_band(12, 3),
    "projective plane": lambda: surftopo.projective_plane(),
    "klein bottle": lambda: surftopo.klein_bottle(12, 6),
    "N3": lambda: surftopo.non_orientable(3),
}


@pytest.mark.parametrize("name", list(NON_ORIENTABLE))
def test_non_orientable_symmetric_psd_and_delaunay(name):
    V, F = NON_ORIENTABLE[name]()
    V = jitter(V, 0.05, 7)
    L, M = surftopo.laplacian(V, F)
    check_structure(L, M, V, F, 1)
    if surftopo.info(V, F)["closed"]:
        # Every edge interior and Delaunay: its weight (cot γ + cot δ)/2 is non-negative.
        off = L.toarray() - np.diag(L.diagonal())
        assert off.max() <= 1e-14 * abs(L).max()


def three_pieces():
    """A Möbius band, a disk and a sphere in one file, and each piece's own arrays."""
    V1, F1 = jitter(surftopo.mobius_band(10, 2)[0], 0.05, 8), surftopo.mobius_band(10, 2)[1]
    V2, F2 = jitter(surftopo.disk(5)[0], 0.05, 9), surftopo.disk(5)[1]
    V3, F3 = surftopo.icosphere(1)
    V = np.vstack([V1, V2 + 3, V3 - 3])
    F = np.vstack([F1, F2 + len(V1), F3 + len(V1) + len(V2)])
    return V, F, [(V1, F1), (V2, F2), (V3, F3)]


def test_pieces_are_independent_blocks():
    V, F, [(V1, F1), (V2, F2), (V3, F3)] = three_pieces()
    L, M = surftopo.laplacian(V, F)
    check_structure(L, M, V, F, 3)
    blocks = [(0, len(V1), V1, F1), (len(V1), len(V1) + len(V2), V2, F2)]
    blocks.append((len(V1) + len(V2), len(V), V3, F3))
    for lo, hi, Vk, Fk in blocks:
        Lk, Mk = surftopo.laplacian(Vk, Fk)
        assert abs(L[lo:hi, lo:hi] - Lk).max() <= 1e-14 * abs(Lk).max()
        # Lengths from shifted positions differ by rounding.
        assert abs(M[lo:hi, lo:hi] - Mk).max() <= 1e-14 * abs(Mk).max()
        assert L[lo:hi].nnz == Lk.nnz


def test_the_wave_and_theorem_1_refuse_naming_flip():
    V, F = surftopo.mobius_band()
    for method in ("voronoi", "dubois"):
        with pytest.raises(surftopo.SurftopoError, match="closed orientable surfaces only.*flip"):
            surftopo.laplacian(V, F, method=method)
    L, _ = surftopo.laplacian(V, F, method="auto")
    assert (L != surftopo.laplacian(V, F, method="flip")[0]).nnz == 0
