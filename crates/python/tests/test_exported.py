"""Meshes as exporters write them, through the CLI and the package alike, every output read back
by trimesh, meshio, scipy and numpy: vertices in no face keep their index (empty matrix rows,
outputs on the input's vertex list), polygon faces (read as lists, padded arrays or triangles;
cut by the CLI the same way), per-vertex attributes, the Python contract the CLI has
(unrepresentable matrices refused, ``__version__``, ``format="csc"``)."""

from __future__ import annotations

import subprocess

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import surftopo
from conftest import run_cli

trimesh = pytest.importorskip("trimesh")
meshio = pytest.importorskip("meshio")

pytestmark = pytest.mark.filterwarnings("ignore:The default value for `spmatrix`:DeprecationWarning")


def loose_sphere(tmp_path):
    """An icosphere whose vertex list has three vertices in no face (first, middle, last)."""
    V, F = surftopo.icosphere(1)
    W = np.vstack([[[9.0, 9.0, 9.0]], V[:20], [[7.0, 7.0, 7.0]], V[20:], [[5.0, 5.0, 5.0]]])
    G = np.where(F >= 20, F + 2, F + 1)
    path = tmp_path / "loose.obj"
    surftopo.write_mesh(path, W, G)
    return path, W, G


def test_matrices_keep_the_input_numbering(cli, tmp_path):
    path, W, G = loose_sphere(tmp_path)
    run_cli(cli, "delaunay", path, "--laplacian", tmp_path / "L.mtx", "--mass", tmp_path / "M.npz")
    loaded = trimesh.load(path, process=False, maintain_order=True)  # OBJ: keep every vertex
    n = len(loaded.vertices)
    assert n == len(W) == len(meshio.read(path).points)
    L_cli = scipy.io.mmread(tmp_path / "L.mtx").tocsr()
    M_cli = scipy.sparse.load_npz(tmp_path / "M.npz")
    L, M = surftopo.laplacian(W, G)
    assert L_cli.shape == M_cli.shape == L.shape == (n, n)
    assert abs(L_cli - L).max() <= 1e-12 * abs(L).max()
    assert abs(M_cli - M).max() <= 1e-12 * abs(M).max()
    loose = [0, 21, n - 1]
    for i in loose:
        assert L_cli[i].nnz == 0 and L_cli[:, i].nnz == 0 and M_cli[i, i] == 0
    # The rows of the other vertices are those of the sphere without the loose vertices.
    V, F = surftopo.icosphere(1)
    L0, _ = surftopo.laplacian(V, F)
    kept = [i for i in range(n) if i not in loose]
    assert abs(L_cli[kept][:, kept] - L0).max() <= 1e-12 * abs(L0).max()


def test_quads_and_irreducible_are_on_the_input_vertex_list(cli, tmp_path):
    path, W, G = loose_sphere(tmp_path)
    run_cli(cli, "quad", path, "-o", tmp_path / "q.obj")
    run_cli(cli, "irreducible", path, "-o", tmp_path / "i.ply")
    quads = meshio.read(tmp_path / "q.obj")
    assert np.array_equal(quads.points, W)
    Q_cli = quads.cells_dict["quad"]
    Q, _ = surftopo.quadrangulate(W, G)
    assert np.array_equal(Q_cli, Q)
    reduced = trimesh.load(tmp_path / "i.ply", process=False)
    assert np.array_equal(reduced.vertices, W)
    V2, F2, stats = surftopo.irreducible(W, G)
    assert np.array_equal(V2, W) and np.array_equal(reduced.faces, F2)
    assert sorted(set(F2.ravel().tolist())) == stats["vertex_indices"].tolist()
    assert len(stats["vertex_indices"]) == 4  # a tetrahedron, on input indices


PRISM = (
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
    "f 1 3 2\nf 4 5 6\nf 1 2 5 4\nf 2 3 6 5\nf 3 1 4 6\n"
)


def test_polygons_are_read_and_cut_as_the_cli_cuts_them(cli, tmp_path):
    path = tmp_path / "prism.obj"
    path.write_text(PRISM)
    V, faces = surftopo.read_mesh(path)
    assert [f.tolist() for f in faces] == [
        [0, 2, 1], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [2, 0, 3, 5]
    ]
    mesh = meshio.read(path)
    assert np.array_equal(mesh.cells_dict["triangle"], np.array(faces[:2]))
    assert np.array_equal(mesh.cells_dict["quad"], np.array(faces[2:]))
    same = surftopo.read_mesh(path, polygons="list")[1]
    assert all(np.array_equal(a, b) for a, b in zip(same, faces))
    _, padded, counts = surftopo.read_mesh(path, polygons="padded")
    assert counts.tolist() == [3, 3, 4, 4, 4] and padded.shape == (5, 4)
    for row, face, k in zip(padded, faces, counts):
        assert row[:k].tolist() == face.tolist() and (row[k:] == -1).all()
    _, T = surftopo.read_mesh(path, polygons="triangles")
    # Each quad in two triangles on its own corners, oriented as the quad: a closed surface.
    assert T.shape == (8, 3) and surftopo.info(V, T)["closed"]
    assert surftopo.info(V, T)["valid"]
    # The CLI cuts the file the same way: its Laplacian is the package's on those triangles.
    run_cli(cli, "delaunay", path, "--laplacian", tmp_path / "L.mtx")
    L_cli = scipy.io.mmread(tmp_path / "L.mtx").tocsr()
    L, _ = surftopo.laplacian(V, T)
    assert abs(L_cli - L).max() <= 1e-12 * abs(L).max()
    # A quad-only input: `quad` returns its own quads (meshio reads them back).
    cube = tmp_path / "cube.obj"
    cube.write_text(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
    )
    run_cli(cli, "quad", cube, "-o", tmp_path / "cube-q.obj")
    assert np.array_equal(
        meshio.read(tmp_path / "cube-q.obj").cells_dict["quad"], surftopo.read_mesh(cube)[1]
    )


