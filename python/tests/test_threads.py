"""Laws evaluated from several Python threads at once, with the GIL released."""

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import frictionlab


def contacts(n, seed):
    rng = np.random.default_rng(seed)
    return (rng.uniform(0, 2, n), rng.uniform(-5, 5, n), np.full(n, 0.01), rng.uniform(0.001, 0.01, n),
            rng.uniform(0, 3, n), rng.uniform(0, 20, n), np.full(n, 0.3))


def test_threads_at_once_give_the_serial_results():
    laws = [frictionlab.Law(n) for n in ("exact", "pade-printed-minor", "moller-ellipsoidal", "coulomb-decoupled")]
    jobs = [(law, contacts(3000, seed)) for seed in range(4) for law in laws]
    serial = [law(*c) for law, c in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(lambda job: job[0](*job[1]), jobs))
    for s, p in zip(serial, parallel):
        for a, b in zip(s, p):
            np.testing.assert_array_equal(a, b)


def test_the_gil_is_released_during_evaluation():
    # A call that holds the GIL lets no other Python thread run until it returns. The main thread
    # sleeps 50 ms while a worker evaluates for much longer; it wakes while the worker is still in
    # the call only if the call released the GIL.
    law = frictionlab.Law("exact")
    c = contacts(2000, 1)
    t0 = time.perf_counter()
    law(*c)
    per_element = (time.perf_counter() - t0) / 2000
    n = int(min(4e6, max(2000, 1.0 / per_element)))  # about one second of evaluation
    big = contacts(n, 2)
    started, times = threading.Event(), {}

    def work():
        started.set()
        law(*big)
        times["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    time.sleep(0.05)
    woke = time.perf_counter()
    worker.join()
    assert times["end"] - woke > 0.2, "the main thread could not run while the law was evaluated"
