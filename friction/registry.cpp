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

// A law's role in the toolkit: facts about how it is used rather than what it computes (those
// are the law's own: has_poles(), promises()).
struct Entry {
  Factory make;
  bool reference = false;
  bool slow = false;
};

template <class Law>
Factory factory() {
  return [] { return std::make_unique<Law>(); };
}

// The one list of laws. Add a law here and it is known to the command line, the benchmarks, the
// accuracy study and the soundness tests.
const std::vector<Entry>& entries() {
  static const std::vector<Entry> all = {
      {factory<ExactLaw>(), /*reference=*/true, /*slow=*/false},
      {factory<ExactReferenceLaw>(), false, /*slow=*/true},
      {[] { return std::make_unique<PadePrintedLaw>(PadeAlpha::major); }},
      {[] { return std::make_unique<PadePrintedLaw>(PadeAlpha::minor); }},
      {factory<PadeReconstructedLaw>()},
      {factory<MollerEllipsoidalLaw>()},
      {factory<CoulombDecoupledLaw>()},
  };
  return all;
}

LawInfo info_of(const Entry& e) {
  const auto law = e.make();
  return {std::string(law->name()), std::string(law->summary()), e.reference, e.slow, law->has_poles(),
          law->promises()};
}

const Entry& entry(std::string_view name) {
  for (const auto& e : entries()) {
    if (e.make()->name() == name) return e;
  }
  std::string known;
  for (const auto& info : list_laws()) known += (known.empty() ? "" : ", ") + info.name;
  throw std::invalid_argument("unknown friction law '" + std::string(name) + "'; known laws: " + known);
}

}  // namespace

std::vector<LawInfo> list_laws() {
  std::vector<LawInfo> out;
  for (const auto& e : entries()) out.push_back(info_of(e));
  return out;
}

LawInfo law_info(std::string_view name) { return info_of(entry(name)); }

std::unique_ptr<FrictionLaw> make_law(std::string_view name) { return entry(name).make(); }

std::string reference_law_name() {
  for (const auto& e : entries()) {
    if (e.reference) return std::string(e.make()->name());
  }
  throw std::logic_error("the registry has no reference law");
}

std::unique_ptr<FrictionLaw> make_reference_law() { return make_law(reference_law_name()); }

}  // namespace frictionlab::friction
