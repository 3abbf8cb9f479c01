"""frictionlab.Law: every law equals the command line bit for bit; broadcasting; errors."""

import os

import numpy as np
import pytest

import frictionlab
from conftest import bits, read_csv_columns, run_cli

INPUTS = ("U", "Omega", "a", "b", "psi", "N", "k")


def random_contacts(n, seed):
    """Contacts over the laws' domain, with the special values 0 (U, Omega, N) and b = a."""
    rng = np.random.default_rng(seed)
    a = 10.0 ** rng.uniform(-4, -1, n)
    c = {
        "U": 10.0 ** rng.uniform(-4, 1, n),
        "Omega": rng.choice([-1, 1], n) * 10.0 ** rng.uniform(-2, 3, n),
        "a": a,
        "b": a * rng.uniform(0.05, 1.0, n),
        "psi": rng.uniform(-4, 4, n),
        "N": 10.0 ** rng.uniform(-1, 3, n),
        "k": rng.uniform(0, 1, n),
    }
    c["U"][:3] = 0.0
    c["Omega"][3:6] = 0.0
    c["N"][6] = 0.0
    c["b"][7] = c["a"][7]
    return c


def cli_forces(cli, tmp_path, law, contacts):
    path = tmp_path / "contacts.csv"
    n = len(contacts["U"])
    with open(path, "w") as f:
        f.write(",".join(INPUTS) + "\n")
        for i in range(n):
            f.write(",".join(repr(float(contacts[k][i])) for k in INPUTS) + "\n")
    out = tmp_path / "forces.csv"
    done = run_cli(cli, "friction", "--law", law, str(path))
    out.write_text(done.stdout)
    cols = read_csv_columns(out)
    for k in INPUTS:  # the command read the same inputs
        np.testing.assert_array_equal(bits(cols[k]), bits(contacts[k]))
    assert cols["law"] == [law] * n
    return cols["F1"], cols["F2"], cols["M"]


@pytest.mark.parametrize("law", frictionlab.law_specs())
def test_every_law_equals_the_command_line_bit_for_bit(cli, tmp_path, law):
    slow = frictionlab.Law(law).slow
    contacts = random_contacts(8 if slow else 400, seed=7)
    expected = cli_forces(cli, tmp_path, law, contacts)
    got = frictionlab.Law(law)(*(contacts[k] for k in INPUTS))
    for e, g in zip(expected, got):
        assert g.dtype == np.float64 and g.shape == e.shape
        # The command writes a zero as "0" whatever its sign (no "-0" in a table): + 0.0 drops the
        # sign of a zero and changes nothing else.
        np.testing.assert_array_equal(bits(g + 0.0), bits(e))


def test_laws_lists_the_registry_with_summaries(cli):
    # `frictionlab laws`: a heading, then one line per law, its parameters indented below it.
    listed = [line for line in run_cli(cli, "laws").stdout.splitlines()[1:] if not line.startswith(" ")]
    infos = frictionlab.laws()
    assert [line.split()[0] for line in listed] == [i["name"] for i in infos]
    for line, info in zip(listed, infos):
        assert line.split(None, 1)[1].strip() == info["summary"]
    assert [i["name"] for i in infos if i["reference"]] == ["exact"]
    law = frictionlab.Law("exact")
    assert (law.name, law.spec, law.reference, law.has_poles) == ("exact", "exact", True, False)
    assert frictionlab.Law("pade-printed").has_poles
    # An alias is listed with its law, not as a law; it makes that law and keeps the spec as given.
    names = [i["name"] for i in infos]
    assert "moller-ellipsoidal" not in names and "coulomb-decoupled" not in names
    assert infos[names.index("ellipsoidal")]["aliases"] == {"moller-ellipsoidal": "ellipsoidal"}
    alias = frictionlab.Law("coulomb-decoupled")
    assert (alias.name, alias.spec) == ("decoupled", "coulomb-decoupled")
    # Variants are specs of the listed laws with one choice parameter set.
    names = [i["name"] for i in infos]
    specs = frictionlab.law_specs()
    assert [s for s in specs if ":" not in s] == names
    for spec in specs:
        if ":" in spec:
            name, setting = spec.split(":")
            key, value = setting.split("=")
            (param,) = [p for p in infos[names.index(name)]["parameters"] if p["key"] == key]
            assert param["kind"] == "choice" and value in param["choices"] and value != param["default"]
            assert frictionlab.Law(spec).spec == spec and frictionlab.Law(spec).name == name


