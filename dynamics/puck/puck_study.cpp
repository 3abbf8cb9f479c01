#include "dynamics/puck/puck_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "dynamics/puck/puck_scenario.h"
#include "friction/registry.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {
namespace {

// The pressure models the study asks the registry for besides the registered laws.
const std::vector<std::string> kPressureSpecs = {"exact:pressure=uniform", "exact:pressure=punch"};
// Samples of the disk runs: fine enough to draw the ratio down to ~1e-3 of the energy (below, the
// decades of the summary take over).
constexpr double kDiskOutputDt = 1e-4;
constexpr double kEllipseOutputDt = 1e-3;
constexpr double kDriftKappa = 0.5;

// Keeps (E/E0, ratio) while both motions go on, and the path.
class Collector final : public PuckObserver {
 public:
  Collector(double a, double e0) : a_(a), e0_(e0) {}
  void sample(const PuckSample& s) override {
    path.emplace_back(position(s.x));
    if (!s.mode.slip && !s.mode.spin && s.contact.Omega != 0.0 && e0_ > 0.0)
      curve.emplace_back(s.energy / e0_, s.contact.U / (a_ * std::abs(s.contact.Omega)));
  }
  std::vector<std::pair<double, double>> curve;
  std::vector<Eigen::Vector2d> path;

 private:
  double a_, e0_;
};

std::string num(double x) { return support::shortest(x); }

PuckRunSummary run(const PuckScenario& s, PuckObserver* observer) {
  const auto law = friction::make_law(s.law);
  const PuckOnPlane sys(s.puck, s.k, s.g, *law);
  return simulate_puck(sys, initial_state(s), s.run, observer);
}

}  // namespace

void PuckStudyOptions::validate() const {
  const auto positive = [](const char* option, const std::vector<double>& v) {
    if (v.empty()) throw std::invalid_argument(std::string(option) + " must list at least one value");
    for (const double x : v)
      if (!(std::isfinite(x) && x > 0.0)) throw support::invalid_value(option, x, "every value must be finite and > 0");
  };
  positive("--kappas", kappas);
  positive("--run-kappas", run_kappas);
  positive("--start-ratios", start_ratios);
  if (!(threshold_fraction > 0.0 && threshold_fraction <= 1e-2))
    throw support::invalid_value("--threshold-fraction", threshold_fraction, "it must be in (0, 1e-2]");
}

std::vector<std::string> default_study_laws(std::vector<std::string>* unavailable) {
  std::vector<std::string> laws;
  // A slow law (milliseconds per call: a quadrature cross-check of another law) would make the study
  // take hours; the registry says which.
  for (const auto& info : friction::list_laws())
    if (!info.slow) laws.push_back(info.name);
  for (const auto& spec : kPressureSpecs) {
    try {
      (void)friction::make_law(spec);
      laws.push_back(spec);
    } catch (const std::invalid_argument&) {
      if (unavailable) unavailable->push_back(spec);
    }
  }
  return laws;
}

PuckStudyResults run_puck_study(const PuckStudyOptions& options) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  PuckStudyResults r;
  r.laws = options.laws.empty() ? default_study_laws(&r.unavailable) : options.laws;
  for (const auto& law : r.laws) {
    try {
      (void)friction::make_law(law);
    } catch (const std::invalid_argument& e) {
      throw support::invalid_value("--laws", std::string_view(law), e.what());
    }
  }
  r.disk_file = options.scenario_dir / "puck-disk.toml";
  r.ellipse_file = options.scenario_dir / "puck-ellipse.toml";
  for (const auto& f : {r.disk_file, r.ellipse_file})
    if (!std::filesystem::exists(f))
      throw std::invalid_argument("scenario file '" + f.string() + "' does not exist (--scenarios names its folder)");
  const ScenarioDocument disk_doc = ScenarioDocument::read(r.disk_file);
  const ScenarioDocument ellipse_doc = ScenarioDocument::read(r.ellipse_file);
  const PuckScenario disk_base = resolve_puck(disk_doc);
  r.disk_omega0 = disk_base.initial.omega;
  const double ga = disk_base.g * disk_base.puck.a;

  for (const auto& spec : r.laws) {
    const auto law = friction::make_law(spec);
    for (const double kappa : options.kappas) r.theory.push_back({spec, kappa, analyse_terminal_ratio(*law, kappa)});
    std::vector<std::pair<double, double>> drift;
    for (int i = 0; i <= 160; ++i) {
      const double ratio = std::pow(10.0, -2.0 + 4.0 * i / 160.0);
      drift.emplace_back(ratio, terminal_ratio_drift(*law, kDriftKappa, ratio));
    }
    r.drift.emplace_back(spec, std::move(drift));

    for (const double kappa : options.run_kappas) {
      for (const double r0 : options.start_ratios) {
        DiskRun d;
        d.law = spec;
        d.kappa = kappa;
        d.start_ratio = r0;
        const double m = disk_base.puck.mass, a = disk_base.puck.a;
        d.overrides = {"contact.law=" + spec,
                       "puck.inertia=" + num(kappa * m * a * a),
                       "initial.v=[" + num(r0 * a * r.disk_omega0) + ", 0]",
                       "run.output_dt=" + num(kDiskOutputDt),
                       "run.rest_slip_speed=" + num(options.threshold_fraction * std::sqrt(ga)),
                       "run.rest_spin=" + num(options.threshold_fraction * std::sqrt(disk_base.g / a))};
        const PuckScenario s = resolve_puck(disk_doc, d.overrides);
        Collector c(a, 0.5 * m * std::pow(r0 * a * r.disk_omega0, 2) + 0.5 * s.puck.inertia * r.disk_omega0 * r.disk_omega0);
        d.summary = run(s, &c);
        d.ratio_curve = std::move(c.curve);
        for (const auto& q : d.summary.ratio_by_energy) d.ratio_curve.emplace_back(q.fraction, q.ratio);
        std::sort(d.ratio_curve.begin(), d.ratio_curve.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
        r.disk.push_back(std::move(d));
      }
    }

    EllipseRun e;
    e.law = spec;
    e.overrides = {"contact.law=" + spec, "run.output_dt=" + num(kEllipseOutputDt)};
    const PuckScenario s = resolve_puck(ellipse_doc, e.overrides);
    Collector c(s.puck.a, 0.0);
    e.summary = run(s, &c);
    e.path = std::move(c.path);
    e.offset = path_offset(s.initial.position, s.initial.v, position(e.summary.x_final));
    r.ellipse.push_back(std::move(e));
  }
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace frictionlab::dynamics::puck
