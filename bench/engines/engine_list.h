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

/// Those not built, as "Bullet (libbullet-dev)"; empty when all are.
[[nodiscard]] std::vector<std::string> missing_engines();

}  // namespace frictionlab::engines
