#include "dynamics/ensemble/replica.h"

#include <algorithm>

#include "dynamics/ensemble/random_stream.h"

namespace frictionlab::dynamics::ensemble {

StartState perturb_replica(StartState state, double size, double rate_scale, std::uint64_t seed, long start,
                           long replica) {
  if (replica == 0) return state;
  RandomStream rng(derive_seed(seed, static_cast<std::uint64_t>(start), static_cast<std::uint64_t>(replica)));
  Eigen::Vector3d u;
  Eigen::Vector3d w;
  for (int i = 0; i < 3; ++i) u[i] = rng.uniform(-1.0, 1.0);
  for (int i = 0; i < 3; ++i) w[i] = rng.uniform(-1.0, 1.0);
  const Eigen::Vector3d gamma = state.initial.gamma + size * u;
  state.initial.gamma = gamma / gamma.norm();
  state.initial.omega += size * std::max(state.initial.omega.norm(), rate_scale) * w;
  state.gamma_set = true;
  state.omega_set = true;
  return state;
}

}  // namespace frictionlab::dynamics::ensemble
