#include "dynamics/ensemble/task_execution.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <exception>
#include <memory>
#include <numbers>
#include <optional>

#include "dynamics/core/shadow_laws.h"
#include "dynamics/core/shadow_observer.h"
#include "dynamics/ensemble/run_recorder.h"
#include "dynamics/io/run_folder.h"
#include "dynamics/body/equations_of_motion.h"
#include "dynamics/paper/divergence.h"
#include "dynamics/paper/experiment_report.h"
#include "dynamics/paper/spin_reversals.h"
#include "dynamics/paper/trajectory_compare.h"
#include "dynamics/puck/puck_run.h"
#include "dynamics/puck/puck_summary_json.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::ensemble {
namespace {

// Samples to reserve at most (the recorder grows beyond if needed).
constexpr std::size_t kMaxReserve = 200'000;

// gamma3(t) of a reference run, kept for comparisons.
struct Reference {
  bool ran = false;
  std::vector<double> t;
  std::vector<double> gamma3;
  std::array<std::vector<double>, 3> axis;  // the symmetry axis in world axes
  double dt = 0.0;  // its sample interval
};

struct RunOutput {
  FinishedRun finished;
  Reference series;
  bool interrupted = false;
};

// The reference law's runs carry the study's shadow laws (EnsemblePlan::shadow_laws): made per
// run, their statistics only (no file), beside the run's own observer.
class ShadowRecord {
 public:
  ShadowRecord(const EnsemblePlan& plan, const RunId& id, const friction::FrictionLaw& own, const MotionPhaseRule& rule) {
    if (id.law != 0 || plan.shadow_laws().empty()) return;
    std::vector<const friction::FrictionLaw*> laws;
    for (const std::string& spec : plan.shadow_laws()) {
      owned_.push_back(friction::make_law(spec));
      laws.push_back(owned_.back().get());
    }
    laws_.emplace(own, std::move(laws), rule);
  }
  [[nodiscard]] ShadowLaws* laws() { return laws_ ? &*laws_ : nullptr; }

  /// The shadow columns of `r` from the statistics (every contact state).
  void fill(RunRecord& r) const {
    if (!laws_) return;
    constexpr int kF = 2;  // shadow_output_names(): F1, F2, F, M, P
    constexpr int kM = 3;
    for (std::size_t i = 0; i < laws_->size() && i < r.shadow.size(); ++i) {
      const ShadowLawStatistics& st = laws_->statistics(i);
      const auto& all = st.errors[kMotionPhases];
      ShadowColumns& c = r.shadow[i];
      c.F_median = all[kF].quantile(0.5);
      c.F_p95 = all[kF].quantile(0.95);
      c.F_max = all[kF].max();
      c.M_median = all[kM].quantile(0.5);
      c.M_max = all[kM].max();
      c.dE = st.difference;
      c.failures = st.failures;
    }
  }

