"""The tufted-cover Laplacian (Sharp & Crane 2020) of non-manifold meshes and triangle soups:
against robust_laplacian.mesh_laplacian (same mollification factor) to 1e-8 relative, on soups
made here (fins, books, pinched vertices, duplicate faces, pieces, random soups) and on shared
meshes made non-manifold; the automatic choice for non-manifold input, and the errors."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import scipy.sparse

import surftopo
from conftest import CLI_MESHES, run_cli
from verify import laplacian_spectrum, triangle_areas


def _book(pages):
    """``pages`` triangles on the edge (0, 0, 0)-(1, 0, 0), alternately oriented."""
    V = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    F = []
    for k in range(pages):
        a = 0.4 + 5.6 * k / pages + 0.1 * (k % 3)
        V.append([0.3 + 0.1 * k, np.cos(a) * (0.7 + 0.1 * k), np.sin(a) * (0.7 + 0.1 * k)])
        F.append([0, 1, k + 2] if k % 2 == 0 else [1, 0, k + 2])
    return np.array(V), np.array(F)


def _pinched_cones():
    """Two closed cones (double pyramids) sharing their apex: a pinched vertex."""
    V, F = [[0.0, 0.0, 0.0]], []
    for side, shift in ((1, 0.0), (-1, 0.3)):
        ring = len(V)
        for k in range(5):
            a = 2 * np.pi * k / 5 + shift
            V.append([np.cos(a), np.sin(a), side * 1.0])
        bottom = len(V)
        V.append([0.0, 0.2, side * 1.7])
        for k in range(5):
            u, w = ring + k, ring + (k + 1) % 5
            F += [[0, u, w], [bottom, w, u]] if side == 1 else [[0, w, u], [bottom, u, w]]
    return np.array(V), np.array(F)


def _random_soup(seed, points=14, faces=40):
    """Faces on random triples of few points, two points left unreferenced."""
    rng = np.random.default_rng(seed)
    V = rng.uniform(-1, 1, (points, 3))
    F = []
    while len(F) < faces:
        f = rng.integers(0, points - 2, 3)
        if len(set(f.tolist())) == 3:
            F.append(f)
    return V, np.array(F)


def _duplicates_and_fins(V, F):
    """Some faces duplicated (half of them reversed), with fins on two of their edges: books
    whose faces tie in angle (a face and its duplicate), which geometry-central orders by its
    list of an edge's halfedges around the edge as its first face's side runs."""
    extra_V, extra_F = [], []
    for k in range(0, len(F), 37):
        f = F[k]
        extra_F.append(f if k % 2 else f[::-1])
        for a, b in ((f[0], f[1]), (f[1], f[2])):
            normal = np.cross(V[f[1]] - V[f[0]], V[f[2]] - V[f[0]])
            tip = (V[a] + V[b]) / 2 + 0.3 * normal / np.linalg.norm(normal) * np.linalg.norm(V[b] - V[a])
            extra_F.append([a, b, len(V) + len(extra_V)])
            extra_V.append(tip + 0.01 * np.sin(k + a))
    return np.vstack([V, extra_V]), np.vstack([F, extra_F])


def _soups():
    soups = {"triangle (fins)": (np.array([[0, 0, 0], [1, 0.1, 0], [0.3, 0.9, 0.2]], float), np.array([[0, 1, 2]]))}
    for pages in (3, 4, 7):
        soups[f"book of {pages}"] = _book(pages)
    soups["pinched cones"] = _pinched_cones()
    V, F = surftopo.icosphere(1)
    soups["icosphere with duplicate faces"] = (V, np.vstack([F, F[:7], F[3:5, ::-1]]))
    V2 = np.vstack([V, V + [3.0, 0.0, 0.0]])
    soups["two pieces, one with a fin"] = (V2, np.vstack([F, F + len(V), [[0, 1, len(V)]]]))
    strip = np.array([[0, 1, 2], [2, 1, 3], [2, 3, 4], [4, 3, 5]])
    W = np.array([[0, 0, 0], [1, 0, 0.1], [0, 1, 0], [1.2, 1, 0], [0, 2, 0.3], [1, 2.2, 0]], float)
    soups["open strip (fins)"] = (W, strip)
    soups["icosphere with duplicates and fins on their edges"] = _duplicates_and_fins(*surftopo.icosphere(3))
    for seed in range(6):
        soups[f"random soup {seed}"] = _random_soup(seed)
    # A collinear face: mollification matters.
    soups["book with a flat page"] = (
        np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, 0, 0], [0.5, -1, 0.3]], float),
        np.array([[0, 1, 2], [0, 1, 3], [1, 0, 4]]),
    )
    return soups


SOUPS = _soups()


def _referenced(F, n):
    used = np.zeros(n, bool)
    used[np.asarray(F).ravel()] = True
    return used


def _assert_agrees(V, F, factor, name):
    """L and M agree with robust_laplacian's to 1e-8 relative; returns False (and checks what
    remains) where robust_laplacian's L is not Delaunay: geometry-central flips an edge only while
    its cotan weight is below -1e-6, so it may leave weights in [-1e-6, 0) (positive off-diagonal
    entries), where ours flips to the Delaunay triangulation."""
    robust_laplacian = pytest.importorskip(
        "robust_laplacian", reason="robust_laplacian is not installed: cross-check skipped"
    )
    V, F = np.asarray(V, float), np.asarray(F)
    L, M = surftopo.laplacian(V, F, tufted=True, mollify_factor=factor)
    Lr, Mr = robust_laplacian.mesh_laplacian(V, F.astype(np.int64), mollify_factor=factor)
    # robust_laplacian puts 1 on an unreferenced vertex's diagonal (and a small negative mass);
    # ours are zero rows: compare the referenced ones.
    keep = np.flatnonzero(_referenced(F, len(V)))
    L, Lr, M, Mr = (A.tocsr()[keep][:, keep] for A in (L, Lr, M, Mr))
    scale = abs(Lr).max()
    if scipy.sparse.triu(Lr, 1).max() > 0:
        assert scipy.sparse.triu(L, 1).max() <= 1e-12 * scale, name
        assert abs(L - Lr).max() <= 1e-5 * scale, name
        assert M.sum() == pytest.approx(Mr.sum(), rel=1e-12), name
        return False
    assert abs(L - Lr).max() <= 1e-8 * scale, name
    assert abs(M - Mr).max() <= 1e-8 * abs(Mr).max(), name
    return True


@pytest.mark.parametrize("name", SOUPS)
@pytest.mark.parametrize("factor", [1e-5, 1e-3])
def test_agrees_with_robust_laplacian(name, factor):
    V, F = SOUPS[name]
    assert _assert_agrees(V, F, factor, name)


@pytest.mark.parametrize("name", SOUPS)
def test_symmetric_psd_zero_row_sums_mass_is_area(name):
    V, F = SOUPS[name]
    L, M = surftopo.laplacian(V, F, tufted=True, mollify_factor=0.0 if "flat" not in name else 1e-5)
    dense, _, _ = laplacian_spectrum(L)
    assert (M - scipy.sparse.diags(M.diagonal())).nnz == 0
    if "flat" not in name:
        # Areas from lengths (Kahan's formula) of the needle joining the two pieces agree with the
        # cross product to about 1e-9.
        area = triangle_areas(np.asarray(V, float), F).sum()
        assert M.diagonal().sum() == pytest.approx(area, rel=1e-8)
    unreferenced = ~_referenced(F, len(V))
    assert np.all(M.diagonal()[unreferenced] == 0)
    assert np.all(np.abs(dense[unreferenced]).sum(axis=1) == 0)


def test_non_manifold_input_is_tufted_automatically_with_a_warning():
    V, F = _book(4)
    with pytest.warns(UserWarning, match="not a manifold"):
        L, M = surftopo.laplacian(V, F)
    Lt, Mt = surftopo.laplacian(V, F, tufted=True)
    assert (L != Lt).nnz == 0 and (M != Mt).nnz == 0
    with pytest.raises(surftopo.InvalidMeshError) as e:
        surftopo.laplacian(V, F, tufted=False)
    assert e.value.kind == "NonManifoldEdge"


def test_closed_manifold_tufted_equals_intrinsic_delaunay():
    for V, F in (surftopo.icosphere(3), surftopo.torus(20, 9), surftopo.genus_surface(2, 1)):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # no warning on a manifold
            L, M = surftopo.laplacian(V, F)
        Lt, Mt = surftopo.laplacian(V, F, tufted=True)
        assert abs(L - Lt).max() <= 1e-12 * abs(L).max()
        assert abs(M - Mt).max() <= 1e-12 * abs(M).max()


def test_bad_input_names_the_element():
    V, F = _book(3)
    with pytest.raises(surftopo.InvalidMeshError) as e:
        surftopo.laplacian(V, np.vstack([F, [[0, 2, 2]]]), tufted=True)
    assert e.value.face == 3 and e.value.vertex == 2
    with pytest.raises(surftopo.InvalidMeshError):
        surftopo.laplacian(V, np.zeros((0, 3), np.int64), tufted=True)
    with pytest.raises(surftopo.InvalidInputError, match="mollify factor"):
        surftopo.laplacian(V, F, tufted=True, mollify_factor=-1.0)
    flat = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0]], float)
    with pytest.raises(surftopo.InvalidGeometryError) as e:
        surftopo.laplacian(flat, [[0, 1, 2]], tufted=True, mollify_factor=0.0)
    assert e.value.face == 0
    with pytest.raises(surftopo.InvalidInputError):
        surftopo.laplacian(V, F, tufted=True, method="voronoi")


def _made_non_manifold(V, F, seed):
    """A closed mesh with a book of 3 pages on some edges (a fin triangle on each), duplicate
    faces, and a second copy pinched at one vertex."""
    rng = np.random.default_rng(seed)
    n = len(V)
    picks = rng.choice(len(F), 20, replace=False)
    extra_V, extra_F = [], []
    for k, f in enumerate(F[picks[:10]]):
        a, b, c = V[f]
        normal = np.cross(b - a, c - a)
        normal /= np.linalg.norm(normal)
        size = np.linalg.norm(b - a)
        extra_V.append((a + b) / 2 + 0.7 * size * normal)
        extra_F.append([f[0], f[1], n + k])
    V2 = np.vstack([V, extra_V])
    W = V - V[0]
    W = W @ np.diag([-1.0, 1.0, 1.0]) + V[0]  # a mirror copy sharing vertex 0
    F_copy = F[:, ::-1] + len(V2)
    F_copy[F_copy == len(V2)] = 0
    V3 = np.vstack([V2, W])
    F3 = np.vstack([F, extra_F, F[picks[10:]], F_copy])
    return V3, F3


@pytest.mark.parametrize("file", CLI_MESHES)
def test_shared_meshes_agree_with_robust_laplacian(file, shared_meshes):
    path = shared_meshes / file
    if not path.is_file():
        pytest.skip(f"{path} is missing from SURFTOPO_MESHES")
    V, F = surftopo.read_mesh(path)
    # torus_288 is a regular torus: robust_laplacian leaves 8 edges with weights in [-1e-6, 0)
    # (and its co-circular quads make the lumped mass depend on the Delaunay triangulation).
    delaunay_there = file != "torus_288.off.gz"
    assert _assert_agrees(V, F, 1e-5, file) == delaunay_there
    V3, F3 = _made_non_manifold(V, F, 1)
    assert _assert_agrees(V3, F3, 1e-5, f"{file} made non-manifold") == delaunay_there


def test_cli_writes_what_scipy_and_numpy_read(cli, tmp_path):
    """`surftopo delaunay` on a non-manifold OBJ: the .npz Laplacian (scipy.sparse.load_npz) and
    the .npy mass diagonal (numpy.load) are the package's tufted matrices."""
    V, F = _pinched_cones()
    F = np.vstack([F, F[:3]])  # and duplicate faces
    path = tmp_path / "soup.obj"
    surftopo.write_mesh(path, V, F)
    result = run_cli(cli, "delaunay", path, "--laplacian", tmp_path / "L.npz", "--mass", tmp_path / "M.npy")
    assert "not a manifold" in result.stderr
    L = scipy.sparse.load_npz(tmp_path / "L.npz")
    mass = np.load(tmp_path / "M.npy")
    Lp, Mp = surftopo.laplacian(V, F, tufted=True)
    assert abs(L - Lp).max() <= 1e-15 * abs(Lp).max()
    assert np.abs(mass - Mp.diagonal()).max() <= 1e-15 * mass.max()
