#pragma once
// Fields of a CSV row (RFC 4180): a field with a comma, a quote or a line break is quoted, its
// quotes doubled; numbers are written as the shortest text that reads back to the same double
// (support::shortest), and a missing value (NaN) as an empty field.

#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::dynamics::ensemble {

/// Appends `field` to `row`, quoted if it must be.
void append_text_field(std::string& row, std::string_view field);
/// Appends the shortest round-trip text of `x`, or nothing for NaN.
void append_number_field(std::string& row, double x);

/// The fields of one line (without its line ending). A quote left open is std::invalid_argument.
[[nodiscard]] std::vector<std::string> split_csv_line(std::string_view line);

/// A field as a number: empty is NaN; anything but a whole number is std::invalid_argument naming `column`.
[[nodiscard]] double parse_number_field(const std::string& field, std::string_view column);

}  // namespace frictionlab::dynamics::ensemble
