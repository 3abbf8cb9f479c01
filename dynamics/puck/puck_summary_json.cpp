#include "dynamics/puck/puck_summary_json.h"

#include <cmath>

#include "dynamics/puck/terminal_ratio.h"
#include "dynamics/body/summary_json.h"

namespace frictionlab::dynamics::puck {
namespace {

support::Json vec2(const Eigen::Vector2d& v) { return support::Json::array({v[0], v[1]}); }
support::Json vec(const std::vector<double>& v) { return support::Json(v); }

}  // namespace

PathOffset path_offset(const Eigen::Vector2d& start, const Eigen::Vector2d& direction, const Eigen::Vector2d& end) {
  const double n = direction.norm();
  if (!(n > 0.0)) return {};
  const Eigen::Vector2d d = direction / n;
  const Eigen::Vector2d r = end - start;
  return {r.dot(d), d.x() * r.y() - d.y() * r.x()};
}

support::Json puck_summary_json(const PuckScenario& scenario, const friction::FrictionLaw& law, const PuckRunSummary& s) {
  const Puck& p = scenario.puck;
  const PuckState& x = s.x_final;
  support::Json j;
  j["scenario"] = {{"name", scenario.name}, {"source", scenario.source}, {"overrides", scenario.overrides}};
  j["model"] = "puck";
  j["law"] = scenario.law;
  j["termination"] = termination_json(s.reason, s.message, s.rule, s.thresholds);
  j["final_time"] = s.t_final;
  j["t_end"] = scenario.run.t_end;
  j["slip_stop_time"] = s.slip_stop_time;
  j["spin_stop_time"] = s.spin_stop_time;
  j["terminal_ratio"] = s.terminal_ratio;
  j["terminal_ratio_limit"] = s.terminal_ratio_limit;
  support::Json by_energy = support::Json::array();
  for (const RatioAtEnergy& r : s.ratio_by_energy)
    by_energy.push_back({{"level", r.level}, {"t", r.t}, {"kinetic_fraction", r.fraction}, {"ratio", r.ratio}});
  j["ratio_by_energy"] = by_energy;
  if (p.a == p.b) {
    const TerminalRatioAnalysis a = analyse_terminal_ratio(law, p.inertia_ratio());
    j["terminal_ratio_theory"] = {{"kappa", a.kappa},
                                  {"regime", a.regime},
                                  {"attracting", vec(a.attracting)},
                                  {"convergence_exponents", vec(a.exponents)},
                                  {"repelling", vec(a.repelling)},
                                  {"small_ratio_slope", a.small_slope},
                                  {"large_ratio_limit", a.large_limit}};
  } else {
    j["terminal_ratio_theory"] = nullptr;  // the fixed-point analysis is for a circular patch
  }
  const PathOffset off = path_offset(scenario.initial.position, scenario.initial.v, position(x));
  j["path"] = {{"distance", (position(x) - scenario.initial.position).norm()},
               {"along_initial_velocity", off.along},
               {"lateral_deviation", off.lateral},
               {"heading_turned", heading(x) - scenario.initial.heading}};
  j["steps"] = s.steps;
  j["rejected_steps"] = s.rejected_steps;
  j["rhs_calls"] = s.rhs_calls;
  j["samples"] = s.samples;
  j["sample_rhs_calls"] = s.sample_rhs_calls;
  j["hermite_samples"] = s.hermite_samples;
  j["wall_time_s"] = s.wall_time;
  j["initial_energy"] = s.initial_energy;
  j["final_energy"] = s.final_energy;
  j["work_sliding"] = slide_work(x);
  j["work_spinning"] = spin_work(x);
  j["held_slide_energy"] = s.held_slide_energy;
  j["held_spin_energy"] = s.held_spin_energy;
  j["energy_balance_error"] = s.final_energy + slide_work(x) + spin_work(x) - s.initial_energy;
  j["final_state"] = {{"t", s.t_final},
                      {"position", vec2(position(x))},
                      {"heading", heading(x)},
                      {"v", vec2(velocity(x))},
                      {"omega", spin(x)},
                      {"slip_held", s.holds.slip},
                      {"spin_held", s.holds.spin}};
  j["puck"] = {{"mass", p.mass}, {"inertia", p.inertia}, {"inertia_default", !scenario.inertia_given},
               {"a", p.a},       {"b", p.b},             {"inertia_ratio", p.inertia_ratio()}};
  j["contact"] = {{"k", scenario.k}, {"g", scenario.g}, {"N", p.mass * scenario.g}};
  j["integrator"] = {{"method", scenario.run.integrator.method},
                     {"abs_tol", scenario.run.integrator.abs_tol},
                     {"rel_tol", scenario.run.integrator.rel_tol},
                     {"output_dt", scenario.run.output_dt},
                     {"abs_tol_per_component",
                      {{"position", position(s.abs_tol)[0]},
                       {"heading", heading(s.abs_tol)},
                       {"v", velocity(s.abs_tol)[0]},
                       {"omega", spin(s.abs_tol)},
                       {"work", slide_work(s.abs_tol)}}}};
  const BodyScales sc = puck_scales(p, scenario.g);
  j["scales"] = {{"size_a", sc.size}, {"speed_sqrt_ga", sc.speed}, {"rate_sqrt_g_over_a", sc.rate}, {"energy_mga", sc.energy}};
  j["rest_thresholds"] = {{"slip_speed", s.slip_speed.value}, {"spin", s.spin.value}};
  return j;
}

}  // namespace frictionlab::dynamics::puck
