"""Irreducible triangulations, quadrangulations, info, files and generators, each checked from
the definitions (tests/verify.py)."""

from __future__ import annotations

import numpy as np
import pytest

import surftopo
from verify import (
    classify,
    edges_of,
    euler_characteristic,
    is_closed_oriented,
    is_irreducible,
    is_irreducible_surface,
    quads_pair_triangles,
)

SURFACES = {
    "icosphere(2)": lambda: surftopo.icosphere(2),
    "torus(10, 6)": lambda: surftopo.torus(10, 6),
    "genus_surface(3, 1)": lambda: surftopo.genus_surface(3, 1),
    "cavity_box(4, 2, 3000)": lambda: surftopo.cavity_box(4, 2, 3000),
}


@pytest.mark.parametrize("name", SURFACES)
@pytest.mark.parametrize("algorithm", ["rs", "schipper", "brute-force"])
def test_irreducible(name, algorithm):
    V, F = SURFACES[name]()
    V2, F2, stats = surftopo.irreducible(V, F, algorithm=algorithm, seed=5, compact=True)
    chi = euler_characteristic(F)
    assert euler_characteristic(F2) == chi and is_closed_oriented(F2)
    assert is_irreducible(F2)
    assert np.array_equal(np.unique(F2), np.arange(len(V2)))
    kept = stats["vertex_indices"]
    assert np.array_equal(V2, V[kept]) and len(set(kept.tolist())) == len(kept)
    # By default, the input's vertex list and numbering: the same triangles on V's indices.
    V_all, F_all, _ = surftopo.irreducible(V, F, algorithm=algorithm, seed=5)
    assert np.array_equal(V_all, V) and np.array_equal(F_all, kept[F2])
    genus = (2 - chi) // 2
    counts = {k: stats["input"][k] for k in ("vertices", "edges", "faces", "genus")}
    assert counts == {
        "vertices": len(V), "edges": len(edges_of(F)), "faces": len(F), "genus": genus
    }
    assert [s["name"] for s in stats["output"]["surfaces"]] == [
        s["name"] for s in stats["input"]["surfaces"]
    ]
    assert stats["output"]["vertices"] == len(V2) and stats["output"]["faces"] == len(F2)
    assert stats["contractions"] == len(V) - len(V2)
    assert stats["algorithm"] == algorithm
    assert ("seed" in stats) == (algorithm == "brute-force")
    if algorithm == "rs":
        assert stats["edges_tested_more_than_once"] == 0
    if genus == 0:
        assert len(V2) == 4


