// frictionlab._core._accuracy: the accuracy study of bench/accuracy (the code of `frictionlab
// accuracy`), its values returned as arrays instead of written as tables.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <vector>

#include "bench/accuracy/study.h"
#include "bindings.h"

namespace frictionlab::python {
namespace {

constexpr std::array<const char*, 3> kComponents = {"F1", "F2", "M"};

// A grid-indexed vector as an array of shape (mu, psi, sign, s): the grid's own index order.
py::array_t<double> on_grid(const std::vector<double>& v, const accuracy::Grid& g) {
  const std::vector<py::ssize_t> shape = {static_cast<py::ssize_t>(g.mu().size()), static_cast<py::ssize_t>(g.psi().size()),
                                          static_cast<py::ssize_t>(accuracy::Grid::kSigns.size()),
                                          static_cast<py::ssize_t>(g.s().size())};
  py::array_t<double> a(shape);
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict values_dict(const accuracy::LawValues& v, const accuracy::Grid& g) {
  py::dict d;
  d["F1"] = on_grid(v.F1, g);
  d["F2"] = on_grid(v.F2, g);
  d["M"] = on_grid(v.M, g);
  return d;
}

py::dict stats_dict(const accuracy::ErrorStats& e) {
  py::dict d;
  d["max_abs"] = e.max_abs;
  d["rms"] = e.rms;
  d["median_abs"] = e.median_abs;
  d["p95_abs"] = e.p95_abs;
  d["finite"] = e.finite;
  d["nonfinite"] = e.nonfinite;
  return d;
}

py::dict study(const std::vector<std::string>& laws, std::size_t s_points, std::size_t mu_points,
               std::size_t psi_points, double s_min, double s_max, double mu_min, std::size_t threads) {
  accuracy::StudyOptions options;
  options.grid.s_points = s_points;
  options.grid.mu_points = mu_points;
  options.grid.psi_points = psi_points;
  options.grid.s_min = s_min;
  options.grid.s_max = s_max;
  options.grid.mu_min = mu_min;
  options.laws = laws;
  options.threads = threads;
  accuracy::StudyResult r = [&] {
    const py::gil_scoped_release release;  // laws written in Python take it back per call
    return accuracy::run_study(options);
  }();
  const accuracy::Grid& g = r.grid;
  py::dict out;
  out["s"] = py::array_t<double>(static_cast<py::ssize_t>(g.s().size()), g.s().data());
  out["mu"] = py::array_t<double>(static_cast<py::ssize_t>(g.mu().size()), g.mu().data());
  out["psi"] = py::array_t<double>(static_cast<py::ssize_t>(g.psi().size()), g.psi().data());
  const std::array<double, 2> signs = {static_cast<double>(accuracy::Grid::kSigns[0]),
                                       static_cast<double>(accuracy::Grid::kSigns[1])};
  out["sign"] = py::array_t<double>(2, signs.data());
  out["reference"] = r.reference.law;
  out["reference_values"] = values_dict(r.reference, g);
  out["reference_seconds"] = r.reference_seconds;
  py::list per_law;
  for (std::size_t i = 0; i < r.summaries.size(); ++i) {
    const accuracy::LawSummary& s = r.summaries[i];
    py::dict d;
    d["law"] = s.law;
    d["summary"] = s.description;
    d["values"] = values_dict(r.values[i], g);
    py::dict errors;
    for (std::size_t c = 0; c < 3; ++c) errors[kComponents[c]] = stats_dict(s.overall.error[c]);
    d["errors"] = errors;
    d["dissipation_violations"] = s.overall.dissipation.violations;
    d["singular_points"] = s.overall.singular_points;
    d["seconds"] = s.seconds;
    per_law.append(d);
  }
  out["laws"] = per_law;
  return out;
}

}  // namespace

void bind_accuracy(py::module_& m) {
  m.def("_accuracy", &study, py::arg("laws"), py::arg("s_points"), py::arg("mu_points"), py::arg("psi_points"),
        py::arg("s_min"), py::arg("s_max"), py::arg("mu_min"), py::arg("threads"),
        "Internal: frictionlab.accuracy() calls it (bench/accuracy's run_study on the given grid).");
}

}  // namespace frictionlab::python
