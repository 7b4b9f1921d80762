#!/usr/bin/env python3
"""surftopo.laplacian(V, F, tufted=True) side by side with robust_laplacian.mesh_laplacian on
non-manifold meshes and triangle soups (the tufted cover of Sharp & Crane 2020), in process. A
benchmark, not a test.

Inputs: shared meshes of about 50k-100k faces (SURFTOPO_MESHES, relative to the repository root)
as they are and made non-manifold (fins making books of 3 faces on 5% of the faces' edges, 5% of
the faces duplicated, a mirror copy pinched at one vertex: `_made_non_manifold` of the tests, with
the seed given), and generated soups: an icosphere whose triangles share no vertex (every edge a
fin), and one with 10% duplicate faces and books. Both contenders run with mollify_factor 1e-5
(robust_laplacian's default). Rounds alternate which contender runs first; the table gives the
medians and the ratio of the medians, and the agreement of the two Laplacians (maximum entry
difference over the largest entry, referenced vertices).

    python crates/python/benchmarks/tufted_bench.py --rounds 7 --seed 11 --out results/tufted.md
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import surftopo
from bench_support import REPOSITORY, command_line, header, publish, shared_meshes

sys.path.insert(0, str(REPOSITORY / "crates" / "python" / "tests"))
from test_tufted import _made_non_manifold  # noqa: E402  (the tests' non-manifold maker)

SHARED = ["venus_50k.off.gz", "koala.obj.gz", "horse_48k.off.gz", "armadillo_43k.obj.gz"]


def unshared(V, F):
    """Every triangle with its own three vertices: a soup of fins."""
    return V[F.ravel()], np.arange(3 * len(F)).reshape(-1, 3)


def with_books_and_duplicates(V, F, seed):
    """10% of the faces duplicated (half of them reversed) and fins on 5% of the edges."""
    rng = np.random.default_rng(seed)
    dup = F[rng.choice(len(F), len(F) // 10, replace=False)]
    dup[::2] = dup[::2, ::-1]
    picks = F[rng.choice(len(F), len(F) // 20, replace=False)]
    apex = V[picks[:, :2]].mean(axis=1) + 0.3 * rng.standard_normal((len(picks), 3)) * 0.01
    fins = np.column_stack([picks[:, 0], picks[:, 1], len(V) + np.arange(len(picks))])
    return np.vstack([V, apex]), np.vstack([F, dup, fins])


def inputs(seed):
    for short, V, F in shared_meshes(SHARED):
        yield short, V, F
        yield f"{short} made non-manifold", *_made_non_manifold(V, F, seed)
    V, F = surftopo.icosphere(5)
    yield "icosphere(5), no shared vertex", *unshared(V, F)
    V, F = surftopo.icosphere(6)
    yield "icosphere(6) + books, duplicates", *with_books_and_duplicates(V, F, seed)


def timed(f):
    start = time.perf_counter()
    result = f()
    return time.perf_counter() - start, result


def measure(name, V, F, rounds, robust_laplacian):
    ours = lambda: surftopo.laplacian(V, F, tufted=True, mollify_factor=1e-5)  # noqa: E731
    theirs = lambda: robust_laplacian.mesh_laplacian(V, F, mollify_factor=1e-5)  # noqa: E731
    ours(), theirs()  # warm-up
    times = {"surftopo": [], "robust_laplacian": []}
    for k in range(rounds):
        order = [("surftopo", ours), ("robust_laplacian", theirs)]
        for who, f in order if k % 2 == 0 else order[::-1]:
            times[who].append(timed(f)[0])
    (L, M), (Lr, Mr) = ours(), theirs()
    used = np.zeros(len(V), bool)
    used[F.ravel()] = True
    keep = np.flatnonzero(used)
    L, Lr, M, Mr = (A.tocsr()[keep][:, keep] for A in (L, Lr, M, Mr))
    import scipy.sparse

    return {
        "input": name,
        "vertices": int(len(V)),
        "faces": int(len(F)),
        "surftopo_median_s": statistics.median(times["surftopo"]),
        "robust_laplacian_median_s": statistics.median(times["robust_laplacian"]),
        "ratio_of_medians": statistics.median(times["robust_laplacian"])
        / statistics.median(times["surftopo"]),
        "median_paired_ratio": statistics.median(
            p / q for p, q in zip(times["robust_laplacian"], times["surftopo"])
        ),
        "laplacian_relative_difference": float(abs(L - Lr).max() / abs(Lr).max()),
        "mass_relative_difference": float(abs(M - Mr).max() / abs(Mr).max()),
        "robust_positive_off_diagonal": int((scipy.sparse.triu(Lr, 1) > 0).sum()),
    }


def table(results):
    lines = [
        "| input | vertices | faces | surftopo (ms) | robust_laplacian (ms) | ratio of medians "
        "| median of paired ratios | L difference | M difference "
        "| robust_laplacian's positive off-diagonals |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in results:
        lines.append(
            f"| {r['input']} | {r['vertices']} | {r['faces']} | {1e3 * r['surftopo_median_s']:.1f} "
            f"| {1e3 * r['robust_laplacian_median_s']:.1f} | {r['ratio_of_medians']:.1f}x "
            f"| {r['median_paired_ratio']:.1f}x "
            f"| {r['laplacian_relative_difference']:.1e} | {r['mass_relative_difference']:.1e} "
            f"| {r['robust_positive_off_diagonal']} |"
        )
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--out", type=Path, help="markdown report (a .jsonl beside it)")
    args = parser.parse_args()
    import robust_laplacian

    load_start = os.getloadavg()[0]
    results = []
    for name, V, F in inputs(args.seed):
        r = measure(name, V, F, args.rounds, robust_laplacian)
        results.append(r)
        print(json.dumps(r), file=sys.stderr)
    command = command_line()
    ratios = [r["ratio_of_medians"] for r in results]
    paired = [r["median_paired_ratio"] for r in results]
    versions = {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "robust_laplacian": getattr(robust_laplacian, "__version__", "installed"),
    }
    title = "# The tufted-cover Laplacian: surftopo against robust_laplacian"
    report = "\n".join(header(title, command, load_start, versions) + [
        "",
        f"Median wall time over {args.rounds} rounds of `surftopo.laplacian(V, F, tufted=True, "
        "mollify_factor=1e-5)` and `robust_laplacian.mesh_laplacian(V, F, mollify_factor=1e-5)`, "
        "in process, the rounds alternating which runs first (one warm-up call each). The "
        "differences are the largest entry difference over the largest entry (referenced "
        "vertices; robust_laplacian gives unreferenced ones a 1 on the diagonal). Where "
        "robust_laplacian's Laplacian has positive off-diagonal entries, geometry-central stopped "
        "flipping with cotan weights in [-1e-6, 0) (its `delaunayEPS`), where surftopo flips to "
        "the Delaunay triangulation; co-circular quads then also give another lumped mass.",
        "",
        table(results),
        "",
        f"Ratios of medians: {min(ratios):.1f}x to {max(ratios):.1f}x "
        f"(median {statistics.median(ratios):.1f}x); medians of paired ratios "
        f"{min(paired):.1f}x to {max(paired):.1f}x (median {statistics.median(paired):.1f}x).",
        "",
    ])
    publish(report, results, command, args.out)


if __name__ == "__main__":
    main()
