#pragma once
// frictionlab's rows of the engines' side by side: a problem (bench/engines/problems.h) run from
// its scenario with a law, its samples in the engines' terms (bench/engines/engine.h) so that
// bench/engines/measures.h measures every run the same way.

#include <filesystem>
#include <string>

#include "bench/engines/engine.h"
#include "bench/engines/problems.h"

namespace frictionlab::engines {

struct FrictionlabRun {
  Run run;             ///< samples (Sample::com[2] is NaN: the reduced state has no height of the centre)
  std::string ended;   ///< the run's termination reason and time ("rest at 5.505 s")
};

/// Runs `problem`'s scenario with the law `law_spec` (a registry spec) and `overrides`
/// ("key=value", as `frictionlab simulate --set`), writing the run folder to `out_dir`.
[[nodiscard]] FrictionlabRun run_frictionlab(const Problem& problem, const std::string& law_spec,
                                             const std::filesystem::path& out_dir,
                                             const std::vector<std::string>& overrides = {});

}  // namespace frictionlab::engines
