#pragma once
// The "shadow" block of summary.json for a run with shadow laws (dynamics/core/shadow_laws.h;
// docs/dynamics.md §10 lists its keys).

#include "dynamics/core/shadow_csv.h"
#include "dynamics/core/shadow_laws.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics {

/// The statistics of `laws` and what `csv` (may be null) wrote; `run_work` (J) is the friction work
/// of the run as its state integrated it (the base of each law's dissipation).
[[nodiscard]] support::Json shadow_json(const ShadowLaws& laws, const ShadowCsv* csv, double run_work);

}  // namespace frictionlab::dynamics
