"""Intrinsic Delaunay triangulations, portalgons and the isometry test."""

from __future__ import annotations

import math

import numpy as np
import pytest

import surftopo
from verify import triangle_areas


def test_flat_torus_needs_x_minus_one_flips():
    # Section 9 of the intrinsic-Delaunay paper: T_x needs x - 1 flips for integer x and ends
    # with the 1 x 2 rectangle split by a diagonal (lengths 1, 2, sqrt 5).
    for x in (2, 10, 50):
        t = surftopo.intrinsic_delaunay(surftopo.flat_torus(float(x)))
        assert t.flips == x - 1 and t.stats["non_delaunay_edges"] == 0
        assert sorted(t.edge_lengths.tolist()) == pytest.approx([1.0, 2.0, math.sqrt(5.0)])
        tessellation = t.tessellation()
        assert (tessellation.polygon_count, tessellation.side_count) == (1, 4)
        assert tessellation.area == pytest.approx(2.0)
        # One vertex, only loops: the Laplacian is the 1 x 1 zero matrix.
        assert t.laplacian().shape == (1, 1) and t.laplacian().nnz <= 1
        assert t.laplacian().toarray()[0, 0] == 0.0


def check_delaunay_on(t, area: float) -> np.ndarray:
    """Checks from the triangulation's edge lengths alone that the two angles opposite every edge
    sum to at most pi (the intrinsic Delaunay condition) and that the triangles' areas (Heron) sum
    to `area`; returns the areas."""
    faces, edges, lengths, face_edges = t.faces, t.edges, t.edge_lengths, t.face_edges
    sides = lengths[face_edges]

    def opposite_angle(f, i):
        a, b, c = sides[f, i], sides[f, (i + 1) % 3], sides[f, (i + 2) % 3]
        return math.acos(max(-1.0, min(1.0, (b * b + c * c - a * a) / (2 * b * c))))

    angle_sum = np.zeros(len(edges))
    for f in range(len(faces)):
        for i in range(3):
            angle_sum[face_edges[f, i]] += opposite_angle(f, i)
    assert angle_sum.max() <= math.pi + 1e-9
    s = sides.sum(axis=1) / 2
    heron = np.sqrt(s * (s - sides[:, 0]) * (s - sides[:, 1]) * (s - sides[:, 2]))
    assert heron.sum() == pytest.approx(area, rel=1e-10)
    return heron


