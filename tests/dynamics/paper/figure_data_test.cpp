// The figures' data (dynamics/paper/figure_data.h) on synthetic runs with known answers:
// quantiles, the nutation band of gamma3, the 2-s time average of an impact train.

#include "dynamics/paper/figure_data.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>

namespace frictionlab::dynamics::paper {
namespace figure_data_test {

constexpr double kDt = 0.01;        // s, the paper job's sample interval
constexpr double kRounding = 1e-12;
// The data files keep seven significant digits.
constexpr double kFileDigits = 1e-6;

struct Quantities {
  double gamma3 = 0.0, force = 0.0, moment = 0.0, major = 0.0, ratio = 1.0, n = 1.0;
};

// A run sampled every kDt on [0, t_end], its quantities given by f(i, t).
RunSeries synthetic(double t_end, const std::function<Quantities(long, double)>& f) {
  RunSeries s;
  const long n = std::lround(t_end / kDt);
  for (long i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) * kDt;
    const Quantities q = f(i, t);
    s.push(t, q.gamma3, 1.0, q.force, q.moment, q.major, q.ratio, q.n, 0.0, 0.0, 0.0, true);
  }
  return s;
}

TEST(PaperFigureData, QuantileInterpolatesBetweenOrderStatistics) {
  std::vector<double> v;
  for (int i = 100; i >= 0; --i) v.push_back(i);  // 0..100, unsorted
  EXPECT_NEAR(quantile(v, 0.05), 5.0, kRounding);
  EXPECT_NEAR(quantile(v, 0.95), 95.0, kRounding);
  EXPECT_EQ(quantile(v, 0.0), 0.0);
  EXPECT_EQ(quantile(v, 1.0), 100.0);
  EXPECT_NEAR(quantile({0.0, 10.0}, 0.25), 2.5, kRounding);
  EXPECT_EQ(quantile({std::nan(""), 3.0}, 0.5), 3.0);  // non-finite values are skipped
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
  EXPECT_TRUE(std::isnan(quantile({std::nan("")}, 0.5)));
}

// A 10-Hz nutation sampled at 100 Hz takes ten phases, 2 pi k/10: its 5 % and 95 % quantiles
// over whole periods are -A sin(0.4 pi) and +A sin(0.4 pi) (the two lowest phases fill the lowest
// 20 % of the samples), its mean 0.
TEST(PaperFigureData, TheGamma3BandIsTheNutationOfEachBin) {
  constexpr double kAmplitude = 0.01;
  const RunSeries s = synthetic(10.0, [](long i, double) {
    Quantities q;
    q.gamma3 = 0.5 + kAmplitude * std::sin(2.0 * std::numbers::pi * static_cast<double>(i) / 10.0);
    return q;
  });
  const auto bins = figure_bins(s, 0.0, 9.99, 9);  // 1.11-s bins: 111 samples each, 11.1 periods
  ASSERT_EQ(bins.size(), 9u);
  const double edge = kAmplitude * std::sin(0.4 * std::numbers::pi);
  for (const auto& b : bins) {
    EXPECT_NEAR(b.gamma3.lo, 0.5 - edge, kRounding) << b.t;
    EXPECT_NEAR(b.gamma3.hi, 0.5 + edge, kRounding) << b.t;
    EXPECT_NEAR(b.gamma3.mean, 0.5, 0.1 * kAmplitude) << b.t;  // a tenth of a period left over
  }
}

// |F| as a train of impacts: one sample in five carries 5 N, the others 0 (out of contact). Each
// bin is two samples wide, so its own mean would be 0 or 2.5 N; the line is the mean over the 2-s
// window around the bin, the time average 1 N to within one impact's share of the window, and the
// band runs from 0 to the impacts' 5 N.
TEST(PaperFigureData, ImpactDominatedQuantitiesAreTimeAveragedOverTwoSeconds) {
  constexpr double kImpact = 5.0;  // N
  const RunSeries s = synthetic(20.0, [](long i, double) {
    Quantities q;
    q.force = i % 5 == 0 ? kImpact : 0.0;
    q.n = q.force;
    q.moment = 1e-3 * q.force;  // N m
    q.major = 1e-3 * q.force;   // m
    return q;
  });
  const auto bins = figure_bins(s, 0.0, 20.0, 1000);
  const double samples_in_window = kImpactWindow / kDt + 1.0;
  const double one_impact = kImpact / samples_in_window;
  int interior = 0;
  for (const auto& b : bins) {
    if (b.t < 0.5 * kImpactWindow || b.t > 20.0 - 0.5 * kImpactWindow) continue;  // windows cut by the ends
    ++interior;
    EXPECT_NEAR(b.force.mean, 1.0, one_impact) << b.t;
    EXPECT_EQ(b.force.lo, 0.0) << b.t;
    EXPECT_EQ(b.force.hi, kImpact) << b.t;
    EXPECT_NEAR(b.n_over_mg.mean, 1.0, one_impact) << b.t;
    EXPECT_NEAR(b.moment.mean, 1.0, one_impact) << b.t;  // N mm
    EXPECT_NEAR(b.major.mean, 1.0, one_impact) << b.t;   // mm
  }
  EXPECT_GT(interior, 800);
}

TEST(PaperFigureData, EmptyBinsAreLeftOutAndAxisRatioSkipsNoContact) {
  RunSeries s = synthetic(1.0, [](long, double) { return Quantities{}; });
  s.push(5.0, 0.0, 1.0, 0.0, 0.0, 0.0, std::nan(""), 0.0, 0.0, 0.0, 0.0, false);  // a gap, then no contact
  const auto bins = figure_bins(s, 0.0, 5.0, 10);  // 0.5-s bins: [1.5, 4.5) hold no sample
  ASSERT_EQ(bins.size(), 4u);
  EXPECT_NEAR(bins.back().t, 4.75, kRounding);
  EXPECT_TRUE(std::isnan(bins.back().axis_ratio.mean));
  EXPECT_EQ(bins.front().axis_ratio.mean, 1.0);
}

TEST(PaperFigureData, FilesHoldEveryColumnAndTheCapsAreTheirBandTops) {
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab_figure_data_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  const RunSeries s = synthetic(60.0, [](long i, double t) {
    Quantities q;
    q.force = t < 30.0 ? (i % 5 == 0 ? 7.0 : 0.0) : 1.0;  // impacts (95 % quantile 7 N), then 1 N
    q.n = 1.0 + 0.01 * t;                                  // 1.6 at the end
    q.moment = 3e-3;                                       // 3 N mm
    q.major = 2e-3;                                        // 2 mm
    return q;
  });
  const FigureRanges written = write_figure_data(dir, "run", s);
  const FigureRanges read = read_figure_ranges(dir, "run");
  EXPECT_EQ(written.full.force, read.full.force);
  EXPECT_EQ(written.early.n_over_mg, read.early.n_over_mg);
  EXPECT_NEAR(read.full.force, 7.0, kFileDigits);
  EXPECT_NEAR(read.full.moment, 3.0, kFileDigits);
  EXPECT_NEAR(read.full.major, 2.0, kFileDigits);
  EXPECT_NEAR(read.full.n_over_mg, 1.6, 0.011);  // the last window reaches t = 60 s
  EXPECT_NEAR(read.early.n_over_mg, 1.4, 0.011);  // the zoom's last window ends at 40.75 s

  std::ifstream full(dir / "run.full.dat");
  std::string header;
  std::getline(full, header);
  EXPECT_EQ(header.front(), '#');
  std::string first;
  std::getline(full, first);
  std::istringstream cells(first);
  int columns = 0;
  for (std::string c; cells >> c;) ++columns;
  EXPECT_EQ(columns, FigureColumns::n_mean);
  std::ifstream end(dir / "run.end.dat");
  std::getline(end, header);
  double t_last = 0.0;
  end >> t_last;
  EXPECT_EQ(t_last, 60.0);
  std::filesystem::remove_all(dir);
  EXPECT_THROW((void)read_figure_ranges(dir, "run"), std::runtime_error);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
