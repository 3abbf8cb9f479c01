#pragma once
// Contacts in the dimensionless form every law depends on (docs/model.md, scaling):
// a = 1 m, b = mu, U = s |Omega|, N = 1 N, k = 1, so F1, F2 read per kN and M per kN a.

#include <cmath>

#include "friction/law.h"

namespace frictionlab::friction {

inline ContactInput dimensionless_contact(double s, double mu, double psi, double omega = 1.0) {
  ContactInput in;
  in.a = 1.0;
  in.b = mu;
  in.psi = psi;
  in.Omega = omega;
  in.U = s * std::abs(omega);
  in.N = 1.0;
  in.k = 1.0;
  return in;
}

}  // namespace frictionlab::friction
