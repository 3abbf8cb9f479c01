"""frictionlab.register_law: a law written in Python, used like a built-in one.

The Python law here implements the formula of coulomb-decoupled (friction/coulomb_decoupled_law.h):
F1 = kN if U > 0 else 0, F2 = 0, M = M0 sign(Omega) with M0 = (3/8) k N a E(e), e^2 = 1 - (b/a)^2,
E the complete elliptic integral of the second kind, here by the arithmetic-geometric mean
(Abramowitz & Stegun 17.6) instead of Boost's Carlson forms: E may differ in the last bits, so M
is compared to 1e-14 relative (the law's declared tolerance) and F1, F2 bit for bit.
"""

import math
import os
import threading

import numpy as np
import pytest

import frictionlab

NAME = "py-coulomb"


def ellipe(e):
    """E(e), modulus e in [0, 1): AGM, A&S 17.6.3-4."""
    a, b, c = 1.0, math.sqrt((1.0 - e) * (1.0 + e)), e
    total, power = c * c / 2.0, 0.5
    while abs(c) > 1e-15 * a:  # quadratic convergence: the next term is below 1e-30
        a, b, c = (a + b) / 2.0, math.sqrt(a * b), (a - b) / 2.0
        power *= 2.0
        total += power * c * c
    return math.pi / (2.0 * a) * (1.0 - total)


def coulomb(U, Omega, a, b, psi, N, k):
    F0 = k * N
    if F0 == 0.0:
        return 0.0, 0.0, 0.0
    F1 = F0 if U > 0.0 else 0.0
    M = 0.0
    if Omega != 0.0:
        mu = b / a
        e = math.sqrt((1.0 - mu) * (1.0 + mu))
        M = math.copysign(3.0 / 8.0 * F0 * a * ellipe(e), Omega)
    return F1, 0.0, M


@pytest.fixture(autouse=True)
def registered():
    frictionlab.register_law(NAME, coulomb, summary="decoupled Coulomb, in Python")
    yield
    assert frictionlab.unregister_law(NAME)


def contacts(n, seed=3):
    rng = np.random.default_rng(seed)
    a = 10.0 ** rng.uniform(-3, -1, n)
    c = [rng.uniform(0, 2, n), rng.uniform(-50, 50, n), a, a * rng.uniform(0.05, 1, n), rng.uniform(0, 3, n),
         rng.uniform(0, 20, n), rng.uniform(0, 1, n)]
    c[0][:5] = 0.0
    c[1][5:10] = 0.0
    return c


def test_reproduces_coulomb_decoupled():
    c = contacts(2000)
    F1, F2, M = frictionlab.Law(NAME)(*c)
    G1, G2, GM = frictionlab.Law("coulomb-decoupled")(*c)
    np.testing.assert_array_equal(F1, G1)
    np.testing.assert_array_equal(F2, G2)
    np.testing.assert_allclose(M, GM, rtol=1e-14, atol=0)
    assert np.count_nonzero(M) > 1900  # the moment was compared, not zeros


def test_listed_and_known_by_name():
    info = [i for i in frictionlab.laws() if i["name"] == NAME]
    assert info and info[0]["summary"] == "decoupled Coulomb, in Python"
    assert not info[0]["reference"] and not info[0]["slow"]
    assert frictionlab.Law(NAME).name == NAME


