// The extension module frictionlab._core; the package frictionlab (python/frictionlab/) is its
// public face (docs/python.md).

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "friction/support/checked_output.h"
#include "friction/reference_laws.h"

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  m.doc() = "frictionlab's compiled core; use the package frictionlab (docs/python.md).";
  frictionlab::friction::register_reference_laws();  // exact-reference (GSL), as in the command
  // A file that cannot be written is an OSError in Python, as a failed open() would be.
  // Exported as frictionlab.OutputError (python/frictionlab/__init__.py), and named so.
  auto output_error = py::register_exception<frictionlab::support::OutputError>(m, "OutputError", PyExc_OSError);
  output_error.attr("__module__") = "frictionlab";
  output_error.doc() = "A file or folder of the results could not be written (an OSError); the message names it "
                       "and the system's reason, as the command line's one line does.";
  frictionlab::python::bind_laws(m);
  frictionlab::python::bind_simulate(m);
  frictionlab::python::bind_accuracy(m);
  frictionlab::python::bind_python_laws(m);
  frictionlab::python::bind_ensemble(m);
}
