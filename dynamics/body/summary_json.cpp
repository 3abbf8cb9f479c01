#include "dynamics/body/summary_json.h"

namespace frictionlab::dynamics {
namespace {

support::Json vec3(const Eigen::Vector3d& v) { return support::Json::array({v[0], v[1], v[2]}); }

}  // namespace

support::Json termination_json(Termination reason, const std::string& message, const std::string& rule,
                               const std::vector<Threshold>& thresholds) {
  support::Json list = support::Json::array();
  for (const Threshold& t : thresholds)
    list.push_back({{"key", t.key}, {"value", t.value}, {"unit", t.unit}, {"source", t.source}});
  return {{"reason", to_string(reason)}, {"message", message}, {"rule", rule}, {"thresholds", list}};
}

support::Json summary_json(const Scenario& scenario, const RunSummary& s) {
  const Body& body = scenario.body;
  const double weight = body.mass * scenario.contact.g;
  const StateVector& x = s.x_final;
  support::Json j;
  j["scenario"] = {{"name", scenario.name}, {"source", scenario.source}, {"overrides", scenario.overrides}};
  j["law"] = scenario.law;
  j["termination"] = termination_json(s.reason, s.message, s.rule, s.thresholds);
  j["final_time"] = s.t_final;
  j["t_end"] = scenario.run.t_end;
  j["steps"] = s.steps;
  j["rejected_steps"] = s.rejected_steps;
  j["rhs_calls"] = s.rhs_calls;
  j["samples"] = s.samples;
  j["sample_rhs_calls"] = s.sample_rhs_calls;
  j["hermite_samples"] = s.hermite_samples;
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
  // The final pose (dynamics/body/state.h): not fed back, carried beside the state (run.pose).
  if (scenario.run.pose) {
    const Eigen::Quaterniond q = orientation_quaternion(x);
    j["final_state"]["position"] = support::Json::array({position(x)[0], position(x)[1]});
    j["final_state"]["orientation"] = support::Json::array({q.w(), q.x(), q.y(), q.z()});
  }
  if (body.axisymmetric) {
    const AxisymmetricBody& a = *body.axisymmetric;
    j["body"] = {{"profile", scenario.body_spec.preset.empty() ? std::string("chi2") : scenario.body_spec.preset},
                 {"chi2", a.profile.chi2().coefficients()},
                 {"z_lo", a.profile.z_lo()},
                 {"z_hi", a.profile.z_hi()},
                 {"mass", body.mass},
                 {"com", a.com},
                 {"A", a.A},
                 {"C", a.C},
                 {"homogeneous_centroid", a.homogeneous.centroid}};
  } else {
    j["body"] = {{"mass", body.mass}, {"homogeneous_centroid", vec3(body.homogeneous.centroid)}};
  }
  j["body"]["shape"] = std::string(body.shape->kind());
  if (!scenario.body_spec.shape_parameters.empty()) {
    support::Json parameters = support::Json::object();
    for (const auto& [name, values] : scenario.body_spec.shape_parameters)
      parameters[name] = values.size() == 1 ? support::Json(values.front()) : support::Json(values);
    j["body"]["parameters"] = parameters;
  }
  j["body"]["centre_of_mass"] = vec3(body.centre_of_mass);
  support::Json inertia = support::Json::array();
  for (int i = 0; i < 3; ++i) inertia.push_back(vec3(body.inertia.row(i).transpose()));
  j["body"]["inertia"] = inertia;
  j["contact"] = {{"k", scenario.contact.k}, {"lambda", scenario.contact.lambda}, {"g", scenario.contact.g}};
  j["contact"]["patch"] = scenario.contact.patch == PatchModel::hertz ? "hertz" : "section";
  if (scenario.contact.patch == PatchModel::hertz) j["contact"]["E_star"] = scenario.contact.E_star;
  j["integrator"] = {{"method", scenario.run.integrator.method},
                     {"abs_tol", scenario.run.integrator.abs_tol},
                     {"rel_tol", scenario.run.integrator.rel_tol},
                     {"output_dt", scenario.run.output_dt},
                     {"abs_tol_per_component",
                      {{"v", velocity(s.abs_tol)[0]},
                       {"omega", angular_velocity(s.abs_tol)[0]},
                       {"gamma", vertical(s.abs_tol)[0]},
                       {"eps", height(s.abs_tol)},
                       {"work", slide_work(s.abs_tol)}}}};
  j["scales"] = {{"size_R", s.scales.size},
                 {"speed_sqrt_gR", s.scales.speed},
                 {"rate_sqrt_g_over_R", s.scales.rate},
                 {"energy_mgR", s.scales.energy},
                 {"static_compression", s.scales.compression},
                 {"liftoff_speed", s.scales.liftoff_speed}};
  j["rest_thresholds"] = {{"slip_speed", s.rest.slip_speed.value},
                          {"spin", s.rest.spin.value},
                          {"kinetic_energy", s.rest.kinetic_energy.value},
                          {"settle_time", s.settle.time.value},
                          {"settle_normal_speed", s.settle.normal_speed.value}};
  j["stick"] = {{"enabled", scenario.run.stick},
                {"degenerate_law", s.stick_degenerate},
                {"entries", s.stick_entries},
                {"exits", s.stick_exits},
                {"time_s", s.stick_time},
                {"first_entry_time", s.first_stick_entry >= 0.0 ? support::Json(s.first_stick_entry) : support::Json(nullptr)},
                {"first_exit_time", s.first_stick_exit >= 0.0 ? support::Json(s.first_stick_exit) : support::Json(nullptr)},
                {"projections", s.stick_projections},
                {"creep_entries", s.creep_entries},
                {"creep_unresolved", s.creep_unresolved},
                {"projection_loss", s.stick_projection_loss},
                {"limit_set_evaluations", s.limit_set_evaluations},
                {"hold_time", s.stick_hold.value}};
  j["slip_hold"] = {{"enabled", scenario.run.slip_hold},
                    {"entries", s.hold_entries},
                    {"exits", s.hold_exits},
                    {"time_s", s.hold_time},
                    {"first_entry_time", s.first_hold_entry >= 0.0 ? support::Json(s.first_hold_entry) : support::Json(nullptr)},
                    {"law_evaluations", s.hold_evaluations},
                    {"zero_slip_entries", s.hold_zero_entries},
                    {"force_limit_exits", s.hold_force_exits},
                    {"first_force_limit_exit_time",
                     s.first_force_exit >= 0.0 ? support::Json(s.first_force_exit) : support::Json(nullptr)}};
  j["spin_hold"] = {{"enabled", scenario.run.slip_hold},
                    {"entries", s.spin_hold_entries},
                    {"exits", s.spin_hold_exits},
                    {"moment_limit_exits", s.spin_moment_exits},
                    {"time_s", s.spin_hold_time},
                    {"first_entry_time",
                     s.first_spin_hold_entry >= 0.0 ? support::Json(s.first_spin_hold_entry) : support::Json(nullptr)}};
  return j;
}

}  // namespace frictionlab::dynamics
