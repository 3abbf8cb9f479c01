"""frictionlab.accuracy: the study's values are the laws' values on its grid."""

import numpy as np
import pytest

import frictionlab
from conftest import run_cli

GRID = dict(s_points=12, mu_points=4, psi_points=5)


def test_values_are_the_laws_at_the_grid_contacts():
    study = frictionlab.accuracy(["pade-printed", "coulomb-decoupled"], **GRID)
    assert study.reference == "exact" and study.laws == ["pade-printed", "coulomb-decoupled"]
    assert study.s[0] == 1e-3 and study.s[-1] == 1e3 and len(study.s) == 12
    assert study.mu[0] == 0.05 and study.mu[-1] == 1.0
    assert study.psi[0] == 0.0 and study.psi[2] == np.pi / 2 and study.psi[-1] == np.pi
    np.testing.assert_array_equal(study.sign, [-1, 1])
    s, mu, psi, sign = study.grid()
    # The grid's contacts: a = 1 m, b = mu m, U = s m/s, Omega = sign 1/s, N = 1 N, k = 1.
    for law in ["exact", "pade-printed", "coulomb-decoupled"]:
        F1, F2, M = frictionlab.Law(law)(s, sign, 1.0, mu, psi, 1.0, 1.0)
        values = study.values[law]
        assert values["F1"].shape == (4, 5, 2, 12)
        np.testing.assert_array_equal(values["F1"], F1)
        np.testing.assert_array_equal(values["F2"], F2)
        np.testing.assert_array_equal(values["M"], M)


def test_error_statistics_are_those_of_the_arrays():
    study = frictionlab.accuracy("pade-printed", **GRID)
    for c in ("F1", "F2", "M"):
        err = np.abs(study.error("pade-printed", c)).ravel()
        stats = study.errors["pade-printed"][c]
        assert stats["max_abs"] == err.max()
        assert stats["rms"] == pytest.approx(np.sqrt(np.mean(err ** 2)), rel=1e-12)
        assert stats["finite"] == err.size and stats["nonfinite"] == 0
        # Nearest-rank quantiles: the ceil(q n)-th smallest.
        ranked = np.sort(err)
        assert stats["median_abs"] == ranked[int(np.ceil(0.5 * err.size)) - 1]
        assert stats["p95_abs"] == ranked[int(np.ceil(0.95 * err.size)) - 1]


def test_default_laws_and_errors(cli, tmp_path):
    study = frictionlab.accuracy(s_points=3, mu_points=2, psi_points=3)
    expected = [i["name"] for i in frictionlab.laws() if not i["reference"] and not i["slow"]]
    assert study.laws == expected
    done = run_cli(cli, "accuracy", "--out", tmp_path, "--psi-points", 4, "--no-plots", check=False)
    message = done.stderr.removeprefix("frictionlab: error: ").strip()
    with pytest.raises(ValueError) as e:
        frictionlab.accuracy(psi_points=4)
    assert str(e.value) == message
    with pytest.raises(ValueError, match="unknown friction law 'nope'"):
        frictionlab.accuracy("nope", **GRID)
    with pytest.raises(ValueError, match="s_points"):
        frictionlab.accuracy(s_points=-1)