def test_delaunay_condition_and_structure():
    V, F = surftopo.torus(30, 5)
    V = V * np.array([6.0, 1.0, 1.0])  # stretched: long thin triangles, many flips
    t = surftopo.intrinsic_delaunay(V, F)
    assert t.flips > 0 and t.stats["flips"] == t.flips
    faces, edges, lengths, face_edges = t.faces, t.edges, t.edge_lengths, t.face_edges
    assert faces.shape == F.shape and edges.shape == (3 * len(F) // 2, 2)
    assert face_edges.shape == F.shape and lengths.shape == (len(edges),)
    # Every edge is on two face sides, whose corners are the edge's ends.
    assert np.array_equal(np.bincount(face_edges.ravel()), np.full(len(edges), 2))
    for f in range(len(faces)):
        for i in range(3):
            ends = {faces[f, i], faces[f, (i + 1) % 3]}
            assert ends == set(edges[face_edges[f, i]].tolist())
    # The intrinsic Delaunay condition, and the same surface: same total area, same vertex set.
    heron = check_delaunay_on(t, triangle_areas(V, F).sum())
    assert t.mass().diagonal().sum() == pytest.approx(heron.sum(), rel=1e-12)


def test_json_round_trip_gives_the_same_laplacian():
    V, F = surftopo.genus_surface(2, 1)
    t = surftopo.intrinsic_delaunay(V, F)
    p = surftopo.Portalgon.from_json(t.to_json())
    assert p.polygon_count == len(F) and p.matched_pairs == 3 * len(F) // 2
    again = surftopo.intrinsic_delaunay(p)
    assert again.flips == 0
    assert abs(again.laplacian() - t.laplacian()).max() <= 1e-12 * abs(t.laplacian()).max()
    assert p.to_json() == t.to_portalgon().to_json()


def test_isometric():
    V, F = surftopo.torus(12, 6)
    rotation = np.linalg.qr(np.random.default_rng(3).normal(size=(3, 3)))[0]
    assert surftopo.isometric((V, F), (V @ rotation.T + 1.5, F))
    assert not surftopo.isometric((V, F), (2.0 * V, F))
    t = surftopo.intrinsic_delaunay(V, F)
    assert surftopo.isometric(t, (V, F))
    assert surftopo.isometric(surftopo.Portalgon.from_json(t.to_json()), (V, F))
    # A mirror image is accepted unless reflections are excluded.
    mirrored = V * np.array([-1.0, 1.0, 1.0])
    assert surftopo.isometric((V, F), (mirrored, F[:, ::-1]))
    with pytest.raises(ValueError, match="a surface is"):
        surftopo.isometric(V, F)



def t_x_exact(x: int) -> surftopo.Portalgon:
    """Dubois' T_x (Section 9) by exact corners: (0,0), (1,0), (x,2) and its half-turn image
    (1+x,2), (x,2), (1,0), side i glued to side i."""
    text = (
        '{"polygons": ['
        f'{{"corners": [[0, 0], [1, 0], ["{x}", 2]]}}, '
        f'{{"corners": [["{x + 1}", 2], ["{x}", 2], [1, 0]]}}], '
        '"matching": [[[0, 0], [1, 0]], [[0, 1], [1, 1]], [[0, 2], [1, 2]]]}'
    )
    return surftopo.Portalgon.from_json(text)


def relative_difference(a, b) -> float:
    return abs(a - b).max() / abs(b).max()


@pytest.mark.parametrize("method", ["auto", "flip", "voronoi", "dubois"])
def test_every_method_gives_a_delaunay_triangulation_and_the_same_laplacian(method):
    # The cotan Laplacian depends on the surface only (Bobenko-Springborn): every method gives
    # flipping's, and a triangulation that passes the Delaunay check written here.
    V, F = surftopo.torus(12, 6)
    V = V * np.array([3.0, 1.0, 1.0])  # stretched: flipping has work to do
    L_flip, M_flip = surftopo.laplacian(V, F)
    L, M = surftopo.laplacian(V, F, method=method)
    assert L.shape == M.shape == (len(V), len(V))
    assert relative_difference(L, L_flip) <= 1e-9
    assert M.diagonal().sum() == pytest.approx(M_flip.diagonal().sum(), rel=1e-12)
    t = surftopo.intrinsic_delaunay(V, F, method=method)
    check_delaunay_on(t, triangle_areas(V, F).sum())
    assert relative_difference(t.laplacian(), L_flip) <= 1e-9
    flips = surftopo.intrinsic_delaunay(V, F).flips
    assert flips > 0
    assert t.flips == (0 if method in ("voronoi", "dubois") else flips)
    assert t.stats["non_delaunay_edges"] == 0


@pytest.mark.parametrize("method, x", [("auto", 10**12), ("dubois", 10**12), ("voronoi", 10**3)])
def test_exact_methods_give_d_x(method, x):
    # T_x at x = 10^12 is beyond flipping in double precision (the wave's events grow as x, so it
    # gets x = 10^3); exactly, its Delaunay tessellation D_x is the 1 x 2 rectangle (Section 9):
    # one polygon of four sides and area 2, cut into two triangles of sides 1, 2, sqrt 5; one
    # vertex, so the Laplacian is the 1 x 1 zero matrix.
    t = surftopo.intrinsic_delaunay(t_x_exact(x), method=method, exact=True)
    tessellation = t.tessellation()
    assert (tessellation.polygon_count, tessellation.side_count) == (1, 4)
    assert tessellation.area == pytest.approx(2.0)
    assert sorted(t.edge_lengths.tolist()) == pytest.approx([1.0, 2.0, math.sqrt(5.0)])
    check_delaunay_on(t, 2.0)
    assert t.laplacian().shape == (1, 1) and t.laplacian().toarray()[0, 0] == 0.0
    assert t.flips == 0


def test_refused_methods_and_arithmetics_say_why():
    V, F = surftopo.icosphere(1)
    with pytest.raises(surftopo.InvalidInputError, match="exact corners"):
        surftopo.intrinsic_delaunay(V, F, method="voronoi", exact=True)
    with pytest.raises(surftopo.InvalidInputError, match="exact corners"):
        surftopo.laplacian(V, F, method="voronoi", exact=True)
    with pytest.raises(surftopo.InvalidInputError, match="lengths"):
        surftopo.intrinsic_delaunay(t_x_exact(10), method="flip", exact=True)
    with pytest.raises(surftopo.InvalidInputError, match="method"):
        surftopo.intrinsic_delaunay(V, F, method="delaunay")
    with pytest.raises(surftopo.InvalidInputError, match="flip"):
        surftopo.intrinsic_delaunay(V, F, method="voronoi", max_flips=10)


def test_exact_corners_beyond_doubles_are_kept_for_exact_runs():
    # T_x for x = 10^30 + 1 by exact corners: in doubles x + 1 rounds to x (a zero side), so
    # only the exact methods can take it; the document is read, and the double-precision run
    # refuses it as a numerical failure naming exact=True (never a silently different surface:
    # its rounded lengths make a triangle of area 5e29 instead of 1).
    x = 10**30
    text = (
        '{"polygons": [{"corners": [["0", "0"], ["1", "0"], ["%d", "2"]]},'
        ' {"corners": [["1", "0"], ["%d", "2"], ["%d", "2"]]}],'
        ' "matching": [[[0, 0], [1, 1]], [[0, 1], [1, 2]], [[0, 2], [1, 0]]]}' % (x, x + 1, x)
    )
    t = surftopo.Portalgon.from_json(text)
    assert t.polygon_count == 2
    for method in ["auto", "flip", "voronoi", "dubois"]:
        with pytest.raises(surftopo.NumericalBreakdownError, match="exact=True"):
            surftopo.intrinsic_delaunay(t, method=method)
    with pytest.raises(surftopo.NumericalBreakdownError, match="exact=True"):
        surftopo.isometric(t, t)
    d = surftopo.intrinsic_delaunay(t, method="dubois", exact=True)
    # D_x of an integer x is the rectangle 1 x 2 cut by a diagonal: lengths 1, 2 and sqrt(5).
    assert sorted(np.round(d.edge_lengths, 12)) == pytest.approx([1.0, 2.0, math.sqrt(5)])
