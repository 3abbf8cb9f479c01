#include "dynamics/scenario_run.h"

#include <stdexcept>
#include <system_error>

#include "dynamics/equations_of_motion.h"
#include "dynamics/summary_json.h"
#include "dynamics/trajectory_csv.h"
#include "friction/registry.h"
#include "friction/support/checked_output.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics {
namespace {

// Sends every report to two observers.
class Tee final : public Observer {
 public:
  Tee(Observer& a, Observer* b) : a_(a), b_(b) {}
  void sample(const Sample& s) override {
    a_.sample(s);
    if (b_) b_->sample(s);
  }
  void step(double t) override {
    a_.step(t);
    if (b_) b_->step(t);
  }

 private:
  Observer& a_;
  Observer* b_;
};

void create_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw support::OutputError("cannot create the output folder '" + dir.string() + "': " + ec.message());
}

}  // namespace

ScenarioRun run_scenario(const Scenario& scenario, const std::filesystem::path& out_dir, Observer* progress,
                         const std::atomic<bool>* cancel) {
  const auto law = friction::make_law(scenario.law);
  const BodyOnPlane sys(scenario.body, scenario.contact, *law);
  const StateVector x0 = initial_state(scenario);
  (void)sys.contact_state(x0);  // the law must accept the initial state: fail before writing

  create_folder(out_dir);
  ScenarioRun run;
  run.trajectory_csv = out_dir / "trajectory.csv";
  run.summary_json = out_dir / "summary.json";
  support::write_file_atomically(out_dir / "scenario.toml", "# " + support::one_line(scenario.source) +
                                                                " resolved; rerun: frictionlab simulate scenario.toml\n" +
                                                                scenario.resolved_toml + "\n");
  TrajectoryCsv csv(run.trajectory_csv);
  Tee tee(csv, progress);
  RunOptions options = scenario.run;
  options.cancel = cancel;
  // A failing trajectory write stops the run with reason output-error (dynamics/observer.h).
  run.summary = simulate(sys, x0, options, &tee);
  if (run.summary.reason == Termination::output_error) run.output_error = run.summary.message;
  try {
    csv.close();
  } catch (const OutputFailure& e) {
    if (run.output_error.empty()) run.output_error = e.what();
  }
  support::Json summary = summary_json(scenario, run.summary);
  summary["output"] = {{"trajectory_rows", csv.rows()},
                       {"error", run.output_error.empty() ? support::Json(nullptr) : support::Json(run.output_error)}};
  support::write_file_atomically(run.summary_json, support::json_text(summary));
  return run;
}

}  // namespace frictionlab::dynamics
