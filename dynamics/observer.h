#pragma once
// What a run reports while it goes: samples on the output grid (and at the end), and progress.

#include "dynamics/equations_of_motion.h"
#include "dynamics/state.h"

namespace frictionlab::dynamics {

/// One output sample.
struct Sample {
  double t = 0.0;             ///< s
  const StateVector& x;       ///< the state (gamma as integrated, not renormalised)
  const ContactState& contact;
  double energy = 0.0;        ///< total mechanical energy, J
  double kinetic = 0.0;       ///< kinetic energy, J
};

class Observer {
 public:
  virtual ~Observer() = default;
  /// At t = 0, at every multiple of the output interval, and once at the final time.
  virtual void sample(const Sample& s) = 0;
  /// After every accepted step (cheap; for progress display).
  virtual void step(double /*t*/) {}
};

}  // namespace frictionlab::dynamics