 private:
  std::vector<std::unique_ptr<friction::FrictionLaw>> owned_;
  std::optional<ShadowLaws> laws_;
};

// A run of the puck model: its summary's features (the quantities of its summary.json,
// dynamics/puck/puck_summary_json.h). No samples are kept: the puck's features come from the
// summary, and a puck study has no divergence times (its runs are compared by their features).
void run_puck(const EnsemblePlan& plan, const RunId& id, const ExecuteOptions& options, RunOutput& out) {
  RunRecord& r = out.finished.record;
  const puck::PuckScenario s = plan.puck_scenario(id);
  const auto law = friction::make_law(s.law);
  const puck::PuckOnPlane sys(s.puck, s.k, s.g, *law);
  RunOptions run = s.run;
  run.cancel = options.cancel;
  ShadowRecord shadow(plan, id, *law, puck::motion_phase_rule(sys, run));
  std::optional<ShadowObserver<puck::PuckOnPlane>> observer;
  if (shadow.laws()) observer.emplace(sys, *shadow.laws(), nullptr);
  const puck::PuckRunSummary sum =
      puck::simulate_puck(sys, puck::initial_state(s), run, observer ? &*observer : nullptr);
  if (sum.reason == Termination::interrupted) {
    out.interrupted = true;
    return;
  }
  const puck::PuckState& x = sum.x_final;
  const puck::PathOffset off = puck::path_offset(s.initial.position, s.initial.v, puck::position(x));
  r.reason = std::string(to_string(sum.reason));
  r.t_final = sum.t_final;
  r.steps = sum.steps;
  r.rhs_calls = sum.rhs_calls + sum.sample_rhs_calls;
  r.puck.slip_stop_time = sum.slip_stop_time;
  r.puck.spin_stop_time = sum.spin_stop_time;
  r.puck.terminal_ratio = sum.terminal_ratio;
  r.puck.terminal_ratio_limit = sum.terminal_ratio_limit;
  r.puck.path_along = off.along;
  r.puck.path_lateral = off.lateral;
  r.puck.turned = puck::heading(x) - s.initial.heading;
  r.work_slide = puck::slide_work(x);
  r.work_spin = puck::spin_work(x);
  r.final_class = puck_outcome_class(r.reason, r.puck.terminal_ratio);
  shadow.fill(r);
  if (sum.reason != Termination::t_end && sum.reason != Termination::rest) r.message = sum.message;
}

RunOutput run_one(const EnsemblePlan& plan, const RunId& id, const ExecuteOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  RunOutput out;
  RunRecord& r = out.finished.record;
  r.model = plan.model();
  r.run = plan.run_index(id);
  r.start = id.start;
  r.replica = id.replica;
  r.law = plan.study().laws.at(static_cast<std::size_t>(id.law));
  r.values = plan.start_values(id.start);
  r.shadow.assign(plan.shadow_laws().size(), ShadowColumns{});
  if (plan.model() == RunModel::puck) {
    try {
      run_puck(plan, id, options, out);
      if (out.interrupted) return out;
    } catch (const std::exception& e) {
      r.reason = std::string(RunRecord::kFailed);
      r.final_class = puck_outcome_class(r.reason, kNaN);
      r.message = support::one_line(e.what());
    }
    r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return out;
  }
  try {
    const Scenario s = plan.scenario(id);
    const auto law = friction::make_law(s.law);
    const BodyOnPlane sys(s.body, s.contact, *law);
    const double weight = s.body.mass * s.contact.g;
    RunRecorder recorder(weight, options.trajectories ? plan.study().trajectory_dt : 0.0);
    const auto expected = static_cast<std::size_t>(std::min(1e9, s.run.t_end / s.run.output_dt)) + 2;
    paper::RunSeries& series = recorder.series();
    const std::size_t reserve = std::min(kMaxReserve, expected);
    series.t.reserve(reserve);
    series.gamma3.reserve(reserve);
    series.kinetic.reserve(reserve);
    series.spin.reserve(reserve);
    series.in_contact.reserve(reserve);
    RunOptions run = s.run;
    run.cancel = options.cancel;
    ShadowRecord shadow(plan, id, *law, motion_phase_rule(sys, run));
    std::optional<ShadowObserver<BodyOnPlane>> shadow_observer;
    if (shadow.laws()) shadow_observer.emplace(sys, *shadow.laws(), nullptr);
    // The recorder first: the tee samples as it asks (interpolated, run_recorder.h).
    TeeObserver<Observer, Sample> observers({&recorder, shadow_observer ? &*shadow_observer : nullptr});
    const RunSummary sum = simulate(sys, initial_state(s), run, &observers);
    if (sum.reason == Termination::interrupted) {
      out.interrupted = true;
      return out;
    }
    const paper::FeatureThresholds th;
    const paper::RunFeatures f = paper::extract_features(series, th);
    r.reason = std::string(to_string(sum.reason));
    r.t_final = sum.t_final;
    r.steps = sum.steps;
    r.rhs_calls = sum.rhs_calls + sum.sample_rhs_calls;
    r.t_vertical = f.vertical.t_reached;
    r.vertical_pole = f.vertical.pole;
    r.plateau_tilt_deg = f.plateau.found ? f.plateau.tilt_deg() : kNaN;
    r.t_rest = sum.reason == Termination::rest || sum.reason == Termination::rolling ? sum.t_final : kNaN;
    r.final_gamma3 = f.gamma3_final_mean;
    r.final_class = outcome_class(r.reason, r.final_gamma3, th);
    r.liftoffs = sum.liftoffs;
    r.min_n_over_mg = sum.min_normal_force / weight;
    r.work_slide = slide_work(sum.x_final);
    r.work_spin = spin_work(sum.x_final);
    const paper::SpinReversals reversals = paper::spin_reversals(series.t, series.spin);
    r.spin_reversals = reversals.count;
    r.t_first_reversal = reversals.t_first;
    r.final_spin_sense = reversals.final_sense;
    shadow.fill(r);
    if (sum.reason != Termination::t_end && sum.reason != Termination::rest && sum.reason != Termination::rolling)
      r.message = sum.message;
    out.series.ran = true;
    out.series.dt = s.run.output_dt;
    out.series.t = std::move(series.t);
    out.series.gamma3 = std::move(series.gamma3);
    out.series.axis = {std::move(series.axis_x), std::move(series.axis_y), std::move(series.axis_z)};
    out.finished.trajectory = std::move(recorder.trajectory());
  } catch (const std::exception& e) {
    r.reason = std::string(RunRecord::kFailed);
    r.final_class = outcome_class(r.reason, kNaN);
    r.message = support::one_line(e.what());
  }
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return out;
}

// Fills the divergence columns of `r` (its own series `own`) against `ref`.
void compare(RunRecord& r, const Reference& own, const Reference& ref, const std::string& ref_name) {
  if (!own.ran || !ref.ran || own.t.empty() || ref.t.empty()) return;
  const paper::Divergence d =
      paper::first_divergence(ref.t, ref.gamma3, own.t, own.gamma3, paper::kDivergenceThreshold, ref.dt);
  r.diverge_ref = ref_name;
  r.diverge_horizon = d.horizon;
  r.t_diverge = d.found ? d.t : kNaN;
  // The angle between the two bodies' axes (dynamics/paper/divergence.h).
  const paper::DistanceSeries axes = paper::axis_distance(ref.t, ref.axis, own.t, own.axis);
  if (axes.t.empty()) return;
  r.t_part = paper::parting_time(axes);
  r.axis_angle_deg.assign(kAxisAngleTimes.size(), kNaN);
  for (std::size_t k = 0; k < kAxisAngleTimes.size(); ++k) {
    const double T = kAxisAngleTimes[k];
    if (T <= axes.t.back()) r.axis_angle_deg[k] = paper::interpolate(axes.t, axes.angle, T) * (180.0 / std::numbers::pi);
  }
}

}  // namespace

