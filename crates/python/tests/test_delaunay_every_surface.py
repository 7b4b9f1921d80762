"""intrinsic_delaunay on surfaces with boundary, non-orientable surfaces and files of several
pieces: the triangulation checked edge by edge from the returned lengths, its Laplacian rebuilt
from them and against libigl on open meshes, the tessellation read back as JSON and checked
cell by cell, everything equal to the CLI's output on the same file."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import surftopo
from conftest import run_cli
from verify import triangle_areas
from test_every_surface import (
    NON_ORIENTABLE,
    check_structure,
    cut_holes,
    jitter,
    open_meshes,
    three_pieces,
)


def surfaces():
    kinds = dict(open_meshes())
    for name, make in NON_ORIENTABLE.items():
        V, F = make()
        kinds[name] = (jitter(V, 0.05, 7), F)
    kinds["three pieces"] = three_pieces()[:2]
    kinds["square grid"] = surftopo.disk(6)
    return kinds


def opposite_angles(t):
    """Per edge of the returned triangulation: the angles opposite it in its faces (law of
    cosines from the returned lengths)."""
    lengths = t.edge_lengths[t.face_edges]
    angles = [[] for _ in range(len(t.edge_lengths))]
    for face, sides in zip(t.face_edges, lengths):
        for i in range(3):
            a, b, c = sides[i], sides[(i + 1) % 3], sides[(i + 2) % 3]
            cosine = (b * b + c * c - a * a) / (2 * b * c)
            angles[face[i]].append(math.acos(min(1.0, max(-1.0, cosine))))
    return angles


def cotan_laplacian(t):
    """The Laplacian assembled from the returned triangles alone: half the cotangent of each
    angle on the edge opposite it."""
    n = t.vertex_count
    L = np.zeros((n, n))
    for face, edges in zip(t.faces, t.face_edges):
        sides = t.edge_lengths[edges]
        for i in range(3):
            a, b, c = sides[i], sides[(i + 1) % 3], sides[(i + 2) % 3]
            cosine = (b * b + c * c - a * a) / (2 * b * c)
            weight = 0.5 * cosine / math.sqrt(max(0.0, 1 - cosine * cosine))
            u, v = face[i], face[(i + 1) % 3]
            L[u, v] -= weight
            L[v, u] -= weight
            L[u, u] += weight
            L[v, v] += weight
    return L


def cross(u, v):
    """The z component of the cross product of plane vectors (arrays of them)."""
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def circumcircle(a, b, c):
    bx, by, cx, cy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
    d = 2 * (bx * cy - by * cx)
    ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d
    uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d
    return np.array([a[0] + ux, a[1] + uy]), math.hypot(ux, uy)


def check_tessellation(text, info):
    """The tessellation as JSON: each polygon inscribed and convex, each glued pair strictly
    Delaunay (inscribed angles summing to less than pi) with equal sides, the unmatched sides
    as many as the boundary edges, V - E + F the surface's Euler characteristic."""
    doc = json.loads(text)
    polygons = [np.array(p["corners"], dtype=float) for p in doc["polygons"]]
    for c in polygons:
        centre, r = circumcircle(*c[:3])
        assert np.abs(np.hypot(*(c - centre).T) - r).max() <= 1e-9 * r
        edge = np.roll(c, -1, axis=0) - c
        assert (cross(edge, np.roll(edge, -1, axis=0)) > 0).all()

    def angle(k, i):
        c = polygons[k]
        n = len(c)
        p, q, x = c[i], c[(i + 1) % n], c[(i + 2) % n]
        u, v = p - x, q - x
        return math.atan2(abs(cross(u, v)), np.dot(u, v))

    def length(k, i):
        c = polygons[k]
        return float(np.hypot(*(c[(i + 1) % len(c)] - c[i])))

    for pair in doc["matching"]:
        (p, i), (q, j) = pair[0], pair[1]
        assert angle(p, i) + angle(q, j) < math.pi
        assert length(p, i) == pytest.approx(length(q, j), rel=1e-9)
    sides = sum(len(c) for c in polygons)
    boundary = sides - 2 * len(doc["matching"])
    assert boundary == info["boundary_edges"]
    labels = {v for p in doc["polygons"] for v in p["vertices"]}
    assert len(labels) == info["vertices"]
    chi = len(labels) - (len(doc["matching"]) + boundary) + len(polygons)
    assert chi == info["vertices"] - info["edges"] + info["faces"]
    reversed_pairs = sum(1 for pair in doc["matching"] if len(pair) == 3 and pair[2])
    return doc, reversed_pairs


