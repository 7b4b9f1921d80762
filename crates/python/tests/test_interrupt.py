"""Ctrl-C stops every long call promptly, with KeyboardInterrupt, and the next call works.

Each case runs in a subprocess a call that takes seconds even in a release build (tens of
seconds in a debug one), sends it SIGINT half a second after the call starts, and asserts that
KeyboardInterrupt arrives in under 3 seconds from the start (about 0.5 s expected: the calling
thread checks for signals every 20 ms) without the call returning; then a small call in the same
process must give a correct result. The interrupted work must stop too, not run on in the
background: after a second to wind down, the process' CPU time grows by less than a fifth of a
second over the next second (a worker still running would add up to a second per second).
"""

from __future__ import annotations

import json
import signal
import subprocess
import sys
import textwrap
import time

import pytest

# A closed torus grid of 2 m n triangles built with numpy (no library call, so the setup is fast).
GRID = """
import numpy as np

def torus_grid(m, n):
    i, j = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")
    u, v = 2 * np.pi * i / m, 2 * np.pi * j / n
    V = np.stack([(2 + np.cos(v)) * np.cos(u), (2 + np.cos(v)) * np.sin(u), np.sin(v)], -1)
    k = lambda a, b: ((a % m) * n + b % n).ravel()
    F = np.concatenate([
        np.stack([k(i, j), k(i + 1, j), k(i, j + 1)], -1),
        np.stack([k(i + 1, j), k(i + 1, j + 1), k(i, j + 1)], -1),
    ])
    return V.reshape(-1, 3), F
"""

# Each long call (`setup` runs before the clock starts). Time for each, measured uninterrupted:
# debug build (`maturin develop --profile dev`) / the release build is a few times faster.
CALLS = {
    # Diks–Stanczyk on 2,000,000 triangles: about 50 s debug.
    "quadrangulate": (
        "V, F = torus_grid(1000, 1000)",
        "surftopo.quadrangulate(V, F, algorithm='ds')",
    ),
    # Brute-force reduction of 2,000,000 triangles: 12.5 s debug.
    "irreducible": (
        "V, F = torus_grid(1000, 1000)",
        "surftopo.irreducible(V, F, algorithm='brute-force')",
    ),
    # The intrinsic Delaunay Laplacian of 2,000,000 triangles: 5.3 s debug.
    "laplacian": ("V, F = torus_grid(1000, 1000)", "surftopo.laplacian(V, F)"),
    # T_10000 refined 100 x 100: about 10^8 flips, minutes in either build.
    "intrinsic_delaunay": (
        "T = surftopo.flat_torus(10000.0, 100)",
        "surftopo.intrinsic_delaunay(T)",
    ),
    # The same flips, twice, before the tessellations are compared.
    "isometric": ("T = surftopo.flat_torus(10000.0, 100)", "surftopo.isometric(T, T)"),
    # Irreducible genus-2 triangulations up to 11 vertices: 35 s debug (its search also stops).
    "census": ("", "surftopo.census('genus-2', max_vertices=11)"),
    # Theorem 1 in exact arithmetic on a pillowcase sheared by 10^100: about 15 s of CPU in a
    # release build (results/exact_growth.md), longer in debug.
    "dubois": (
        "T = surftopo.Portalgon.from_json(SHEARED_PILLOWCASE)",
        "surftopo.intrinsic_delaunay(T, method='dubois', exact=True)",
    ),
}

# Two unit squares sheared by X = 10^100, glued into a pillowcase (four cone points of angle
# pi): the triangles of `surftopo_intrinsic::pillowcase` for u = (1, 0), v = (X, 1).
X = 10**100
SHEARED_PILLOWCASE = json.dumps({
    "polygons": [
        {"corners": [[0, 0], [1, 0], [str(X), 1]]},
        {"corners": [[1, 0], [str(X + 1), 1], [str(X), 1]]},
        {"corners": [[1, 0], [2, 0], [str(X + 1), 1]]},
        {"corners": [[2, 0], [str(X + 2), 1], [str(X + 1), 1]]},
    ],
    "matching": [[[0, 0], [2, 0]], [[1, 1], [3, 1]], [[0, 2], [3, 0]],
                 [[0, 1], [1, 2]], [[1, 0], [2, 2]], [[2, 1], [3, 2]]],
})

SCRIPT = """
import sys, time
import surftopo
SHEARED_PILLOWCASE = {pillowcase!r}
{grid}
{setup}
print("calling", flush=True)
start = time.perf_counter()
try:
    {call}
    print("returned", time.perf_counter() - start, flush=True)
except KeyboardInterrupt:
    print("interrupted", time.perf_counter() - start, flush=True)
# The work stopped: no CPU time spent once it wound down.
time.sleep(1.0)
cpu = time.process_time()
time.sleep(1.0)
print("cpu", time.process_time() - cpu, flush=True)
# Nothing is left half-done: the next call works.
Q, stats = surftopo.quadrangulate(*surftopo.torus(6, 4))
print("after", Q.shape[0], stats["paired_percent"], flush=True)
"""


@pytest.mark.parametrize("name", sorted(CALLS))
def test_ctrl_c_stops_a_long_call_promptly(name):
    setup, call = CALLS[name]
    script = SCRIPT.format(grid=GRID, setup=setup, call=call, pillowcase=SHEARED_PILLOWCASE)
    child = subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(script)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert child.stdout is not None
        first = child.stdout.readline()
        assert first.strip() == "calling", (first, child.stderr.read() if child.stderr else "")
        time.sleep(0.5)
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    lines = out.split()
    assert child.returncode == 0, (out, err)
    assert lines[0] == "interrupted", (out, err)
    elapsed = float(lines[1])
    # The signal came 0.5 s after the start; the call would run for many seconds more.
    assert 0.4 <= elapsed < 3.0, elapsed
    assert lines[2] == "cpu", out
    assert float(lines[3]) < 0.2, f"the interrupted work ran on: {out}"
    # 6 x 4 torus: 48 triangles, 24 quads, all paired.
    assert lines[4:] == ["after", "24", "100.0"], out
