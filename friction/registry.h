#pragma once
// Friction laws by name. Callers choose a law once, from a name, and never branch on it again.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "friction/law.h"

namespace frictionlab::friction {

/// Name and one-line summary of a registered law.
struct LawInfo {
  std::string name;
  std::string summary;
};

/// Every registered law, in a stable order.
[[nodiscard]] std::vector<LawInfo> list_laws();

/// The law called `name`; throws std::invalid_argument listing the known names otherwise.
[[nodiscard]] std::unique_ptr<FrictionLaw> make_law(std::string_view name);

}  // namespace frictionlab::friction
