#include "dynamics/paper/experiment_runner.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "dynamics/paper/along_motion.h"
#include "dynamics/paper/feature_json.h"
#include "dynamics/paper/figure_data.h"
#include "dynamics/paper/run_record.h"
#include "dynamics/paper/run_series.h"
#include "dynamics/body/body.h"
#include "dynamics/body/scenario_run.h"
#include "friction/law_spec.h"
#include "friction/support/checked_input.h"
#include "friction/support/checked_output.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

// Samples to reserve at most (the recorder grows beyond if needed).
constexpr std::size_t kMaxReserve = 1'000'000;

// What a result needs of the planned scenario, whether the run is made or kept.
void take_scenario_facts(RunResult& r) {
  const Scenario& scenario = *r.spec.scenario;
  r.weight = scenario.body.mass * scenario.contact.g;
  r.t_end = scenario.run.t_end;
  const Body& body = scenario.body;
  // The paper's bodies are bodies of revolution; another shape has no poles to name (1).
  const std::optional<AxisymmetricBody>& a = body.axisymmetric;
  r.low_pole = !a || a->com - a->profile.z_lo() <= a->profile.z_hi() - a->com ? 1 : -1;
}

// features.json: the features, their thresholds, and how trajectory.csv was thinned.
support::Json features_record(const RunResult& r, int every, long rows) {
  support::Json j = features_json(r.features, r.thresholds);
  j["trajectory_csv"] = {{"every_nth_sample", every}, {"rows", rows}};
  return j;
}

// An earlier run's record that a run stopped half way (killed from outside) would leave behind as
// if it were its own.
void remove_old_record(const std::filesystem::path& dir) {
  std::error_code ignored;
  for (const char* f : {"features.json", "summary.json", "gamma3.csv"}) std::filesystem::remove(dir / f, ignored);
}

void run_one(RunResult& r, const RunnerOptions& options, std::atomic<double>* progress_t) {
  const RunSpec& spec = r.spec;
  if (!spec.scenario) throw std::invalid_argument("run " + r.name() + " has no scenario (plan it with plan_runs)");
  const Scenario& scenario = *spec.scenario;
  take_scenario_facts(r);
  remove_old_record(spec.out_dir);
  SeriesRecorder recorder(r.weight, progress_t);
  recorder.series().reserve(
      std::min<std::size_t>(kMaxReserve, static_cast<std::size_t>(scenario.run.t_end / scenario.run.output_dt) + 2));
  const ScenarioRun run = run_scenario(scenario, spec.out_dir, &recorder, options.cancel);
  r.summary = run.summary;
  r.executed = true;
  if (!run.output_error.empty()) r.error = run.output_error;  // its trajectory is incomplete

  // Everything is measured on every sample, before trajectory.csv is thinned.
  const RunSeries& s = recorder.series();
  r.features = extract_features(s, r.thresholds);
  if (!options.plot_data_dir.empty()) r.figure_ranges = write_figure_data(options.plot_data_dir, plot_data_stem(spec), s);
  const ComparisonSeries compared =
      thin_series({s.t, s.gamma3, moving_average(s.t, s.gamma3, r.thresholds.smoothing_window), s.axis_x, s.axis_y,
                   s.axis_z},
                  kComparisonEvery);
  write_comparison_series(spec.out_dir / "gamma3.csv", compared);
  // An incomplete trajectory (its output failed) is left as it is.
  const bool thin = options.trajectory_every > 1 && run.output_error.empty();
  const long rows = thin ? thin_csv(run.trajectory_csv, options.trajectory_every) : csv_data_rows(run.trajectory_csv);
  // The shadow laws' figure data from every sample, then shadow.csv thinned like the trajectory.
  const std::filesystem::path shadow_csv = spec.out_dir / "shadow.csv";
  if (!scenario.run.shadow.empty() && std::filesystem::exists(shadow_csv)) {
    if (!options.plot_data_dir.empty()) write_shadow_figure_data(shadow_csv, options.plot_data_dir, plot_data_stem(spec));
    if (thin) (void)thin_csv(shadow_csv, options.trajectory_every);
  }
  support::write_file_atomically(spec.out_dir / "features.json",
                                 support::json_text(features_record(r, options.trajectory_every, rows)));
  r.t = compared.t;
  r.gamma3 = compared.gamma3;
  r.gamma3_smooth = compared.gamma3_smooth;
  r.axis = {compared.axis_x, compared.axis_y, compared.axis_z};
}

