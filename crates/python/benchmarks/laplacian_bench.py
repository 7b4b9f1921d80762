#!/usr/bin/env python3
"""surftopo.laplacian side by side with robust_laplacian.mesh_laplacian and
igl.intrinsic_delaunay_cotmatrix (when installed), and surftopo's Python overhead over its Rust
call. A benchmark, not a test.

Inputs: the shared meshes of about 100k faces (SURFTOPO_MESHES, relative to the repository root)
and two generated ones. Each round calls every contender once on the same arrays, the first one
rotating from round to round; the table gives the median over the rounds, the ratio of the
medians and the median of the per-round ratios (each peer's time over surftopo's in the same
round). surftopo is timed through `surftopo._native._laplacian_timed`, the code of
`surftopo.laplacian` that also returns the seconds of the library calls inside it (soup to
matrices, GIL released); the wall time around the same call adds everything else (reading the
numpy arrays, index conversion, the checks of the matrices, building the two
scipy.sparse.csr_matrix), and the median over the rounds of wall / library - 1 is the overhead.

    python crates/python/benchmarks/laplacian_bench.py --rounds 15 --out results/python_laplacian.md

`--cut-holes B --seed S` cuts B seeded holes into every input and adds generated open surfaces
(a disk, an annulus, a Möbius band of about 100k faces): open meshes, where boundary edges are
never flipped and keep their one half-cotangent in surftopo and libigl, while robust_laplacian's
tufted cover glues each face to its mirror image along the boundary, so a boundary edge facing an
obtuse angle is flipped there (the columns `obtuse` and `robust / tufted`: README, "boundary
condition").
"""

from __future__ import annotations

import argparse
import itertools
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
from test_boundary_condition import boundary_edges  # noqa: E402  (the tests' count)
SHARED = [
    "venus_50k.off.gz",
    "seahorse2_100K.off.gz",
    "koala.obj.gz",
    "hand1_50k.off.gz",
    "gargoyle_50k.off.gz",
    "horse_48k.off.gz",
]


def inputs(limit_faces: tuple[int, int]):
    """(name, V, F) of the shared meshes within the face range, then generated ones."""
    for name, V, F in shared_meshes(SHARED):
        if limit_faces[0] <= len(F) <= limit_faces[1]:
            yield name, V, F
    yield "icosphere(6)", *surftopo.icosphere(6)
    yield "torus(250, 200)", *surftopo.torus(250, 200)


def generated_open():
    """(name, V, F) of generated open surfaces of about 100k faces."""
    yield "disk(224)", *surftopo.disk(224)
    yield "annulus(500, 100)", *surftopo.annulus(500, 100)
    yield "mobius_band(500, 100)", *surftopo.mobius_band(500, 100)


def cut_holes(V, F, holes, seed):
    """Removes the faces around `holes` vertices chosen at random (seeded), no two within two
    edges of each other, so each hole is one boundary loop; the vertices stay (empty rows)."""
    rng = np.random.default_rng(seed)
    neighbours = [[] for _ in range(len(V))]
    for a, b in np.vstack([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]).tolist():
        neighbours[a].append(b)
        neighbours[b].append(a)
    blocked = np.zeros(len(V), bool)
    centres = []
    for v in rng.permutation(len(V)).tolist():
        if len(centres) == holes:
            break
        ring = {v} | {w for u in [v, *neighbours[v]] for w in neighbours[u]}
        ring |= {w for u in list(ring) for w in neighbours[u]}
        if not blocked[list(ring)].any():
            centres.append(v)
            blocked[list(ring)] = True
    return V, F[~np.isin(F, centres).any(axis=1)]


def peers():
    """The installed peers: name -> function(V, F) returning the Laplacian."""
    found = {}
    try:
        import robust_laplacian

        found["robust_laplacian"] = lambda V, F: robust_laplacian.mesh_laplacian(V, F)[0]
    except ImportError:
        print("note: robust_laplacian is not installed (pip install robust_laplacian)",
              file=sys.stderr)
    try:
        import igl

        found["igl"] = lambda V, F: igl.intrinsic_delaunay_cotmatrix(V, F)[0]
    except ImportError:
        print("note: libigl is not installed (pip install libigl)", file=sys.stderr)
    return found


