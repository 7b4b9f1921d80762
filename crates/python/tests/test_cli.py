"""The Python results equal the CLI's on shared meshes (SURFTOPO_MESHES): the Laplacian and mass
matrix to 1e-12, the same intrinsic triangulation file, and the same quads and irreducible
triangulation for the same algorithm and seed."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.io

import surftopo
from conftest import CLI_MESHES, run_cli


@pytest.fixture(scope="module", params=CLI_MESHES)
def mesh(request, shared_meshes):
    path = shared_meshes / request.param
    if not path.is_file():
        pytest.skip(f"{path} is missing from SURFTOPO_MESHES")
    V, F = surftopo.read_mesh(path)
    assert surftopo.info(V, F)["unreferenced_vertices"] == 0
    return path, V, F


# Newer scipy warns that mmread will return sparse arrays; the test converts either way.
@pytest.mark.filterwarnings("ignore:The default value for `spmatrix`:DeprecationWarning")
def test_laplacian_and_mass_equal_the_cli(cli, mesh, tmp_path):
    path, V, F = mesh
    out = tmp_path / "d.json"
    run_cli(cli, "delaunay", path, "-o", out, "--laplacian", tmp_path / "L.mtx",
            "--mass", tmp_path / "M.mtx")
    L_cli = scipy.io.mmread(tmp_path / "L.mtx").tocsr()
    M_cli = scipy.io.mmread(tmp_path / "M.mtx").tocsr()
    L, M = surftopo.laplacian(V, F)
    assert L.shape == L_cli.shape
    assert abs(L - L_cli).max() <= 1e-12 * max(1.0, abs(L_cli).max())
    assert abs(M - M_cli).max() <= 1e-12 * max(1.0, abs(M_cli).max())
    t = surftopo.intrinsic_delaunay(V, F)
    assert abs(t.laplacian() - L_cli).max() <= 1e-12 * max(1.0, abs(L_cli).max())
    assert t.to_json() == out.read_text()


@pytest.mark.parametrize("algorithm,seed", [("ks", 1), ("lrs", 1), ("sg", 3), ("ps", 7)])
def test_quads_equal_the_cli(cli, mesh, tmp_path, algorithm, seed):
    path, V, F = mesh
    out = tmp_path / "q.obj"
    run_cli(cli, "quad", path, "-o", out, "--algorithm", algorithm, "--seed", seed)
    Vq, Q_cli = surftopo.read_mesh(out)
    Q, _ = surftopo.quadrangulate(V, F, algorithm=algorithm, seed=seed)
    assert np.array_equal(Vq, V)
    assert np.array_equal(Q, Q_cli)


@pytest.mark.parametrize("algorithm,seed", [("rs", 1), ("schipper", 1), ("brute-force", 5)])
def test_irreducible_equals_the_cli(cli, mesh, tmp_path, algorithm, seed):
    path, V, F = mesh
    out = tmp_path / "i.obj"
    run_cli(cli, "irreducible", path, "-o", out, "--algorithm", algorithm, "--seed", seed)
    V_cli, F_cli = surftopo.read_mesh(out)
    V2, F2, stats = surftopo.irreducible(V, F, algorithm=algorithm, seed=seed)
    assert np.array_equal(V2, V_cli)
    assert np.array_equal(F2, F_cli)


def test_info_equals_the_cli(cli, mesh):
    import json

    path, V, F = mesh
    cli_info = json.loads(run_cli(cli, "info", path, "--json").stdout)
    info = surftopo.info(V, F)
    # Warnings name the file and line in the CLI, the face alone here; and the option each has.
    cli_warnings, warnings = cli_info.pop("warnings"), info.pop("warnings")
    # The file's per-vertex properties (normals...) are not in the arrays.
    info["vertex_properties"] = cli_info["vertex_properties"]
    assert len(cli_warnings) == len(warnings)
    for a, b in zip(cli_warnings, warnings):
        assert a.split("face ", 1)[1].split(";")[0] == b.split("face ", 1)[1].split(";")[0]
    assert info == cli_info
