#pragma once
// Registration of built-in laws from frictionlab's own optional libraries (friction/reference_laws.h):
// a law that, unlike a user's (register_law()), cannot be unregistered and takes its name and
// summary from the law itself. Not for user code.

#include <vector>

#include "friction/registry.h"

namespace frictionlab::friction {

/// Adds the law `factory` makes (its name() and summary() at `parameters`' defaults) as built in.
/// std::invalid_argument if its name is taken.
void register_built_in_law(LawFactory factory, std::vector<LawParameter> parameters, LawFacts facts);

}  // namespace frictionlab::friction
