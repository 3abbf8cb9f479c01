#include "bench/accuracy/singularity.h"

#include <cmath>
#include <memory>

#include "friction/registry.h"

namespace frictionlab::accuracy {
namespace {

constexpr Component kComponents[] = {Component::F1, Component::F2, Component::M};

}  // namespace

bool is_singular(double F1, double F2, double M) {
  const auto bad = [](double x) { return !std::isfinite(x) || std::abs(x) > kSingularMagnitude; };
  return bad(F1) || bad(F2) || bad(M);
}

std::string_view component_name(Component c) {
  switch (c) {
    case Component::F1: return "F1";
    case Component::F2: return "F2";
    case Component::M: return "M";
  }
  return "?";
}

std::optional<DenominatorFunction> known_denominators(std::string_view law) {
  std::shared_ptr<const friction::FrictionLaw> made = friction::make_law(law);
  if (!made->has_poles()) return std::nullopt;
  return [made](double s, double mu, double psi) {
    const friction::PoleDenominators d = made->pole_denominators(to_contact({s, mu, psi, 1}));
    return Denominators{d.F1, d.F2, d.M};
  };
}

std::vector<PoleBracket> pole_brackets(const Grid& grid, const DenominatorFunction& den) {
  std::vector<PoleBracket> out;
  const auto& s = grid.s();
  for (std::size_t imu = 0; imu < grid.mu().size(); ++imu) {
    for (std::size_t ipsi = 0; ipsi < grid.psi().size(); ++ipsi) {
      Denominators prev = den(s[0], grid.mu()[imu], grid.psi()[ipsi]);
      for (std::size_t is = 1; is < s.size(); ++is) {
        const Denominators cur = den(s[is], grid.mu()[imu], grid.psi()[ipsi]);
        for (const Component c : kComponents) {
          // A sign change, or a node exactly on the pole (then bracket it from the left).
          const bool change = (prev[c] < 0.0 && cur[c] >= 0.0) || (prev[c] > 0.0 && cur[c] <= 0.0);
          if (change) out.push_back({c, imu, ipsi, s[is - 1], s[is]});
        }
        prev = cur;
      }
    }
  }
  return out;
}

std::vector<std::uint8_t> singularity_map(const Grid& grid, const LawValues& law,
                                          const std::optional<DenominatorFunction>& den) {
  const std::size_t ns = grid.s().size();
  const std::size_t npsi = grid.psi().size();
  std::vector<std::uint8_t> map(grid.mu().size() * npsi * ns, 0);
  for (std::size_t imu = 0; imu < grid.mu().size(); ++imu) {
    for (std::size_t ipsi = 0; ipsi < npsi; ++ipsi) {
      for (std::size_t is = 0; is < ns; ++is) {
        std::uint8_t bits = 0;
        if (den) {
          const Denominators d = (*den)(grid.s()[is], grid.mu()[imu], grid.psi()[ipsi]);
          if (d.F2 < 0.0) bits |= kF2DenominatorNegative;
          if (d.M < 0.0) bits |= kMDenominatorNegative;
          if (d.F1 < 0.0) bits |= kF1DenominatorNegative;
        }
        for (std::size_t isign = 0; isign < Grid::kSigns.size(); ++isign) {
          const std::size_t i = grid.index(imu, ipsi, isign, is);
          if (is_singular(law.F1[i], law.F2[i], law.M[i])) bits |= kSingularValue;
        }
        map[(imu * npsi + ipsi) * ns + is] = bits;
      }
    }
  }
  return map;
}

}  // namespace frictionlab::accuracy
