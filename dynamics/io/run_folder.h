#pragma once
// The pieces of a run written to a folder that the body's and the puck's runs share
// (dynamics/body/scenario_run.h, dynamics/puck/puck_scenario_run.h): the folder with the resolved
// scenario beside the outputs, a tee of observers, and the summary.json's output record.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "dynamics/core/observer.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics {

/// Creates `out_dir` and writes `scenario.toml` in it: the resolved scenario, headed by where it
/// came from, so that `frictionlab simulate scenario.toml` reruns it. support::OutputError on failure.
void start_run_folder(const std::filesystem::path& out_dir, const std::string& source,
                      const std::string& resolved_toml);

/// What a run's trajectory writer did, for the summary.
struct TrajectoryOutput {
  long rows = 0;            ///< rows given to the writer
  std::uint64_t bytes = 0;  ///< the file's size, header included, bytes
  long max_bytes = 0;       ///< its limit, run.max_output_bytes
  std::string error;        ///< why the file is incomplete (a write or its close failed), or empty
};

/// Adds {"output": {"trajectory_rows", "trajectory_bytes", "max_output_bytes", "error"}} to
/// `summary` (error null when there is none) and writes it to `path` atomically.
void write_run_summary(const std::filesystem::path& path, support::Json summary, const TrajectoryOutput& output);

/// Sends every report of a run to several observers (null ones skipped): the trajectory writer,
/// the shadow laws' writer and a caller's progress display; `Base` is the run's observer interface.
/// Samples are taken as the first observer asks (its sample_accuracy()).
template <class Base, class SampleType>
class TeeObserver final : public Base {
 public:
  TeeObserver(std::initializer_list<Base*> observers) {
    for (Base* o : observers) {
      if (o) observers_.push_back(o);
    }
  }
  void sample(const SampleType& s) override {
    for (Base* o : observers_) o->sample(s);
  }
  void step(double t) override {
    for (Base* o : observers_) o->step(t);
  }
  void accepted(const SampleType& s) override {
    for (Base* o : observers_) {
      if (o->wants_accepted_steps()) o->accepted(s);
    }
  }
  [[nodiscard]] bool wants_accepted_steps() const override {
    return std::any_of(observers_.begin(), observers_.end(), [](const Base* o) { return o->wants_accepted_steps(); });
  }
  [[nodiscard]] SampleAccuracy sample_accuracy() const override {
    return observers_.empty() ? SampleAccuracy::method_step : observers_.front()->sample_accuracy();
  }

 private:
  std::vector<Base*> observers_;
};

/// Closes a trajectory writer after the run; a failure to close is the run's output error unless
/// the run already recorded one.
template <class Writer>
void close_trajectory(Writer& writer, std::string& output_error) {
  try {
    writer.close();
  } catch (const OutputFailure& e) {
    if (output_error.empty()) output_error = e.what();
  }
}

}  // namespace frictionlab::dynamics
