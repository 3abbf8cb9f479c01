// frictionlab._core.run_scenario: one scenario run through dynamics::run_scenario (the command
// line's code: the same files, the same numbers), its trajectory also kept in memory as columns,
// with Ctrl-C and a progress callback served between integrator steps.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <atomic>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "file_errors.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"
#include "dynamics/io/toml_nesting.h"
#include "dynamics/body/trajectory_csv.h"

namespace frictionlab::python {
namespace {

constexpr std::size_t kColumns = dynamics::kTrajectoryColumns.size();

// Keeps every sample as a row of columns, and between steps (at most every `interval` seconds of
// wall time) takes the GIL to let Python handle signals (KeyboardInterrupt) and to call the
// progress callback. Either may stop the run, through the run's cancel flag.
class Collector final : public dynamics::Observer {
 public:
  Collector(py::object progress, double t_end, double interval, std::atomic<bool>& cancel)
      : progress_(std::move(progress)), t_end_(t_end), interval_(interval), cancel_(cancel) {}

  void sample(const dynamics::Sample& s) override {
    const auto row = dynamics::trajectory_row(s);
    for (std::size_t i = 0; i < kColumns; ++i) columns_[i].push_back(row[i]);
  }

  void step(double t) override {
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_).count() < interval_) return;
    last_ = now;
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
      stop_with(py::error_already_set());
      return;
    }
    if (progress_.is_none() || cancel_.load()) return;  // a callback that said stop is not asked again
    try {
      const py::object answer = progress_(t, t_end_);
      if (answer.is(py::bool_(false))) cancel_ = true;
    } catch (py::error_already_set& e) {
      stop_with(std::move(e));
    }
  }

  /// After the run, with the GIL: a Ctrl-C that came after the last look (or inside a law written
  /// in Python, which re-arms it) still counts.
  void look_at_signals() {
    if (!pending_ && PyErr_CheckSignals() != 0) pending_.emplace(py::error_already_set());
  }

  /// The exception that stopped the run (KeyboardInterrupt, or the callback's), or None.
  [[nodiscard]] py::object pending() const { return pending_ ? pending_->value() : py::none(); }
  [[nodiscard]] std::array<std::vector<double>, kColumns>& columns() { return columns_; }

 private:
  void stop_with(py::error_already_set&& e) {
    if (!pending_) pending_.emplace(std::move(e));
    cancel_ = true;
  }

  py::object progress_;
  double t_end_;
  double interval_;
  std::atomic<bool>& cancel_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  std::optional<py::error_already_set> pending_;
  std::array<std::vector<double>, kColumns> columns_;
};

// A NumPy array that owns `v` (no copy).
py::array_t<double> to_array(std::vector<double>&& v) {
  auto* owned = new std::vector<double>(std::move(v));
  const py::capsule free(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(static_cast<py::ssize_t>(owned->size()), owned->data(), free);
}

py::tuple run(const std::optional<std::string>& path, const std::string& text, const std::string& source,
              const std::vector<std::string>& overrides, const std::string& out_dir, py::object progress,
              double interval) {
  const dynamics::ScenarioDocument doc =
      path ? reading_file(*path, [&] { return dynamics::ScenarioDocument::read(*path); })
           : dynamics::ScenarioDocument::parse(text, source);
  const dynamics::Scenario scenario = doc.resolve(overrides);
  std::atomic<bool> cancel{false};
  Collector collector(std::move(progress), scenario.run.t_end, interval, cancel);
  {
    const py::gil_scoped_release release;
    (void)dynamics::run_scenario(scenario, out_dir, &collector, &cancel);
  }
  collector.look_at_signals();
  py::dict trajectory;
  auto& columns = collector.columns();
  for (std::size_t i = 0; i < kColumns; ++i) {
    if (!dynamics::trajectory_column_written(i, scenario.run.pose)) continue;  // run.pose = false
    const py::str name(dynamics::kTrajectoryColumns[i].data(), dynamics::kTrajectoryColumns[i].size());
    py::array_t<double> column = to_array(std::move(columns[i]));
    if (dynamics::kTrajectoryColumns[i] == "in_contact" || dynamics::kTrajectoryColumns[i] == "stick" ||
        dynamics::kTrajectoryColumns[i] == "slip_held") {
      trajectory[name] = column.attr("astype")("bool");
    } else {
      trajectory[name] = std::move(column);
    }
  }
  return py::make_tuple(trajectory, collector.pending());
}

}  // namespace

void bind_simulate(py::module_& m) {
  m.def("_run_scenario", &run, py::arg("path"), py::arg("text"), py::arg("source"), py::arg("overrides"),
        py::arg("out_dir"), py::arg("progress"), py::arg("interval"),
        R"doc(_run_scenario(path, text, source, overrides, out_dir, progress, interval) -> (trajectory, pending)

Internal: frictionlab.simulate() calls it. Reads the scenario file `path` (or parses the TOML
`text`, named `source`), applies the "key=value" overrides, runs it into `out_dir` exactly as
`frictionlab simulate` does, and returns the trajectory columns (dict of float64 arrays,
in_contact and stick bool) and the exception that stopped the run (KeyboardInterrupt, or one raised by
`progress(t, t_end)`), or None. `interval` (s of wall time) is how often signals are checked
and progress is called.)doc");
  m.def(
      "_check_toml_nesting", [](int depth, const std::string& where) { dynamics::check_toml_nesting(depth, where); },
      py::arg("depth"), py::arg("where"),
      R"doc(_check_toml_nesting(depth, where)

Internal: raises ValueError (the message of a TOML file nested as deeply) if `depth` levels are
more than a scenario may nest (dynamics/io/toml_nesting.h). to_toml() asks before it writes a dict.)doc");
}

}  // namespace frictionlab::python
