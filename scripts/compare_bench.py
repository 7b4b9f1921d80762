#!/usr/bin/env python3
"""Side-by-side timing of two builds of the `quad_tables` example on the same inputs.

    scripts/compare_bench.py BASE_QUAD_TABLES NEW_QUAD_TABLES [--rounds R] [--runs N] NAME...

Each NAME is passed as `--only NAME` (shared meshes whose name contains it; `SURFTOPO_MESHES`
must be set, as an absolute path: a relative one is taken from each build's own checkout). The two binaries run in alternate rounds, so that a slow spell of the shared machine
hits both; per input, algorithm and augmenting strategy the script prints, for each build, the
minimum over the rounds of `total_seconds` (itself the minimum over `--runs` calls of
`quadrangulate_with`, wall clock) and of `cpu_seconds` (the thread's CPU time per call, averaged
over the runs), and the ratios new / base. Nothing is written into the repository.
"""
import argparse
import json
import subprocess
import tempfile
from pathlib import Path


def run(binary, names, runs, out):
    args = [binary, "--no-groups", "--runs", str(runs), "--ds-max-triangles", "0",
            "--global-max-work", "0", "--out", str(out)]
    for name in names:
        args += ["--only", name]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    records = {}
    for line in Path(str(out) + ".jsonl").read_text().splitlines():
        r = json.loads(line)
        records[(r["input"], r["algorithm"], r["augment"])] = (r["total_seconds"], r["cpu_seconds"])
    return records


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("names", nargs="+")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--runs", type=int, default=5)
    a = parser.parse_args()
    best = {"base": {}, "new": {}}
    with tempfile.TemporaryDirectory() as work:
        for k in range(a.rounds):
            for side in ("base", "new"):
                got = run(getattr(a, side), a.names, a.runs, Path(work) / f"{side}{k}")
                for key, (wall, cpu) in got.items():
                    w, c = best[side].get(key, (float("inf"), float("inf")))
                    best[side][key] = (min(w, wall), min(c, cpu))
    print(f"{'input':<20} {'algorithm':<10} {'augment':<12} {'base wall':>10} {'new wall':>10} "
          f"{'ratio':>6} {'base cpu':>10} {'new cpu':>10} {'ratio':>6}")
    for key in sorted(best["base"]):
        (bw, bc), new = best["base"][key], best["new"].get(key)
        if new is None:
            continue
        nw, nc = new
        cpu_ratio = nc / bc if bc > 0 else float("nan")
        print(f"{key[0]:<20} {key[1]:<10} {key[2]:<12} {bw:>10.5f} {nw:>10.5f} {nw / bw:>6.3f} "
              f"{bc:>10.5f} {nc:>10.5f} {cpu_ratio:>6.3f}")


if __name__ == "__main__":
    main()
