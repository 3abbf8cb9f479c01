#pragma once
// What a model tells the shadow laws (dynamics/core/shadow_laws.h) about one state of its run: the
// contact as a friction law sees it, and what the run's own law gives there.

#include "friction/law.h"

namespace frictionlab::dynamics {

struct ShadowPoint {
  /// In contact with a patch (N > 0, a > 0): the laws are evaluated; otherwise there is no friction.
  bool in_contact = false;
  /// The contact as the run's law saw it (U, Omega, a, b, psi, N, k), bit for bit.
  friction::ContactInput input;
  /// The run's own law at `input` when the run used it there (the free mode), so that it is not
  /// evaluated twice; otherwise (a held or stuck contact, whose friction is not the law's)
  /// own_known is false and the shadow evaluates the run's law at `input` itself.
  friction::FrictionForces own;
  bool own_known = false;
  /// The speed of the contact along the normal, m/s (the body's eps'; 0 on a rigid plane).
  double normal_speed = 0.0;
};

}  // namespace frictionlab::dynamics
