#include "dynamics/body/scenario_run.h"

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/io/run_folder.h"
#include "dynamics/body/summary_json.h"
#include "dynamics/body/trajectory_csv.h"
#include "friction/registry.h"

namespace frictionlab::dynamics {

ScenarioRun run_scenario(const Scenario& scenario, const std::filesystem::path& out_dir, Observer* progress,
                         const std::atomic<bool>* cancel) {
  const auto law = friction::make_law(scenario.law);
  const BodyOnPlane sys(scenario.body, scenario.contact, *law);
  const StateVector x0 = initial_state(scenario);
  (void)sys.contact_state(x0);  // the law must accept the initial state: fail before writing

  start_run_folder(out_dir, scenario.source, scenario.resolved_toml);
  ScenarioRun run;
  run.trajectory_csv = out_dir / "trajectory.csv";
  run.summary_json = out_dir / "summary.json";
  TrajectoryCsv csv(run.trajectory_csv, static_cast<std::uint64_t>(scenario.run.max_output_bytes));
  TeeObserver<Observer, Sample> tee(csv, progress);
  RunOptions options = scenario.run;
  options.cancel = cancel;
  // A failing trajectory write stops the run with reason output-error (dynamics/core/observer.h).
  run.summary = simulate(sys, x0, options, &tee);
  if (run.summary.reason == Termination::output_error) run.output_error = run.summary.message;
  close_trajectory(csv, run.output_error);
  write_run_summary(run.summary_json, summary_json(scenario, run.summary),
                    {csv.rows(), csv.bytes(), scenario.run.max_output_bytes, run.output_error});
  return run;
}

}  // namespace frictionlab::dynamics
