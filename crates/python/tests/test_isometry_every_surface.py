"""isometric and isometry_verdict on every surface kind (boundary loops, non-orientable, several
pieces, closed), against `surftopo isometric --json` on the same files: the same verdict on each
pair. Portalgon files of version 2 (what intrinsic_delaunay(...).to_json() and `surftopo delaunay
-o` write for such meshes) are read back by Portalgon.from_json and are surfaces like the mesh
they were written from."""

from __future__ import annotations

import json
import subprocess

import numpy as np
import pytest

import surftopo
from test_delaunay_every_surface import surfaces
from test_every_surface import NON_ORIENTABLE


def all_kinds():
    """The kinds of test_delaunay_every_surface, and a closed torus."""
    kinds = surfaces()
    kinds["closed torus"] = surftopo.torus(12, 6)
    return kinds


SURFACES = all_kinds()


def cli_verdict(cli, tmp_path, a, b):
    """`surftopo isometric A B --json` on two surfaces written as OBJ files (or given as
    portalgon JSON text): the verdict and the exit code."""
    paths = []
    for k, s in enumerate((a, b)):
        if isinstance(s, str):
            path = tmp_path / f"s{k}.json"
            path.write_text(s)
        else:
            path = tmp_path / f"s{k}.obj"
            surftopo.write_mesh(path, *s)
        paths.append(path)
    result = subprocess.run(
        [str(cli), "isometric", *map(str, paths), "--json"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode in (0, 1, 3), result.stderr
    return json.loads(result.stdout)["verdict"], result.returncode


@pytest.mark.parametrize("name", list(SURFACES))
def test_python_and_cli_agree_on_every_surface_kind(name, cli, tmp_path):
    V, F = SURFACES[name]
    mirror = V * np.array([-1.0, 1.0, 1.0])
    pairs = {
        "moved": ((V, F), (V + 1.0, F), "isometric"),
        "mirror": ((V, F), (mirror, F), "isometric"),
        "scaled": ((V, F), (1.001 * V, F), "not isometric"),
    }
    for label, (a, b, expected) in pairs.items():
        verdict, reason = surftopo.isometry_verdict(a, b)
        assert verdict == expected, f"{name} {label}: {reason}"
        assert surftopo.isometric(a, b) == (expected == "isometric")
        theirs = cli_verdict(cli, tmp_path, a, b)[0]
        assert theirs == verdict, f"{name} {label}: CLI {theirs}, Python {verdict}"


@pytest.mark.parametrize("name", list(SURFACES))
def test_version_2_files_read_back_as_the_surface_they_were_written_from(name, cli, tmp_path):
    V, F = SURFACES[name]
    text = surftopo.intrinsic_delaunay(V, F).to_json()
    doc = json.loads(text)
    non_closed = name != "closed torus"
    assert (doc["version"] == 2) == (name in NON_ORIENTABLE or name == "three pieces")
    p = surftopo.Portalgon.from_json(text)
    assert p.polygon_count == len(F)
    verdict, reason = surftopo.isometry_verdict((V, F), p)
    assert verdict == "isometric", f"{name}: {reason}"
    assert cli_verdict(cli, tmp_path, (V, F), text)[0] == "isometric"
    # Read back, the same triangulation: no flip, the same Laplacian on the labels' rows (the
    # mesh's vertex indices without those in no face, which have no label: label k is the
    # k-th used vertex).
    t = surftopo.intrinsic_delaunay(p)
    assert t.stats["flips"] == 0
    L = surftopo.laplacian(V, F)[0].toarray()
    used = np.unique(F)
    Lp = t.laplacian().toarray()
    scale = np.abs(L).max()
    assert Lp.shape == (len(used), len(used))
    assert np.abs(L[np.ix_(used, used)] - Lp).max() <= 1e-12 * scale
    if non_closed:
        with pytest.raises(surftopo.InvalidInputError, match="flip"):
            surftopo.intrinsic_delaunay(p, method="voronoi")


def test_a_flat_vertex_on_a_moebius_band_is_undecided_in_both(cli, tmp_path):
    V, F = surftopo.mobius_band(9, 3)
    coarse = (V, F)
    # Split one grid triangle at its centroid: a flat interior vertex, the same surface.
    a, b, c = F[0]
    V2 = np.vstack([V, (V[a] + V[b] + V[c]) / 3])
    n = len(V)
    F2 = np.vstack([F[1:], [[a, b, n], [b, c, n], [c, a, n]]])
    verdict, reason = surftopo.isometry_verdict(coarse, (V2, F2))
    assert verdict == "undecided", reason
    assert not surftopo.isometric(coarse, (V2, F2))
    assert cli_verdict(cli, tmp_path, coarse, (V2, F2)) == ("undecided", 3)


def test_a_version_2_file_with_an_inconsistent_gluing_is_refused_naming_the_polygon():
    V, F = surftopo.mobius_band(9, 3)
    doc = json.loads(surftopo.intrinsic_delaunay(V, F).to_json())
    k = next(i for i, pair in enumerate(doc["matching"]) if len(pair) == 3)
    (p, i), _ = doc["matching"][k][:2]
    doc["polygons"][p]["lengths"][i] *= 1.5
    with pytest.raises(surftopo.PortalgonError, match=f"\\({p}, {i}\\)"):
        surftopo.Portalgon.from_json(json.dumps(doc))
