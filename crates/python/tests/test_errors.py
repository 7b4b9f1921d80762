"""Invalid input raises ValueError subclasses that name the element, with the CLI's message."""

from __future__ import annotations

import functools

import numpy as np
import pytest

import surftopo


def test_isometric_takes_surfaces_with_boundary_and_non_orientable_ones():
    # Compared on their covers as `surftopo isometric` compares them
    # (test_isometry_every_surface.py checks the verdicts against the CLI's).
    V, F = surftopo.torus(5, 4)
    assert surftopo.isometric((V, F[1:]), (V + 1.0, F[1:]))
    assert not surftopo.isometric((V, F[1:]), (V, F))
    assert surftopo.isometric(surftopo.klein_bottle(6, 5), surftopo.klein_bottle(6, 5))


def test_index_out_of_range_names_the_face():
    V, F = surftopo.tetrahedron()
    for bad in (4, -1, 2**40):
        G = F.copy()
        G[2, 1] = bad
        with pytest.raises(surftopo.InvalidMeshError) as caught:
            surftopo.laplacian(V, G)
        assert (caught.value.face, caught.value.vertex) == (2, bad)
        assert str(caught.value) == f"face 2: vertex index {bad} out of range (4 vertices)"
    for layout in (np.ascontiguousarray, np.asfortranarray):
        G = layout(F.astype(np.int32))
        G[3, 0] = -7
        with pytest.raises(surftopo.InvalidMeshError) as caught:
            surftopo.laplacian(V, G)
        assert (caught.value.face, caught.value.vertex) == (3, -7)


def test_non_manifold_edge_and_disconnected_and_non_finite():
    V, F = surftopo.tetrahedron()
    fin = np.vstack([V, [[1.0, 1.0, 1.0]]])
    with pytest.raises(surftopo.InvalidMeshError, match="non-manifold edge") as caught:
        surftopo.laplacian(fin, np.vstack([F, [[0, 1, 4]]]), tufted=False)
    assert caught.value.kind == "NonManifoldEdge" and caught.value.edge == (0, 1)
    # By default, the tufted cover takes it, with a warning.
    with pytest.warns(UserWarning, match="not a manifold"):
        surftopo.laplacian(fin, np.vstack([F, [[0, 1, 4]]]))
    two = np.vstack([V, V + 5.0])
    # isometric, laplacian and intrinsic_delaunay take the two pieces: one block each.
    pair = (two, np.vstack([F, F + 4]))
    assert surftopo.isometric(pair, pair)
    assert surftopo.intrinsic_delaunay(two, np.vstack([F, F + 4])).faces.shape == (8, 3)
    L, _ = surftopo.laplacian(two, np.vstack([F, F + 4]))
    assert L[:4, 4:].nnz == 0 and (L[:4, :4] != surftopo.laplacian(V, F)[0]).nnz == 0
    W = V.copy()
    W[3, 2] = np.nan
    with pytest.raises(surftopo.InvalidMeshError, match="vertex 3: non-finite") as caught:
        surftopo.laplacian(W, F)
    assert caught.value.vertex == 3


def test_degenerate_geometry_and_mollify():
    V, F = surftopo.tetrahedron()
    W = V.copy()
    W[3] = W[0]
    with pytest.raises(surftopo.InvalidGeometryError) as caught:
        surftopo.laplacian(W, F)
    assert isinstance(caught.value, ValueError) and caught.value.edge is not None
    assert caught.value.kind == "NonPositiveLength"
    L, M = surftopo.laplacian(W, F, mollify=1e-3)
    assert np.isfinite(L.data).all() and M.diagonal().min() > 0


def test_flip_limit():
    with pytest.raises(surftopo.FlipLimitError) as caught:
        surftopo.intrinsic_delaunay(surftopo.flat_torus(100.0), max_flips=10)
    assert caught.value.flips == 10 and caught.value.pending > 0
    assert caught.value.kind == "MaxFlips"