def test_per_vertex_attributes_are_returned(tmp_path):
    V, F = surftopo.tetrahedron()
    lines = [f"v {x} {y} {z}" for x, y, z in V]
    lines += [f"vt {i / 10} {i / 5}" for i in range(len(V))]
    lines += [f"vn 0 0 {i}" for i in range(len(V))]
    lines += ["f " + " ".join(f"{v + 1}/{v + 1}/{v + 1}" for v in f) for f in F]
    path = tmp_path / "attributes.obj"
    path.write_text("\n".join(lines) + "\n")
    V2, F2, attributes = surftopo.read_mesh(path, attributes=True)
    assert np.array_equal(V2, V) and np.array_equal(F2, F)
    uv = np.column_stack([attributes["u"], attributes["v"]])
    assert np.allclose(uv, trimesh.load(path, process=False).visual.uv)
    assert attributes["nz"].tolist() == list(range(len(V)))


def test_unrepresentable_matrices_are_refused_as_in_the_cli(cli, tmp_path):
    V, F = surftopo.icosphere(1)
    for scale in (1e200, 1e-200):
        with pytest.raises(surftopo.InvalidGeometryError, match="double precision"):
            surftopo.laplacian(V * scale, F)
        path = tmp_path / "scaled.obj"
        surftopo.write_mesh(path, V * scale, F)
        out = subprocess.run(
            [str(cli), "delaunay", str(path), "--mass", str(tmp_path / "M.mtx")],
            capture_output=True,
            text=True,
        )
        assert out.returncode == 2 and "double precision" in out.stderr, out.stderr


def test_version_and_csc(cli):
    out = run_cli(cli, "--version").stdout.split()
    assert surftopo.__version__ == out[-1]
    V, F = surftopo.torus(12, 6)
    L, M = surftopo.laplacian(V, F)
    Lc, Mc = surftopo.laplacian(V, F, format="csc")
    assert Lc.format == "csc" and Mc.format == "csc" and L.format == "csr"
    assert abs(Lc - L).max() == 0 and abs(Mc - M).max() == 0
    with pytest.raises(surftopo.InvalidInputError, match="format"):
        surftopo.laplacian(V, F, format="coo")


def test_info_warns_and_hints_as_the_cli():
    V, F = surftopo.tetrahedron()
    soup_V = V[F].reshape(-1, 3)
    soup_F = np.arange(len(soup_V)).reshape(-1, 3)
    info = surftopo.info(soup_V, soup_F)
    assert info["weld_hint"] == (
        "`weld=True` would merge 8 vertices into others at the same position, making one "
        "closed surface (sphere)"
    )
    assert surftopo.info(soup_V, soup_F, weld=True)["weld_hint"] is None
    needle = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1e-10, 0], [0.3, 0.3, 1]], dtype=float)
    G = np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]])
    info = surftopo.info(needle, G)
    assert info["valid"] and info["near_degenerate_faces"] == 1
    assert info["warnings"][0].startswith("face 0: near-degenerate: height 1.0e-10")
    with pytest.raises(surftopo.InvalidGeometryError):
        surftopo.laplacian(needle, G)
    L, _ = surftopo.laplacian(needle, G, mollify=1e-6)
    assert L.shape == (4, 4)


def test_quads_cut_into_no_surface_are_read_as_the_cli_reads_them(cli, tmp_path):
    # LRS quads on the demo's input: ear clipping gives a duplicate triangle, the fans a surface;
    # read_mesh(polygons="triangles") gives the CLI's triangles, so both Laplacians agree.
    g2 = tmp_path / "g2.obj"
    run_cli(cli, "generate", "genus", "--genus", "2", "--size", "2", "--flips", "1000",
            "--seed", "7", "-o", g2)
    quads = tmp_path / "q.obj"
    run_cli(cli, "quad", g2, "--algorithm", "lrs", "-o", quads)
    V, T = surftopo.read_mesh(quads, polygons="triangles")
    info = surftopo.info(V, T)
    assert info["genus"] == 2 and info["duplicate_faces"] == 0
    V2, F2, stats = surftopo.irreducible(V, T)
    assert stats["output"]["genus"] == 2
    assert trimesh.load(quads, process=False, maintain_order=True).vertices.shape == V.shape
