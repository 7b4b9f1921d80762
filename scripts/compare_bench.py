#!/usr/bin/env python3
"""Side-by-side timing of two builds of the `quad_tables` example on the same inputs.

    scripts/compare_bench.py BASE_QUAD_TABLES NEW_QUAD_TABLES [--rounds R] [--runs N] NAME...

Each NAME is passed as `--only NAME` (shared meshes whose name contains it; `SURFTOPO_MESHES`
must be set). The two binaries run in alternate rounds, so that a slow spell of the shared machine
hits both; per input, algorithm and augmenting strategy the script prints the minimum over the
rounds of `total_seconds` (itself the minimum over `--runs` calls of `quadrangulate_with`) for each
build and their ratio new / base. Nothing is written into the repository.
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
        records[(r["input"], r["algorithm"], r["augment"])] = r["total_seconds"]
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
                for key, t in got.items():
                    best[side][key] = min(t, best[side].get(key, float("inf")))
    print(f"{'input':<24} {'algorithm':<10} {'augment':<24} {'base s':>10} {'new s':>10} {'new/base':>8}")
    for key in sorted(best["base"]):
        b, n = best["base"][key], best["new"].get(key)
        if n is None:
            continue
        print(f"{key[0]:<24} {key[1]:<10} {key[2]:<24} {b:>10.5f} {n:>10.5f} {n / b:>8.3f}")


if __name__ == "__main__":
    main()
