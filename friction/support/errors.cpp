#include "friction/support/errors.h"

#include "friction/support/number_format.h"

namespace frictionlab::support {
namespace {

std::string compose(std::string_view key, std::string_view value_text, std::string_view rule) {
  std::string m;
  m.reserve(key.size() + value_text.size() + rule.size() + 16);
  m.append(key).append(" = ").append(value_text).append(" is invalid: ").append(rule);
  return m;
}

}  // namespace

InvalidValue::InvalidValue(std::string_view key, std::string_view value_text, std::string_view rule)
    : std::invalid_argument(compose(key, value_text, rule)), key_(key) {}

InvalidValue::InvalidValue(std::string_view key, std::string message)
    : std::invalid_argument(std::move(message)), key_(key) {}

InvalidValue invalid_value(std::string_view key, double value, std::string_view rule) {
  return {key, message_number(value), rule};
}

InvalidValue invalid_value(std::string_view key, long long value, std::string_view rule) {
  return {key, std::to_string(value), rule};
}

InvalidValue invalid_value(std::string_view key, std::string_view value, std::string_view rule) {
  std::string quoted = "'";
  quoted.append(value).push_back('\'');
  return {key, quoted, rule};
}

InvalidValue invalid_value(std::string_view key, std::span<const double> values, std::string_view rule) {
  return {key, message_list(values), rule};
}

std::string one_line(std::string_view message) {
  std::string out;
  out.reserve(message.size());
  bool blank = false;
  for (const char c : message) {
    const bool space = c == ' ' || c == '\n' || c == '\r' || c == '\t';
    if (space) {
      blank = !out.empty();
      continue;
    }
    if (blank) out.push_back(' ');
    blank = false;
    out.push_back(c);
  }
  return out;
}

}  // namespace frictionlab::support
