#pragma once
// Replicas of a start: copies whose initial state differs by a tiny seeded perturbation, so that
// the spread of one law's outcomes over them measures the chaos of the motion (the floor against
// which a law-vs-law difference is read; docs/ensembles.md §4).
//
// Replica 0 is the start itself. Replica r > 0 moves, with u, w uniform in [-1, 1]^3 drawn from
// RandomStream(derive_seed(seed, start, r)) (the same on every machine, whoever runs it):
//   gamma -> (gamma + size u) / |gamma + size u|       (a tilt of about size rad)
//   omega -> omega + size max(|omega|, sqrt(g/R)) w     (sqrt(g/R): the body's rate scale,
//                                                         dynamics/body/body_scales.h, for a start at rest)
// `size` is the study's replicas.size (dimensionless). v and eps are not perturbed.

#include <cstdint>

#include "dynamics/ensemble/varied_key.h"

namespace frictionlab::dynamics::ensemble {

/// `state` perturbed as replica `replica` of start `start` (replica 0: unchanged). `rate_scale` =
/// sqrt(g/R) of the body (1/s).
[[nodiscard]] StartState perturb_replica(StartState state, double size, double rate_scale, std::uint64_t seed,
                                         long start, long replica);

}  // namespace frictionlab::dynamics::ensemble
