#include "dynamics/paper/trajectory_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "friction/support/errors.h"

namespace frictionlab::dynamics::paper {
namespace {

// Linear interpolation with a cursor that only moves forward (x non-decreasing between calls).
class Cursor {
 public:
  Cursor(const std::vector<double>& t, const std::vector<double>& y) : t_(t), y_(y) {}
  double at(double x) {
    if (t_.empty() || x < t_.front() || x > t_.back()) return std::numeric_limits<double>::quiet_NaN();
    while (i_ + 1 < t_.size() && t_[i_ + 1] < x) ++i_;
    if (i_ + 1 >= t_.size() || t_[i_] >= x) return y_[i_];
    const double w = (x - t_[i_]) / (t_[i_ + 1] - t_[i_]);
    return y_[i_] + w * (y_[i_ + 1] - y_[i_]);
  }

 private:
  const std::vector<double>& t_;
  const std::vector<double>& y_;
  std::size_t i_ = 0;
};

}  // namespace

double interpolate(const std::vector<double>& t, const std::vector<double>& y, double x) {
  if (t.empty() || x < t.front() || x > t.back()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
  if (j == 0) return y.front();
  if (j == t.size()) return y.back();
  const std::size_t i = j - 1;
  if (t[j] == t[i]) return y[i];
  const double w = (x - t[i]) / (t[j] - t[i]);
  return y[i] + w * (y[j] - y[i]);
}

Divergence first_divergence(const std::vector<double>& ta, const std::vector<double>& ya,
                            const std::vector<double>& tb, const std::vector<double>& yb, double threshold,
                            double dt) {
  if (!(std::isfinite(dt) && dt > 0.0))
    throw support::invalid_value("comparison grid step dt", dt, "it must be finite and > 0 s");
  if (!(std::isfinite(threshold) && threshold >= 0.0))
    throw support::invalid_value("divergence threshold", threshold, "it must be finite and >= 0");
  Divergence d;
  if (ta.empty() || tb.empty()) return d;
  const double start = std::max(ta.front(), tb.front());
  d.horizon = std::min(ta.back(), tb.back());
  Cursor a(ta, ya);
  Cursor b(tb, yb);
  for (long k = 0;; ++k) {
    double x = start + static_cast<double>(k) * dt;
    const bool last = x >= d.horizon;
    if (last) x = d.horizon;
    if (std::abs(a.at(x) - b.at(x)) > threshold) {
      d.found = true;
      d.t = x;
      return d;
    }
    if (last) break;
  }
  return d;
}

double tilt_difference_deg(double gamma3_a, double gamma3_b) {
  const auto tilt = [](double g) { return std::acos(std::clamp(g, -1.0, 1.0)); };
  return std::abs(tilt(gamma3_a) - tilt(gamma3_b)) * 180.0 / std::numbers::pi;
}

}  // namespace frictionlab::dynamics::paper
