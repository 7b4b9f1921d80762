"""Polygon meshes in every function that needs triangles, as the CLI takes them: faces in any form
``read_mesh`` returns (an ``(m, k)`` array, a padded array, a list), cut into triangles by the
CLI's rule (``surftopo_mesh::triangulate_polygons``), a quad-only input's own quads from
``quadrangulate``. Checked against independent computations (a fan triangulation written here,
counts of the polygons' sides) and against the CLI on the same files."""

from __future__ import annotations

import json
from collections import Counter

import numpy as np
import pytest
import scipy.io

import surftopo
from conftest import run_cli
from verify import is_closed_oriented, is_irreducible_surface

pytestmark = pytest.mark.filterwarnings("ignore:The default value for `spmatrix`:DeprecationWarning")


def pentagonal_prism():
    """Two pentagons and five quads: a closed polygon mesh (sphere), every face planar, convex."""
    angles = 2 * np.pi * np.arange(5) / 5
    ring = np.column_stack([np.cos(angles), np.sin(angles)])
    V = np.vstack([np.column_stack([ring, np.zeros(5)]), np.column_stack([ring, np.ones(5)])])
    faces = [list(range(4, -1, -1)), list(range(5, 10))]
    faces += [[i, (i + 1) % 5, (i + 1) % 5 + 5, i + 5] for i in range(5)]
    return V, faces