def test_broadcasting_follows_numpy():
    law = frictionlab.Law("exact")
    U = np.linspace(0.0, 2.0, 5)                 # (5,)
    Omega = np.array([[-3.0], [0.5], [4.0]])     # (3, 1)
    F1, F2, M = law(U, Omega, 0.01, 0.006, 0.4, 9.81, 0.3)
    assert F1.shape == F2.shape == M.shape == (3, 5)
    for i in range(3):
        for j in range(5):
            one = law(float(U[j]), float(Omega[i, 0]), 0.01, 0.006, 0.4, 9.81, 0.3)
            assert (F1[i, j], F2[i, j], M[i, j]) == one
    # Shapes as NumPy broadcasts them, including empty and higher-dimensional ones.
    for shapes in [((2, 1, 4), (3, 1)), ((0,), ()), ((1,), (6,)), ((2, 3), (2, 3))]:
        a, b = np.ones(shapes[0]), np.ones(shapes[1])
        F1, _, _ = law(a, b, 1.0, 0.5, 0.0, 1.0, 1.0)
        assert F1.shape == np.broadcast(a, b).shape


def test_scalars_give_floats_and_inputs_convert_like_numpy():
    law = frictionlab.Law("coulomb-decoupled")
    f = law(1, 2, 0.01, 0.005, 0.3, 10, 0.2)  # Python ints
    assert all(type(x) is float for x in f)
    assert law(np.float32(1), 2, 0.01, 0.005, 0.3, 10, 0.2) == law(float(np.float32(1)), 2.0, 0.01, 0.005, 0.3, 10.0, 0.2)
    assert law(np.array(1.0), 2, 0.01, 0.005, 0.3, 10, 0.2) == f  # 0-d arrays are scalars
    lists = law([1, 2], [2, 2], 0.01, 0.005, 0.3, 10, 0.2)
    assert lists[0].shape == (2,)


def test_strided_and_transposed_inputs_are_read_where_they_are():
    law = frictionlab.Law("exact")
    base = np.linspace(0.0, 1.0, 24).reshape(4, 6)
    views = [base[:, ::2], base.T, base[::-1, 1:5]]
    for v in views:
        got = law(v, 1.5, 0.02, 0.01, 0.3, 2.0, 0.4)
        copy = law(np.ascontiguousarray(v), 1.5, 0.02, 0.01, 0.3, 2.0, 0.4)
        for g, c in zip(got, copy):
            assert g.flags.c_contiguous and g.shape == v.shape
            np.testing.assert_array_equal(bits(g), bits(c))


def test_bad_element_is_a_value_error_with_the_command_lines_message(cli, tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("U,Omega,a,b,psi,N,k\n1,2,0.01,0.005,0.3,10,0.2\n1,2,0.01,0.02,0.3,10,0.2\n")
    done = run_cli(cli, "friction", str(path), check=False)
    assert done.returncode == 1
    prefix = "frictionlab: error: input line 3: "
    assert done.stderr.startswith(prefix)
    cli_message = done.stderr[len(prefix):].strip()

    law = frictionlab.Law("exact")
    b = np.array([[0.005, 0.005], [0.005, 0.02]])  # element [1, 1] has b > a
    with pytest.raises(ValueError) as e:
        law(1.0, 2.0, 0.01, b, 0.3, 10.0, 0.2)
    assert str(e.value) == "element [1, 1]: " + cli_message
    with pytest.raises(ValueError) as e:
        law(1.0, 2.0, 0.01, 0.02, 0.3, 10.0, 0.2)
    assert str(e.value) == cli_message  # a scalar call names no element
    with pytest.raises(ValueError, match=r"element \[2\]: friction input U = nan is invalid"):
        law(np.array([0.0, 1.0, np.nan]), 1.0, 1.0, 1.0, 0.0, 1.0, 1.0)


def test_other_errors():
    law = frictionlab.Law("exact")
    with pytest.raises(ValueError, match="could not be broadcast"):
        law(np.zeros(3), np.zeros(4), 1.0, 1.0, 0.0, 1.0, 1.0)
    with pytest.raises(TypeError, match="friction input Omega"):
        law(1.0, "fast", 1.0, 1.0, 0.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="unknown friction law 'nope'.*exact"):
        frictionlab.Law("nope")
    with pytest.raises(ValueError, match="exact has no parameter 'n'"):
        frictionlab.Law("exact:n=1")
    with pytest.raises(TypeError):
        law(1.0, 1.0)


def test_help_states_units():
    doc = frictionlab.Law.__doc__ + frictionlab.Law.__call__.__doc__
    for text in ("m/s", "1/s", "rad", "N m", "broadcast", "ValueError", "GIL"):
        assert text in doc
    for f in (frictionlab.laws, frictionlab.simulate, frictionlab.accuracy):
        assert f.__doc__ and len(f.__doc__) > 200


def test_version_is_the_projects():
    import re
    cmakelists = os.path.join(os.environ["FRICTIONLAB_DATA_DIR"], "..", "CMakeLists.txt")
    with open(cmakelists) as f:
        version = re.search(r"project\(frictionlab VERSION ([0-9.]+)", f.read()).group(1)
    assert frictionlab.__version__ == version