// scenario.toml holds `scenario` as resolved: its text after the leading comment lines.
bool same_resolved_scenario(const std::filesystem::path& file, const Scenario& scenario) {
  std::string text;
  try {
    text = support::read_file(file, "scenario file");
  } catch (const support::InputError&) {
    return false;  // unreadable: the run is done again
  }
  std::size_t pos = 0;
  while (pos < text.size() && text[pos] == '#') {
    const std::size_t end = text.find('\n', pos);
    pos = end == std::string::npos ? text.size() : end + 1;
  }
  return text.compare(pos, std::string::npos, scenario.resolved_toml + "\n") == 0;
}

// Why a summary does not record a complete run ("" if it does).
std::string incomplete_run(const RunSummary& s, const support::Json& summary) {
  if (s.reason == Termination::interrupted) return "it was interrupted";
  if (s.reason == Termination::output_error || s.reason == Termination::output_limit) return "its output failed";
  if (!summary.contains("output") || !summary["output"].contains("error") || !summary["output"]["error"].is_null())
    return "its output failed";
  return "";
}

std::string thinning_text(long every) {
  return every == 1 ? std::string("every sample") : "every " + std::to_string(every) + "th sample";
}

}  // namespace

// The label is a law spec (e.g. exact:pressure=uniform): made safe for file names and gnuplot.
std::string plot_data_stem(const RunSpec& spec) { return spec.group() + "-" + friction::law_file_stem(spec.label); }

void RunnerOptions::validate() const {
  thresholds.validate();
  if (trajectory_every < 1)
    throw support::invalid_value("trajectory_every", static_cast<long long>(trajectory_every), "it must be >= 1");
}

std::string keep_finished_run(RunResult& r, const RunnerOptions& options) {
  const RunSpec& spec = r.spec;
  if (!spec.scenario) return "it has no planned scenario";
  const std::filesystem::path& dir = spec.out_dir;
  if (!std::filesystem::exists(dir / "summary.json")) return "not run before (no summary.json)";
  if (!same_resolved_scenario(dir / "scenario.toml", *spec.scenario)) return "its scenario changed";
  RunResult kept = r;
  take_scenario_facts(kept);
  try {
    const support::Json summary = read_json_file(dir / "summary.json");
    kept.summary = summary_from_json(summary, kept.weight);
    if (std::string why = incomplete_run(kept.summary, summary); !why.empty()) return why;
    const support::Json features = read_json_file(dir / "features.json");
    if (features.at("thresholds") != features_json(RunFeatures{}, kept.thresholds).at("thresholds"))
      return "its feature thresholds differ";
    const long every = features.at("trajectory_csv").at("every_nth_sample").get<long>();
    if (every != options.trajectory_every)
      return "its trajectory.csv keeps " + thinning_text(every) + ", this job " + thinning_text(options.trajectory_every);
    const long samples = summary.at("output").at("trajectory_rows").get<long>();
    if (csv_data_rows(dir / "trajectory.csv") != thinned_rows(samples, options.trajectory_every))
      return "its trajectory.csv is incomplete";
    kept.features = features_from_json(features);
    ComparisonSeries compared = read_comparison_series(dir / "gamma3.csv");
    kept.t = std::move(compared.t);
    kept.gamma3 = std::move(compared.gamma3);
    kept.gamma3_smooth = std::move(compared.gamma3_smooth);
    kept.axis = {std::move(compared.axis_x), std::move(compared.axis_y), std::move(compared.axis_z)};
    if (!options.plot_data_dir.empty()) {
      if (!std::filesystem::exists(options.plot_data_dir / (plot_data_stem(spec) + ".end.dat")))
        return "its plot data is missing";
      if (!spec.scenario->run.shadow.empty() &&
          !std::filesystem::exists(options.plot_data_dir / (plot_data_stem(spec) + ".shadow.dat")))
        return "its shadow laws' plot data is missing";
      kept.figure_ranges = read_figure_ranges(options.plot_data_dir, plot_data_stem(spec));
    }
  } catch (const std::exception& e) {
    return std::string("its record is unreadable (") + e.what() + ")";
  }
  kept.executed = true;
  kept.resumed = true;
  kept.error.clear();
  r = std::move(kept);
  return "";
}

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
  options.validate();
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
      if (options.resume) {
        const std::string why = keep_finished_run(r, options);
        if (why.empty()) {
          if (options.progress) options.progress->finished(slot, "kept  " + r.name() + ": " + describe(r));
          continue;
        }
        if (options.progress) options.progress->note("redo  " + r.name() + ": " + why);
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