def cube():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                  [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
    F = np.array([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4],
                  [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])
    return V, F


def quad_torus(m=8, n=6):
    """A torus of revolution as an ``m x n`` grid of quads (genus 1)."""
    u = 2 * np.pi * np.arange(m) / m
    v = 2 * np.pi * np.arange(n) / n
    uu, vv = np.meshgrid(u, v, indexing="ij")
    V = np.column_stack([((2 + np.cos(vv)) * np.cos(uu)).ravel(),
                         ((2 + np.cos(vv)) * np.sin(uu)).ravel(), np.sin(vv).ravel()])
    at = lambda i, j: (i % m) * n + (j % n)  # noqa: E731
    F = np.array([[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
                  for i in range(m) for j in range(n)])
    return V, F


def padded(faces):
    width = max(len(f) for f in faces)
    out = -np.ones((len(faces), width), dtype=np.int64)
    for row, f in zip(out, faces):
        row[: len(f)] = f
    return out


def fan(faces):
    """Corner 0's fan of every face (independent of the library's rule)."""
    return np.array([[f[0], f[i], f[i + 1]] for f in faces for i in range(1, len(f) - 1)])


def sides(faces):
    return {tuple(sorted((f[i], f[(i + 1) % len(f)]))) for f in faces for i in range(len(f))}


def quads_cover_polygons(Q, faces):
    """Each quad is two triangles glued along a diagonal, each triangle on the corners of one
    input polygon, and each polygon of k sides holds exactly k - 2 of them: the quads cover the
    polygons (a triangle on a polygon's corners that is no part of it would make one polygon hold
    more than k - 2 triangles or another fewer)."""
    corners = [set(f) for f in faces]
    held = Counter()
    for a, b, c, d in np.asarray(Q).tolist():
        for t1, t2 in (((a, b, c), (a, c, d)), ((b, c, d), (b, d, a))):
            homes = [[k for k, s in enumerate(corners) if set(t) <= s] for t in (t1, t2)]
            if all(len(h) == 1 for h in homes):
                held.update(h[0] for h in homes)
                break
        else:
            return False
    return all(held[k] == len(f) - 2 for k, f in enumerate(faces))


FORMS = ["list", "padded", "array"]


def as_form(faces, form):
    if form == "list":
        return [np.asarray(f) for f in faces]
    if form == "padded":
        return padded(faces)
    return np.asarray(faces)  # every face of the same size


@pytest.mark.parametrize("form", FORMS)
def test_the_laplacian_of_polygons_is_that_of_any_triangulation(form):
    # The cotan Laplacian of the intrinsic Delaunay triangulation of planar convex faces does not
    # depend on how they were cut (co-circular diagonals have weight 0): an independent check.
    for V, faces in (cube(), quad_torus(), pentagonal_prism()):
        faces = [list(f) for f in faces]
        if form == "array" and len({len(f) for f in faces}) > 1:
            continue
        L, M = surftopo.laplacian(V, as_form(faces, form))
        L_fan, M_fan = surftopo.laplacian(V, fan(faces))
        assert L.shape == (len(V), len(V))
        assert abs(L - L_fan).max() <= 1e-12 * abs(L_fan).max()
        assert M.sum() == pytest.approx(M_fan.sum(), rel=1e-12)  # the same total area


@pytest.mark.parametrize("form", FORMS)
def test_info_counts_polygons(form):
    V, faces = pentagonal_prism()
    if form == "array":
        V, faces = quad_torus()
        faces = faces.tolist()
    info = surftopo.info(V, as_form(faces, form))
    assert info["faces"] == len(faces) and info["edges"] == len(sides(faces))
    chi = len(V) - len(sides(faces)) + len(faces)
    assert info["euler_characteristic"] == chi and info["closed"] and info["valid"]
    assert not info["simplicial"]
    assert [s["faces"] for s in info["surfaces"]] == [len(faces)]
    assert info["genus"] == (2 - chi) // 2


@pytest.mark.parametrize("form", FORMS)
def test_a_quad_only_input_gives_its_own_quads(form):
    for V, F in (cube(), quad_torus()):
        faces = F.tolist()
        Q, stats = surftopo.quadrangulate(V, as_form(faces, form), algorithm="sg",
                                          objective="quality")
        # The input's quads, as listed (each face already oriented as its piece).
        assert Q.tolist() == faces
        assert stats["objective"] == "count" and stats["file_order"]


def test_polygons_are_quadrangulated_on_their_own_vertices():
    V, faces = pentagonal_prism()
    for form in ("list", "padded"):
        Q, stats = surftopo.quadrangulate(V, as_form(faces, form))
        assert Q.max() < len(V) and len(Q) == (3 + 3 + 5 * 2) // 2
        assert is_closed_oriented(Q)  # closed, oriented as the input
        assert quads_cover_polygons(Q, faces)
        assert len(stats["triangles"]) == 0


def test_irreducible_takes_polygons():
    for V, F in (quad_torus(), pentagonal_prism()):
        faces = [list(f) for f in F]
        V2, T, stats = surftopo.irreducible(V, [np.asarray(f) for f in faces])
        assert np.array_equal(V2, V)  # the input's vertex list
        assert is_irreducible_surface(T)
        chi = len(V) - len(sides(faces)) + len(faces)
        used = np.unique(T)
        assert len(used) - len({tuple(sorted(e)) for t in T.tolist()
                                for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}) \
            + len(T) == chi
        assert stats["vertex_indices"].tolist() == used.tolist()


def test_intrinsic_delaunay_and_isometric_take_polygons():
    V, F = cube()
    tri = surftopo.intrinsic_delaunay(V, [np.asarray(f) for f in F])
    assert len(tri.faces) == 12
    assert surftopo.isometric((V, F), (V, fan(F.tolist())))


def test_errors_name_the_polygon():
    V, F = cube()
    # A seventh quad on the cube's edge (0, 4), whose first face is face 2 (the cut's triangles
    # 4 and 5): the error names the polygon.
    faces = F.tolist() + [[6, 2, 0, 4]]
    for function in (surftopo.irreducible, surftopo.quadrangulate):
        with pytest.raises(surftopo.InvalidMeshError) as caught:
            function(V, [np.asarray(f) for f in faces])
        assert caught.value.face == 2, caught.value
        assert "edge (0, 4): in 3 faces (first: face 2)" in str(caught.value)
    with pytest.raises(surftopo.InvalidInputError, match="face 1 has 2 vertices"):
        surftopo.info(V, [[0, 1, 2], [0, 1]])
    with pytest.raises(surftopo.InvalidInputError):
        surftopo.info(V, [[0, 1, 2], [0, 1, 9]])


def test_write_mesh_takes_every_form(tmp_path):
    V, faces = pentagonal_prism()
    for form in ("list", "padded"):
        path = tmp_path / f"prism-{form}.off"
        surftopo.write_mesh(path, V, as_form(faces, form))
        _, back = surftopo.read_mesh(path, polygons="list")
        assert [f.tolist() for f in back] == faces


def test_cli_and_package_agree_on_polygon_files(cli, tmp_path):
    meshes = {"prism": pentagonal_prism(), "cube": cube(), "torus": quad_torus()}
    for name, (V, F) in meshes.items():
        faces = [list(f) for f in F]
        path = tmp_path / f"{name}.obj"
        surftopo.write_mesh(path, V, [np.asarray(f) for f in faces])
        V_read, read = surftopo.read_mesh(path, polygons="list")
        _, pad, _ = surftopo.read_mesh(path, polygons="padded")
        for given in (read, pad):
            info = json.loads(run_cli(cli, "info", path, "--json").stdout)
            mine = surftopo.info(V_read, given)
            for key in ("vertices", "edges", "faces", "euler_characteristic", "genus",
                        "closed", "valid", "simplicial", "surfaces", "problems"):
                assert mine[key] == info[key], key
            quads = tmp_path / f"{name}-q.obj"
            run_cli(cli, "quad", path, "-o", quads)
            Q, _ = surftopo.quadrangulate(V_read, given)
            assert [f.tolist() for f in surftopo.read_mesh(quads, polygons="list")[1]] \
                == Q.tolist()
            reduced = tmp_path / f"{name}-i.obj"
            run_cli(cli, "irreducible", path, "-o", reduced)
            _, T, _ = surftopo.irreducible(V_read, given)
            assert np.array_equal(surftopo.read_mesh(reduced)[1], T)
            run_cli(cli, "delaunay", path, "--laplacian", tmp_path / "L.mtx",
                    "--mass", tmp_path / "M.mtx")
            L, M = surftopo.laplacian(V_read, given)
            for cli_matrix, matrix in (("L.mtx", L), ("M.mtx", M)):
                from_cli = scipy.io.mmread(tmp_path / cli_matrix).tocsr()
                assert abs(from_cli - matrix).max() <= 1e-12 * abs(matrix).max()
