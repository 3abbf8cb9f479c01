#pragma once
// A run's shadow laws as its folder carries them (run.shadow; dynamics/core/shadow_laws.h): the laws
// made from their specs, their statistics, shadow.csv beside trajectory.csv, and the "shadow" block
// of summary.json. Shared by every model's scenario run (dynamics/body/scenario_run.h,
// dynamics/puck/puck_scenario_run.h); the model's own part is its ShadowObserver.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/core/motion_phase.h"
#include "dynamics/core/shadow_csv.h"
#include "dynamics/core/shadow_laws.h"
#include "friction/law.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics {

class ShadowOutput {
 public:
  /// No specs: inactive (nothing is made or written). Otherwise makes each law (std::invalid_argument
  /// naming run.shadow for a bad spec) and creates `csv_file` (support::OutputError if it cannot).
  ShadowOutput(const friction::FrictionLaw& own, const std::vector<std::string>& specs, const MotionPhaseRule& rule,
               const std::filesystem::path& csv_file, std::uint64_t max_bytes);

  [[nodiscard]] bool active() const { return laws_ != nullptr; }
  /// The laws' statistics and the file (active only).
  [[nodiscard]] ShadowLaws& laws() { return *laws_; }
  [[nodiscard]] ShadowCsv* csv() { return csv_.get(); }
  /// Closes shadow.csv (never throws: a failure is reported in the summary).
  void close();
  /// Adds {"shadow": ...} (dynamics/core/shadow_json.h) to `summary` if active; `run_work` (J): the
  /// run's friction work.
  void add_to(support::Json& summary, double run_work) const;

 private:
  std::vector<std::unique_ptr<friction::FrictionLaw>> owned_;
  std::unique_ptr<ShadowLaws> laws_;
  std::unique_ptr<ShadowCsv> csv_;
};

}  // namespace frictionlab::dynamics
