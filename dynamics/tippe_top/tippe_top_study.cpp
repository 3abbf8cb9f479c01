#include "dynamics/tippe_top/tippe_top_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "dynamics/body/scenario.h"
#include "dynamics/tippe_top/tippe_top_observables.h"
#include "friction/registry.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::tippe_top {
namespace {

// The spin-moment variants: the decoupled law with the exact pure-spin torque, and without any.
const std::vector<std::string> kSpinMomentSpecs = {"decoupled", "decoupled:r_spin=0"};
// The figures' curves keep one point per this interval (s).
constexpr double kCurveDt = 1e-2;

// Measures a run sample by sample.
class Meter final : public Observer {
 public:
  Meter(const BodyOnPlane& sys, TippeTopRun& run) : sys_(sys), run_(run) {}

  void sample(const Sample& s) override {
    const double g3 = gamma3(s.x);
    watch.add(s.t, g3);
    const double J = jellett_quantity(sys_.body(), s.x, s.contact);
    const double rate = jellett_rate(s.contact);
    const double work = slide_work(s.x) + spin_work(s.x);
    if (first_) {
      first_ = false;
      e0_ = s.energy;
      e_min_ = s.energy;
      run_.jellett0 = J;
    } else {
      integral_ += 0.5 * (s.t - t_prev_) * (rate + rate_prev_);
    }
    const double jscale = std::abs(run_.jellett0);
    run_.max_energy_rise = std::max(run_.max_energy_rise, (s.energy - e_min_) / e0_);
    e_min_ = std::min(e_min_, s.energy);
    run_.energy_balance_error = std::max(run_.energy_balance_error, std::abs(s.energy + work - e0_) / e0_);
    run_.max_jellett_change = std::max(run_.max_jellett_change, std::abs(J - run_.jellett0) / jscale);
    run_.jellett_identity_error =
        std::max(run_.jellett_identity_error, std::abs(J - run_.jellett0 - integral_) / jscale);
    if (run_.gamma3_curve.empty() || s.t >= next_curve_t_) {
      run_.gamma3_curve.emplace_back(s.t, g3);
      run_.jellett_curve.emplace_back(s.t, J / run_.jellett0);
      next_curve_t_ = s.t + kCurveDt;
    }
    last_g3 = g3;
    t_prev_ = s.t;
    rate_prev_ = rate;
  }

  InversionWatch watch;
  double last_g3 = 0.0;

 private:
  const BodyOnPlane& sys_;
  TippeTopRun& run_;
  bool first_ = true;
  double e0_ = 0.0, e_min_ = 0.0;
  double integral_ = 0.0, t_prev_ = 0.0, rate_prev_ = 0.0;
  double next_curve_t_ = 0.0;
};

bool accepted(const std::string& spec) {
  try {
    (void)friction::make_law(spec);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

void TippeTopStudyOptions::validate() const {
  if (max_steps <= 0) throw support::invalid_value("--max-steps", static_cast<long long>(max_steps), "it must be > 0");
  if (!(std::isfinite(output_dt) && output_dt > 0.0 && output_dt <= 0.1))
    throw support::invalid_value("--output-dt", output_dt, "it must be in (0, 0.1] s");
}

std::vector<std::string> default_tippe_top_laws(std::vector<std::string>* unavailable) {
  std::vector<std::string> laws;
  // A slow law (milliseconds per call, a quadrature cross-check) would take hours here.
  for (const auto& info : friction::list_laws())
    if (!info.slow) laws.push_back(info.name);
  for (const auto& spec : kSpinMomentSpecs) {
    if (std::find(laws.begin(), laws.end(), spec) != laws.end()) continue;
    if (accepted(spec))
      laws.push_back(spec);
    else if (unavailable)
      unavailable->push_back(spec);
  }
  return laws;
}

TippeTopRun run_tippe_top(const std::filesystem::path& scenario, const std::string& law,
                          const TippeTopStudyOptions& options) {
  TippeTopRun run;
  run.law = law;
  // Without stick (docs/dynamics.md §5): the study compares the laws through the inversion, and
  // ends each run where the contact first stops slipping and spinning (its figures and tables,
  // docs/tippe-top.md, were made so).
  run.overrides = {"contact.law=" + law, "run.output_dt=" + support::shortest(options.output_dt),
                   "run.max_steps=" + std::to_string(options.max_steps), "run.stick=false"};
  run.overrides.insert(run.overrides.end(), options.overrides.begin(), options.overrides.end());
  const Scenario s = load_scenario(scenario, run.overrides);
  const auto made = friction::make_law(s.law);
  const BodyOnPlane sys(s.body, s.contact, *made);
  Meter meter(sys, run);
  run.summary = simulate(sys, initial_state(s), s.run, &meter);
  run.started_upright = meter.watch.started_upright();
  run.horizontal_time = meter.watch.horizontal_time();
  run.inversion_time = meter.watch.inversion_time();
  run.min_gamma3 = meter.watch.min_gamma3();
  run.min_gamma3_time = meter.watch.min_gamma3_time();
  run.final_gamma3 = meter.last_g3;
  return run;
}

TippeTopStudyResults run_tippe_top_study(const TippeTopStudyOptions& options) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  TippeTopStudyResults r;
  r.scenario = options.scenario;
  if (!std::filesystem::is_regular_file(r.scenario))
    throw std::invalid_argument("scenario file '" + r.scenario.string() + "' does not exist (--scenario names it)");
  r.laws = options.laws.empty() ? default_tippe_top_laws(&r.unavailable) : options.laws;
  for (const auto& law : r.laws)
    if (!accepted(law)) {
      try {
        (void)friction::make_law(law);
      } catch (const std::invalid_argument& e) {
        throw support::invalid_value("--laws", std::string_view(law), e.what());
      }
    }
  for (const auto& law : r.laws) r.runs.push_back(run_tippe_top(r.scenario, law, options));
  r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace frictionlab::dynamics::tippe_top
