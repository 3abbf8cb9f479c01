// `frictionlab simulate SCENARIO.toml [--law NAME] [--set key=value]... --out DIR`: one run of the
// body-on-plane dynamics (docs/dynamics.md), or of the sliding-spinning puck for a scenario with
// `model = "puck"` (docs/puck.md). SCENARIO may also name a shipped scenario (dynamics/io/shipped_data.h).
// Writes DIR/trajectory.csv, DIR/summary.json and DIR/scenario.toml; prints one line on stdout.
// Exit codes:
//   0  the run ended by t_end, rest or rolling;
//   3  it stopped early (stagnation, chatter, law-pole, non-finite, law-error, integrator-failure,
//      max-steps, output-limit, flat-face: the model's point contact ends, interrupted by SIGINT,
//      SIGTERM or SIGHUP): its files are written and the summary says why;
//   1  an error: bad input (nothing run), or an output that could not be written (the run stopped
//      there; what was written is valid). One line on stderr.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/cli/commands.h"
#include "dynamics/puck/puck_scenario_run.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"
#include "dynamics/io/shipped_data.h"
#include "friction/law_spec.h"
#include "friction/registry.h"
#include "friction/support/checked_output.h"
#include "friction/support/errors.h"
#include "friction/support/interrupt_guard.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

constexpr int kExitStoppedEarly = 3;
constexpr double kProgressRefreshSeconds = 0.1;
constexpr int kProgressBarWidth = 40;

// A one-line progress bar in simulated time, on stderr (only used when stderr is a terminal).
class ProgressBar final : public dynamics::Observer {
 public:
  explicit ProgressBar(double t_end) : t_end_(t_end) {}
  ~ProgressBar() override {
    if (drawn_) std::fputs("\r\033[K", stderr);
  }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void sample(const dynamics::Sample&) override {}
  void step(double t) override {
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && std::chrono::duration<double>(now - last_).count() < kProgressRefreshSeconds) return;
    last_ = now;
    drawn_ = true;
    const double f = std::min(1.0, t / t_end_);
    const int filled = static_cast<int>(f * kProgressBarWidth);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kProgressBarWidth, '.');
    const std::string line =
        "\r[" + bar + "] t = " + support::significant(t, 4) + " / " + support::significant(t_end_, 4) + " s";
    std::fputs(line.c_str(), stderr);
    std::fflush(stderr);
  }

 private:
  double t_end_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

struct SimulateOptions {
  std::string scenario;
  std::string law;
  std::string shadow;
  std::vector<std::string> set;
  std::string out;
};

// The progress bar as the puck's observer.
class PuckProgress final : public dynamics::puck::PuckObserver {
 public:
  explicit PuckProgress(ProgressBar& bar) : bar_(bar) {}
  void sample(const dynamics::puck::PuckSample&) override {}
  void step(double t) override { bar_.step(t); }

 private:
  ProgressBar& bar_;
};

// Exit code and the lines on stdout and stderr, the same for every model.
void report(const std::string& name, dynamics::Termination reason, const std::string& message, double t_final,
            long steps, long rhs_calls, double wall_time, const std::string& output_error,
            const std::filesystem::path& trajectory, const std::filesystem::path& summary) {
  const std::string why(dynamics::to_string(reason));
  if (!output_error.empty())
    throw support::OutputError(output_error + "; the run stopped at t = " + support::message_number(t_final) + " s (" +
                               why + "), see " + summary.string());
  std::printf("%s: %s at t = %s s; %ld steps, %ld RHS calls, %s s wall; wrote %s, %s\n", name.c_str(), why.c_str(),
              support::significant(t_final, 6).c_str(), steps, rhs_calls, support::significant(wall_time, 3).c_str(),
              trajectory.c_str(), summary.c_str());
  const bool normal = reason == dynamics::Termination::t_end || reason == dynamics::Termination::rest ||
                      reason == dynamics::Termination::rolling;
  if (!normal) {
    std::fprintf(stderr, "frictionlab: simulate: the run stopped early (%s): %s\n", why.c_str(),
                 support::one_line(message).c_str());
    throw CLI::RuntimeError(kExitStoppedEarly);
  }
}

