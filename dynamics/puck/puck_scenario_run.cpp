#include "dynamics/puck/puck_scenario_run.h"

#include <system_error>

#include "dynamics/puck/puck_summary_json.h"
#include "dynamics/puck/puck_trajectory_csv.h"
#include "friction/registry.h"
#include "friction/support/checked_output.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::puck {
namespace {

class Tee final : public PuckObserver {
 public:
  Tee(PuckObserver& a, PuckObserver* b) : a_(a), b_(b) {}
  void sample(const PuckSample& s) override {
    a_.sample(s);
    if (b_) b_->sample(s);
  }
  void step(double t) override {
    a_.step(t);
    if (b_) b_->step(t);
  }

 private:
  PuckObserver& a_;
  PuckObserver* b_;
};

}  // namespace

PuckScenarioRun run_puck_scenario(const PuckScenario& scenario, const std::filesystem::path& out_dir,
                                  PuckObserver* progress, const std::atomic<bool>* cancel) {
  const auto law = friction::make_law(scenario.law);
  const PuckOnPlane sys(scenario.puck, scenario.k, scenario.g, *law);
  const PuckState x0 = initial_state(scenario);
  (void)sys.contact(x0);  // the law must accept the initial state: fail before writing

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw support::OutputError("cannot create the output folder '" + out_dir.string() + "': " + ec.message());
  PuckScenarioRun run;
  run.trajectory_csv = out_dir / "trajectory.csv";
  run.summary_json = out_dir / "summary.json";
  support::write_file_atomically(out_dir / "scenario.toml", "# " + support::one_line(scenario.source) +
                                                                " resolved; rerun: frictionlab simulate scenario.toml\n" +
                                                                scenario.resolved_toml + "\n");
  PuckTrajectoryCsv csv(run.trajectory_csv, scenario.puck.a);
  Tee tee(csv, progress);
  RunOptions options = scenario.run;
  options.cancel = cancel;
  run.summary = simulate_puck(sys, x0, options, &tee);
  if (run.summary.reason == Termination::output_error) run.output_error = run.summary.message;
  try {
    csv.close();
  } catch (const OutputFailure& e) {
    if (run.output_error.empty()) run.output_error = e.what();
  }
  support::Json summary = puck_summary_json(scenario, *law, run.summary);
  summary["output"] = {{"trajectory_rows", csv.rows()},
                       {"error", run.output_error.empty() ? support::Json(nullptr) : support::Json(run.output_error)}};
  support::write_file_atomically(run.summary_json, support::json_text(summary));
  return run;
}

}  // namespace frictionlab::dynamics::puck
