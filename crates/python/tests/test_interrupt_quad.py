"""Ctrl-C stops `quadrangulate` by every pairing method while its pairing runs, whatever the
machine's speed.

Each case runs in a subprocess: the call uninterrupted (the duration `full` of a second such
call is this machine's measure of the work), then the same call again with SIGINT raised from a timer thread
at `full / 2`. The second call must raise KeyboardInterrupt before it would have finished (well
under `full`), and the work must stop, not run on in the background: after a moment to wind
down, the process' CPU time grows by less than a fifth of a second over the next second (the
pairing loops read the stop flag every few thousand steps: `surftopo_mesh::stop`). Then a small
call in the same process must give a correct result.

On these meshes most of a call is the surface's build, whose loops stopped already; that each
pairing loop itself stops (SG, PS, KS with its shortcuts, the augmenting paths, LRS's expansion,
the blossom and its fast mode) is checked in Rust, with the flag set before the work starts:
`crates/matching/tests/stop.rs`, `crates/quad/tests/stop.rs` (both fail without the checks).
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

import pytest
from test_interrupt import GRID, SCRIPT

# test_interrupt.py's script: the setup (here the uninterrupted calls and the timer), the call
# interrupted, the CPU check, the small call after.
SETUP = """
import signal, threading
V, F = torus_grid({m}, {m})
run = lambda: surftopo.quadrangulate(V, F, algorithm={algorithm!r}, objective={objective!r})
# The uninterrupted time, on the second of two calls (the first warms caches and allocator up).
run()
t0 = time.perf_counter()
run()
full = time.perf_counter() - t0
print("full", full, flush=True)
threading.Timer(full / 2, lambda: signal.raise_signal(signal.SIGINT)).start()
"""

# (algorithm, objective, grid size m: 2 m^2 triangles, enough for seconds in a debug build).
CASES = [
    ("sg", "count", 500),
    ("ps", "count", 500),
    ("ks", "count", 500),
    ("lrs", "count", 300),
    ("ds", "count", 300),
    ("ks", "quality-fast", 300),
    ("ks", "quality", 400),
]


@pytest.mark.parametrize(("algorithm", "objective", "m"), CASES)
def test_ctrl_c_stops_quadrangulate_during_its_pairing(algorithm, objective, m):
    setup = SETUP.format(m=m, algorithm=algorithm, objective=objective)
    script = SCRIPT.format(grid=GRID, setup=setup, call="run()", pillowcase="")
    done = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(script)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    lines = done.stdout.split()
    assert done.returncode == 0, (done.stdout, done.stderr)
    assert lines[0] == "full", done.stdout
    full = float(lines[1])
    assert lines[2] == "calling", done.stdout
    assert lines[3] == "interrupted", (done.stdout, done.stderr)
    elapsed = float(lines[4])
    # Stopped promptly after the signal at full / 2, well before the call would have ended.
    assert 0.4 * full <= elapsed < 0.8 * full, (full, elapsed)
    assert lines[5] == "cpu", done.stdout
    assert float(lines[6]) < 0.2, f"the interrupted work ran on: {done.stdout}"
    # 6 x 4 torus: 48 triangles, 24 quads, all paired.
    assert lines[7:] == ["after", "24", "100.0"], done.stdout
