#include "dynamics/paper/feature_json.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace frictionlab::dynamics::paper {
namespace {

support::Json episode(const VerticalEpisode& e, double t_final) {
  return {{"reached", e.reached}, {"t_reached", e.t_reached}, {"pole", e.pole},
          {"left", e.left},       {"t_left", e.t_left},       {"duration", e.duration(t_final)}};
}

const support::Json& member(const support::Json& j, const char* key) {
  if (!j.is_object() || !j.contains(key)) throw std::runtime_error(std::string("features.json: '") + key + "' is missing");
  return j.at(key);
}

double number(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (v.is_null()) return kNaN;
  if (!v.is_number()) throw std::runtime_error(std::string("features.json: '") + key + "' is not a number");
  return v.get<double>();
}

long integer(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (!v.is_number_integer()) throw std::runtime_error(std::string("features.json: '") + key + "' is not an integer");
  return v.get<long>();
}

bool flag(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (!v.is_boolean()) throw std::runtime_error(std::string("features.json: '") + key + "' is not true or false");
  return v.get<bool>();
}

VerticalEpisode episode_from(const support::Json& j) {
  VerticalEpisode e;
  e.reached = flag(j, "reached");
  e.t_reached = number(j, "t_reached");
  e.pole = static_cast<int>(integer(j, "pole"));
  e.left = flag(j, "left");
  e.t_left = number(j, "t_left");
  return e;
}

}  // namespace

support::Json features_json(const RunFeatures& f, const FeatureThresholds& th) {
  const Plateau& p = f.plateau;
  support::Json j;
  j["thresholds"] = {{"vertical", th.vertical},
                     {"near_vertical", th.near_vertical},
                     {"smoothing_window_s", th.smoothing_window},
                     {"plateau_window_s", th.plateau_window},
                     {"plateau_band", th.plateau_band},
                     {"plateau_rate_per_s", th.plateau_rate},
                     {"plateau_min_move", th.plateau_min_move},
                     {"first_move", th.first_move}};
  j["t_final"] = f.t_final;
  j["gamma3_initial"] = f.gamma3_initial;
  j["gamma3_final"] = f.gamma3_final;
  j["gamma3_final_mean"] = f.gamma3_final_mean;
  j["kinetic_final"] = f.kinetic_final;
  j["max_abs_gamma3"] = f.max_abs_gamma3;
  j["first_move"] = {{"direction", f.first_move}, {"t", f.t_first_move}};
  j["vertical"] = episode(f.vertical, f.t_final);
  j["near_vertical"] = episode(f.near_vertical, f.t_final);
  j["plateau"] = {{"found", p.found},
                  {"t_from", p.t_from},
                  {"t_start", p.t_start},
                  {"gamma3", p.gamma3},
                  {"tilt_deg", p.found ? p.tilt_deg() : std::nan("")},
                  {"t_end", p.t_end},
                  {"lasts_to_end", p.lasts_to_end}};
  j["rise_extreme"] = f.rise_extreme;
  j["descent_oscillation"] = f.descent_oscillation;
  j["sampled_liftoffs"] = f.sampled_liftoffs;
  j["sampled_liftoffs_before_plateau"] = f.sampled_liftoffs_before_plateau;
  j["last_sampled_liftoff"] = f.last_sampled_liftoff;
  return j;
}

RunFeatures features_from_json(const support::Json& j) {
  RunFeatures f;
  f.t_final = number(j, "t_final");
  f.gamma3_initial = number(j, "gamma3_initial");
  f.gamma3_final = number(j, "gamma3_final");
  f.gamma3_final_mean = number(j, "gamma3_final_mean");
  f.kinetic_final = number(j, "kinetic_final");
  f.max_abs_gamma3 = number(j, "max_abs_gamma3");
  const support::Json& first = member(j, "first_move");
  f.first_move = static_cast<int>(integer(first, "direction"));
  f.t_first_move = number(first, "t");
  f.vertical = episode_from(member(j, "vertical"));
  f.near_vertical = episode_from(member(j, "near_vertical"));
  const support::Json& p = member(j, "plateau");
  f.plateau.found = flag(p, "found");
  f.plateau.t_from = number(p, "t_from");
  f.plateau.t_start = number(p, "t_start");
  f.plateau.gamma3 = number(p, "gamma3");
  f.plateau.t_end = number(p, "t_end");
  f.plateau.lasts_to_end = flag(p, "lasts_to_end");
  f.rise_extreme = number(j, "rise_extreme");
  f.descent_oscillation = number(j, "descent_oscillation");
  f.sampled_liftoffs = integer(j, "sampled_liftoffs");
  f.sampled_liftoffs_before_plateau = integer(j, "sampled_liftoffs_before_plateau");
  f.last_sampled_liftoff = number(j, "last_sampled_liftoff");
  return f;
}

}  // namespace frictionlab::dynamics::paper
