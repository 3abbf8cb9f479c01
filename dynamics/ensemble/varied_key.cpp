#include "dynamics/ensemble/varied_key.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynamics/shapes/solid_mass_properties.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {
namespace {

std::string vector_text(const Eigen::Vector3d& v) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    if (i > 0) out += ", ";
    support::append_shortest(out, v[i]);
  }
  return out + "]";
}

std::string matrix_text(const Eigen::Matrix3d& m) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    if (i > 0) out += ", ";
    out += vector_text(m.row(i).transpose());
  }
  return out + "]";
}

// body.misalignment (varied_key.h): the base tensor J with its horizontal principal axes turned to
// `delta` about e3, its principal moments kept.
Eigen::Matrix3d misaligned_inertia(const Eigen::Matrix3d& J, const std::string& key, double delta) {
  if (!(std::abs(delta) < std::numbers::pi / 4))
    throw support::invalid_value(key, delta,
                                 "it is the angle (rad) of the principal axis nearest e1 from e1: |delta| < pi/4");
  if (J(0, 2) != 0.0 || J(2, 0) != 0.0 || J(1, 2) != 0.0 || J(2, 1) != 0.0)
    throw support::invalid_value(key, delta,
                                 "it turns the principal axes about e3, which must be one: the base's body.inertia "
                                 "needs J13 = J23 = 0, but J13 = " + support::message_number(J(0, 2)) +
                                     ", J23 = " + support::message_number(J(1, 2)) + " kg m^2");
  if (J(0, 0) == J(1, 1))
    throw support::invalid_value(key, delta,
                                 "the base's body.inertia has J11 = J22: equal horizontal moments have no misalignment, "
                                 "and with J12 != 0 the principal axes are at 45 degrees to e1 (none is nearest e1)");
  // The horizontal block alone (e3's moment set to 0, the smallest): a C equal to A or B cannot
  // then mix e3 into the horizontal axes. Columns 1, 2 are those axes; A's is the one nearest e1.
  Eigen::Matrix3d horizontal = J;
  horizontal(2, 2) = 0.0;
  const shapes::PrincipalInertia p = shapes::principal_inertia(horizontal);
  const int a = std::abs(p.axes(0, 1)) >= std::abs(p.axes(0, 2)) ? 1 : 2;
  const Eigen::Vector3d moments(p.moments[a], p.moments[3 - a], J(2, 2));
  return shapes::inertia_from_principal(moments, Eigen::Vector3d::UnitZ(), delta);
}

}  // namespace

VariedKey VariedKey::parse(const std::string& key, const std::string& where, bool puck) {
  VariedKey k;
  k.name_ = key;
  if (puck && key == "initial.omega") return k;  // the puck's spin: a scalar
  if (key == "initial.gamma3") {
    k.kind_ = Kind::gamma3;
    return k;
  }
  if (key == "body.misalignment") {
    k.kind_ = Kind::misalignment;
    return k;
  }
  for (const auto& [prefix, kind] : {std::pair{std::string("initial.omega"), Kind::omega},
                                     std::pair{std::string("initial.v"), Kind::velocity}}) {
    if (key == prefix)
      throw support::invalid_value(where, std::string_view(key),
                                   "it is a vector; vary its components " + prefix + "1, " + prefix + "2, " + prefix + "3");
    if (key.size() == prefix.size() + 1 && key.compare(0, prefix.size(), prefix) == 0 && key.back() >= '1' &&
        key.back() <= '3') {
      k.kind_ = kind;
      k.component_ = key.back() - '1';
      return k;
    }
  }
  if (key == "initial.gamma")
    throw support::invalid_value(where, std::string_view(key),
                                 "it is a unit vector; vary the tilt initial.gamma3 (gamma = (sqrt(1 - gamma3^2), 0, gamma3))");
  if (key == "contact.law")
    throw support::invalid_value(where, std::string_view(key), "the laws are the study's `laws`, not a varied key");
  return k;
}

StartState apply_start(const InitialState& base, const Eigen::Matrix3d& base_inertia, const std::vector<VariedKey>& keys,
                       const std::vector<double>& values) {
  StartState s;
  s.initial = base;
  s.inertia = base_inertia;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const VariedKey& k = keys[i];
    const double x = values.at(i);
    if (!std::isfinite(x)) throw support::invalid_value(k.name(), x, "it must be finite");
    switch (k.kind()) {
      case VariedKey::Kind::plain: {
        std::string o = k.name() + "=";
        support::append_shortest(o, x);
        s.overrides.push_back(std::move(o));
        break;
      }
      case VariedKey::Kind::gamma3:
        if (!(std::abs(x) <= 1.0)) throw support::invalid_value(k.name(), x, "it is a cosine: -1 <= gamma3 <= 1");
        s.initial.gamma = Eigen::Vector3d(std::sqrt(1.0 - x * x), 0.0, x);
        s.gamma_set = true;
        break;
      case VariedKey::Kind::omega:
        s.initial.omega[k.component()] = x;
        s.omega_set = true;
        break;
      case VariedKey::Kind::velocity:
        s.initial.v[k.component()] = x;
        s.velocity_set = true;
        break;
      case VariedKey::Kind::misalignment:
        s.inertia = misaligned_inertia(base_inertia, k.name(), x);
        s.inertia_set = true;
        break;
    }
  }
  return s;
}

std::vector<std::string> start_overrides(const StartState& state) {
  std::vector<std::string> out = state.overrides;
  if (state.inertia_set) out.push_back("body.inertia=" + matrix_text(state.inertia));
  if (state.gamma_set) out.push_back("initial.gamma=" + vector_text(state.initial.gamma));
  if (state.omega_set) out.push_back("initial.omega=" + vector_text(state.initial.omega));
  if (state.velocity_set) out.push_back("initial.v=" + vector_text(state.initial.v));
  return out;
}

std::vector<std::string> puck_start_overrides(const Eigen::Vector2d& base_v, const std::vector<VariedKey>& keys,
                                              const std::vector<double>& values) {
  std::vector<std::string> out;
  Eigen::Vector2d v = base_v;
  bool v_set = false;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const VariedKey& k = keys[i];
    const double x = values.at(i);
    if (!std::isfinite(x)) throw support::invalid_value(k.name(), x, "it must be finite");
    if (k.kind() == VariedKey::Kind::plain) {
      std::string o = k.name() + "=";
      support::append_shortest(o, x);
      out.push_back(std::move(o));
    } else if (k.kind() == VariedKey::Kind::velocity && k.component() < 2) {
      v[k.component()] = x;
      v_set = true;
    } else {
      throw support::invalid_value(k.name(), x,
                                   "it is a key of the body model; a puck varies initial.v1, initial.v2 "
                                   "(its velocity [vx, vy]) and scalar keys such as initial.omega");
    }
  }
  if (v_set) {
    std::string o = "initial.v=[";
    support::append_shortest(o, v[0]);
    o += ", ";
    support::append_shortest(o, v[1]);
    out.push_back(o + "]");
  }
  return out;
}

}  // namespace frictionlab::dynamics::ensemble