bool execute_task(const EnsemblePlan& plan, const TaskOrder& order, const ExecuteOptions& options,
                  const std::function<void(FinishedRun&&)>& emit) {
  const Task& task = order.task;
  const auto todo = [&](long run) { return std::binary_search(order.todo.begin(), order.todo.end(), run); };
  const std::string& reference_name = plan.study().reference_law();
  Reference first_reference;  // the reference law on the pair's first replica
  for (long k = 0; k < task.replica_count; ++k) {
    const long replica = task.first_replica + k;
    const long ref_run = plan.run_index({task.start, replica, 0});
    bool others = false;
    for (int law = 1; law < plan.laws(); ++law) others = others || todo(plan.run_index({task.start, replica, law}));
    const bool floor_later = k == 0 && task.replica_count == 2 && todo(plan.run_index({task.start, replica + 1, 0}));
    if (!todo(ref_run) && !others && !floor_later) continue;

    RunOutput ref = run_one(plan, {task.start, replica, 0}, options);
    if (ref.interrupted) return false;
    if (k == 1) compare(ref.finished.record, ref.series, first_reference, "replica:" + std::to_string(task.first_replica));
    if (todo(ref_run)) emit(std::move(ref.finished));
    for (int law = 1; law < plan.laws(); ++law) {
      if (options.cancel && options.cancel->load()) return false;
      if (!todo(plan.run_index({task.start, replica, law}))) continue;
      RunOutput run = run_one(plan, {task.start, replica, law}, options);
      if (run.interrupted) return false;
      compare(run.finished.record, run.series, ref.series, reference_name);
      emit(std::move(run.finished));
    }
    if (k == 0) first_reference = std::move(ref.series);
    if (options.cancel && options.cancel->load()) return false;
  }
  return true;
}

}  // namespace frictionlab::dynamics::ensemble
