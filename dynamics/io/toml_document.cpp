#include "dynamics/io/toml_document.h"

#include <sstream>
#include <stdexcept>

#include "dynamics/io/toml_nesting.h"

namespace frictionlab::dynamics {

toml::table parse_toml(std::string_view text, const std::string& source) {
  check_toml_nesting(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream m;
    m << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    throw std::invalid_argument(m.str());
  }
}

std::optional<toml::table> try_parse_toml(std::string_view text, const std::string& source) {
  check_toml_nesting(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

}  // namespace frictionlab::dynamics
