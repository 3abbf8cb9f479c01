#include "dynamics/puck/puck_equations.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {

PuckOnPlane::PuckOnPlane(const Puck& puck, double k, double g, const friction::FrictionLaw& law)
    : puck_(puck), k_(k), g_(g), law_(law) {
  puck_.validate();
  if (!(std::isfinite(k) && k >= 0.0)) throw support::invalid_value("contact.k", k, "it must be finite and >= 0");
  if (!(std::isfinite(g) && g >= 0.0)) throw support::invalid_value("contact.g", g, "it must be finite and >= 0 m/s^2");
}

PuckContact PuckOnPlane::contact(const PuckState& x, Holds holds) const {
  PuckContact c;
  const Eigen::Vector2d v = holds.slip ? Eigen::Vector2d::Zero() : Eigen::Vector2d(velocity(x));
  const double th = heading(x);
  const Eigen::Vector2d major(std::cos(th), std::sin(th));
  c.U = v.norm();
  c.Omega = holds.spin ? 0.0 : spin(x);
  c.N = puck_.mass * g_;
  // Below the smallest normal double the slip direction is noise: no slip, e1 = the major axis.
  if (c.U >= std::numeric_limits<double>::min()) {
    c.e1 = v / c.U;
    c.psi = std::remainder(th - std::atan2(c.e1.y(), c.e1.x()), std::numbers::pi);  // the axis is a line
    if (c.psi < 0.0) c.psi += std::numbers::pi;
    if (c.psi >= std::numbers::pi) c.psi -= std::numbers::pi;
  } else {
    c.U = 0.0;
    c.e1 = major;
    c.psi = 0.0;
  }
  if (puck_.a == puck_.b) c.psi = 0.0;  // a circle has no axis
  c.friction = law_.evaluate({c.U, c.Omega, puck_.a, puck_.b, c.psi, c.N, k_});
  const Eigen::Vector2d e2(-c.e1.y(), c.e1.x());  // z x e1
  c.force = -c.friction.F1 * c.e1 - c.friction.F2 * e2;
  return c;
}

void PuckOnPlane::derivatives(const PuckState& x, const PuckContact& c, Holds holds, PuckState& dxdt) const {
  position(dxdt) = holds.slip ? Eigen::Vector2d::Zero() : Eigen::Vector2d(velocity(x));
  heading(dxdt) = holds.spin ? 0.0 : spin(x);
  velocity(dxdt) = holds.slip ? Eigen::Vector2d::Zero() : Eigen::Vector2d(c.force / puck_.mass);
  spin(dxdt) = holds.spin ? 0.0 : -c.friction.M / puck_.inertia;
  slide_work(dxdt) = c.friction.F1 * c.U;
  spin_work(dxdt) = c.friction.M * c.Omega;
}

std::string PuckOnPlane::describe_friction(const PuckState& x, const Holds& holds) const {
  const auto num = [](double v) { return support::message_number(v); };
  try {
    const PuckContact c = contact(x, holds);
    return "friction law '" + std::string(law_.name()) + "' gives F1 = " + num(c.friction.F1) + " N, F2 = " +
           num(c.friction.F2) + " N, M = " + num(c.friction.M) + " N m at U = " + num(c.U) + " m/s, Omega = " +
           num(c.Omega) + " 1/s, psi = " + num(c.psi);
  } catch (const std::exception& e) {
    return e.what();
  }
}

double PuckOnPlane::energy(const PuckState& x) const {
  return 0.5 * puck_.mass * velocity(x).squaredNorm() + 0.5 * puck_.inertia * spin(x) * spin(x);
}

}  // namespace frictionlab::dynamics::puck
