#include "dynamics/paper/figure_data.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "friction/support/checked_output.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

constexpr double kMilli = 1e3;  // m -> mm, N m -> N mm

struct Stats {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  int count = 0;
  void add(double x) {
    if (!std::isfinite(x)) return;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    sum += x;
    ++count;
  }
  [[nodiscard]] double mean() const { return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN(); }
};

// Seven significant digits (plenty for a figure); "NaN" is gnuplot's missing value.
std::string cell(double x) { return std::isfinite(x) ? support::significant(x, 7) : "NaN"; }

std::string triple(const Stats& x) {
  return x.count > 0 ? cell(x.lo) + ' ' + cell(x.hi) + ' ' + cell(x.mean()) : std::string("NaN NaN NaN");
}

void raise(double& cap, const Stats& x) {
  if (x.count > 0) cap = std::max(cap, x.mean());
}

// One line: min, max, mean of each quantity over samples [i0, i1), at bin centre t_mid; raises the caps.
void write_bin(std::string& out, const RunSeries& s, std::size_t i0, std::size_t i1, double t_mid, AxisCaps& caps) {
  Stats g, w, f, m, a, r, nn;
  for (std::size_t i = i0; i < i1; ++i) {
    g.add(s.gamma3[i]);
    w.add(s.omega_sq[i]);
    f.add(s.force[i]);
    m.add(kMilli * s.moment[i]);
    a.add(kMilli * s.major[i]);
    r.add(s.axis_ratio[i]);
    nn.add(s.n_over_mg[i]);
  }
  out += cell(t_mid) + ' ' + triple(g) + ' ' + cell(w.mean()) + ' ' + triple(f) + ' ' + triple(m) + ' ' + triple(a) +
         ' ' + triple(r) + ' ' + triple(nn) + '\n';
  raise(caps.force, f);
  raise(caps.moment, m);
  raise(caps.major, a);
  raise(caps.n_over_mg, nn);
}

// `bins` bins of equal width over [t0, t1] (the last bin closed); one bin if t1 <= t0.
AxisCaps write_bins(const std::filesystem::path& path, const RunSeries& s, double t0, double t1, int bins_wanted) {
  std::string out = "# t_s, then min max mean of: gamma3; omega_sq_per_s2 (mean only); F_N; M_Nmm; a_mm; b/a; N/(m g)\n";
  AxisCaps caps;
  const std::size_t n = s.size();
  const int bins = t1 > t0 ? bins_wanted : 1;
  const double width = (t1 - t0) / bins;
  std::size_t i = static_cast<std::size_t>(std::lower_bound(s.t.begin(), s.t.end(), t0) - s.t.begin());
  for (int b = 0; b < bins && i < n; ++b) {
    const bool last = b + 1 == bins;
    const double hi = last ? t1 : t0 + (b + 1) * width;
    const std::size_t first = i;
    while (i < n && (s.t[i] < hi || (last && s.t[i] <= hi))) ++i;
    if (i > first) write_bin(out, s, first, i, t0 + (b + 0.5) * width, caps);
  }
  support::write_file_atomically(path, out);
  return caps;
}

}  // namespace

FigureRanges write_figure_data(const std::filesystem::path& dir, const std::string& stem, const RunSeries& s) {
  std::filesystem::create_directories(dir);
  const double t_final = s.empty() ? 0.0 : s.t.back();
  FigureRanges r;
  r.full = write_bins(dir / (stem + ".full.dat"), s, 0.0, t_final, kFigureBins);
  r.early = write_bins(dir / (stem + ".early.dat"), s, 0.0, std::min(t_final, kEarlyWindow), kEarlyBins);
  std::string end = "# t_s gamma3 omega_sq_per_s2 F_N M_Nmm a_mm ratio N_over_mg (last sample)\n";
  if (!s.empty()) {
    const std::size_t k = s.size() - 1;
    end += cell(s.t[k]) + ' ' + cell(s.gamma3[k]) + ' ' + cell(s.omega_sq[k]) + ' ' + cell(s.force[k]) + ' ' +
           cell(kMilli * s.moment[k]) + ' ' + cell(kMilli * s.major[k]) + ' ' + cell(s.axis_ratio[k]) + ' ' +
           cell(s.n_over_mg[k]) + '\n';
  }
  support::write_file_atomically(dir / (stem + ".end.dat"), end);
  return r;
}

}  // namespace frictionlab::dynamics::paper
