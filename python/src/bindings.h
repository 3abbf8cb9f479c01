#pragma once
// The parts of the extension module frictionlab._core (python/src/module.cpp assembles them).

#include <pybind11/pybind11.h>

namespace frictionlab::python {

namespace py = pybind11;

void bind_laws(py::module_& m);      ///< laws(), Law
void bind_simulate(py::module_& m);  ///< _run_scenario
void bind_accuracy(py::module_& m);  ///< _accuracy
void bind_python_laws(py::module_& m);  ///< _register_law, _unregister_law
void bind_ensemble(py::module_& m);  ///< _run_ensemble

}  // namespace frictionlab::python
