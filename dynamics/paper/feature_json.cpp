#include "dynamics/paper/feature_json.h"

#include <charconv>
#include <cmath>
#include <string>

namespace frictionlab::dynamics::paper {
namespace {

std::string num(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string boolean(bool b) { return b ? "true" : "false"; }

std::string episode(const VerticalEpisode& e, double t_final) {
  return "{\"reached\": " + boolean(e.reached) + ", \"t_reached\": " + num(e.t_reached) +
         ", \"pole\": " + std::to_string(e.pole) + ", \"left\": " + boolean(e.left) + ", \"t_left\": " +
         num(e.t_left) + ", \"duration\": " + num(e.duration(t_final)) + "}";
}

}  // namespace

void write_features_json(std::ostream& out, const RunFeatures& f, const FeatureThresholds& th) {
  const Plateau& p = f.plateau;
  out << "{\n"
      << "  \"thresholds\": {\"vertical\": " << num(th.vertical) << ", \"near_vertical\": " << num(th.near_vertical)
      << ", \"smoothing_window_s\": " << num(th.smoothing_window) << ", \"plateau_window_s\": " << num(th.plateau_window) << ", \"plateau_band\": " << num(th.plateau_band)
      << ", \"plateau_rate_per_s\": " << num(th.plateau_rate) << ", \"plateau_min_move\": "
      << num(th.plateau_min_move) << ", \"first_move\": " << num(th.first_move) << "},\n"
      << "  \"t_final\": " << num(f.t_final) << ",\n"
      << "  \"gamma3_initial\": " << num(f.gamma3_initial) << ",\n"
      << "  \"gamma3_final\": " << num(f.gamma3_final) << ",\n"
      << "  \"gamma3_final_mean\": " << num(f.gamma3_final_mean) << ",\n"
      << "  \"kinetic_final\": " << num(f.kinetic_final) << ",\n"
      << "  \"max_abs_gamma3\": " << num(f.max_abs_gamma3) << ",\n"
      << "  \"first_move\": {\"direction\": " << f.first_move << ", \"t\": " << num(f.t_first_move) << "},\n"
      << "  \"vertical\": " << episode(f.vertical, f.t_final) << ",\n"
      << "  \"near_vertical\": " << episode(f.near_vertical, f.t_final) << ",\n"
      << "  \"plateau\": {\"found\": " << boolean(p.found) << ", \"t_from\": " << num(p.t_from)
      << ", \"t_start\": " << num(p.t_start) << ", \"gamma3\": " << num(p.gamma3) << ", \"tilt_deg\": "
      << num(p.found ? p.tilt_deg() : std::nan("")) << ", \"t_end\": " << num(p.t_end)
      << ", \"lasts_to_end\": " << boolean(p.lasts_to_end) << "},\n"
      << "  \"rise_extreme\": " << num(f.rise_extreme) << ",\n"
      << "  \"descent_oscillation\": " << num(f.descent_oscillation) << ",\n"
      << "  \"sampled_liftoffs\": " << f.sampled_liftoffs << ",\n"
      << "  \"sampled_liftoffs_before_plateau\": " << f.sampled_liftoffs_before_plateau << ",\n"
      << "  \"last_sampled_liftoff\": " << num(f.last_sampled_liftoff) << "\n"
      << "}\n";
}

}  // namespace frictionlab::dynamics::paper
