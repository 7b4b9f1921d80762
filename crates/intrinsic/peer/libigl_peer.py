#!/usr/bin/env python3
"""libigl peer for the intrinsic Delaunay benchmark (not used by CI).

Times `igl.intrinsic_delaunay_cotmatrix(V, F)` (libigl's Python bindings: edge-length
computation, intrinsic Delaunay flips and cotangent matrix assembly, from V and F) on shared
meshes, and writes each Laplacian in Matrix Market format for comparison with ours:

    python3 -m venv /tmp/igl && /tmp/igl/bin/pip install libigl scipy numpy
    /tmp/igl/bin/python crates/intrinsic/peer/libigl_peer.py \
        --meshes ../shared/meshes --out /tmp/igl-peer \
        gargoyle_50k.off.gz koala.obj.gz venus_50k.off.gz

For every mesh NAME it writes OUT/NAME.libigl.mtx (libigl's sign convention: negative
semidefinite, i.e. the negative of surftopo-intrinsic's Laplacian; full 17-digit values) and one
JSON line to OUT/libigl.jsonl: {"input", "vertices", "faces", "seconds" (best wall-clock time of
--repeat runs), "cpu_seconds" (mean thread CPU time per run, time.thread_time()), "runs",
"libigl_version"}. Then `cargo run --release -p surftopo-intrinsic --example
delaunay_bench -- --peer OUT` compares both Laplacians and timings.

The meshes are gunzipped to a temporary file and read with igl.read_triangle_mesh, which keeps
the file's vertex order (the shared meshes used here have no unreferenced vertices, so it is also
surftopo's order).
"""

import argparse
import gzip
import importlib.metadata
import json
import os
import shutil
import sys
import tempfile
import time

import igl
import numpy as np
import scipy.io


def read_mesh(path):
    suffix = os.path.splitext(path[:-3] if path.endswith(".gz") else path)[1]
    with tempfile.NamedTemporaryFile(suffix=suffix, delete=False) as tmp:
        opener = gzip.open if path.endswith(".gz") else open
        with opener(path, "rb") as src:
            shutil.copyfileobj(src, tmp)
        name = tmp.name
    try:
        v, f = igl.read_triangle_mesh(name)
    finally:
        os.unlink(name)
    return np.ascontiguousarray(v, dtype=np.float64), np.ascontiguousarray(f, dtype=np.int64)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--meshes", default=os.environ.get("SURFTOPO_MESHES", "../shared/meshes"))
    parser.add_argument("--out", required=True)
    parser.add_argument("--repeat", type=int, default=10)
    parser.add_argument("names", nargs="+")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    version = importlib.metadata.version("libigl")
    with open(os.path.join(args.out, "libigl.jsonl"), "w") as log:
        for name in args.names:
            v, f = read_mesh(os.path.join(args.meshes, name))
            best = float("inf")
            lap = None
            cpu = time.thread_time()
            for _ in range(args.repeat):
                start = time.perf_counter()
                lap, _, _ = igl.intrinsic_delaunay_cotmatrix(v, f)
                best = min(best, time.perf_counter() - start)
            mean_cpu = (time.thread_time() - cpu) / args.repeat
            scipy.io.mmwrite(
                os.path.join(args.out, name + ".libigl.mtx"),
                lap.tocoo(),
                comment="libigl intrinsic_delaunay_cotmatrix (negative semidefinite)",
                precision=17,
            )
            row = {
                "input": name,
                "vertices": int(v.shape[0]),
                "faces": int(f.shape[0]),
                "seconds": best,
                "cpu_seconds": mean_cpu,
                "runs": args.repeat,
                "libigl_version": version,
            }
            log.write(json.dumps(row) + "\n")
            print(json.dumps(row), file=sys.stderr)


if __name__ == "__main__":
    main()
