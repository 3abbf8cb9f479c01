#include "dynamics/cli/option_values.h"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "friction/support/errors.h"

namespace frictionlab::cli {
namespace {

bool all_digits(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// Checks `text` and writes it back without leading zeros (CLI11 reads "010" as octal: 8).
void check_integer(const std::string& option, std::string& text, bool is_signed) {
  const std::size_t sign = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
  const std::string_view digits = std::string_view(text).substr(sign);
  const std::string range = is_signed ? "from -9223372036854775808 to 9223372036854775807"
                                      : "from 0 to 18446744073709551615";
  if (!all_digits(digits) || (!is_signed && text[0] == '-'))
    throw support::invalid_value(option, std::string_view(text),
                                 std::string("it must be ") + (is_signed ? "an integer" : "a whole number") +
                                     " in decimal digits");
  errno = 0;
  if (is_signed) {
    (void)std::strtoll(text.c_str(), nullptr, 10);
  } else {
    (void)std::strtoull(text.c_str(), nullptr, 10);
  }
  if (errno == ERANGE)
    throw support::invalid_value(option, std::string_view(text),
                                 "it must be " + std::string(is_signed ? "an integer " : "a whole number ") + range);
  const std::size_t first = text.find_first_not_of('0', sign);
  text.erase(sign, (first == std::string::npos ? text.size() - 1 : first) - sign);
}

void check_number(const std::string& option, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return;  // not a number: CLI11 says so
  const bool overflow = errno == ERANGE && std::isinf(x);
  const bool underflow = (errno == ERANGE && !std::isinf(x)) || (x != 0.0 && std::abs(x) < DBL_MIN);
  if (overflow || underflow)
    throw support::invalid_value(option, std::string_view(text),
                                 std::string(overflow ? "it overflows" : "it underflows") +
                                     " a double: a number must be 0 or of magnitude from 2.2250738585072014e-308 "
                                     "to 1.7976931348623157e+308");
}

void check_text(const std::string& option, const std::string& text) {
  if (text.empty())
    throw support::invalid_value(option, std::string_view(text),
                                 "it is empty: give a value, or leave the option out for its default");
}

void add_check(CLI::Option& option) {
  const std::string type = option.get_type_name();
  const std::string name = option.get_name();
  if (type == "INT" || type == "UINT") {
    const bool is_signed = type == "INT";
    option.transform(CLI::Validator([name, is_signed](std::string& v) {  // drops leading zeros
                   check_integer(name, v, is_signed);
                   return std::string();
                 },
                 ""));
  } else if (type == "FLOAT") {
    option.check(CLI::Validator([name](std::string& v) {
                   check_number(name, v);
                   return std::string();
                 },
                 ""));
  } else if (type == "TEXT") {
    option.check(CLI::Validator([name](std::string& v) {
                   check_text(name, v);
                   return std::string();
                 },
                 ""));
  }
}

}  // namespace

int int_option(const char* option, long long value) {
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw support::invalid_value(option, value,
                                 "it must be from " + std::to_string(std::numeric_limits<int>::min()) + " to " +
                                     std::to_string(std::numeric_limits<int>::max()));
  return static_cast<int>(value);
}

void check_option_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size_max() == 0 || option->get_expected_max() == 0) continue;  // a flag
    add_check(*option);
  }
  for (CLI::App* sub : app.get_subcommands({})) check_option_values(*sub);
}

}  // namespace frictionlab::cli