def timed(f, *args):
    start = time.perf_counter()
    result = f(*args)
    return time.perf_counter() - start, result


def measure(name, V, F, rounds, contenders):
    calls = {"surftopo": None, **contenders}
    times = {k: [] for k in calls}
    library, overhead = [], []
    timed(surftopo.laplacian, V, F)  # warm-up
    for peer, f in contenders.items():
        timed(f, V, F)
    for k in range(rounds):
        order = list(calls)
        for who in order[k % len(order):] + order[:k % len(order)]:
            if who == "surftopo":
                # The code of surftopo.laplacian, also returning the seconds of the library calls.
                wall, (_, _, seconds) = timed(surftopo._native._laplacian_timed, V, F)
                times[who].append(wall)
                library.append(seconds)
                overhead.append(wall / seconds - 1.0)
            else:
                times[who].append(timed(calls[who], V, F)[0])
    # The same operator: libigl's with the opposite sign; robust_laplacian's (PSD like surftopo's)
    # after its default intrinsic mollification (1e-5), which changes the lengths around
    # near-degenerate triangles, so it is compared with surftopo's mollified by the same factor,
    # and on open meshes also with surftopo's tufted Laplacian (the same cover).
    # Rows of referenced vertices only: robust_laplacian puts a 1 on the diagonal of the others
    # (the centres of the holes cut).
    used = np.unique(F)
    referenced = lambda A: A.tocsr()[used][:, used]  # noqa: E731
    L = referenced(surftopo.laplacian(V, F)[0])
    agreement = {}
    for peer, f in contenders.items():
        other = referenced(f(V, F))
        if peer == "igl":
            agreement[peer] = float(abs(L + other).max() / abs(L).max())
        else:
            mollified = referenced(surftopo.laplacian(V, F, mollify=1e-5)[0])
            agreement[peer] = float(abs(mollified - other).max() / abs(L).max())
            tufted = referenced(surftopo.laplacian(V, F, tufted=True, mollify_factor=1e-5)[0])
            agreement[peer + "_tufted"] = float(abs(tufted - other).max() / abs(other).max())
    boundary, obtuse = boundary_edges(V, F)
    median = {k: statistics.median(v) for k, v in times.items()}
    return {
        "input": name,
        "faces": int(len(F)),
        "boundary_edges": boundary,
        "boundary_edges_facing_obtuse": obtuse,
        "surftopo_s": median["surftopo"],
        "library_s": statistics.median(library),
        "overhead_median": statistics.median(overhead),
        "overhead_max": max(overhead),
        **{f"{peer}_s": median[peer] for peer in contenders},
        **{f"{peer}_ratio_of_medians": median[peer] / median["surftopo"] for peer in contenders},
        **{
            f"{peer}_median_paired_ratio": statistics.median(
                p / q for p, q in zip(times[peer], times["surftopo"])
            )
            for peer in contenders
        },
        **{f"{peer}_relative_difference": d for peer, d in agreement.items()},
        "rounds": {k: v for k, v in times.items()},
    }


def table(results, contenders):
    head = ("| input | faces | boundary edges (facing an obtuse angle) | surftopo.laplacian (ms) "
            "| Rust call (ms) | overhead (median, max) |")
    rule = "|---|---:|---:|---:|---:|---:|"
    for peer in contenders:
        head += f" {peer} (ms) | {peer} / surftopo (of medians, paired) | {peer} difference |"
        rule += "---:|---:|---:|"
    if "robust_laplacian" in contenders:
        head += " robust_laplacian / surftopo tufted difference |"
        rule += "---:|"
    lines = [head, rule]
    for r in results:
        line = (
            f"| {r['input']} | {r['faces']} | {r['boundary_edges']} "
            f"({r['boundary_edges_facing_obtuse']}) | {1e3 * r['surftopo_s']:.2f} | "
            f"{1e3 * r['library_s']:.2f} | {100 * r['overhead_median']:.1f}%, "
            f"{100 * r['overhead_max']:.1f}% |"
        )
        for peer in contenders:
            line += (
                f" {1e3 * r[peer + '_s']:.1f} | {r[peer + '_ratio_of_medians']:.1f}x, "
                f"{r[peer + '_median_paired_ratio']:.1f}x | "
                f"{r[peer + '_relative_difference']:.1e} |"
            )
        if "robust_laplacian" in contenders:
            line += f" {r['robust_laplacian_tufted_relative_difference']:.1e} |"
        lines.append(line)
    return "\n".join(lines)


