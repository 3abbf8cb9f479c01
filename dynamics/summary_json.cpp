#include "dynamics/summary_json.h"

namespace frictionlab::dynamics {
namespace {

support::Json vec3(const Eigen::Vector3d& v) { return support::Json::array({v[0], v[1], v[2]}); }

}  // namespace

support::Json summary_json(const Scenario& scenario, const RunSummary& s) {
  const Body& body = scenario.body;
  const double weight = body.mass * scenario.contact.g;
  const StateVector& x = s.x_final;
  support::Json j;
  j["scenario"] = {{"name", scenario.name}, {"source", scenario.source}, {"overrides", scenario.overrides}};
  j["law"] = scenario.law;
  j["termination"] = {{"reason", to_string(s.reason)}, {"message", s.message}};
  j["final_time"] = s.t_final;
  j["t_end"] = scenario.run.t_end;
  j["steps"] = s.steps;
  j["rejected_steps"] = s.rejected_steps;
  j["rhs_calls"] = s.rhs_calls;
  j["wall_time_s"] = s.wall_time;
  j["liftoffs"] = s.liftoffs;
  j["landings"] = s.landings;
  j["min_N_over_mg"] = weight > 0.0 ? support::Json(s.min_normal_force / weight) : support::Json(nullptr);
  j["initial_energy"] = s.initial_energy;
  j["final_energy"] = s.final_energy;
  j["work_sliding"] = slide_work(x);
  j["work_spinning"] = spin_work(x);
  j["energy_balance_error"] = s.final_energy + slide_work(x) + spin_work(x) - s.initial_energy;
  j["max_gamma_drift"] = s.max_gamma_drift;
  j["final_state"] = {{"t", s.t_final},
                      {"gamma", vec3(vertical(x))},
                      {"omega", vec3(angular_velocity(x))},
                      {"v", vec3(velocity(x))},
                      {"eps", height(x)}};
  j["body"] = {{"profile", scenario.body_spec.preset.empty() ? std::string("chi2") : scenario.body_spec.preset},
               {"chi2", body.profile.chi2().coefficients()},
               {"z_lo", body.profile.z_lo()},
               {"z_hi", body.profile.z_hi()},
               {"mass", body.mass},
               {"com", body.com},
               {"A", body.A},
               {"C", body.C},
               {"homogeneous_centroid", body.homogeneous.centroid}};
  j["contact"] = {{"k", scenario.contact.k}, {"lambda", scenario.contact.lambda}, {"g", scenario.contact.g}};
  j["integrator"] = {{"method", scenario.run.integrator.method},
                     {"abs_tol", scenario.run.integrator.abs_tol},
                     {"rel_tol", scenario.run.integrator.rel_tol},
                     {"output_dt", scenario.run.output_dt}};
  j["rest_thresholds"] = {{"slip_speed", scenario.run.rest.slip_speed},
                          {"spin", scenario.run.rest.spin},
                          {"kinetic_energy", scenario.run.rest.kinetic_energy}};
  return j;
}

}  // namespace frictionlab::dynamics