def test_two_triangle_sphere_is_refused():
    # (V, F) arrays cannot make loops or multi-edges; two triangles on the same three vertices
    # are the only non-simplicial closed soup, and building refuses it for every function.
    V = np.eye(3)
    F = np.array([[0, 1, 2], [0, 2, 1]])
    refusing = functools.partial(surftopo.laplacian, tufted=False)
    for call in (surftopo.irreducible, surftopo.quadrangulate, refusing):
        with pytest.raises(surftopo.InvalidMeshError) as caught:
            call(V, F)
        assert caught.value.kind == "DuplicateFace" and caught.value.face == 1
    # laplacian's default takes it through the tufted cover (a doubled triangle), with a warning.
    with pytest.warns(UserWarning, match="not a manifold"):
        surftopo.laplacian(V, F)


def test_bad_names_list_the_allowed_values():
    V, F = surftopo.tetrahedron()
    with pytest.raises(ValueError, match=r"objective: expected one of \"count\", \"quality\", \"quality-fast\", got \"best\""):
        surftopo.quadrangulate(V, F, objective="best")
    with pytest.raises(surftopo.InvalidInputError) as caught:
        surftopo.quadrangulate(V, F, objective="best")
    assert caught.value.kind is None
    with pytest.raises(ValueError, match=r"method: expected one of \"auto\", \"flip\", \"voronoi\", \"dubois\", got \"x\""):
        surftopo.intrinsic_delaunay(V, F, method="x")
    with pytest.raises(ValueError, match=r"\"rs\", \"schipper\", \"brute-force\""):
        surftopo.irreducible(V, F, algorithm="x")
    with pytest.raises(ValueError, match=r"\"sg\", \"ps\", \"lrs\", \"ds\", \"ks\""):
        surftopo.quadrangulate(V, F, algorithm="x")


def test_shapes_and_dtypes():
    V, F = surftopo.tetrahedron()
    with pytest.raises(ValueError, match=r"vertices: expected shape \(n, 3\), got \(4, 2\)"):
        surftopo.laplacian(V[:, :2], F)
    with pytest.raises(ValueError, match=r"faces: expected shape \(m, k\) with k >= 3, got \(4, 2\)"):
        surftopo.laplacian(V, F[:, :2])
    with pytest.raises(TypeError, match="integer"):
        surftopo.laplacian(V, F.astype(float))


def test_files(tmp_path):
    with pytest.raises(FileNotFoundError):
        surftopo.read_mesh(tmp_path / "missing.obj")
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
    with pytest.raises(surftopo.MeshFileError, match="bad.obj:4"):
        surftopo.read_mesh(bad)
    with pytest.raises(surftopo.MeshFileError, match="unsupported file extension"):
        surftopo.write_mesh(tmp_path / "x.xyz", *surftopo.tetrahedron())


def test_portalgon_errors():
    with pytest.raises(surftopo.PortalgonError, match="portalgon JSON"):
        surftopo.Portalgon.from_json("{")
    text = surftopo.flat_torus(3.0).to_json().replace('"matching":[[[0,0],[1,1]],', '"matching":[')
    with pytest.raises(surftopo.PortalgonError) as caught:
        surftopo.intrinsic_delaunay(surftopo.Portalgon.from_json(text))
    assert caught.value.polygon is not None


def test_arrays_of_the_wrong_kind_or_shape_are_refused():
    V, F = surftopo.tetrahedron()
    with pytest.raises(surftopo.InvalidInputError, match=r"faces: expected a two-dimensional array of shape \(m, k\), got shape \(12,\)"):
        surftopo.info(V, F.ravel())
    with pytest.raises(surftopo.InvalidInputError, match=r"vertices: expected a two-dimensional array"):
        surftopo.laplacian(V.ravel(), F)
    with pytest.raises(TypeError, match="vertices: expected real numbers, got an array of dtype <U"):
        surftopo.info(V.astype(str), F)
    with pytest.raises(TypeError, match="vertices: expected real numbers, got an array of dtype complex128"):
        surftopo.laplacian(V + 0j, F)
    with pytest.raises(TypeError, match="vertices: expected real numbers, got an array of dtype bool"):
        surftopo.info(V > 0, F)
    with pytest.raises(TypeError, match="faces: expected integers, got an array of dtype float64"):
        surftopo.info(V, F.astype(float))
    # Lists of numbers and other real dtypes still work.
    assert surftopo.info(V.tolist(), F.tolist())["valid"]
    assert surftopo.info(V.astype(np.float32), F.astype(np.uint16))["valid"]