def summary(results, contenders):
    """The range and median of each peer's ratios over the inputs."""
    lines = []
    for peer in contenders:
        of_medians = sorted(r[peer + "_ratio_of_medians"] for r in results)
        paired = sorted(r[peer + "_median_paired_ratio"] for r in results)
        lines.append(
            f"{peer} / surftopo: ratios of medians {of_medians[0]:.1f}x to {of_medians[-1]:.1f}x "
            f"(median {statistics.median(of_medians):.1f}x); medians of paired ratios "
            f"{paired[0]:.1f}x to {paired[-1]:.1f}x (median {statistics.median(paired):.1f}x)."
        )
    overhead = [r["overhead_median"] for r in results]
    lines.append(
        f"Python layer over the Rust call: median overhead {100 * min(overhead):.1f}% to "
        f"{100 * max(overhead):.1f}% per input."
    )
    return "\n\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--min-faces", type=int, default=80_000)
    parser.add_argument("--max-faces", type=int, default=120_000)
    parser.add_argument("--out", type=Path, help="markdown report (a .jsonl beside it)")
    parser.add_argument("--cut-holes", type=int, default=0, help="holes cut into every input")
    parser.add_argument("--seed", type=int, default=1, help="the holes' seed")
    args = parser.parse_args()
    contenders = peers()
    load_start = os.getloadavg()[0]
    cases = inputs((args.min_faces, args.max_faces))
    if args.cut_holes:
        holed = ((f"{name} ({args.cut_holes} holes)", *cut_holes(V, F, args.cut_holes, args.seed))
                 for name, V, F in cases)
        cases = itertools.chain(holed, generated_open())
    results = []
    for name, V, F in cases:
        r = measure(name, V, F, args.rounds, contenders)
        results.append(r)
        print(json.dumps({k: v for k, v in r.items() if k != "rounds"}), file=sys.stderr)
    command = command_line()
    versions = {"python": platform.python_version(), "numpy": np.__version__}
    for module in ("scipy", "robust_laplacian", "igl"):
        try:
            versions[module] = getattr(__import__(module), "__version__", "installed")
        except ImportError:
            pass
    title = "# surftopo.laplacian against robust_laplacian and libigl"
    report = "\n".join(header(title, command, load_start, versions) + [
        "",
        f"Median wall time over {args.rounds} rounds (each round calls every contender once, the "
        "first one rotating, after one warm-up call each); the ratios are the ratio of the "
        "medians and the median of the per-round ratios. surftopo is timed through "
        "`surftopo._native._laplacian_timed`, the code of surftopo.laplacian that also returns the "
        "seconds of the library calls inside it (mesh build, lengths, flips, Laplacian, mass: the "
        "Rust call column); the overhead is wall / Rust - 1 of the same call (median and maximum "
        "over the rounds): reading the numpy arrays, converting the indices, checking the "
        "matrices, building the two scipy.sparse.csr_matrix. Every contender runs with its "
        "defaults (robust_laplacian mollifies by 1e-5, surftopo does not). Differences are the "
        "largest entry difference over the largest entry, on the referenced vertices "
        "(robust_laplacian puts a 1 on the diagonal of the others: the centres of the holes): "
        "libigl's with the opposite sign; "
        "robust_laplacian's with surftopo's `mollify=1e-5`, and (last column) with surftopo's "
        "`tufted=True` (the same cover, the same factor). On open meshes robust_laplacian's tufted "
        "cover flips the boundary edges facing an obtuse angle, which libigl and surftopo keep "
        "(the natural boundary condition; README, boundary condition).",
        "",
        table(results, contenders),
        "",
        summary(results, contenders),
        "",
    ])
    publish(report, results, command, args.out)


if __name__ == "__main__":
    main()