@pytest.mark.parametrize("name", SURFACES)
@pytest.mark.parametrize("algorithm", ["sg", "ps", "lrs", "ds", "ks"])
def test_quadrangulate(name, algorithm):
    V, F = SURFACES[name]()
    Q, stats = surftopo.quadrangulate(V, F, algorithm=algorithm, seed=2)
    assert Q.shape == (len(F) // 2, 4) and Q.dtype == np.int64
    assert is_closed_oriented(Q)
    assert euler_characteristic(Q) == euler_characteristic(F)
    assert np.array_equal(np.unique(Q), np.arange(len(V)))
    if algorithm != "lrs":  # LRS pairs the triangles of a flipped triangulation K
        assert quads_pair_triangles(Q, F)
    assert stats["algorithm"] == algorithm and stats["faces"] == len(F)
    assert list(stats) == [
        "algorithm", "faces", "initial_pairing_seconds", "paired_percent", "unpaired",
        "augmentation_seconds", "total_seconds", "flipped_edges", "file_order",
        "subdivision_levels", "unpaired_triangles", "deficiency_lower_bound", "added_vertices",
        "objective", "cost", "optimality_gap", "quality", "bad_quads_percent",
        "median_max_angle_deviation", "triangles", "added_positions", "added_edges",
    ]
    assert stats["unpaired_triangles"] == stats["deficiency_lower_bound"] == 0
    assert stats["triangles"].shape == (0, 3) and stats["added_positions"].shape == (0, 3)
    assert stats["objective"] == "count" and stats["optimality_gap"] is None


@pytest.mark.parametrize("name", SURFACES)
def test_quality_objectives(name):
    V, F = SURFACES[name]()
    _, count = surftopo.quadrangulate(V, F)
    Q, exact = surftopo.quadrangulate(V, F, objective="quality")
    Qf, fast = surftopo.quadrangulate(V, F, objective="quality-fast")
    for quads in (Q, Qf):
        assert quads.shape == (len(F) // 2, 4) and is_closed_oriented(quads)
        assert quads_pair_triangles(quads, F)
    assert exact["objective"] == "quality" and exact["optimality_gap"] == 0
    assert fast["objective"] == "quality-fast" and fast["optimality_gap"] is None
    # The optimum costs no more than any other perfect pairing (up to the costs' rounding).
    assert exact["cost"] <= fast["cost"] + 1e-6 and exact["cost"] <= count["cost"] + 1e-6
    assert 0.0 <= exact["quality"]["min"] <= exact["quality"]["median"] <= 1.0


def test_seeded_algorithms_are_deterministic():
    V, F = surftopo.torus(15, 8)
    for algorithm in ("sg", "ps"):
        a, _ = surftopo.quadrangulate(V, F, algorithm=algorithm, seed=4)
        b, _ = surftopo.quadrangulate(V, F, algorithm=algorithm, seed=4)
        assert np.array_equal(a, b)
    a = surftopo.irreducible(V, F, algorithm="brute-force", seed=9)
    b = surftopo.irreducible(V, F, algorithm="brute-force", seed=9)
    assert np.array_equal(a[1], b[1]) and np.array_equal(a[0], b[0])


def test_int32_and_int64_faces_agree():
    V, F = surftopo.genus_surface(2, 1)
    for call in (
        lambda G: surftopo.quadrangulate(V, G, algorithm="sg", seed=1)[0],
        lambda G: surftopo.irreducible(V, G, algorithm="brute-force", seed=1)[1],
    ):
        assert np.array_equal(call(F.astype(np.int32)), call(F.astype(np.int64)))
        assert np.array_equal(call(np.asfortranarray(F)), call(F))


def test_info():
    V, F = surftopo.torus(6, 4)
    info = surftopo.info(V, F)
    assert list(info) == [
        "vertices", "edges", "faces", "point_cloud", "vertex_properties", "genus",
        "euler_characteristic", "components", "closed", "orientable", "boundary_loops",
        "boundary_edges", "simplicial", "valid", "reoriented_faces", "unreferenced_vertices",
        "welded_vertices", "non_finite_coordinates", "zero_area_faces", "degenerate_faces",
        "duplicate_faces", "non_manifold_edges", "non_manifold_vertices", "other_problems",
        "problems_total", "problems_truncated", "problems", "near_degenerate_faces", "warnings",
        "weld_hint", "surfaces",
    ]
    assert (info["vertices"], info["edges"], info["faces"], info["genus"]) == (24, 72, 48, 1)
    assert info["valid"] and info["problems"] == []
    # A face removed: a torus with one boundary loop, no problem.
    holed = surftopo.info(V, F[1:])
    assert holed["valid"] and holed["genus"] == 1 and not holed["closed"]
    assert (holed["boundary_edges"], holed["boundary_loops"]) == (3, 1)
    assert holed["surfaces"] == [{
        "faces": 47, "euler_characteristic": -1, "orientable": True, "boundary_loops": 1,
        "genus": 1, "crosscaps": None, "euler_genus": 2, "name": "genus 1 with 1 boundary loop",
    }]
    # A fin: a face on an edge that has two already.
    fin = np.vstack([F, [[F[0][0], F[0][1], len(V)]]])
    broken = surftopo.info(np.vstack([V, [[9.0, 9.0, 9.0]]]), fin)
    assert not broken["valid"] and broken["surfaces"] == [] and broken["genus"] is None
    assert broken["non_manifold_edges"] == 1
    assert broken["problems"][0].startswith("non-manifold edge")
    # Welding: the same torus with one vertex duplicated in place.
    W = np.vstack([V, V[:1]])
    G = F.copy()
    G[F == 0] = len(V)
    G[0] = F[0]
    assert not surftopo.info(W, G)["closed"]
    welded = surftopo.info(W, G, weld=True)
    assert welded["valid"] and welded["closed"] and welded["welded_vertices"] == 1


@pytest.mark.parametrize("extension", ["obj", "off", "ply", "obj.gz"])
def test_files_round_trip(tmp_path, extension):
    V, F = surftopo.genus_surface(2, 1)
    path = tmp_path / f"mesh.{extension}"
    surftopo.write_mesh(path, V, F)
    V2, F2 = surftopo.read_mesh(path)
    assert np.array_equal(V, V2) and np.array_equal(F, F2)
    Q, _ = surftopo.quadrangulate(V, F)
    surftopo.write_mesh(path, V, Q)
    V3, Q3 = surftopo.read_mesh(path)
    assert np.array_equal(V, V3) and np.array_equal(Q, Q3)


def test_generators():
    for (V, F), chi in [
        (surftopo.tetrahedron(), 2),
        (surftopo.icosphere(3), 2),
        (surftopo.torus(), 0),
        (surftopo.genus_surface(4, 1), -6),
        (surftopo.cavity_box(9, 3, 5000), -4),
    ]:
        assert V.dtype == np.float64 and V.shape[1] == 3 and F.dtype == np.int64
        assert is_closed_oriented(F) and euler_characteristic(F) == chi
    assert len(surftopo.icosphere(3)[1]) == 20 * 4**3
    with pytest.raises(ValueError, match="at least 3"):
        surftopo.torus(2, 5)
    with pytest.raises(ValueError, match="at most 200000000"):
        surftopo.icosphere(14)


def test_unreferenced_vertices_keep_input_indices():
    V, F = surftopo.torus(8, 5)
    # An unreferenced vertex inserted at index 3: every index returned must still point into
    # the new V.
    W = np.vstack([V[:3], [[7.0, 7.0, 7.0]], V[3:]])
    G = np.where(F >= 3, F + 1, F)
    Q, _ = surftopo.quadrangulate(W, G, algorithm="sg", seed=3)
    Q0, _ = surftopo.quadrangulate(V, F, algorithm="sg", seed=3)
    assert np.array_equal(Q, np.where(Q0 >= 3, Q0 + 1, Q0))
    assert quads_pair_triangles(Q, G)
    V2, F2, stats = surftopo.irreducible(W, G, compact=True)
    assert 3 not in stats["vertex_indices"].tolist()
    assert np.array_equal(V2, W[stats["vertex_indices"]])
    V3, F3, _ = surftopo.irreducible(W, G)
    assert np.array_equal(V3, W) and 3 not in F3 and np.array_equal(V3[F3], V2[F2])
    assert surftopo.info(W, G)["unreferenced_vertices"] == 1


GENERAL = {
    "disk(4)": (lambda: surftopo.disk(4), [(1, True, 1)], range(3, 4)),
    "annulus(8, 3)": (lambda: surftopo.annulus(8, 3), [(0, True, 2)], None),
    "mobius_band(8, 2)": (lambda: surftopo.mobius_band(8, 2), [(0, False, 1)], range(5, 7)),
    "projective_plane()": (surftopo.projective_plane, [(1, False, 0)], range(6, 8)),
    "klein_bottle(8, 6)": (lambda: surftopo.klein_bottle(8, 6), [(0, False, 0)], range(8, 12)),
    "non_orientable(3)": (lambda: surftopo.non_orientable(3), [(-1, False, 0)], None),
}


@pytest.mark.parametrize("name", GENERAL)
@pytest.mark.parametrize("algorithm", ["rs", "schipper", "brute-force"])
def test_irreducible_of_every_surface(name, algorithm):
    make, pieces, vertex_counts = GENERAL[name]
    V, F = make()
    assert classify(F) == pieces
    names = [s["name"] for s in surftopo.info(V, F)["surfaces"]]
    V2, F2, stats = surftopo.irreducible(V, F, algorithm=algorithm, seed=3, compact=True)
    assert classify(F2) == pieces and is_irreducible_surface(F2)
    assert [s["name"] for s in stats["output"]["surfaces"]] == names
    assert np.array_equal(V2, V[stats["vertex_indices"]])
    if vertex_counts is not None:
        assert len(V2) in vertex_counts
    # Two pieces at once: each reduced.
    W, G, _ = surftopo.irreducible(np.vstack([V, V + 5.0]), np.vstack([F, F + len(V)]),
                                   algorithm=algorithm)
    assert classify(G) == sorted(pieces * 2) and is_irreducible_surface(G)
