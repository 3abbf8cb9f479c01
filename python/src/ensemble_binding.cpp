// frictionlab._core._run_ensemble: a study file through dynamics::ensemble::run_ensemble_job, the
// job `frictionlab ensemble` runs (built by the same ensemble_job_options), on a thread of its own
// while the caller's thread, without the GIL, looks at Python between waits: Ctrl-C and the
// progress callback stop the job through its cancel flag (the runs in flight stop between steps,
// the finished ones stay in runs.csv).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "bindings.h"
#include "file_errors.h"
#include "dynamics/ensemble/ensemble_job.h"

namespace frictionlab::python {
namespace {

namespace ens = dynamics::ensemble;

py::tuple run(const std::string& study, const std::string& out, int threads, bool resume, bool figures,
              py::object progress, double interval) {
  ens::JobOptions job = ens::ensemble_job_options(study, out, threads, resume, false, figures);
  std::atomic<bool> cancel{false};
  std::atomic<long> done{-1};
  std::atomic<long> total{0};
  job.cancel = &cancel;
  job.on_progress = [&done, &total](long d, long t) {
    total = t;
    done = d;
  };

  std::mutex mutex;
  std::condition_variable finished_cv;
  bool finished = false;
  ens::JobOutcome outcome;
  std::exception_ptr error;
  std::optional<py::error_already_set> pending;  // made and destroyed with the GIL held
  long shown = -1;
  {
    const py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        outcome = ens::run_ensemble_job(job);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      finished = true;
      finished_cv.notify_all();
    });
    const auto wait = std::chrono::duration<double>(interval);
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex);
        if (finished_cv.wait_for(lock, wait, [&] { return finished; })) break;
      }
      const py::gil_scoped_acquire gil;
      if (pending) continue;
      if (PyErr_CheckSignals() != 0) {
        pending.emplace(py::error_already_set());
        cancel = true;
        continue;
      }
      const long d = done.load();
      // Once the callback has said stop, it is not asked again (the runs that end meanwhile are kept).
      if (progress.is_none() || cancel.load() || d == shown || d < 0) continue;
      shown = d;
      try {
        if (progress(d, total.load()).is(py::bool_(false))) cancel = true;
      } catch (py::error_already_set& e) {
        pending.emplace(std::move(e));
        cancel = true;
      }
    }
    worker.join();
  }
  // std::invalid_argument: ValueError, nothing ran; an OSError if the study file cannot be read.
  if (error) reading_file(study, [&] { std::rethrow_exception(error); });
  // A Ctrl-C that came after the last look still counts.
  if (!pending && PyErr_CheckSignals() != 0) pending.emplace(py::error_already_set());

  const ens::SessionSummary& s = outcome.summary;
  py::dict summary;
  summary["total"] = s.total;
  summary["done_before"] = s.done_before;
  summary["done_now"] = s.done_now;
  summary["failed_now"] = s.failed_now;
  summary["early_now"] = s.early_now;
  summary["remaining"] = s.remaining();
  summary["complete"] = s.complete;
  summary["interrupted"] = outcome.interrupted;
  summary["output_error"] = s.output_error;
  summary["threads"] = outcome.threads;
  summary["ranks"] = outcome.ranks;
  summary["wall_time"] = outcome.wall_time;
  summary["figure_errors"] = outcome.figure_errors;
  summary["command"] = job.command;
  const std::string report = outcome.report.empty() ? std::string() : outcome.report.string();
  return py::make_tuple(summary, report, pending ? pending->value() : py::none());
}

}  // namespace

void bind_ensemble(py::module_& m) {
  m.def("_run_ensemble", &run, py::arg("study"), py::arg("out"), py::arg("threads"), py::arg("resume"),
        py::arg("figures"), py::arg("progress"), py::arg("interval"),
        R"doc(_run_ensemble(study, out, threads, resume, figures, progress, interval) -> (summary, report, pending)

Internal: frictionlab.ensemble() calls it. Runs the study file `study` into the folder `out`
exactly as `frictionlab ensemble STUDY --out OUT [--threads N] [--resume] [--no-figures]` does;
returns the session's summary (dict), the path of report.md ("" if not written) and the
exception that stopped the job (KeyboardInterrupt, or one raised by `progress(done, total)`), or
None. `interval` (s of wall time) is how often signals are checked and progress is called.)doc");
}

}  // namespace frictionlab::python
