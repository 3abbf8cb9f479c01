#include "dynamics/core/shadow_json.h"

#include <string>

namespace frictionlab::dynamics {
namespace {

constexpr double kMedian = 0.5;
constexpr double kHigh = 0.95;

support::Json error_block(const std::array<LogHistogram, kShadowOutputs>& outputs) {
  support::Json j = support::Json::object();
  for (int k = 0; k < kShadowOutputs; ++k) {
    const LogHistogram& h = outputs[static_cast<std::size_t>(k)];
    j[shadow_output_names()[static_cast<std::size_t>(k)]] = {
        {"median", h.quantile(kMedian)}, {"p95", h.quantile(kHigh)}, {"max", h.weight() > 0.0 ? support::Json(h.max()) : support::Json()}};
  }
  return j;
}

}  // namespace

support::Json shadow_json(const ShadowLaws& laws, const ShadowCsv* csv, double run_work) {
  support::Json j;
  j["evaluated_at"] =
      "statistics: the end of every accepted step, weighted by the step's length; shadow.csv: every output sample";
  j["errors_are"] = "|law - run's law| at the run's contact: F1, F2, F = hypot(F1, F2) per k N; M per k N a; P in W";
  j["quantile_resolution"] = "within 2.3 % (a logarithmic histogram, 100 bins a decade); max exact";
  j["steps"] = laws.steps();
  const MotionPhaseRule& r = laws.rule();
  j["phase_rule"] = {{"rest_slip_speed", r.rest_slip_speed},
                     {"rest_spin", r.rest_spin},
                     {"settle_normal_speed", r.settle_normal_speed}};
  support::Json times = support::Json::object();
  for (MotionPhase p : motion_phases()) times[std::string(to_string(p))] = laws.phase_time()[static_cast<std::size_t>(p)];
  j["phase_time_s"] = times;
  j["own_law"] = std::string(laws.own().spec());
  j["run_work_J"] = run_work;
  j["own_trapezoid_J"] = laws.own_dissipated();
  j["own_failures"] = laws.own_failures();
  support::Json list = support::Json::array();
  for (std::size_t i = 0; i < laws.size(); ++i) {
    const ShadowLawStatistics& s = laws.statistics(i);
    support::Json l;
    l["law"] = std::string(laws.law(i).spec());
    l["failures"] = s.failures;
    l["first_failure_time"] = s.first_failure_time >= 0.0 ? support::Json(s.first_failure_time) : support::Json();
    l["first_failure"] = s.first_failure.empty() ? support::Json() : support::Json(s.first_failure);
    l["dissipated_J"] = run_work + s.difference;
    l["difference_J"] = s.difference;
    l["skipped_time_s"] = s.skipped_time;
    support::Json errors;
    errors["contact"] = error_block(s.errors[kMotionPhases]);
    for (MotionPhase p : motion_phases()) {
      if (p == MotionPhase::airborne) continue;
      errors[std::string(to_string(p))] = error_block(s.errors[static_cast<std::size_t>(p)]);
    }
    l["errors"] = errors;
    list.push_back(l);
  }
  j["laws"] = list;
  if (csv) {
    j["csv"] = {{"file", csv->path().filename().string()},
                {"rows", csv->rows()},
                {"bytes", csv->bytes()},
                {"error", csv->error().empty() ? support::Json() : support::Json(csv->error())}};
  }
  return j;
}

}  // namespace frictionlab::dynamics
