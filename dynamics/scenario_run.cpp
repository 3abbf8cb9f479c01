#include "dynamics/scenario_run.h"

#include <fstream>
#include <stdexcept>

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

std::ofstream open_for_writing(const std::filesystem::path& p) {
  std::ofstream out(p);
  if (!out) throw std::runtime_error("cannot write '" + p.string() + "'");
  return out;
}

}  // namespace

ScenarioRun run_scenario(const Scenario& scenario, const std::filesystem::path& out_dir, Observer* progress,
                         const std::atomic<bool>* cancel) {
  const auto law = friction::make_law(scenario.law);
  const BodyOnPlane sys(scenario.body, scenario.contact, *law);
  const StateVector x0 = initial_state(scenario);
  (void)sys.contact_state(x0);  // the law must accept the initial state: fail before writing

  std::filesystem::create_directories(out_dir);
  ScenarioRun run;
  run.trajectory_csv = out_dir / "trajectory.csv";
  run.summary_json = out_dir / "summary.json";
  support::write_file_atomically(out_dir / "scenario.toml", "# " + support::one_line(scenario.source) +
                                                                " resolved; rerun: frictionlab simulate scenario.toml\n" +
                                                                scenario.resolved_toml + "\n");
  std::ofstream csv = open_for_writing(run.trajectory_csv);
  TrajectoryCsv writer(csv);
  Tee tee(writer, progress);
  RunOptions options = scenario.run;
  options.cancel = cancel;
  run.summary = simulate(sys, x0, options, &tee);
  csv.flush();
  if (!csv) throw std::runtime_error("writing the output in '" + out_dir.string() + "' failed");
  support::write_file_atomically(run.summary_json, support::json_text(summary_json(scenario, run.summary)));
  return run;
}

}  // namespace frictionlab::dynamics
