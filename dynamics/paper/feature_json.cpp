#include "dynamics/paper/feature_json.h"

#include <cmath>

namespace frictionlab::dynamics::paper {
namespace {

support::Json episode(const VerticalEpisode& e, double t_final) {
  return {{"reached", e.reached}, {"t_reached", e.t_reached}, {"pole", e.pole},
          {"left", e.left},       {"t_left", e.t_left},       {"duration", e.duration(t_final)}};
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

}  // namespace frictionlab::dynamics::paper
