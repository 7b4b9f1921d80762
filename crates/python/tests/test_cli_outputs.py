"""Every matrix output of `surftopo delaunay` read back by the library users read it with:
`.npz` by `scipy.sparse.load_npz`, `.npy` by `numpy.load`, `.mtx` by `scipy.io.mmread`; each
equal to the package's own matrices. Generated inputs only (no shared meshes needed)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import surftopo
from conftest import run_cli


@pytest.mark.filterwarnings("ignore:The default value for `spmatrix`:DeprecationWarning")
def test_npz_npy_and_mtx_outputs_load_in_scipy_and_numpy(cli, tmp_path):
    mesh = tmp_path / "g.ply"
    run_cli(cli, "generate", "genus", "--genus", "2", "--size", "4", "--flips", "50", "-o", mesh)
    run_cli(cli, "delaunay", mesh, "--laplacian", tmp_path / "L.npz", "--mass", tmp_path / "M.npz")
    run_cli(cli, "delaunay", mesh, "--laplacian", tmp_path / "L.mtx", "--mass", tmp_path / "M.npy")
    L_npz = scipy.sparse.load_npz(tmp_path / "L.npz")
    M_npz = scipy.sparse.load_npz(tmp_path / "M.npz")
    L_mtx = scipy.io.mmread(tmp_path / "L.mtx").tocsr()
    M_npy = np.load(tmp_path / "M.npy")
    V, F = surftopo.read_mesh(mesh)
    L, M = surftopo.laplacian(V, F)
    assert L_npz.shape == L.shape == (len(V), len(V))
    assert L_npz.format == "csr" and L_npz.dtype == np.float64
    scale = abs(L).max()
    assert abs(L_npz - L).max() <= 1e-12 * scale
    assert abs(L_mtx - L).max() <= 1e-12 * scale
    assert abs(M_npz - M).max() <= 1e-12 * abs(M).max()
    assert M_npy.shape == (len(V),) and np.allclose(M_npy, M.diagonal(), rtol=1e-12, atol=0)
    # The Laplacian is positive semidefinite with rows summing to zero.
    assert np.abs(np.asarray(L_npz.sum(axis=1))).max() <= 1e-9 * scale
