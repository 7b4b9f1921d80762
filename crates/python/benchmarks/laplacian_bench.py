#!/usr/bin/env python3
"""surftopo.laplacian side by side with robust_laplacian.mesh_laplacian and
igl.intrinsic_delaunay_cotmatrix (when installed), and surftopo's Python overhead over its Rust
call. A benchmark, not a test.

Inputs: the shared meshes of about 100k faces (SURFTOPO_MESHES, relative to the repository root)
and two generated ones. Each round calls every contender once on the same arrays, in turn; the
table gives the minimum over the rounds and the ratios of minima. surftopo is timed through
`surftopo._native._laplacian_timed`, the code of `surftopo.laplacian` that also returns the seconds
of the library calls inside it (soup to matrices, GIL released); the wall time around the same
call adds everything else (reading the numpy arrays, index conversion, building the two
scipy.sparse.csr_matrix), and the median over the rounds of wall / library - 1 is the overhead.

    python crates/python/benchmarks/laplacian_bench.py --rounds 15 --out results/python_laplacian.md

`--cut-holes B` cuts B holes into every input first (open meshes: boundary edges are never
flipped and keep their one half-cotangent in every contender).
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

import surftopo

REPOSITORY = Path(__file__).resolve().parents[3]
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
    folder = os.environ.get("SURFTOPO_MESHES")
    if folder:
        root = Path(folder) if Path(folder).is_absolute() else REPOSITORY / folder
        for name in SHARED:
            path = root / name
            if path.is_file():
                V, F = surftopo.read_mesh(path)
                if limit_faces[0] <= len(F) <= limit_faces[1]:
                    yield name.split(".")[0], V, F
    else:
        print("note: SURFTOPO_MESHES is not set: generated inputs only", file=sys.stderr)
    yield "icosphere(6)", *surftopo.icosphere(6)
    yield "torus(250, 200)", *surftopo.torus(250, 200)


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
    rows = {"surftopo": [], "library": [], "overhead": []}
    rows.update({k: [] for k in contenders})
    timed(surftopo.laplacian, V, F)  # warm-up
    for _ in range(rounds):
        # The same code as surftopo.laplacian, also returning the seconds of the library calls.
        wall, (_, _, library) = timed(surftopo._native._laplacian_timed, V, F)
        rows["surftopo"].append(wall)
        rows["library"].append(library)
        rows["overhead"].append(wall / library - 1.0)
        for peer, f in contenders.items():
            rows[peer].append(timed(f, V, F)[0])
    # The same operator: libigl's with the opposite sign; robust_laplacian's (PSD like surftopo's)
    # after its default intrinsic mollification (1e-5), which changes the lengths around
    # near-degenerate triangles, so it is compared with surftopo's mollified by the same factor.
    L, _ = surftopo.laplacian(V, F)
    agreement = {}
    for peer, f in contenders.items():
        other = f(V, F)
        if peer == "igl":
            agreement[peer] = float(abs(L + other).max() / abs(L).max())
        else:
            mollified, _ = surftopo.laplacian(V, F, mollify=1e-5)
            agreement[peer] = float(abs(mollified - other).max() / abs(L).max())
    return {
        "input": name,
        "faces": int(len(F)),
        "surftopo_s": min(rows["surftopo"]),
        "library_s": min(rows["library"]),
        "overhead_median": statistics.median(rows["overhead"]),
        "overhead_max": max(rows["overhead"]),
        **{f"{peer}_s": min(rows[peer]) for peer in contenders},
        **{f"{peer}_relative_difference": agreement[peer] for peer in contenders},
    }


def table(results, contenders):
    head = "| input | faces | surftopo.laplacian (ms) | Rust call (ms) | overhead (median, max) |"
    rule = "|---|---:|---:|---:|---:|"
    for peer in contenders:
        head += f" {peer} (ms) | {peer} / surftopo |"
        rule += "---:|---:|"
    lines = [head, rule]
    for r in results:
        line = (
            f"| {r['input']} | {r['faces']} | {1e3 * r['surftopo_s']:.2f} | "
            f"{1e3 * r['library_s']:.2f} | {100 * r['overhead_median']:.1f}%, "
            f"{100 * r['overhead_max']:.1f}% |"
        )
        for peer in contenders:
            line += f" {1e3 * r[peer + '_s']:.1f} | {r[peer + '_s'] / r['surftopo_s']:.1f}x |"
        lines.append(line)
    return "\n".join(lines)


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
    results = []
    for name, V, F in inputs((args.min_faces, args.max_faces)):
        if args.cut_holes:
            V, F = cut_holes(V, F, args.cut_holes, args.seed)
            name += f" ({args.cut_holes} holes)"
        r = measure(name, V, F, args.rounds, contenders)
        results.append(r)
        print(json.dumps(r), file=sys.stderr)
    command = "python " + " ".join([str(Path(sys.argv[0]))] + sys.argv[1:])
    versions = {"python": platform.python_version(), "numpy": np.__version__}
    for module in ("scipy", "robust_laplacian", "igl"):
        try:
            versions[module] = getattr(__import__(module), "__version__", "installed")
        except ImportError:
            pass
    report = "\n".join([
        "# surftopo.laplacian against robust_laplacian and libigl",
        "",
        f"Command: `SURFTOPO_MESHES={os.environ.get('SURFTOPO_MESHES', '')} {command}`",
        "",
        f"Date: {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC; "
        f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at the end; "
        + ", ".join(f"{k} {v}" for k, v in versions.items()),
        "",
        f"Minimum wall time over {args.rounds} rounds (each round calls every contender once, in "
        "turn, after one warm-up call of surftopo.laplacian). surftopo is timed through "
        "`surftopo._native._laplacian_timed`, the code of surftopo.laplacian that also returns the "
        "seconds of the library calls inside it (mesh build, lengths, flips, Laplacian, mass: the "
        "Rust call column); the overhead is wall / Rust - 1 of the same call (median and maximum "
        "over the rounds): reading the numpy arrays, converting the indices, building the two "
        "scipy.sparse.csr_matrix. Every contender runs with its defaults (robust_laplacian "
        "mollifies by 1e-5, surftopo does not). The peers' Laplacians agree with surftopo's to "
        "the relative difference in the .jsonl (libigl's with the opposite sign; "
        "robust_laplacian's with surftopo's `mollify=1e-5`).",
        "",
        table(results, contenders),
        "",
    ])
    print(report)
    if args.out:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(report)
        args.out.with_suffix(".jsonl").write_text(
            "".join(json.dumps({**r, "command": command}) + "\n" for r in results)
        )


if __name__ == "__main__":
    main()
