#include "dynamics/ensemble/variant.h"

#include "friction/support/errors.h"

namespace frictionlab::dynamics::ensemble {

Variant parse_variant(std::string_view label, const std::string& key) {
  const std::size_t at = label.find('@');
  Variant v;
  v.law = std::string(label.substr(0, at));
  if (v.law.empty()) throw support::invalid_value(key, label, "it must name a law (LAW or LAW@PATCH, e.g. exact@hertz)");
  if (at == std::string_view::npos) return v;
  v.patch = std::string(label.substr(at + 1));
  if (v.patch.empty() || v.patch.find('@') != std::string::npos)
    throw support::invalid_value(key, label, "after '@' comes one contact model (LAW@PATCH, e.g. exact@hertz)");
  return v;
}

std::vector<std::string> variant_overrides(const Variant& v) {
  std::vector<std::string> o{"contact.law=" + v.law};
  if (!v.patch.empty()) o.push_back("contact.patch=" + v.patch);
  return o;
}

}  // namespace frictionlab::dynamics::ensemble
