#include "dynamics/rigid_rolling/rattleback_presets.h"

namespace frictionlab::dynamics::rigid_rolling {

EllipsoidBody kane_levinson_rattleback() {
  constexpr double kMass = 1.0;             // kg (the source gives inertia per unit mass)
  constexpr double kSquareCm = 1e-4;        // m^2 per cm^2
  EllipsoidBody b;
  b.semi_axes = Eigen::Vector3d(0.20, 0.03, 0.02);
  b.centre_height = 0.01;                   // the ellipsoid's centre 1 cm above G
  b.mass = kMass;
  b.inertia << 2.0, 0.2, 0.0,               // J12 = +0.2 cm^2 (tensor element, z up; header comment)
               0.2, 16.0, 0.0,
               0.0, 0.0, 17.0;
  b.inertia *= kMass * kSquareCm;
  b.gravity = 9.81;
  return b;
}

}  // namespace frictionlab::dynamics::rigid_rolling
