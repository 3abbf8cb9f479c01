#include "dynamics/body/scenario_run.h"

#include <optional>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/io/run_folder.h"
#include "dynamics/body/summary_json.h"
#include "dynamics/body/trajectory_csv.h"
#include "dynamics/core/shadow_observer.h"
#include "dynamics/io/shadow_output.h"
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
  const auto max_bytes = static_cast<std::uint64_t>(scenario.run.max_output_bytes);
  TrajectoryCsv csv(run.trajectory_csv, max_bytes, scenario.run.pose);
  // Shadow laws (run.shadow): evaluated along the run beside its law, never changing it.
  ShadowOutput shadow(*law, scenario.run.shadow, motion_phase_rule(sys, scenario.run), out_dir / "shadow.csv", max_bytes);
  std::optional<ShadowObserver<BodyOnPlane>> shadow_observer;
  if (shadow.active()) shadow_observer.emplace(sys, shadow.laws(), shadow.csv());
  TeeObserver<Observer, Sample> tee({&csv, shadow_observer ? &*shadow_observer : nullptr, progress});
  RunOptions options = scenario.run;
  options.cancel = cancel;
  // A failing trajectory write stops the run with reason output-error (dynamics/core/observer.h).
  run.summary = simulate(sys, x0, options, &tee);
  if (run.summary.reason == Termination::output_error) run.output_error = run.summary.message;
  close_trajectory(csv, run.output_error);
  shadow.close();
  support::Json summary = summary_json(scenario, run.summary);
  shadow.add_to(summary, slide_work(run.summary.x_final) + spin_work(run.summary.x_final));
  write_run_summary(run.summary_json, std::move(summary),
                    {csv.rows(), csv.bytes(), scenario.run.max_output_bytes, run.output_error});
  return run;
}

}  // namespace frictionlab::dynamics
