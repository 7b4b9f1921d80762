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
    # The intrinsic Delaunay condition: the two angles opposite every edge sum to at most pi.
    sides = lengths[face_edges]

    def opposite_angle(f, i):
        a, b, c = sides[f, i], sides[f, (i + 1) % 3], sides[f, (i + 2) % 3]
        return math.acos(max(-1.0, min(1.0, (b * b + c * c - a * a) / (2 * b * c))))

    angle_sum = np.zeros(len(edges))
    for f in range(len(faces)):
        for i in range(3):
            angle_sum[face_edges[f, i]] += opposite_angle(f, i)
    assert angle_sum.max() <= math.pi + 1e-9
    # Same surface: same total area (Heron), same vertex set.
    s = sides.sum(axis=1) / 2
    heron = np.sqrt(s * (s - sides[:, 0]) * (s - sides[:, 1]) * (s - sides[:, 2]))
    assert heron.sum() == pytest.approx(triangle_areas(V, F).sum(), rel=1e-10)
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
