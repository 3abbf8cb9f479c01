// frictionlab.Law and frictionlab.laws(): the registry's laws, evaluated over NumPy arrays.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

#include "arguments.h"
#include "bindings.h"
#include "broadcast.h"
#include "friction/registry.h"

namespace frictionlab::python {
namespace {

// A law made from a spec, and what the registry says of it.
class Law {
 public:
  explicit Law(const std::string& spec) : spec_(spec), law_(friction::make_law(spec)), info_(friction::law_info(spec)) {}

  [[nodiscard]] const std::string& spec() const { return spec_; }
  [[nodiscard]] std::string name() const { return std::string(law_->name()); }
  [[nodiscard]] const friction::LawInfo& info() const { return info_; }
  [[nodiscard]] const friction::FrictionLaw& law() const { return *law_; }

 private:
  std::string spec_;
  std::unique_ptr<friction::FrictionLaw> law_;
  friction::LawInfo info_;
};

py::object as_result(py::array_t<double>& a, bool scalar) {
  if (scalar) return py::float_(*a.data());
  return std::move(a);
}

// Scalar inputs (Python floats and ints, NumPy float64 scalars) skip the arrays: one contact, the
// same evaluate(), Python floats out. Returns false if an input is anything else.
bool call_scalar(const Law& law, const std::array<py::handle, 7>& inputs, py::tuple& out) {
  std::array<double, 7> v{};
  for (std::size_t i = 0; i < 7; ++i) {
    PyObject* o = inputs[i].ptr();
    if (!PyFloat_Check(o) && !PyLong_Check(o)) return false;
    v[i] = PyFloat_AsDouble(o);
    if (v[i] == -1.0 && PyErr_Occurred()) {  // an int too large for a double: let NumPy say so
      PyErr_Clear();
      return false;
    }
  }
  const friction::ContactInput c{v[0], v[1], v[2], v[3], v[4], v[5], v[6]};
  friction::FrictionForces f;
  {
    const py::gil_scoped_release release;
    f = law.law().evaluate(c);  // std::invalid_argument becomes ValueError, with the same message
  }
  out = py::make_tuple(f.F1, f.F2, f.M);
  return true;
}

// law(U, Omega, a, b, psi, N, k), bound by hand (arguments.h) so that a missing or misspelled
// argument is named as Python names it.
py::tuple call(const Law& law, const py::args& args, const py::kwargs& kwargs) {
  const std::array<py::handle, 7> inputs = bind_arguments("Law.__call__", kInputNames, args, kwargs);
  py::tuple scalar_result;
  if (call_scalar(law, inputs, scalar_result)) return scalar_result;
  const BroadcastInputs in = broadcast_inputs(inputs);
  py::array_t<double> F1(in.shape), F2(in.shape), M(in.shape);
  double* f1 = F1.mutable_data();
  double* f2 = F2.mutable_data();
  double* m = M.mutable_data();
  std::optional<ElementError> error;
  {
    const py::gil_scoped_release release;
    error = evaluate_all(law.law(), in, f1, f2, m);
  }
  if (error) {
    const std::string where = element_name(error->index, in.shape);
    const std::string message = (where.empty() ? "" : "element " + where + ": ") + error->message;
    if (error->invalid_input) throw py::value_error(message);
    throw std::runtime_error(message);
  }
  const bool scalar = in.shape.empty();
  return py::make_tuple(as_result(F1, scalar), as_result(F2, scalar), as_result(M, scalar));
}

py::dict parameter_dict(const friction::LawParameter& p) {
  py::dict d;
  d["key"] = p.key;
  d["kind"] = p.kind == friction::LawParameter::Kind::choice ? "choice" : "number";
  if (p.kind == friction::LawParameter::Kind::choice) {
    d["choices"] = p.choices;
  } else {
    d["min"] = p.min;
    d["max"] = p.max;
    d["unit"] = p.unit;
  }
  d["default"] = p.default_value.empty() ? py::object(py::none()) : py::object(py::str(p.default_value));
  d["rule"] = p.rule();
  d["doc"] = p.doc;
  return d;
}

py::dict info_dict(const friction::LawInfo& info) {
  py::dict d;
  d["name"] = info.name;
  d["summary"] = info.summary;
  d["reference"] = info.reference;
  d["slow"] = info.slow;
  d["has_poles"] = info.has_poles;
  py::list parameters;
  for (const auto& p : info.parameters) parameters.append(parameter_dict(p));
  d["parameters"] = parameters;
  py::dict aliases;
  for (const auto& a : info.aliases) aliases[py::str(a.name)] = a.spec;
  d["aliases"] = aliases;
  return d;
}

// Law(spec), bound by hand like __call__.
Law make_law(const py::args& args, const py::kwargs& kwargs) {
  const auto [spec] = bind_arguments("Law.__init__", std::array<const char*, 1>{"spec"}, args, kwargs);
  if (!py::isinstance<py::str>(spec)) {
    throw py::type_error("Law() argument 'spec' must be str, not " + std::string(py::str(spec.get_type().attr("__name__"))));
  }
  return Law(spec.cast<std::string>());
}

}  // namespace

void bind_laws(py::module_& m) {
  m.def(
      "laws", [] {
        py::list out;
        for (const auto& info : friction::list_laws()) out.append(info_dict(info));
        return out;
      },
      R"doc(laws() -> list[dict]

Every registered friction law, in the registry's order (the reference law, ``exact``, first).
Each entry is a dict with keys ``name`` (str, the spec to pass to :class:`Law`), ``summary``
(one line: what the law is, its source and accuracy), ``reference`` (bool: the law every other
law is measured against), ``slow`` (bool: milliseconds per call, a cross-check rather than a law
for simulations), ``has_poles`` (bool: the law has denominators that can vanish) and
``parameters``: what a spec ``NAME:KEY=VALUE[,KEY=VALUE]`` may set, each a dict with ``key``,
``kind`` ("choice" with ``choices``, or "number" with ``min``, ``max`` and its SI ``unit``),
``default`` (str or None), ``rule`` and ``doc``; ``aliases``: the law's other names, a dict from
each alias to the spec it stands for (e.g. ``{"moller-ellipsoidal": "ellipsoidal"}``): an alias
works wherever a spec does and is not listed as a law of its own. Laws registered with
register_law() come last.)doc");

  m.def(
      "law_specs", [] { return friction::list_law_specs(); },
      R"doc(law_specs() -> list[str]

Every registered law by name, each followed by its variants: the specs that set one choice
parameter to a value other than its default (e.g. ``"exact:pressure=uniform"``).)doc");

  // The docstrings of Law and its methods begin with their signatures; pybind11's own would say
  // "*args, **kwargs" (they are bound by hand).
  py::options options;
  options.disable_function_signatures();
  py::class_<Law>(m, "Law", R"doc(Law(spec)

A law of coupled dry friction (sliding + spinning) over an elliptic Hertz contact patch.

``spec`` names a registered law or an alias of one (see :func:`laws`), e.g. ``"exact"``,
``"pade-printed"``, ``"decoupled"``, optionally with parameters, ``"NAME:KEY=VALUE[,KEY=VALUE]"`` (e.g.
``"exact:pressure=uniform"``; docs/extending.md); an unknown name, key or value raises
ValueError naming it and what is allowed.

Calling the law, ``law(U, Omega, a, b, psi, N, k)``, returns ``(F1, F2, M)``. SI units:

========  =====  ==========================================================================
``U``     m/s    slip speed of the patch centre, >= 0
``Omega`` 1/s    spin about the upward normal, either sign
``a``     m      major semi-axis of the patch, > 0
``b``     m      minor semi-axis of the patch, 0 < b <= a
``psi``   rad    angle from the slip direction e1 to the major axis, counter-clockwise
``N``     N      normal force, >= 0
``k``     1      Coulomb friction coefficient, >= 0
========  =====  ==========================================================================

The friction force on the body is ``-F1 e1 - F2 e2`` (N) and the torque about the patch centre
``-M gamma`` (N m), e1 the slip direction, gamma the upward normal, e2 = gamma x e1
(docs/model.md).

Each input is a number or an array; they broadcast together like NumPy's (``U`` an array of
shape (n,), ``Omega`` of shape (m, 1), the rest scalars: the results have shape (m, n)). With
array input the results are float64 arrays of the broadcast shape (C order); with scalars only,
Python floats. Every element is evaluated by the same C++ function as ``frictionlab friction``,
so the results are the command line's to the last bit. The GIL is released while the law runs:
several Python threads may evaluate laws at once.

An element outside the law's domain raises ValueError naming the element and the rule, e.g.
``element [3]: friction input U = -1 is invalid: the slip speed must be >= 0 m/s ...``; no
result is returned then.)doc")
      .def(py::init(&make_law))
      .def("__call__", &call,
           R"doc(__call__(U, Omega, a, b, psi, N, k) -> (F1, F2, M)

Evaluates the law. Inputs in SI units (U m/s, Omega 1/s, a and b m, psi rad, N in newtons, k
dimensionless), numbers or arrays broadcast together; returns F1 and F2 in newtons and M in
newton metres, arrays of the broadcast shape (floats for scalar input). ValueError names the
first element the law rejects and the rule it breaks; TypeError names an input that is not real
numbers (complex numbers, None, words) and an argument missing or unknown, as Python does.)doc")
      .def_property_readonly("spec", &Law::spec, "The spec the law was made from, verbatim (str).")
      .def_property_readonly("name", &Law::name, "The registered name of the law (str).")
      .def_property_readonly(
          "summary", [](const Law& l) { return l.info().summary; }, "One line: what the law is and where it comes from.")
      .def_property_readonly(
          "reference", [](const Law& l) { return l.info().reference; },
          "True for the law every other law is measured against (exact).")
      .def_property_readonly(
          "slow", [](const Law& l) { return l.info().slow; },
          "True if a call takes milliseconds (a cross-check, not a law for simulations).")
      .def_property_readonly(
          "has_poles", [](const Law& l) { return l.info().has_poles; },
          "True if the law has denominators that can vanish at valid input (its poles).")
      .def("__repr__", [](const Law& l) { return "frictionlab.Law(" + std::string(py::repr(py::str(l.spec()))) + ")"; });
}

}  // namespace frictionlab::python
