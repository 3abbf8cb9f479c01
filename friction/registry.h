#pragma once
// Friction laws by name, with what callers need to know about each. Callers choose a law once,
// from a name, and never branch on it again: a per-law fact (which law is the reference, which is
// too slow for simulations, which has poles, which symmetries it keeps) is read from here.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "friction/law.h"

namespace frictionlab::friction {

/// A registered law and its facts.
struct LawInfo {
  std::string name;
  std::string summary;      ///< one line: what the law is, where it comes from, its accuracy
  bool reference = false;   ///< the law every other law is measured against (exactly one)
  bool slow = false;        ///< milliseconds per call: a cross-check for tests and small studies,
                            ///< not for simulations or full accuracy grids
  bool has_poles = false;   ///< FrictionLaw::has_poles(): it declares denominators to watch
  LawPromises promises;     ///< FrictionLaw::promises()
};

/// Every registered law, in a stable order (the reference first).
[[nodiscard]] std::vector<LawInfo> list_laws();

/// The facts of the law called `name`; throws std::invalid_argument listing the known names.
[[nodiscard]] LawInfo law_info(std::string_view name);

/// The law called `name`; throws std::invalid_argument listing the known names otherwise.
[[nodiscard]] std::unique_ptr<FrictionLaw> make_law(std::string_view name);

/// The name of the reference law ("exact"): the one every other law is compared with.
[[nodiscard]] std::string reference_law_name();

/// A new instance of the reference law.
[[nodiscard]] std::unique_ptr<FrictionLaw> make_reference_law();

}  // namespace frictionlab::friction
