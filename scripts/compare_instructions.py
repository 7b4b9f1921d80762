#!/usr/bin/env python3
"""Instructions executed by two builds of the `surftopo` binary on the same commands, counted by
`valgrind --tool=callgrind` (a count that the load of a shared machine does not disturb), with
the ratio new/base per command and input, and the median ratio per command.

    scripts/compare_instructions.py BASE_BIN NEW_BIN MESH... [--commands info,irreducible,...]

Commands: info, irreducible (rs), schipper, brute-force, quad (ks), quad-sg, quad-ps, quad-lrs,
quad-ds (`--algorithm`), quad-quality, quad-quality-fast (`--objective`), delaunay (flip, with
the Laplacian and mass matrix), delaunay-voronoi (the Voronoi wave, likewise). Each output goes
to a temporary folder; the whole process is counted (reading, building, the algorithm, writing).
"""

from __future__ import annotations

import argparse
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile

COMMANDS = {
    "info": lambda m, o: ["info", m],
    "irreducible": lambda m, o: ["irreducible", m, "-o", f"{o}/i.obj"],
    "schipper": lambda m, o: ["irreducible", m, "-o", f"{o}/i.obj", "--algorithm", "schipper"],
    "brute-force": lambda m, o: ["irreducible", m, "-o", f"{o}/i.obj", "--algorithm",
                                 "brute-force"],
    "quad": lambda m, o: ["quad", m, "-o", f"{o}/q.obj"],
    **{f"quad-{a}": (lambda a: lambda m, o: ["quad", m, "-o", f"{o}/q.obj", "--algorithm", a])(a)
       for a in ("sg", "ps", "lrs", "ds")},
    **{f"quad-{q}": (lambda q: lambda m, o: ["quad", m, "-o", f"{o}/q.obj", "--objective", q])(q)
       for q in ("quality", "quality-fast")},
    "delaunay": lambda m, o: ["delaunay", m, "-o", f"{o}/d.json", "--laplacian", f"{o}/L.mtx",
                              "--mass", f"{o}/M.mtx"],
    "delaunay-voronoi": lambda m, o: ["delaunay", m, "--method", "voronoi", "-o", f"{o}/d.json",
                                      "--laplacian", f"{o}/L.mtx", "--mass", f"{o}/M.mtx"],
}


def instructions(binary: str, args: list[str], work: str) -> int:
    out = f"{work}/callgrind.out"
    run = subprocess.run(
        ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", binary, *args],
        capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{binary} {' '.join(args)}: exit {run.returncode}\n{run.stderr[-2000:]}")
    found = re.search(r"Collected : (\d+)", run.stderr)
    if not found:
        sys.exit(f"no instruction count in valgrind's report:\n{run.stderr[-2000:]}")
    return int(found.group(1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--commands", default=",".join(COMMANDS))
    a = parser.parse_args()
    ratios: dict[str, list[float]] = {}
    print("| command | input | base instructions | new instructions | new/base |")
    print("|---|---|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as work:
        for command in a.commands.split(","):
            for mesh in a.meshes:
                args = COMMANDS[command](mesh, work)
                base = instructions(a.base, args, work)
                new = instructions(a.new, args, work)
                ratios.setdefault(command, []).append(new / base)
                name = pathlib.Path(mesh).name
                print(f"| {command} | {name} | {base:,} | {new:,} | {new / base:.4f} |",
                      flush=True)
    print()
    print("| command | median new/base | max |")
    print("|---|---:|---:|")
    for command, r in ratios.items():
        print(f"| {command} | {statistics.median(r):.4f} | {max(r):.4f} |")


if __name__ == "__main__":
    main()
