#include "dynamics/paper/figure_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <vector>

namespace frictionlab::dynamics::paper {
namespace {

constexpr double kMilli = 1e3;  // m -> mm, N m -> N mm

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double x) {
    if (!std::isfinite(x)) return;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
};

std::string cell(double x) {
  if (!std::isfinite(x)) return "NaN";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", x);
  return buf;
}

// One line: min and max of each quantity over samples [i0, i1), at bin centre t_mid.
void write_bin(std::ostream& out, const RunSeries& s, std::size_t i0, std::size_t i1, double t_mid) {
  Range g, f, m, a, r, nn;
  double omega_sum = 0.0;
  for (std::size_t i = i0; i < i1; ++i) {
    g.add(s.gamma3[i]);
    f.add(s.force[i]);
    m.add(kMilli * s.moment[i]);
    a.add(kMilli * s.major[i]);
    r.add(s.axis_ratio[i]);
    nn.add(s.n_over_mg[i]);
    omega_sum += s.omega_sq[i];
  }
  const auto pair = [](const Range& x) { return x.lo <= x.hi ? cell(x.lo) + ' ' + cell(x.hi) : std::string("NaN NaN"); };
  out << cell(t_mid) << ' ' << pair(g) << ' ' << cell(omega_sum / static_cast<double>(i1 - i0)) << ' ' << pair(f)
      << ' ' << pair(m) << ' ' << pair(a) << ' ' << pair(r) << ' ' << pair(nn) << '\n';
}

// kFigureBins bins of equal width over [t0, t1] (the last bin closed); one bin if t1 <= t0.
void write_bins(const std::filesystem::path& path, const RunSeries& s, double t0, double t1) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path.string() + "'");
  out << "# t_s gamma3_min gamma3_max omega_sq_mean_per_s2 F_min_N F_max_N M_min_Nmm M_max_Nmm a_min_mm a_max_mm "
         "ratio_min ratio_max N_over_mg_min N_over_mg_max\n";
  const std::size_t n = s.size();
  const int bins = t1 > t0 ? kFigureBins : 1;
  const double width = (t1 - t0) / bins;
  std::size_t i = static_cast<std::size_t>(std::lower_bound(s.t.begin(), s.t.end(), t0) - s.t.begin());
  for (int b = 0; b < bins && i < n; ++b) {
    const bool last = b + 1 == bins;
    const double hi = last ? t1 : t0 + (b + 1) * width;
    const std::size_t first = i;
    while (i < n && (s.t[i] < hi || (last && s.t[i] <= hi))) ++i;
    if (i > first) write_bin(out, s, first, i, t0 + (b + 0.5) * width);
  }
  if (!out) throw std::runtime_error("writing '" + path.string() + "' failed");
}

}  // namespace

void write_figure_data(const std::filesystem::path& dir, const std::string& stem, const RunSeries& s) {
  std::filesystem::create_directories(dir);
  const double t_final = s.empty() ? 0.0 : s.t.back();
  write_bins(dir / (stem + ".full.dat"), s, 0.0, t_final);
  write_bins(dir / (stem + ".early.dat"), s, 0.0, std::min(t_final, kEarlyWindow));
  std::ofstream end(dir / (stem + ".end.dat"));
  if (!end) throw std::runtime_error("cannot write '" + (dir / (stem + ".end.dat")).string() + "'");
  end << "# t_s gamma3 omega_sq_per_s2 F_N M_Nmm a_mm ratio N_over_mg (last sample)\n";
  if (!s.empty()) {
    const std::size_t k = s.size() - 1;
    end << cell(s.t[k]) << ' ' << cell(s.gamma3[k]) << ' ' << cell(s.omega_sq[k]) << ' ' << cell(s.force[k]) << ' '
        << cell(kMilli * s.moment[k]) << ' ' << cell(kMilli * s.major[k]) << ' ' << cell(s.axis_ratio[k]) << ' '
        << cell(s.n_over_mg[k]) << '\n';
  }
}

}  // namespace frictionlab::dynamics::paper
