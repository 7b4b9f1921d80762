"""The GIL is released while the libraries compute: another Python thread keeps running."""

from __future__ import annotations

import threading
import time

import surftopo


def test_other_threads_run_during_a_long_call():
    # About three million flips (T_300 refined 100 x 100): most of a second in Rust, with almost
    # no Python work around it.
    portalgon = surftopo.flat_torus(300.0, 100)
    span = {}

    def work():
        span["start"] = time.perf_counter()
        span["flips"] = surftopo.intrinsic_delaunay(portalgon).flips
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    last = time.perf_counter()
    longest_gap = 0.0
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        longest_gap = max(longest_gap, now - last)
        last = now
    worker.join()
    duration = span["end"] - span["start"]
    assert span["flips"] == 299 * 100 * 100
    # Holding the GIL would stall this loop for the whole call.
    assert longest_gap < 0.4 * duration, (longest_gap, duration)