@pytest.mark.parametrize("name", list(surfaces()))
def test_every_surface_flipped_delaunay_edge_by_edge_with_its_laplacian(name):
    V, F = surfaces()[name]
    info = surftopo.info(V, F)
    t = surftopo.intrinsic_delaunay(V, F)
    assert t.stats["non_delaunay_edges"] == 0
    assert len(t.faces) == info["faces"] and len(t.edges) == info["edges"]
    angles = opposite_angles(t)
    assert sum(len(a) == 1 for a in angles) == info["boundary_edges"]
    assert all(len(a) in (1, 2) for a in angles)
    for a in angles:
        if len(a) == 2:
            assert a[0] + a[1] <= math.pi + 1e-9
    L, M = t.laplacian(), t.mass()
    check_structure(L, M, V, F, info["components"])
    dense = cotan_laplacian(t)
    scale = np.abs(dense).max()
    assert np.abs(L.toarray() - dense).max() <= 1e-10 * scale
    L2, M2 = surftopo.laplacian(V, F)
    assert (L != L2).nnz == 0 and (M != M2).nnz == 0
    if name in open_meshes():
        # libigl's cotmatrix (negative semidefinite) on open manifold meshes.
        igl = pytest.importorskip("igl", reason="libigl is not installed: cross-check skipped")
        Li, _, _ = igl.intrinsic_delaunay_cotmatrix(V, F)
        assert abs(L + Li).max() <= 1e-12 * abs(L).max()
    # The tessellation, read back with json and checked.
    _, reversed_pairs = check_tessellation(t.tessellation().to_json(), info)
    assert (reversed_pairs > 0) == (not info["orientable"])
    if name == "square grid":
        assert t.tessellation().polygon_count == 36


def test_holes_cut_from_a_shared_mesh(shared_meshes):
    igl = pytest.importorskip("igl", reason="libigl is not installed: cross-check skipped")
    V, F = surftopo.read_mesh(shared_meshes / "hand_4054.obj.gz")
    V, F = cut_holes(V, F, 8, 6)
    info = surftopo.info(V, F)
    t = surftopo.intrinsic_delaunay(V, F)
    Li, _, _ = igl.intrinsic_delaunay_cotmatrix(V, F)
    assert abs(t.laplacian() + Li).max() <= 1e-12 * abs(Li).max()
    check_tessellation(t.tessellation().to_json(), info)


# Newer scipy warns that mmread will return sparse arrays; the test converts either way.
@pytest.mark.filterwarnings("ignore:The default value for `spmatrix`:DeprecationWarning")
@pytest.mark.parametrize("name", ["disk", "mobius band", "klein bottle", "three pieces"])
def test_equal_to_the_cli(cli, name, tmp_path):
    V, F = surfaces()[name]
    path = tmp_path / "in.obj"
    surftopo.write_mesh(path, V, F)
    V, F = surftopo.read_mesh(path)
    out, tess = tmp_path / "d.json", tmp_path / "t.json"
    run_cli(cli, "delaunay", path, "-o", out, "--tessellation", tess,
            "--laplacian", tmp_path / "L.mtx", "--mass", tmp_path / "M.mtx")
    t = surftopo.intrinsic_delaunay(V, F)
    assert json.loads(t.to_json()) == json.loads(out.read_text())
    assert json.loads(t.tessellation().to_json()) == json.loads(tess.read_text())
    L_cli = scipy.io.mmread(tmp_path / "L.mtx").tocsr()
    M_cli = scipy.io.mmread(tmp_path / "M.mtx").tocsr()
    assert abs(t.laplacian() - L_cli).max() <= 1e-15 * abs(L_cli).max()
    assert abs(t.mass() - M_cli).max() <= 1e-15 * abs(M_cli).max()


@pytest.mark.parametrize("name", ["disk", "mobius band", "projective plane", "three pieces"])
def test_methods_on_every_surface(name):
    V, F = surfaces()[name]
    for method in ("voronoi", "dubois"):
        with pytest.raises(surftopo.SurftopoError, match="closed orientable surfaces only.*flip"):
            surftopo.intrinsic_delaunay(V, F, method=method)
    auto = surftopo.intrinsic_delaunay(V, F, method="auto")
    flip = surftopo.intrinsic_delaunay(V, F, method="flip")
    assert auto.to_json() == flip.to_json()
    with pytest.raises(surftopo.InvalidInputError, match="exact=True needs a Portalgon"):
        surftopo.intrinsic_delaunay(V, F, method="voronoi", exact=True)
    # A triangulation made here is taken again (flipping it again changes nothing).
    again = surftopo.intrinsic_delaunay(flip)
    assert again.flips == 0 and again.to_json() == flip.to_json()


