// frictionlab.register_law: a law written in Python, f(U, Omega, a, b, psi, N, k) -> (F1, F2, M),
// added to the C++ registry (friction/registry.h, register_law) so that every user of laws by
// name (Law(spec), simulations, the accuracy study, the command's code paths) can use it.
//
// The law calls back into Python with the GIL taken for each contact; it may be called from any
// thread (the accuracy study's workers, several Python threads): calls are then serialised by
// the GIL. What f raises becomes the law's error: ValueError a std::invalid_argument (input
// outside the law's domain: a Python ValueError again for Law(), law-error in a simulation),
// anything else a std::runtime_error.

#include <pybind11/pybind11.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "bindings.h"
#include "friction/registry.h"

namespace frictionlab::python {
namespace {

// The Python callable, shared by every instance of the law. Dropped with the GIL while Python
// runs; leaked if the interpreter is gone (a registry destroyed at process exit).
struct Callable {
  explicit Callable(py::object function) : f(std::move(function)) {}
  Callable(const Callable&) = delete;
  Callable& operator=(const Callable&) = delete;
  ~Callable() {
    if (Py_IsInitialized() != 0) {
      const py::gil_scoped_acquire gil;
      f = py::object();
    } else {
      (void)f.release();
    }
  }
  py::object f;
};

std::string contact_text(const friction::ContactInput& in) {
  std::ostringstream m;
  m.precision(17);
  m << "U = " << in.U << ", Omega = " << in.Omega << ", a = " << in.a << ", b = " << in.b << ", psi = " << in.psi.radians()
    << ", N = " << in.N << ", k = " << in.k;
  return m.str();
}

class PythonLaw final : public friction::FrictionLaw {
 public:
  PythonLaw(std::string name, std::string summary, std::shared_ptr<const Callable> f)
      : name_(std::move(name)), summary_(std::move(summary)), f_(std::move(f)) {}
  [[nodiscard]] std::string_view name() const override { return name_; }
  [[nodiscard]] std::string_view summary() const override { return summary_; }

 private:
  [[nodiscard]] friction::FrictionForces do_evaluate(const friction::ContactInput& in) const override {
    friction::FrictionForces out;
    std::string error;
    bool invalid = false;
    {
      const py::gil_scoped_acquire gil;
      try {
        const py::tuple r = py::tuple(f_->f(in.U, in.Omega, in.a, in.b, in.psi.radians(), in.N, in.k));
        if (r.size() != 3) {
          error = "law '" + name_ + "' returned " + std::to_string(r.size()) + " values: it must return (F1, F2, M)";
        } else {
          out = {r[0].cast<double>(), r[1].cast<double>(), r[2].cast<double>()};
        }
      } catch (py::error_already_set& e) {
        // Ctrl-C inside the law: raised again at Python's next look at its signals.
        if (e.matches(PyExc_KeyboardInterrupt)) PyErr_SetInterrupt();
        invalid = e.matches(PyExc_ValueError);
        error = invalid ? std::string(py::str(e.value())) : "law '" + name_ + "': " + e.what();
      } catch (const py::cast_error& e) {
        error = "law '" + name_ + "' returned something other than three numbers (F1, F2, M): " + e.what();
      }
    }
    if (!error.empty()) {
      if (invalid) throw std::invalid_argument(error);
      throw std::runtime_error(error);
    }
    if (!std::isfinite(out.F1) || !std::isfinite(out.F2) || !std::isfinite(out.M)) {
      std::ostringstream m;
      m.precision(17);
      m << "law '" << name_ << "' returned F1 = " << out.F1 << ", F2 = " << out.F2 << ", M = " << out.M << " at "
        << contact_text(in) << ": a law must return finite values (or raise ValueError)";
      throw std::runtime_error(m.str());
    }
    return out;
  }

  std::string name_;
  std::string summary_;
  std::shared_ptr<const Callable> f_;
};

void register_python_law(const std::string& name, py::object f, const std::string& summary, bool slow) {
  if (!PyCallable_Check(f.ptr())) throw py::type_error("register_law: f must be callable, f(U, Omega, a, b, psi, N, k)");
  auto callable = std::make_shared<const Callable>(std::move(f));
  friction::LawRegistration r;
  r.name = name;
  r.summary = summary;
  r.facts.slow = slow;
  r.factory = [name, summary, callable](const friction::LawArguments&) {
    return std::make_unique<PythonLaw>(name, summary, callable);
  };
  friction::register_law(std::move(r));
}

}  // namespace

void bind_python_laws(py::module_& m) {
  m.def("_register_law", &register_python_law, py::arg("name"), py::arg("f"), py::arg("summary"), py::arg("slow"),
        "Internal: frictionlab.register_law() calls it.");
  m.def(
      "_unregister_law", [](const std::string& name) { return friction::unregister_law(name); }, py::arg("name"),
      "Internal: frictionlab.unregister_law() calls it.");
}

}  // namespace frictionlab::python
