#pragma once
// The tippe-top study (`frictionlab tippe-top`, docs/tippe-top.md): the tippe top of
// data/scenarios/tippe-top.toml run with every friction law, from the same start, through its
// inversion to its end (rest, or t_end while it still spins): gamma3 against time, the inversion
// time (gamma3 from near +1 to below -0.9, dynamics/tippe_top/tippe_top_observables.h), the
// energy (never rising under a dissipative law; its balance with the friction work) and Jellett's
// quantity L . r (conserved without a spin moment; with one, changed exactly by -∫ M gamma . r dt).
// The spin moment's effect: the exact law against the decoupled law with the exact pure-spin
// torque and the same law without any spin moment (r_spin = 0), where the registry has them.
//
// Every run is the scenario file with overrides (recorded): `frictionlab simulate FILE --set ...`
// reruns it.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/body/simulation.h"

namespace frictionlab::dynamics::tippe_top {

struct TippeTopStudyOptions {
  std::filesystem::path scenario;  ///< the tippe-top scenario file
  std::vector<std::string> laws;   ///< law specs; empty: default_tippe_top_laws()
  /// Accepted steps allowed per run (run.max_steps): a bound on what the chatter event does not
  /// catch (a discontinuous law that chatters where the slip or the spin passes through 0, with
  /// steps of ~1e-10 s, ends "chatter" after run.max_chatter_steps, dynamics/core/chatter_watch.h), so
  /// that no run grinds for hours.
  long max_steps = 300'000;
  double output_dt = 1e-3;  ///< s: the sampling of gamma3 and of the energy and Jellett checks
  /// More "key=value" overrides of the scenario, applied after the study's own (e.g. run.t_end).
  std::vector<std::string> overrides;

  void validate() const;  ///< std::invalid_argument naming the option
};

/// Every registered law that is not slow (friction/registry.h), then `decoupled` and
/// `decoupled:r_spin=0` where the registry accepts them (those it refuses go to `unavailable`).
[[nodiscard]] std::vector<std::string> default_tippe_top_laws(std::vector<std::string>* unavailable = nullptr);

struct TippeTopRun {
  std::string law;
  std::vector<std::string> overrides;
  RunSummary summary;
  bool started_upright = false;
  double horizontal_time = 0.0;  ///< s, gamma3 first below 0 (NaN: never)
  double inversion_time = 0.0;   ///< s, gamma3 first below -0.9 (NaN: never)
  double min_gamma3 = 0.0;
  double min_gamma3_time = 0.0;
  double final_gamma3 = 0.0;
  double max_energy_rise = 0.0;     ///< largest E(t_i) - min_{j<i} E(t_j) over the samples, / E(0)
  double energy_balance_error = 0.0;  ///< max |E + W_slide + W_spin - E(0)| / E(0) over the samples
  double jellett0 = 0.0;              ///< L . r at t = 0, kg m^3/s
  double max_jellett_change = 0.0;    ///< max |L.r - L.r(0)| / |L.r(0)|
  /// max |L.r - L.r(0) - ∫ -M gamma.r dt| / |L.r(0)| (the integral by the trapezoidal rule over
  /// the samples): the identity of the header comment, checked along the run.
  double jellett_identity_error = 0.0;
  /// Thinned curves for the figures: (t, gamma3), (t, L.r / L.r(0)).
  std::vector<std::pair<double, double>> gamma3_curve, jellett_curve;
};

struct TippeTopStudyResults {
  std::filesystem::path scenario;
  std::vector<std::string> laws;
  std::vector<std::string> unavailable;
  std::vector<TippeTopRun> runs;
  double wall_time = 0.0;
};

/// Runs the study. Throws std::invalid_argument for bad options, a missing or invalid scenario, or
/// an explicitly given law spec the registry refuses.
[[nodiscard]] TippeTopStudyResults run_tippe_top_study(const TippeTopStudyOptions& options);

/// One run of the study: `scenario` with contact.law = law, run.output_dt and run.max_steps set
/// from `options`, then options.overrides, measured. Throws what resolving the scenario throws.
[[nodiscard]] TippeTopRun run_tippe_top(const std::filesystem::path& scenario, const std::string& law,
                                        const TippeTopStudyOptions& options);

}  // namespace frictionlab::dynamics::tippe_top
