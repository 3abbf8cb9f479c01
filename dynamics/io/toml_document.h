#pragma once
// The one way frictionlab parses TOML text (scenarios, studies, the values of --set overrides):
// the text's nesting is checked first (dynamics/io/toml_nesting.h), so that no input can make the
// parser recurse out of the stack, and parse errors become one std::invalid_argument
// "SOURCE:LINE:COLUMN: what is wrong".
// Internal to the readers: it exposes toml++ (a private dependency).

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>

namespace frictionlab::dynamics {

/// The table `text` holds. std::invalid_argument if it nests too deeply or is not TOML.
[[nodiscard]] toml::table parse_toml(std::string_view text, const std::string& source);

/// The same, but text that is not TOML gives std::nullopt (the caller reads it another way);
/// too deep a nesting is still std::invalid_argument.
[[nodiscard]] std::optional<toml::table> try_parse_toml(std::string_view text, const std::string& source);

}  // namespace frictionlab::dynamics