def test_a_non_orientable_tessellation_is_a_version_2_document():
    V, F = surftopo.mobius_band(12, 3)
    p = surftopo.intrinsic_delaunay(V, F).tessellation()
    doc = json.loads(p.to_json())
    assert doc["version"] == 2
    assert p.area == pytest.approx(surftopo.laplacian(V, F)[1].sum(), rel=1e-12)
    # Read back as a version-2 surface (cells of more sides are cut into triangles): the unit
    # square glued to itself with a half twist is a Möbius band of area 1.
    assert surftopo.Portalgon.from_json(p.to_json()).polygon_count == p.polygon_count
    square = {"format": "surftopo-portalgon", "version": 2,
              "polygons": [{"corners": [[0, 0], [1, 0], [1, 1], [0, 1]]}],
              "matching": [[[0, 1], [0, 3], True]]}
    band = surftopo.intrinsic_delaunay(surftopo.Portalgon.from_json(json.dumps(square)))
    assert band.mass().sum() == pytest.approx(1.0, rel=1e-12)
    assert abs(band.laplacian().sum(axis=1)).max() < 1e-12
    square["polygons"][0]["corners"][2] = [1, 2]
    with pytest.raises(surftopo.PortalgonError, match=r"\(0, 1\) and \(0, 3\)"):
        surftopo.Portalgon.from_json(json.dumps(square))
    q = surftopo.intrinsic_delaunay(*surftopo.annulus(12, 3)).tessellation()
    assert surftopo.Portalgon.from_json(q.to_json()).polygon_count == q.polygon_count


@pytest.mark.parametrize("name", ["book of 3", "book of 7", "pinched cones",
                                  "two pieces, one with a fin", "random soup 2"])
def test_tufted_soups_flipped_cover_and_its_laplacian(name):
    from test_tufted import SOUPS

    V, F = SOUPS[name]
    with pytest.warns(UserWarning, match="not a manifold"):
        automatic = surftopo.intrinsic_delaunay(V, F)
    t = surftopo.intrinsic_delaunay(V, F, tufted=True, mollify_factor=1e-5)
    # The cover: every input face twice, every edge in two triangles and Delaunay.
    assert len(t.faces) == 2 * len(F)
    for a in opposite_angles(t):
        assert len(a) == 2 and a[0] + a[1] <= math.pi + 1e-9
    # The cover's area (Heron, from its lengths) is twice the input's (up to mollification).
    a, b, c = np.sort(t.edge_lengths[t.face_edges], axis=1).T[::-1]
    heron = 0.25 * np.sqrt((a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c)))
    area = triangle_areas(np.asarray(V, float), np.asarray(F)).sum()
    assert heron.sum() == pytest.approx(2 * area, rel=1e-3)
    L, M = surftopo.laplacian(V, F, tufted=True)
    assert (t.laplacian() != L).nnz == 0 and (t.mass() != M).nnz == 0
    assert (automatic.laplacian() != L).nnz == 0
    # The folded Laplacian rebuilt from the cover's triangles: half of the cover's.
    dense = cotan_laplacian(t) / 2
    assert np.abs(L.toarray() - dense).max() <= 1e-10 * np.abs(dense).max()
    robust_laplacian = pytest.importorskip("robust_laplacian", reason="cross-check skipped")
    Lr, _ = robust_laplacian.mesh_laplacian(np.asarray(V, float), np.asarray(F, np.int64))
    used = np.unique(np.asarray(F))
    Lr = Lr.tocsr()[used][:, used]
    if scipy.sparse.triu(Lr, 1).max() <= 0:  # robust_laplacian's is Delaunay here
        assert abs(t.laplacian().tocsr()[used][:, used] - Lr).max() <= 1e-8 * abs(Lr).max()
    for what in (t.tessellation, t.to_json, t.to_portalgon):
        with pytest.raises(surftopo.InvalidInputError, match="tufted cover gives"):
            what()


def test_tufted_arguments_as_laplacian_takes_them():
    from test_tufted import SOUPS

    V, F = SOUPS["book of 3"]
    with pytest.raises(surftopo.InvalidMeshError, match="non-manifold edge"):
        surftopo.intrinsic_delaunay(V, F, tufted=False)
    for tufted in (True, None):
        with pytest.raises(surftopo.InvalidInputError, match="method='flip' only"):
            surftopo.intrinsic_delaunay(V, F, tufted=tufted, method="voronoi")
    with pytest.raises(surftopo.InvalidInputError, match="not both"):
        surftopo.intrinsic_delaunay(V, F, mollify=1e-3, mollify_factor=1e-3)
    with pytest.raises(surftopo.InvalidInputError, match="exact=True"):
        surftopo.intrinsic_delaunay(V, F, tufted=True, exact=True)
    # On a closed manifold the tufted cover is two copies: the same Laplacian.
    V, F = surftopo.icosphere(2)
    L = surftopo.intrinsic_delaunay(V, F).laplacian()
    Lt = surftopo.intrinsic_delaunay(V, F, tufted=True, mollify_factor=0.0).laplacian()
    assert abs(L - Lt).max() <= 1e-12 * abs(L).max()
