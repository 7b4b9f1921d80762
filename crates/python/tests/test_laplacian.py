"""The cotan Laplacian and mass matrix: structure, spectrum, input dtypes and layouts, and the
cross-check with robust_laplacian and libigl when they are installed."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse

import surftopo
from verify import laplacian_spectrum, triangle_areas

SURFACES = {
    "icosphere(2)": lambda: surftopo.icosphere(2),
    "torus(9, 7)": lambda: surftopo.torus(9, 7),
    "genus_surface(2, 1)": lambda: surftopo.genus_surface(2, 1),
}


@pytest.mark.parametrize("name", SURFACES)
def test_symmetric_psd_one_zero_mode_rows_sum_to_zero(name):
    V, F = SURFACES[name]()
    L, M = surftopo.laplacian(V, F)
    assert isinstance(L, scipy.sparse.csr_matrix) and isinstance(M, scipy.sparse.csr_matrix)
    n = len(V)
    assert L.shape == M.shape == (n, n)
    dense, eigenvalues, scale = laplacian_spectrum(L)
    # One connected surface: exactly one zero mode (the constants).
    assert eigenvalues[1] > 1e-8 * scale
    assert abs(eigenvalues[0]) <= 1e-10 * scale
    # Intrinsic Delaunay: non-negative weights, so non-positive off-diagonal entries.
    off = dense - np.diag(np.diag(dense))
    assert off.max() <= 1e-15 * scale
    # Lumped mass: diagonal, positive, trace = area.
    assert (M - scipy.sparse.diags(M.diagonal())).nnz == 0
    assert M.diagonal().min() > 0
    assert M.diagonal().sum() == pytest.approx(triangle_areas(V, F).sum(), rel=1e-12)


def test_laplacian_equals_intrinsic_delaunay_laplacian():
    V, F = surftopo.torus(12, 5)
    L, M = surftopo.laplacian(V, F)
    t = surftopo.intrinsic_delaunay(V, F)
    assert abs(L - t.laplacian()).max() <= 1e-13 * abs(L).max()
    assert abs(M - t.mass()).max() == 0


def test_int32_int64_and_layouts_give_the_same_result():
    V, F = surftopo.icosphere(3)
    L, M = surftopo.laplacian(V, F)
    variants = [
        (V, F.astype(np.int32)),
        (V, F.astype(np.int64)),
        (V, F.astype(np.uint32)),
        (np.asfortranarray(V), np.asfortranarray(F.astype(np.int32))),
        (np.asfortranarray(V), np.asfortranarray(F)),
        (np.ascontiguousarray(np.hstack([V, V])[:, :3]), F),  # a C-ordered copy
        (V.tolist(), F.tolist()),
    ]
    for k, (Vk, Fk) in enumerate(variants):
        Lk, Mk = surftopo.laplacian(Vk, Fk)
        assert (Lk != L).nnz == 0 and (Mk != M).nnz == 0, f"variant {k}"
    strided = np.zeros((len(V), 6))
    strided[:, ::2] = V
    Ls, _ = surftopo.laplacian(strided[:, ::2], F)
    assert (Ls != L).nnz == 0


def test_unreferenced_vertices_get_empty_rows():
    V, F = surftopo.icosphere(1)
    extra = np.vstack([V[:5], [[9.0, 9.0, 9.0]], V[5:]])
    G = np.where(F >= 5, F + 1, F)
    L, M = surftopo.laplacian(extra, G)
    L0, M0 = surftopo.laplacian(V, F)
    assert L.shape == (len(V) + 1, len(V) + 1)
    assert L[5].nnz == 0 and L[:, 5].nnz == 0 and M[5, 5] == 0
    keep = [i for i in range(len(V) + 1) if i != 5]
    assert abs(L[keep][:, keep] - L0).max() == 0
    assert abs(M[keep][:, keep] - M0).max() == 0


def _meshes_for_cross_check():
    return [surftopo.icosphere(3), surftopo.torus(20, 9), surftopo.genus_surface(3, 1)]


def test_cross_check_robust_laplacian():
    robust_laplacian = pytest.importorskip(
        "robust_laplacian", reason="robust_laplacian is not installed: cross-check skipped"
    )
    for V, F in _meshes_for_cross_check():
        L, M = surftopo.laplacian(V, F)
        # No mollification is needed on these meshes; robust_laplacian's default (1e-5) adds 0.
        Lr, Mr = robust_laplacian.mesh_laplacian(V, F.astype(np.int64))
        scale = abs(L).max()
        assert abs(L - Lr).max() <= 1e-8 * scale
        assert abs(M - Mr).max() <= 1e-8 * abs(M).max()


def test_cross_check_libigl():
    igl = pytest.importorskip("igl", reason="libigl is not installed: cross-check skipped")
    for V, F in _meshes_for_cross_check():
        L, _ = surftopo.laplacian(V, F)
        # libigl's cotmatrix is negative semidefinite: the opposite sign.
        Li, _, _ = igl.intrinsic_delaunay_cotmatrix(V, F)
        assert abs(L + Li).max() <= 1e-8 * abs(L).max()
