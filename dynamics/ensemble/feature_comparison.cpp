#include "dynamics/ensemble/feature_comparison.h"

#include <cmath>
#include <limits>

#include "dynamics/ensemble/two_sample_distance.h"

namespace frictionlab::dynamics::ensemble {
namespace {

std::vector<const RunRecord*> of_law(const std::vector<RunRecord>& rows, const std::string& law) {
  std::vector<const RunRecord*> out;
  for (const auto& r : rows)
    if (r.law == law) out.push_back(&r);
  return out;
}

// The feature's finite values over the normal runs of `runs` (replica parity -1: all, 0 even, 1 odd).
std::vector<double> values(const std::vector<const RunRecord*>& runs, const FeatureDef& f, int parity) {
  std::vector<double> v;
  for (const RunRecord* r : runs) {
    if (!ended_normally(*r) || (parity >= 0 && r->replica % 2 != parity)) continue;
    const double x = f.value(*r);
    if (std::isfinite(x)) v.push_back(x);
  }
  return v;
}

std::vector<double> quantiles_of(const std::vector<double>& v) {
  std::vector<double> q;
  for (const double p : kQuantiles) q.push_back(quantile(v, p));
  return q;
}

CategoryCounts classes(const std::vector<const RunRecord*>& runs, int parity) {
  CategoryCounts c;
  for (const RunRecord* r : runs)
    if (parity < 0 || r->replica % 2 == parity) ++c[r->final_class];
  return c;
}

double ks_p(const std::vector<double>& a, const std::vector<double>& b) {
  return ks_p_value(ks_statistic(a, b), static_cast<long>(a.size()), static_cast<long>(b.size()));
}

}  // namespace

bool ended_normally(const RunRecord& r) { return r.reason == "t_end" || r.reason == "rest" || r.reason == "rolling"; }

namespace {

// Resolutions: t_vertical is read on samples 0.01 s apart (the shipped studies' output_dt); a tilt
// of 0.1 deg is below what the plateau's 5-s mean resolves; 0.1 s of time to rest is below the
// rest event's settling window (~0.1 s); 1e-3 in gamma3 is the precision of "vertical" itself
// (|gamma3| > 0.999); one lift-off; 1e-3 of the weight; 0.01 J of work (the egg's works are 2-250 J);
// one reversal, and its time on the same 0.01-s samples as t_vertical.
const std::vector<FeatureDef>& body_features() {
  static const std::vector<FeatureDef> features = {
      {"t_vertical", "time to the vertical (|gamma3| > 0.999)", "s", 0.01, [](const RunRecord& r) { return r.t_vertical; }},
      {"plateau_tilt_deg", "tilt of the plateau", "deg", 0.1, [](const RunRecord& r) { return r.plateau_tilt_deg; }},
      {"t_rest", "time to rest or rolling", "s", 0.1, [](const RunRecord& r) { return r.t_rest; }},
      {"final_gamma3", "final gamma3 (mean of the last second)", "", 1e-3,
       [](const RunRecord& r) { return r.final_gamma3; }},
      {"liftoffs", "lift-offs", "", 1.0, [](const RunRecord& r) { return static_cast<double>(r.liftoffs); }},
      {"min_n_over_mg", "min N/(m g)", "", 1e-3, [](const RunRecord& r) { return r.min_n_over_mg; }},
      {"work_slide", "work against sliding", "J", 0.01, [](const RunRecord& r) { return r.work_slide; }},
      {"work_spin", "work against spinning", "J", 0.01, [](const RunRecord& r) { return r.work_spin; }},
      {"spin_reversals", "reversals of the spin about the vertical", "", 1.0,
       [](const RunRecord& r) { return static_cast<double>(r.spin_reversals); }},
      {"t_first_reversal", "time of the first spin reversal", "s", 0.01,
       [](const RunRecord& r) { return r.t_first_reversal; }},
  };
  return features;
}

// The puck's resolutions: stop times and the path are located inside the steps to ~1e-15 s, so the
// resolution is what means anything: 1 ms (the shipped output interval), 0.1 mm of path (a tenth
// of the smallest patch's semi-axis in the shipped study), 0.01 rad of heading, 0.01 in log10 of
// the ratio (2 %), 1e-5 J of work (under 1 % of the smallest initial energy in the shipped study).
// The ratio is compared in log10: it spans 1e-6 .. 1e6 (a law whose motions stop apart), where W1
// of the ratio itself would be its largest values alone.
const std::vector<FeatureDef>& puck_features() {
  static const std::vector<FeatureDef> features = {
      {"slip_stop_time", "time the slip stops", "s", 1e-3, [](const RunRecord& r) { return r.puck.slip_stop_time; }},
      {"spin_stop_time", "time the spin stops", "s", 1e-3, [](const RunRecord& r) { return r.puck.spin_stop_time; }},
      {"log10_terminal_ratio", "log10 of U/(a|Ω|) at the first stop (terminal_ratio)", "", 1e-2,
       [](const RunRecord& r) { return r.puck.terminal_ratio > 0.0 ? std::log10(r.puck.terminal_ratio) : kNaN; }},
      {"path_along", "end of the path along the initial velocity", "m", 1e-4, [](const RunRecord& r) { return r.puck.path_along; }},
      {"path_lateral", "end of the path across the initial velocity (to its left)", "m", 1e-4,
       [](const RunRecord& r) { return r.puck.path_lateral; }},
      {"turned", "angle turned", "rad", 1e-2, [](const RunRecord& r) { return r.puck.turned; }},
      {"work_slide", "work against sliding", "J", 1e-5, [](const RunRecord& r) { return r.work_slide; }},
      {"work_spin", "work against spinning", "J", 1e-5, [](const RunRecord& r) { return r.work_spin; }},
  };
  return features;
}

}  // namespace

const std::vector<FeatureDef>& compared_features(RunModel model) {
  return model == RunModel::puck ? puck_features() : body_features();
}

std::vector<FeatureComparison> compare_features(const std::vector<RunRecord>& rows, const std::vector<std::string>& laws,
                                                RunModel model) {
  std::vector<FeatureComparison> out;
  if (laws.empty()) return out;
  const auto reference = of_law(rows, laws.front());
  for (const auto& f : compared_features(model)) {
    const std::vector<double> ref = values(reference, f, -1);
    const std::vector<double> even = values(reference, f, 0);
    const std::vector<double> odd = values(reference, f, 1);
    Distances floor;
    floor.floor_w1 = floor_is_zero(model) ? 0.0 : wasserstein1(even, odd);
    floor.floor_ks = floor_is_zero(model) ? 0.0 : ks_statistic(even, odd);
    floor.floor_p = floor_is_zero(model) ? kNaN : ks_p(even, odd);
    for (const auto& law : laws) {
      const auto runs = of_law(rows, law);
      FeatureComparison c;
      c.feature = f.name;
      c.law = law;
      c.summary.runs = static_cast<long>(runs.size());
      for (const RunRecord* r : runs) c.summary.normal += ended_normally(*r) ? 1 : 0;
      const std::vector<double> v = values(runs, f, -1);
      c.summary.finite = static_cast<long>(v.size());
      c.summary.quantiles = quantiles_of(v);
      c.distances = floor;
      if (law != laws.front()) {
        c.distances.w1 = wasserstein1(v, ref);
        c.distances.ks = ks_statistic(v, ref);
        c.distances.p = ks_p(v, ref);
        c.distances.verdict = judge(c.distances.p, c.distances.w1, c.distances.floor_w1, f.resolution);
      }
      out.push_back(std::move(c));
    }
  }
  return out;
}

std::vector<ClassComparison> compare_classes(const std::vector<RunRecord>& rows, const std::vector<std::string>& laws,
                                             RunModel model) {
  std::vector<ClassComparison> out;
  if (laws.empty()) return out;
  const auto reference = of_law(rows, laws.front());
  const CategoryCounts ref = classes(reference, -1);
  const CategoryCounts even = classes(reference, 0);
  const CategoryCounts odd = classes(reference, 1);
  for (const auto& law : laws) {
    ClassComparison c;
    c.law = law;
    c.counts = classes(of_law(rows, law), -1);
    c.floor_tv = floor_is_zero(model) ? 0.0 : total_variation(even, odd);
    c.floor_p = floor_is_zero(model) ? kNaN : chi_square_homogeneity_p(even, odd);
    if (law != laws.front()) {
      c.tv = total_variation(c.counts, ref);
      c.p = chi_square_homogeneity_p(c.counts, ref);
      c.verdict = judge(c.p, c.tv, c.floor_tv);
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<DivergenceSummary> compare_divergence(const std::vector<RunRecord>& rows, const std::vector<std::string>& laws,
                                                  double RunRecord::*time) {
  std::vector<DivergenceSummary> out;
  if (laws.empty()) return out;
  const double inf = std::numeric_limits<double>::infinity();
  // Parting times with the unparted at +infinity (for KS), the parted ones alone, the horizons.
  const auto collect = [&](const auto& keep, DivergenceSummary& s, std::vector<double>& censored) {
    std::vector<double> parted;
    std::vector<double> horizons;
    for (const auto& r : rows) {
      if (!keep(r) || std::isnan(r.diverge_horizon)) continue;
      ++s.compared;
      horizons.push_back(r.diverge_horizon);
      const double t = r.*time;
      censored.push_back(std::isnan(t) ? inf : t);
      if (!std::isnan(t)) parted.push_back(t);
    }
    s.parted = static_cast<long>(parted.size());
    s.quantiles = quantiles_of(parted);
    s.median_horizon = quantile(horizons, 0.5);
  };
  DivergenceSummary floor;
  floor.law = "floor";
  std::vector<double> floor_times;
  collect([&](const RunRecord& r) { return r.law == laws.front() && r.diverge_ref.rfind("replica:", 0) == 0; }, floor,
          floor_times);
  for (std::size_t i = 1; i < laws.size(); ++i) {
    DivergenceSummary s;
    s.law = laws[i];
    std::vector<double> times;
    collect([&](const RunRecord& r) { return r.law == laws[i] && r.diverge_ref == laws.front(); }, s, times);
    // Runs compared over less time than the floor takes to part (a law stopped at its pole) say
    // nothing about parting later: no test then. A floor that never parts is compared over its
    // horizon, of which a law's runs must cover half (runs of equal length end at chaotic times).
    const double floor_time = floor.parted > 0 ? floor.quantiles[2] : 0.5 * floor.median_horizon;
    if (!(s.median_horizon < floor_time)) {
      s.ks = ks_statistic(times, floor_times);
      s.p = ks_p(times, floor_times);
    }
    out.push_back(std::move(s));
  }
  out.push_back(std::move(floor));
  return out;
}

}  // namespace frictionlab::dynamics::ensemble
