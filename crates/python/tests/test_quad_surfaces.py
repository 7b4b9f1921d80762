"""`surftopo.quadrangulate` on every compact surface: boundary loops, non-orientable, closed
non-orientable, several pieces; every algorithm and objective, with and without `all_quads`,
checked by the independent checks of verify.py (each input triangle used once, as few left as a
textbook Edmonds maximum matching of the dual allows, the added vertices), and against the
CLI's quad file, read back as OBJ text."""

from __future__ import annotations

import numpy as np
import pytest

import surftopo
from conftest import run_cli
from verify import dual_edges, maximum_matching_size, pairing_uses_triangles

ALGORITHMS = ["sg", "ps", "lrs", "ds", "ks"]
OBJECTIVES = ["quality", "quality-fast"]


def three_ears():
    """A middle triangle with an ear on each side: two triangles stay unpaired."""
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], float)
    F = np.array([[0, 1, 2], [1, 0, 3], [2, 1, 4], [0, 2, 5]])
    return V, F


def odd(V, F):
    """The surface without its last triangle (an odd number of triangles)."""
    return V, F[:-1]


def two_pieces(a, b):
    (Va, Fa), (Vb, Fb) = a, b
    return np.vstack([Va, Vb + 3.0]), np.vstack([Fa, Fb + len(Va)])


SURFACES = {
    "three ears": three_ears(),
    "odd disk": odd(*surftopo.disk(4)),
    "annulus": surftopo.annulus(9, 3),
    "odd Möbius band": odd(*surftopo.mobius_band(9, 3)),
    "projective plane": surftopo.projective_plane(),
    "Klein bottle": surftopo.klein_bottle(8, 6),
    "N3": surftopo.non_orientable(3),
    "two pieces": two_pieces(odd(*surftopo.disk(3)), surftopo.torus(6, 4)),
}
NON_ORIENTABLE = {"odd Möbius band", "projective plane", "Klein bottle", "N3"}


def fewest_left(F):
    """The triangles any pairing leaves: n − 2 ν(dual), by the textbook Edmonds."""
    return len(F) - 2 * maximum_matching_size(len(F), dual_edges(F))


@pytest.mark.parametrize("name", list(SURFACES))
@pytest.mark.parametrize("run", [("algorithm", a) for a in ALGORITHMS]
                         + [("objective", o) for o in OBJECTIVES])
@pytest.mark.parametrize("all_quads", [False, True])
def test_every_surface(name, run, all_quads):
    V, F = SURFACES[name]
    if run == ("algorithm", "lrs") and name in NON_ORIENTABLE:
        with pytest.raises(surftopo.InvalidInputError, match="non-orientable"):
            surftopo.quadrangulate(V, F, algorithm="lrs", all_quads=all_quads)
        return
    Q, stats = surftopo.quadrangulate(V, F, all_quads=all_quads, **{run[0]: run[1]})
    T, added, edges = stats["triangles"], stats["added_positions"], stats["added_edges"]
    assert Q.dtype == np.int64 and Q.shape[1:] == (4,)
    assert T.shape[1:] == (3,) and added.shape[1:] == (3,) and edges.shape[1:] == (2,)
    # LRS pairs the triangles of its flipped triangulation, whose least may differ on small
    # pieces: its own bound is checked by the library's verifier.
    fewest = stats["deficiency_lower_bound"] if run[1] == "lrs" else fewest_left(F)
    assert stats["deficiency_lower_bound"] == fewest
    if all_quads:
        assert len(T) == 0 and len(added) == fewest == stats["added_vertices"]
        # Each added vertex is the midpoint of its boundary edge.
        assert np.allclose(added, 0.5 * (V[edges[:, 0]] + V[edges[:, 1]]))
        boundary = {e for e, n in __import__("verify").edges_of(F).items() if n == 1}
        assert all((min(a, b), max(a, b)) in boundary for a, b in edges.tolist())
    else:
        assert len(T) == fewest == stats["unpaired_triangles"] and len(added) == 0
    if run != ("algorithm", "lrs"):
        assert pairing_uses_triangles(Q, T, F, len(V), edges)
    assert 2 * len(Q) + len(T) == len(F) + len(added)
    if name == "two pieces":
        assert [c["faces"] for c in stats["components"]] == [17, 48]
    else:
        assert "components" not in stats


def test_all_quads_needs_one_vertex_per_leftover():
    V, F = three_ears()
    Q, stats = surftopo.quadrangulate(V, F, all_quads=True)
    assert stats["added_vertices"] == 2 and len(Q) == 3
    Q, stats = surftopo.quadrangulate(V, F)
    assert stats["unpaired_triangles"] == 2 and len(Q) == 1


def test_quads_and_triangles_equal_the_cli(cli, tmp_path):
    """The CLI's file holds the Python result: the vertices, then the added ones; the quads, then
    the triangles left (read as OBJ text)."""
    V, F = odd(*surftopo.annulus(12, 4))
    path = tmp_path / "in.obj"
    surftopo.write_mesh(path, V, F)
    for args, kwargs in [((), {}), (("--all-quads",), {"all_quads": True}),
                         (("--objective", "quality"), {"objective": "quality"})]:
        out = tmp_path / "q.obj"
        run_cli(cli, "quad", path, "-o", out, *args)
        rows = [line.split() for line in out.read_text().splitlines()]
        positions = np.array([[float(x) for x in r[1:4]] for r in rows if r and r[0] == "v"])
        faces = [[int(c.split("/")[0]) - 1 for c in r[1:]] for r in rows if r and r[0] == "f"]
        Q, stats = surftopo.quadrangulate(V, F, **kwargs)
        assert np.array_equal(positions, np.vstack([V, stats["added_positions"]]))
        assert faces == Q.tolist() + stats["triangles"].tolist()
