"""No growth of memory over 1e5 calls."""

import gc
import tracemalloc

import numpy as np

import frictionlab


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_no_growth_over_1e5_calls():
    law = frictionlab.Law("coulomb-decoupled")
    array = np.linspace(0.0, 1.0, 16)
    bad = np.array([1.0, -1.0])

    def calls(n):
        for i in range(n):
            law(1.0, 2.0, 0.01, 0.005, 0.3, 10.0, 0.2)
            if i % 10 == 0:
                law(array, 2.0, 0.01, 0.005, 0.3, 10.0, 0.2)
            if i % 100 == 0:
                try:
                    law(bad, 2.0, 0.01, 0.005, 0.3, 10.0, 0.2)
                except ValueError:
                    pass

    calls(10_000)  # warm up: caches, interned strings, the allocator's pools
    gc.collect()
    tracemalloc.start()
    rss0 = rss_bytes()
    before = tracemalloc.get_traced_memory()[0]
    calls(100_000)
    gc.collect()
    after = tracemalloc.get_traced_memory()[0]
    rss1 = rss_bytes()
    tracemalloc.stop()
    # A leak of one result per call would be >= 100 bytes x 1e5 = 10 MB; allow 1 MB of noise.
    assert after - before < 100_000, f"Python heap grew by {after - before} bytes"
    assert rss1 - rss0 < 1_000_000, f"resident memory grew by {rss1 - rss0} bytes"
