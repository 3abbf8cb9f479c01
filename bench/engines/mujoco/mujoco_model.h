#pragma once
// Internal to the MuJoCo adapter: the checks and resolved numbers that the model text
// (mujoco_model.cpp) and the run (mujoco_world.cpp) share.

#include "bench/engines/engine.h"
#include "bench/engines/mujoco/mujoco_engine.h"

namespace frictionlab::engines::mujoco_detail {

/// std::invalid_argument naming the field, its value and the rule (engine.h's fields, keys as
/// "body.radius", "start.v", "numerics.timestep", ...).
void validate(const RunSpec& spec);

/// The step taken: Numerics::timestep, or MuJoCo's default 0.002 s when it is 0.
[[nodiscard]] double timestep(const RunSpec& spec);
/// The solver's iteration limit: Numerics::iterations, or MujocoOptions::iterations when it is 0.
[[nodiscard]] int iterations(const RunSpec& spec, const MujocoOptions& options);

}  // namespace frictionlab::engines::mujoco_detail
