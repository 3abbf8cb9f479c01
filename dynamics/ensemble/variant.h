#pragma once
// A study's compared variant: a friction law, optionally under a contact model other than the
// base scenario's, written `LAW@PATCH` in the study's `laws` (docs/ensembles.md §1):
//
//   laws = ["exact@section", "exact@hertz"]   # the contact model's effect under the exact law
//   laws = ["exact", "pade-reconstructed"]    # the law's effect under the scenario's model
//
// The label is the run's `law` column in runs.csv and its name in the report; the run's scenario
// gets `contact.law=LAW` and, with a suffix, `contact.patch=PATCH` (docs/contact-models.md §4),
// after the study's `set`. Every variant of a replica runs from the same start, so a variant that
// differs only by its contact model measures that model's effect against the same chaos floor as
// a law's.

#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::dynamics::ensemble {

struct Variant {
  std::string law;    ///< as given to the friction registry
  std::string patch;  ///< contact.patch, or empty: the scenario's own
};

/// Splits `LAW` or `LAW@PATCH` (std::invalid_argument naming `key` when a part is empty or there
/// is more than one '@'). Whether LAW and PATCH exist is checked by the registry and the scenario.
[[nodiscard]] Variant parse_variant(std::string_view label, const std::string& key);

/// The scenario overrides that select the variant: contact.law=LAW [, contact.patch=PATCH].
[[nodiscard]] std::vector<std::string> variant_overrides(const Variant& v);

}  // namespace frictionlab::dynamics::ensemble
