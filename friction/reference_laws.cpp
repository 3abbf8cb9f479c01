#include "friction/reference_laws.h"

#include <memory>
#include <mutex>

#include "friction/exact_reference_law.h"
#include "friction/registry_extension.h"

namespace frictionlab::friction {

void register_reference_laws() {
  static std::once_flag once;
  std::call_once(once, [] {
    LawFacts facts;
    facts.slow = true;
    register_built_in_law(
        [](const LawArguments& a) { return std::make_unique<ExactReferenceLaw>(parse_pressure(a.choice("pressure"))); },
        ExactReferenceLaw::parameters(), facts);
  });
}

}  // namespace frictionlab::friction
