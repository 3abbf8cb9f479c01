#include "dynamics/paper/experiment_runner.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "dynamics/paper/feature_json.h"
#include "dynamics/paper/figure_data.h"
#include "dynamics/paper/run_series.h"
#include "dynamics/body.h"
#include "dynamics/scenario_run.h"
#include "friction/support/checked_output.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

// Samples to reserve at most (the recorder grows beyond if needed).
constexpr std::size_t kMaxReserve = 1'000'000;

void run_one(RunResult& r, const RunnerOptions& options, std::atomic<double>* progress_t) {
  const RunSpec& spec = r.spec;
  if (!spec.scenario) throw std::invalid_argument("run " + r.name() + " has no scenario (plan it with plan_runs)");
  const Scenario& scenario = *spec.scenario;
  r.weight = scenario.body.mass * scenario.contact.g;
  r.t_end = scenario.run.t_end;
  const Body& body = scenario.body;
  r.low_pole = body.com - body.profile.z_lo() <= body.profile.z_hi() - body.com ? 1 : -1;
  SeriesRecorder recorder(r.weight, progress_t);
  recorder.series().reserve(
      std::min<std::size_t>(kMaxReserve, static_cast<std::size_t>(scenario.run.t_end / scenario.run.output_dt) + 2));
  const ScenarioRun run = run_scenario(scenario, spec.out_dir, &recorder, options.cancel);
  r.summary = run.summary;
  r.executed = true;
  if (!run.output_error.empty()) r.error = run.output_error;  // its trajectory is incomplete

  RunSeries& s = recorder.series();
  r.features = extract_features(s, r.thresholds);
  support::write_file_atomically(spec.out_dir / "features.json",
                                 support::json_text(features_json(r.features, r.thresholds)));
  if (!options.plot_data_dir.empty())
    r.figure_ranges = write_figure_data(options.plot_data_dir, spec.group() + "-" + spec.label, s);
  r.gamma3_smooth = moving_average(s.t, s.gamma3, r.thresholds.smoothing_window);
  r.t = std::move(s.t);
  r.gamma3 = std::move(s.gamma3);
}

}  // namespace

bool RunResult::ended_normally() const {
  return executed && (summary.reason == Termination::t_end || summary.reason == Termination::rest ||
                      summary.reason == Termination::rolling);
}

bool RunResult::stagnated() const {
  return executed && (summary.reason == Termination::rest || summary.reason == Termination::rolling);
}

int worker_count(int jobs) {
  if (jobs > 0) return jobs;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

std::string describe(const RunResult& r) {
  if (!r.executed) return "not run: " + r.error;
  std::string out = std::string(to_string(r.summary.reason)) + " at t = " + support::significant(r.summary.t_final, 4) +
                    " s, " + support::fixed(r.summary.wall_time, 2) + " s wall, " + std::to_string(r.summary.rhs_calls) +
                    " RHS calls";
  if (!r.ended_normally() && !r.summary.message.empty()) out += " (" + r.summary.message + ")";
  if (!r.error.empty()) out += "; " + r.error;
  return out;
}

std::vector<RunResult> run_experiments(const std::vector<RunSpec>& specs, const RunnerOptions& options) {
  options.thresholds.validate();
  std::vector<RunResult> results(specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i) {
    results[i].spec = specs[i];
    results[i].thresholds = options.thresholds;
  }
  if (!options.plot_data_dir.empty()) std::filesystem::create_directories(options.plot_data_dir);

  std::atomic<std::size_t> next{0};
  const int workers = std::min<int>(worker_count(options.jobs), static_cast<int>(std::max<std::size_t>(1, specs.size())));
  const auto work = [&](int slot) {
    std::atomic<double> own_t{0.0};
    std::atomic<double>* progress_t = options.progress ? options.progress->slot_time(slot) : &own_t;
    while (true) {
      const std::size_t i = next.fetch_add(1);
      if (i >= specs.size()) return;
      RunResult& r = results[i];
      if (options.cancel && options.cancel->load()) {
        r.error = "skipped (interrupted before it started)";
        continue;
      }
      if (options.progress) options.progress->started(slot, r.name(), r.spec.scenario ? r.spec.scenario->run.t_end : 0.0);
      try {
        run_one(r, options, progress_t);
      } catch (const std::exception& e) {
        // Not an early stop (those are results): the run could not be made or written.
        r.error = e.what();
      }
      if (options.progress) options.progress->finished(slot, "done  " + r.name() + ": " + describe(r));
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);
  for (auto& th : pool) th.join();
  return results;
}

}  // namespace frictionlab::dynamics::paper