def test_simulate_with_it_equals_coulomb_decoupled(scenarios):
    # Without spin (Omega stays exactly 0 for the sliding sphere) the two laws compute the same
    # numbers by the same operations: the runs agree bit for bit.
    path = os.path.join(scenarios, "sphere-sliding.toml")
    ours = frictionlab.simulate(path, law=NAME)
    theirs = frictionlab.simulate(path, law="coulomb-decoupled")
    assert ours.summary["law"] == NAME and ours.reason == theirs.reason == "rolling"
    for name, column in theirs.trajectory.items():
        np.testing.assert_array_equal(ours.trajectory[name], column, err_msg=name)
    # With spin, M differs in its last bits: the spinning sphere's runs agree to rounding.
    path = os.path.join(scenarios, "sphere-spinning.toml")
    ours = frictionlab.simulate(path, law=NAME, overrides={"run.t_end": 0.5})
    theirs = frictionlab.simulate(path, law="coulomb-decoupled", overrides={"run.t_end": 0.5})
    np.testing.assert_array_equal(ours.t, theirs.t)
    np.testing.assert_allclose(ours["Omega"], theirs["Omega"], rtol=1e-12)


def test_accuracy_compares_it_with_exact():
    study = frictionlab.accuracy([NAME, "coulomb-decoupled"], s_points=10, mu_points=3, psi_points=5, threads=2)
    assert study.laws == [NAME, "coulomb-decoupled"]
    np.testing.assert_array_equal(study.values[NAME]["F1"], study.values["coulomb-decoupled"]["F1"])
    np.testing.assert_allclose(study.values[NAME]["M"], study.values["coulomb-decoupled"]["M"], rtol=1e-14)
    for c in ("F1", "F2", "M"):
        assert study.errors[NAME][c]["max_abs"] == pytest.approx(
            study.errors["coulomb-decoupled"][c]["max_abs"], rel=1e-12, abs=1e-15)


def test_several_threads_share_it():
    law = frictionlab.Law(NAME)
    c = contacts(500)
    expected = law(*c)
    results = [None] * 4

    def work(i):
        results[i] = law(*c)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        for a, b in zip(r, expected):
            np.testing.assert_array_equal(a, b)


def test_its_errors_reach_the_caller(scenarios):
    def picky(U, Omega, a, b, psi, N, k):
        if 0.0 < U < 1.0:
            raise ValueError(f"U = {U} is too slow for this law")
        return coulomb(U, Omega, a, b, psi, N, k)

    frictionlab.register_law("py-picky", picky, summary="refuses 0 < U < 1 m/s")
    frictionlab.register_law("py-broken", lambda *x: (1.0, 2.0), summary="returns two values")
    frictionlab.register_law("py-nan", lambda *x: (float("nan"), 0.0, 0.0), summary="returns nan")
    try:
        with pytest.raises(ValueError, match=r"^element \[2\]: U = 0.5 is too slow for this law$"):
            frictionlab.Law("py-picky")(np.array([1.5, 2.0, 0.5]), 1.0, 1.0, 1.0, 0.0, 1.0, 1.0)
        with pytest.raises(RuntimeError, match="returned 2 values"):
            frictionlab.Law("py-broken")(1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0)
        with pytest.raises(RuntimeError, match="returned F1 = nan"):
            frictionlab.Law("py-nan")(1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0)
        # Input is checked before the law sees it, as for every law.
        with pytest.raises(ValueError, match="friction input U = -1 is invalid"):
            frictionlab.Law("py-picky")(-1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0)
        # In a simulation (the sliding sphere slows from 2 m/s), the law's refusal ends the run
        # with reason law-error.
        run = frictionlab.simulate(os.path.join(scenarios, "sphere-sliding.toml"), law="py-picky")
        assert run.reason == "law-error"
        assert "too slow" in run.summary["termination"]["message"]
    finally:
        for name in ("py-picky", "py-broken", "py-nan"):
            frictionlab.unregister_law(name)


def test_registration_errors():
    with pytest.raises(ValueError, match="exact"):
        frictionlab.register_law("exact", coulomb, summary="taken")
    with pytest.raises(ValueError):
        frictionlab.register_law(NAME, coulomb, summary="twice")
    with pytest.raises(TypeError, match="not callable"):
        frictionlab.register_law("py-x", 3.0, summary="not a function")
    assert not frictionlab.unregister_law("py-never-registered")
    with pytest.raises(ValueError):
        frictionlab.unregister_law("exact")
