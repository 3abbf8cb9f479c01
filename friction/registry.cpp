#include "friction/registry.h"

#include <functional>
#include <stdexcept>

#include "friction/coulomb_decoupled_law.h"
#include "friction/exact_law.h"
#include "friction/exact_reference_law.h"
#include "friction/moller_ellipsoidal_law.h"
#include "friction/pade_printed_law.h"
#include "friction/pade_reconstructed_law.h"

namespace frictionlab::friction {
namespace {

using Factory = std::function<std::unique_ptr<FrictionLaw>()>;

template <class Law>
Factory factory() {
  return [] { return std::make_unique<Law>(); };
}

// The one list of laws. Add a law here and it is known to the command line, the benchmarks and
// the accuracy study.
const std::vector<Factory>& factories() {
  static const std::vector<Factory> all = {
      factory<ExactLaw>(),
      factory<ExactReferenceLaw>(),
      [] { return std::make_unique<PadePrintedLaw>(PadeAlpha::major); },
      [] { return std::make_unique<PadePrintedLaw>(PadeAlpha::minor); },
      factory<PadeReconstructedLaw>(),
      factory<MollerEllipsoidalLaw>(),
      factory<CoulombDecoupledLaw>(),
  };
  return all;
}

}  // namespace

std::vector<LawInfo> list_laws() {
  std::vector<LawInfo> out;
  for (const auto& make : factories()) {
    const auto law = make();
    out.push_back({std::string(law->name()), std::string(law->summary())});
  }
  return out;
}

std::unique_ptr<FrictionLaw> make_law(std::string_view name) {
  for (const auto& make : factories()) {
    auto law = make();
    if (law->name() == name) return law;
  }
  std::string known;
  for (const auto& info : list_laws()) known += (known.empty() ? "" : ", ") + info.name;
  throw std::invalid_argument("unknown friction law '" + std::string(name) + "'; known laws: " + known);
}

}  // namespace frictionlab::friction