void run_puck(const dynamics::puck::PuckScenario& scenario, const std::string& out) {
  std::unique_ptr<ProgressBar> bar;
  std::unique_ptr<PuckProgress> progress;
  if (isatty(STDERR_FILENO)) {
    bar = std::make_unique<ProgressBar>(scenario.run.t_end);
    progress = std::make_unique<PuckProgress>(*bar);
  }
  dynamics::puck::PuckScenarioRun result;
  {
    const support::InterruptGuard interrupts;
    result = dynamics::puck::run_puck_scenario(scenario, out, progress.get(), &interrupts.flag());
  }
  progress.reset();
  bar.reset();
  const auto& s = result.summary;
  report(scenario.name, s.reason, s.message, s.t_final, s.steps, s.rhs_calls, s.wall_time, result.output_error,
         result.trajectory_csv, result.summary_json);
}

void run(const SimulateOptions& opt) {
  std::vector<std::string> overrides = opt.set;
  if (!opt.law.empty()) {
    // The law goes into the scenario as an override; a wrong name is the option's fault.
    try {
      (void)friction::make_law(opt.law);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--law " + opt.law + ": " + e.what());
    }
    overrides.push_back("contact.law=" + opt.law);
  }
  if (!opt.shadow.empty()) {
    // The shadow laws go in as run.shadow, a TOML array of their specs.
    std::string array;
    try {
      for (const std::string& spec : friction::split_law_list(opt.shadow)) {
        (void)friction::make_law(spec);
        array += (array.empty() ? "[\"" : ", \"") + spec + "\"";
      }
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--shadow " + opt.shadow + ": " + e.what());
    }
    overrides.push_back("run.shadow=" + array + "]");
  }
  const dynamics::ScenarioDocument document =
      dynamics::ScenarioDocument::read(dynamics::find_shipped_file(opt.scenario, "scenarios", "scenario"));
  if (document.model(overrides) == "puck") {
    run_puck(dynamics::puck::resolve_puck(document, overrides), opt.out);
    return;
  }
  const dynamics::Scenario scenario = document.resolve(overrides);

  std::unique_ptr<ProgressBar> bar;
  if (isatty(STDERR_FILENO)) bar = std::make_unique<ProgressBar>(scenario.run.t_end);
  dynamics::ScenarioRun result;
  {
    // Ctrl-C, kill or a lost terminal: stop between steps and still write the summary.
    const support::InterruptGuard interrupts;
    result = dynamics::run_scenario(scenario, opt.out, bar.get(), &interrupts.flag());
  }
  bar.reset();

  const dynamics::RunSummary& s = result.summary;
  report(scenario.name, s.reason, s.message, s.t_final, s.steps, s.rhs_calls, s.wall_time, result.output_error,
         result.trajectory_csv, result.summary_json);
}

}  // namespace

void register_simulate_command(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  auto* cmd = app.add_subcommand(
      "simulate",
      "Integrate the motion of a body of revolution on a Hertz plane, or of a puck (model = \"puck\");\n"
      "writes DIR/trajectory.csv (a row of ~470 bytes every run.output_dt: 0.1-11 MB for the shipped\n"
      "scenarios; never more than run.max_output_bytes, default 100 MB), summary.json, scenario.toml");
  cmd->add_option("scenario", opt->scenario,
                  "Scenario file (TOML; see docs/dynamics.md), or the name of a shipped one (sphere-sliding, "
                  "egg-printed-a, ...: looked up in data/scenarios here, then the installed data)")
      ->required();
  cmd->add_option("--law", opt->law, "Friction law (overrides contact.law; see `frictionlab laws`)");
  cmd->add_option("--shadow", opt->shadow,
                  "Friction laws evaluated along the run beside its own, without changing it (a list: "
                  "pade-printed,moller-ellipsoidal; sets run.shadow): DIR/shadow.csv and summary.json's \"shadow\"");
  cmd->add_option("--set", opt->set, "Override a scenario key, e.g. --set run.t_end=2 (repeatable)")
      ->allow_extra_args(false);
  cmd->add_option("--out", opt->out, "Output directory (created if needed)")->required();
  cmd->callback([opt] { run(*opt); });
}

}  // namespace frictionlab::cli
