#include "dynamics/paper/run_features.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::paper {
namespace {

void require(bool ok, const char* name, double value, const char* rule) {
  if (!ok) throw support::invalid_value(std::string("feature threshold ") + name, value, rule);
}

int sign(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

// Index of the first sample at or after time x (size() if none).
std::size_t index_at(const std::vector<double>& t, double x) {
  return static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), x) - t.begin());
}

// Entry at |gamma3| > level_in; a spin that has ended when <gamma3>_1 (on the pole's side) has
// reached `level_out`, fallen below it, and later fallen below `level_out - move_on`.
VerticalEpisode vertical_episode(const RunSeries& s, const std::vector<double>& smooth, double level_in,
                                 double level_out, double move_on) {
  VerticalEpisode e;
  const std::size_t n = s.size();
  std::size_t i = 0;
  while (i < n && !(std::abs(s.gamma3[i]) > level_in)) ++i;
  if (i == n) return e;
  e.reached = true;
  e.t_reached = s.t[i];
  e.pole = sign(s.gamma3[i]);
  while (i < n && smooth[i] * e.pole < level_out) ++i;  // the mean settles near the vertical
  while (i < n && smooth[i] * e.pole >= level_out) ++i;  // ... and leaves it
  if (i == n) return e;
  const std::size_t left = i;
  while (i < n && smooth[i] * e.pole >= level_out - move_on) ++i;  // ... for good
  if (i == n) return e;
  e.left = true;
  e.t_left = s.t[left];
  return e;
}

}  // namespace

void FeatureThresholds::validate() const {
  require(std::isfinite(vertical) && vertical < 1.0, "vertical", vertical, "it must be finite and < 1");
  require(std::isfinite(near_vertical) && near_vertical > 0.0 && near_vertical < vertical, "near_vertical",
          near_vertical, "it must be in (0, vertical)");
  require(std::isfinite(smoothing_window) && smoothing_window > 0.0, "smoothing_window", smoothing_window,
          "it must be finite and > 0 s");
  require(std::isfinite(plateau_window) && plateau_window > 0.0, "plateau_window", plateau_window,
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
  // Compensated (Neumaier) prefix sums: a 450 s run has 45 000 samples; plain prefix sums would
  // lose ~1e-9 of the mean to cancellation.
  std::vector<double> sum(n + 1, 0.0);
  std::vector<double> comp(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double s1 = sum[i] + y[i];
    comp[i + 1] = comp[i] + (std::abs(sum[i]) >= std::abs(y[i]) ? (sum[i] - s1) + y[i] : (y[i] - s1) + sum[i]);
    sum[i + 1] = s1;
  }
  std::vector<double> out(n);
  const double half = 0.5 * window;
  std::size_t lo = 0;
  std::size_t hi = 0;  // the window is [lo, hi)
  for (std::size_t i = 0; i < n; ++i) {
    // Samples on a grid sit exactly on the window's edges: include both, whatever the rounding.
    const double slack = 1e-9 * (1.0 + std::abs(t[i]));
    while (lo < i && t[lo] < t[i] - half - slack) ++lo;
    hi = std::max(hi, i + 1);
    while (hi < n && t[hi] <= t[i] + half + slack) ++hi;
    out[i] = ((sum[hi] - sum[lo]) + (comp[hi] - comp[lo])) / static_cast<double>(hi - lo);
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
  f.t_final = t.back();
  f.gamma3_initial = g.front();
  f.gamma3_final = g.back();
  if (!s.kinetic.empty()) f.kinetic_final = s.kinetic.back();
  f.max_abs_gamma3 = 0.0;
  for (const double x : g) f.max_abs_gamma3 = std::max(f.max_abs_gamma3, std::abs(x));

  for (std::size_t i = 1; i < n; ++i) {
    if (std::abs(g[i] - g[0]) > th.first_move) {
      f.first_move = sign(g[i] - g[0]);
      f.t_first_move = t[i];
      break;
    }
  }

  const std::vector<double> mean1 = moving_average(t, g, th.smoothing_window);
  {
    const std::size_t from = index_at(t, t.back() - th.smoothing_window);
    double sum = 0.0;
    for (std::size_t i = from; i < n; ++i) sum += g[i];
    f.gamma3_final_mean = sum / static_cast<double>(n - from);
  }
  f.vertical = vertical_episode(s, mean1, th.vertical, th.near_vertical, th.plateau_min_move);
  f.near_vertical = vertical_episode(s, mean1, th.near_vertical, th.near_vertical, th.plateau_min_move);

  // The plateau: where the fast tilt after the vertical spin (or from the start) ends.
  const std::vector<double> mean5 = moving_average(t, g, th.plateau_window);
  const double half = 0.5 * th.plateau_window;
  Plateau& p = f.plateau;
  const std::size_t i0 = f.vertical.left ? index_at(t, f.vertical.t_left) : 0;
  p.t_from = t[std::min(i0, n - 1)];
  const double anchor = i0 == 0 ? g[0] : mean5[i0];
  std::size_t i_p = n;
  for (std::size_t i = std::max(i0, index_at(t, t.front() + half)); i < n && t[i] <= t.back() - half; ++i) {
    const std::size_t lo = index_at(t, t[i] - half);
    const std::size_t hi = std::min(n - 1, index_at(t, t[i] + half));
    if (!(t[hi] > t[lo])) continue;
    const double rate = (mean5[hi] - mean5[lo]) / (t[hi] - t[lo]);
    if (std::abs(mean5[i] - anchor) > th.plateau_min_move && std::abs(rate) < th.plateau_rate) {
      i_p = i;
      break;
    }
  }
  if (i_p < n) {
    p.found = true;
    p.t_start = t[i_p];
    p.gamma3 = mean5[i_p];
    std::size_t i_end = i_p + 1;
    while (i_end < n && std::abs(mean5[i_end] - p.gamma3) <= th.plateau_band) ++i_end;
    p.lasts_to_end = i_end >= n;
    p.t_end = p.lasts_to_end ? t.back() : t[i_end];

    const int dir = sign(p.gamma3 - g[0]);
    double extreme = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i <= i_p; ++i) extreme = std::max(extreme, dir * g[i]);
    f.rise_extreme = extreme;

    if (!p.lasts_to_end) {
      double hi_dev = -std::numeric_limits<double>::infinity();
      double lo_dev = std::numeric_limits<double>::infinity();
      for (std::size_t j = i_end; j < n && !(std::abs(g[j]) > th.vertical); ++j) {
        hi_dev = std::max(hi_dev, g[j] - mean1[j]);
        lo_dev = std::min(lo_dev, g[j] - mean1[j]);
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
