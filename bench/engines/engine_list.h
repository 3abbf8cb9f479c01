#pragma once
// The engines this build has (each adapter is optional: bench/engines/CMakeLists.txt builds it when
// its Debian package is installed), and those it lacks, for the side by side to run and to name.

#include <memory>
#include <string>
#include <vector>

#include "bench/engines/engine.h"

namespace frictionlab::engines {

/// The engines built, each with its default options (MuJoCo, Bullet, ODE order).
[[nodiscard]] std::vector<std::unique_ptr<Engine>> built_engines();

/// An engine with options of its own, and what they are in a few words.
struct EngineVariant {
  std::string label;  ///< "elliptic cone, impratio 100"
  std::unique_ptr<Engine> engine;
};

/// For each engine built, the options of its own that bring it closest to the answers of the side
/// by side (docs/engines.md §6), beside its defaults: MuJoCo's elliptic cone with impratio 100 (the
/// friction rows' softness 100 times smaller than the normal's), Bullet's second friction direction,
/// ODE's exact LCP (dWorldStep) instead of QuickStep.
[[nodiscard]] std::vector<EngineVariant> tuned_engines();

/// Those not built, as "Bullet (libbullet-dev)"; empty when all are.
[[nodiscard]] std::vector<std::string> missing_engines();

}  // namespace frictionlab::engines
