#pragma once
// How deeply a TOML text nests, measured before it is parsed. toml++ builds, copies, prints and
// destroys nested tables by recursion, so a table or dotted key nested tens of thousands of levels
// deep ([a.a.a...], a.a.a... = 1) exhausts the stack and kills the process. Every TOML text
// frictionlab reads (scenarios, studies, --set values; dynamics/io/toml_document.h) is measured here
// first and refused beyond kMaxTomlNesting levels, without recursion.
//
// Each of these adds one level: a part of a table header ([a.b] is 2; [[a.b]] is 3, its
// elements being tables inside an array), a part of a dotted key (a.b = 1 inside [t] reaches 3),
// an array and an inline table (x = [[1]] reaches 3, x = {y = {z = 1}} reaches 3).

#include <cstddef>
#include <string>
#include <string_view>

namespace frictionlab::dynamics {

/// The deepest nesting a TOML text may have (levels as the header comment counts them).
/// Shipped scenarios reach 3, studies 4 (the values of a [[vary]] table).
inline constexpr int kMaxTomlNesting = 64;

/// The deepest point of a text: its depth and its line (1-based).
struct TomlNesting {
  int depth = 0;
  std::size_t line = 0;
};

/// The nesting of `text`, scanning no further than the first point deeper than `stop_above`
/// (so the scan of a huge nested text ends early). Linear in the text, no recursion; reads
/// malformed text too (the parser reports it afterwards).
[[nodiscard]] TomlNesting toml_nesting(std::string_view text, int stop_above = kMaxTomlNesting);

/// Throws std::invalid_argument "WHERE: nested more than 64 levels deep; ..." if
/// `depth` > kMaxTomlNesting. WHERE names the file and line, the key, or the dict.
void check_toml_nesting(int depth, const std::string& where);

/// check_toml_nesting(toml_nesting(text).depth, "SOURCE:LINE").
void check_toml_nesting(std::string_view text, const std::string& source);

}  // namespace frictionlab::dynamics
