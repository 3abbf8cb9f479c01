#include "dynamics/paper/figure_data.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "friction/support/checked_input.h"
#include "friction/support/checked_output.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

constexpr double kMilli = 1e3;  // m -> mm, N m -> N mm
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Mean and band of values[i0, i1) (times `scale`), skipping non-finite values.
Band band_of(const std::vector<double>& values, std::size_t i0, std::size_t i1, double scale = 1.0) {
  std::vector<double> v;
  v.reserve(i1 - i0);
  double sum = 0.0;
  for (std::size_t i = i0; i < i1; ++i) {
    const double x = scale * values[i];
    if (!std::isfinite(x)) continue;
    v.push_back(x);
    sum += x;
  }
  if (v.empty()) return {kNaN, kNaN, kNaN};
  const double mean = sum / static_cast<double>(v.size());
  return {quantile(v, kBandLow), quantile(std::move(v), kBandHigh), mean};
}

// Samples [first, last) within kImpactWindow/2 of t_mid.
std::pair<std::size_t, std::size_t> impact_window(const std::vector<double>& t, double t_mid) {
  const double half = 0.5 * kImpactWindow;
  const auto lo = std::lower_bound(t.begin(), t.end(), t_mid - half);
  const auto hi = std::upper_bound(lo, t.end(), t_mid + half);
  return {static_cast<std::size_t>(lo - t.begin()), static_cast<std::size_t>(hi - t.begin())};
}

FigureBin make_bin(const RunSeries& s, std::size_t i0, std::size_t i1, double t_mid) {
  FigureBin b{};
  b.t = t_mid;
  b.gamma3 = band_of(s.gamma3, i0, i1);
  b.omega_sq = band_of(s.omega_sq, i0, i1).mean;
  b.axis_ratio = band_of(s.axis_ratio, i0, i1);
  const auto [w0, w1] = impact_window(s.t, t_mid);
  b.force = band_of(s.force, w0, w1);
  b.moment = band_of(s.moment, w0, w1, kMilli);
  b.major = band_of(s.major, w0, w1, kMilli);
  b.n_over_mg = band_of(s.n_over_mg, w0, w1);
  return b;
}

// Seven significant digits (plenty for a figure); "NaN" is gnuplot's missing value.
std::string cell(double x) { return std::isfinite(x) ? support::significant(x, 7) : "NaN"; }

std::string cells(const Band& b) { return cell(b.lo) + ' ' + cell(b.hi) + ' ' + cell(b.mean); }

std::string bins_text(const std::vector<FigureBin>& bins) {
  std::string out =
      "# t_s, then lo (5 %) hi (95 %) mean of: gamma3; omega_sq_per_s2 (mean only); F_N*; M_Nmm*; a_mm*; b/a; "
      "N/(m g)*  (* over the 2-s window centred on the bin)\n";
  for (const auto& b : bins)
    out += cell(b.t) + ' ' + cells(b.gamma3) + ' ' + cell(b.omega_sq) + ' ' + cells(b.force) + ' ' + cells(b.moment) +
           ' ' + cells(b.major) + ' ' + cells(b.axis_ratio) + ' ' + cells(b.n_over_mg) + '\n';
  return out;
}

std::string end_text(const RunSeries& s) {
  std::string out = "# t_s gamma3 omega_sq_per_s2 F_N M_Nmm a_mm ratio N_over_mg (last sample)\n";
  if (s.empty()) return out;
  const std::size_t k = s.size() - 1;
  return out + cell(s.t[k]) + ' ' + cell(s.gamma3[k]) + ' ' + cell(s.omega_sq[k]) + ' ' + cell(s.force[k]) + ' ' +
         cell(kMilli * s.moment[k]) + ' ' + cell(kMilli * s.major[k]) + ' ' + cell(s.axis_ratio[k]) + ' ' +
         cell(s.n_over_mg[k]) + '\n';
}

// The caps of one .dat file: the largest band top of each capped quantity.
AxisCaps read_caps(const std::filesystem::path& path) {
  std::istringstream in;
  try {
    in.str(support::read_file(path, "plot data"));
  } catch (const support::InputError& e) {
    throw std::runtime_error(e.what());  // the job's own file: not bad input
  }
  AxisCaps caps;
  std::vector<double> row;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.front() == '#') continue;
    std::istringstream cells_in(line);
    row.clear();
    for (std::string c; cells_in >> c;) row.push_back(c == "NaN" ? kNaN : std::stod(c));
    if (row.size() != static_cast<std::size_t>(FigureColumns::n_mean))
      throw std::runtime_error("the plot data '" + path.string() + "' has a row of " + std::to_string(row.size()) +
                               " columns, not " + std::to_string(FigureColumns::n_mean));
    const auto raise = [&](double& cap, int column) {
      const double x = row[static_cast<std::size_t>(column - 1)];
      if (std::isfinite(x)) cap = std::max(cap, x);
    };
    raise(caps.force, FigureColumns::force_hi);
    raise(caps.moment, FigureColumns::moment_hi);
    raise(caps.major, FigureColumns::major_hi);
    raise(caps.n_over_mg, FigureColumns::n_hi);
  }
  return caps;
}

}  // namespace

double quantile(std::vector<double> values, double p) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double x) { return !std::isfinite(x); }), values.end());
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  const double pos = std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (pos - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

std::vector<FigureBin> figure_bins(const RunSeries& s, double t0, double t1, int bins_wanted) {
  std::vector<FigureBin> out;
  const std::size_t n = s.size();
  const int bins = t1 > t0 ? bins_wanted : 1;
  const double width = (t1 - t0) / bins;
  std::size_t i = static_cast<std::size_t>(std::lower_bound(s.t.begin(), s.t.end(), t0) - s.t.begin());
  for (int b = 0; b < bins && i < n; ++b) {
    const bool last = b + 1 == bins;
    const double hi = last ? t1 : t0 + (b + 1) * width;
    const std::size_t first = i;
    while (i < n && (s.t[i] < hi || (last && s.t[i] <= hi))) ++i;
    if (i > first) out.push_back(make_bin(s, first, i, t0 + (b + 0.5) * width));
  }
  return out;
}

FigureRanges write_figure_data(const std::filesystem::path& dir, const std::string& stem, const RunSeries& s) {
  std::filesystem::create_directories(dir);
  const double t_final = s.empty() ? 0.0 : s.t.back();
  support::write_file_atomically(dir / (stem + ".full.dat"), bins_text(figure_bins(s, 0.0, t_final, kFigureBins)));
  support::write_file_atomically(dir / (stem + ".early.dat"),
                                 bins_text(figure_bins(s, 0.0, std::min(t_final, kEarlyWindow), kEarlyBins)));
  support::write_file_atomically(dir / (stem + ".end.dat"), end_text(s));
  return read_figure_ranges(dir, stem);
}

FigureRanges read_figure_ranges(const std::filesystem::path& dir, const std::string& stem) {
  return {read_caps(dir / (stem + ".full.dat")), read_caps(dir / (stem + ".early.dat"))};
}

}  // namespace frictionlab::dynamics::paper
