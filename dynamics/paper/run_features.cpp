#include "dynamics/paper/run_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace frictionlab::dynamics::paper {
namespace {

void require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("feature threshold ") + name + " = " + std::to_string(value) +
                                       " is invalid: " + rule);
}

int sign(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

// Index of the first sample at or after time x (size() if none).
std::size_t index_at(const std::vector<double>& t, double x) {
  return static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), x) - t.begin());
}

// The vertical episode with entry at |gamma3| > level_in, exit when the moving average (pole side)
// falls below level_out once its window lies after the entry.
VerticalEpisode vertical_episode(const RunSeries& s, const std::vector<double>& smooth, double level_in,
                                 double level_out, double window) {
  VerticalEpisode e;
  const std::size_t n = s.size();
  std::size_t i_in = n;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::abs(s.gamma3[i]) > level_in) {
      i_in = i;
      break;
    }
  }
  if (i_in == n) return e;
  e.reached = true;
  e.t_reached = s.t[i_in];
  e.pole = sign(s.gamma3[i_in]);
  for (std::size_t j = index_at(s.t, e.t_reached + 0.5 * window); j < n; ++j) {
    if (smooth[j] * e.pole < level_out) {
      e.left = true;
      e.t_left = s.t[j];
      break;
    }
  }
  return e;
}

}  // namespace

void FeatureThresholds::validate() const {
  require(std::isfinite(vertical) && vertical < 1.0, "vertical", vertical, "it must be finite and < 1");
  require(std::isfinite(near_vertical) && near_vertical > 0.0 && near_vertical < vertical, "near_vertical",
          near_vertical, "it must be in (0, vertical)");
  require(std::isfinite(smoothing_window) && smoothing_window > 0.0, "smoothing_window", smoothing_window,
          "it must be finite and > 0 s");
  require(std::isfinite(plateau_band) && plateau_band > 0.0, "plateau_band", plateau_band, "it must be finite and > 0");
  require(std::isfinite(plateau_rate) && plateau_rate > 0.0, "plateau_rate", plateau_rate,
          "it must be finite and > 0 1/s");
  require(std::isfinite(plateau_min_move) && plateau_min_move > 0.0, "plateau_min_move", plateau_min_move,
          "it must be finite and > 0");
  require(std::isfinite(first_move) && first_move > 0.0, "first_move", first_move, "it must be finite and > 0");
}

double Plateau::tilt_deg() const { return std::acos(std::clamp(gamma3, -1.0, 1.0)) * 180.0 / std::numbers::pi; }

std::vector<double> moving_average(const std::vector<double>& t, const std::vector<double>& y, double window) {
  const std::size_t n = t.size();
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + y[i];
  std::vector<double> out(n);
  std::size_t lo = 0;
  std::size_t hi = 0;  // window = [lo, hi)
  for (std::size_t i = 0; i < n; ++i) {
    while (lo < i && t[lo] < t[i] - 0.5 * window) ++lo;
    if (hi < i + 1) hi = i + 1;
    while (hi < n && t[hi] <= t[i] + 0.5 * window) ++hi;
    out[i] = (prefix[hi] - prefix[lo]) / static_cast<double>(hi - lo);
  }
  return out;
}

RunFeatures extract_features(const RunSeries& s, const FeatureThresholds& th) {
  th.validate();
  RunFeatures f;
  const std::size_t n = s.size();
  if (n == 0) return f;
  const auto& t = s.t;
  const auto& g = s.gamma3;
  const double W = th.smoothing_window;
  f.t_final = t.back();
  f.gamma3_initial = g.front();
  f.gamma3_final = g.back();
  if (!s.kinetic.empty()) f.kinetic_final = s.kinetic.back();

  for (std::size_t i = 1; i < n; ++i) {
    if (std::abs(g[i] - g[0]) > th.first_move) {
      f.first_move = sign(g[i] - g[0]);
      f.t_first_move = t[i];
      break;
    }
  }

  const std::vector<double> smooth = moving_average(t, g, W);
  f.vertical = vertical_episode(s, smooth, th.vertical, th.near_vertical, W);
  f.near_vertical = vertical_episode(s, smooth, th.near_vertical, th.near_vertical, W);

  // The plateau: the fast tilt after the vertical spin (or from the start) has ended.
  Plateau& p = f.plateau;
  const std::size_t i0 = f.vertical.left ? index_at(t, f.vertical.t_left) : 0;
  p.t_from = t[std::min(i0, n - 1)];
  const double anchor = i0 == 0 ? g[0] : smooth[i0];
  const double t_lo = t.front() + 0.5 * W;
  const double t_hi = t.back() - 0.5 * W;
  std::size_t i_p = n;
  {
    std::size_t lo = 0;
    std::size_t hi = 0;
    for (std::size_t i = i0; i < n && t[i] <= t_hi; ++i) {
      if (t[i] < t_lo) continue;
      while (lo < i && t[lo] < t[i] - 0.5 * W) ++lo;
      if (hi < i) hi = i;
      while (hi + 1 < n && t[hi + 1] <= t[i] + 0.5 * W) ++hi;
      if (t[hi] <= t[lo]) continue;
      const double rate = (smooth[hi] - smooth[lo]) / (t[hi] - t[lo]);
      if (std::abs(smooth[i] - anchor) > th.plateau_min_move && std::abs(rate) < th.plateau_rate) {
        i_p = i;
        break;
      }
    }
  }
  std::size_t i_end = n;
  if (i_p < n) {
    p.found = true;
    p.t_start = t[i_p];
    p.gamma3 = smooth[i_p];
    for (std::size_t j = i_p + 1; j < n; ++j) {
      if (std::abs(smooth[j] - p.gamma3) > th.plateau_band) {
        i_end = j;
        break;
      }
    }
    p.lasts_to_end = i_end == n;
    p.t_end = p.lasts_to_end ? t.back() : t[i_end];

    const int dir = sign(p.gamma3 - g[0]);
    double extreme = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i <= i_p; ++i) extreme = std::max(extreme, dir * g[i]);
    f.rise_extreme = extreme;

    if (!p.lasts_to_end) {
      double hi_dev = -std::numeric_limits<double>::infinity();
      double lo_dev = std::numeric_limits<double>::infinity();
      for (std::size_t j = i_end; j < n && t[j] <= t_hi; ++j) {
        hi_dev = std::max(hi_dev, g[j] - smooth[j]);
        lo_dev = std::min(lo_dev, g[j] - smooth[j]);
      }
      if (hi_dev >= lo_dev) f.descent_oscillation = hi_dev - lo_dev;
    }
  }

  const double t_rise_end = p.found ? p.t_start : std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < n && i < s.in_contact.size(); ++i) {
    if (s.in_contact[i - 1] && !s.in_contact[i]) {
      ++f.sampled_liftoffs;
      if (t[i] <= t_rise_end) ++f.sampled_liftoffs_before_plateau;
      f.last_sampled_liftoff = t[i];
    }
  }
  return f;
}

}  // namespace frictionlab::dynamics::paper
