"""census and canonical_form: the published counts, each entry checked here with numpy (closed
surface, Euler characteristic, orientability, irreducibility), canonical forms invariant under
relabelling, and the errors."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import surftopo


def edges_of(F):
    E = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [0, 2]]]), axis=1)
    return np.unique(E, axis=0, return_counts=True)


def orientable(F):
    """Propagates face orientations across edges; a conflict means non-orientable."""
    oriented = {0: tuple(F[0])}
    stack = [0]
    by_edge = {}
    for f, t in enumerate(F.tolist()):
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            by_edge.setdefault(frozenset((a, b)), []).append(f)
    ok = True
    while stack:
        f = stack.pop()
        o = oriented[f]
        for i in range(3):
            a, b = o[i], o[(i + 1) % 3]
            for g in by_edge[frozenset((a, b))]:
                if g == f:
                    continue
                c = next(x for x in F[g].tolist() if x not in (a, b))
                want = (b, a, c)
                if g not in oriented:
                    oriented[g] = want
                    stack.append(g)
                elif want not in {oriented[g][r:] + oriented[g][:r] for r in range(3)}:
                    ok = False
    assert len(oriented) == len(F), "not connected"
    return ok


def irreducible(F):
    n = F.max() + 1
    A = np.zeros((n, n), dtype=int)
    for a, b in itertools.combinations(range(3), 2):
        A[F[:, a], F[:, b]] = 1
        A[F[:, b], F[:, a]] = 1
    if n == 4:
        return True
    common = A @ A
    return bool(np.all(common[A == 1] > 2))


@pytest.mark.parametrize(
    "surface, count, chi, is_orientable, vertex_counts",
    [
        ("sphere", 1, 2, True, {4}),
        ("projective-plane", 2, 1, False, {6, 7}),
        ("torus", 21, 0, True, {7, 8, 9, 10}),
        ("klein-bottle", 29, 0, False, {8, 9, 10, 11}),
    ],
)
def test_published_counts(surface, count, chi, is_orientable, vertex_counts):
    entries = surftopo.census(surface)
    assert len(entries) == count
    forms = set()
    for F in entries:
        assert F.dtype == np.int64 and F.shape[1] == 3
        E, per_edge = edges_of(F)
        assert np.all(per_edge == 2)
        n = F.max() + 1
        assert set(np.unique(F)) == set(range(n))
        assert n - len(E) + len(F) == chi
        assert orientable(F) == is_orientable
        assert irreducible(F)
        assert np.array_equal(surftopo.canonical_form(F), F)  # already canonical
        forms.add(F.tobytes())
    assert len(forms) == count
    assert {int(F.max()) + 1 for F in entries} == vertex_counts


def test_canonical_form_ignores_relabelling_and_order():
    rng = np.random.default_rng(5)
    for F in surftopo.census("torus"):
        n = F.max() + 1
        perm = rng.permutation(n)
        G = perm[F][rng.permutation(len(F))]
        G = np.array([row[::-1] if rng.random() < 0.5 else row for row in G])
        assert np.array_equal(surftopo.canonical_form(G.astype(np.int32)), F)


def test_cut_census_and_errors():
    assert len(surftopo.census("torus", max_vertices=8)) == 5
    with pytest.raises(surftopo.InvalidInputError, match="unknown surface"):
        surftopo.census("sfere")
    with pytest.raises(surftopo.InvalidInputError, match="max-vertices"):
        surftopo.census("n3")
    tetra = np.array([[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]])
    with pytest.raises(surftopo.InvalidMeshError) as caught:
        surftopo.canonical_form(tetra[:3])
    assert caught.value.kind == "EdgeFaceCount" and caught.value.face is not None
    with pytest.raises(surftopo.InvalidMeshError) as caught:
        surftopo.canonical_form(np.where(tetra == 3, 4, tetra))
    assert caught.value.vertex == 3
    with pytest.raises(surftopo.InvalidMeshError):
        surftopo.canonical_form(np.array([[0, 1, -1]]))


def test_ctrl_c_stops_a_long_census():
    import signal
    import subprocess
    import sys
    import time

    child = subprocess.Popen(
        [sys.executable, "-c", "import surftopo; surftopo.census('genus-2', max_vertices=14)"],
        stderr=subprocess.PIPE,
    )
    time.sleep(1.5)
    start = time.monotonic()
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=60)
    assert child.returncode != 0
    assert b"KeyboardInterrupt" in stderr
    assert time.monotonic() - start < 30


def test_cli_census_file_reads_as_json_and_equals_the_package(cli, tmp_path):
    """`surftopo census` writes Lutz's format, one JSON array per line (vertices from 1): read
    with json and numpy, it equals surftopo.census (vertices from 0)."""
    import json

    from conftest import run_cli

    out = tmp_path / "kb.txt"
    run_cli(cli, "census", "klein-bottle", "-o", out)
    lines = out.read_text().splitlines()
    entries = surftopo.census("klein-bottle")
    assert len(lines) == len(entries) == 29
    for line, F in zip(lines, entries):
        G = np.array(json.loads(line), dtype=np.int64) - 1
        assert np.array_equal(G, F)
