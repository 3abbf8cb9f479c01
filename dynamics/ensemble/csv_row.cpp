#include "dynamics/ensemble/csv_row.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {

void append_text_field(std::string& row, std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) {
    row.append(field);
    return;
  }
  row.push_back('"');
  for (const char c : field) {
    if (c == '"') row.push_back('"');
    row.push_back(c);
  }
  row.push_back('"');
}

void append_number_field(std::string& row, double x) {
  if (!std::isnan(x)) support::append_shortest(row, x);
}

std::vector<std::string> split_csv_line(std::string_view line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          fields.back().push_back('"');
          ++i;
        } else {
          quoted = false;
        }
      } else {
        fields.back().push_back(c);
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back().push_back(c);
    }
  }
  if (quoted) throw std::invalid_argument("a CSV row ends inside a quoted field");
  return fields;
}

double parse_number_field(const std::string& field, std::string_view column) {
  if (field.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (field == "inf") return std::numeric_limits<double>::infinity();
  if (field == "-inf") return -std::numeric_limits<double>::infinity();
  double x = 0.0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), x);
  if (ec != std::errc() || end != field.data() + field.size())
    throw std::invalid_argument("column " + std::string(column) + " holds '" + field + "', not a number");
  return x;
}

}  // namespace frictionlab::dynamics::ensemble
