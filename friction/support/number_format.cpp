#include "friction/support/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace frictionlab::support {
namespace {

// Non-finite values in one spelling (printf and to_chars would write "-nan" for a negative NaN).
const char* non_finite(double x) { return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf"; }

// The text in [first, last) without its '-' if what follows is a zero ("-0", "-0.00"): a negative
// value that prints as zero prints as "0".
const char* without_negative_zero_sign(const char* first, const char* last) {
  if (first == last || *first != '-') return first;
  for (const char* p = first + 1; p != last; ++p)
    if (*p != '0' && *p != '.') return first;
  return first + 1;
}

// std::to_chars with a precision prints exactly as printf's %.<precision><conversion> would, but
// without the locale (and without a negative zero).
void append_formatted(std::string& out, double x, std::chars_format format, int precision) {
  if (!std::isfinite(x)) {
    out += non_finite(x);
    return;
  }
  char buf[400];  // %.17f of 1e308 has 309 digits before the point
  const char* const end = std::to_chars(buf, buf + sizeof buf, x, format, precision).ptr;
  out.append(without_negative_zero_sign(buf, end), end);
}

}  // namespace

std::string shortest(double x) {
  std::string out;
  append_shortest(out, x);
  return out;
}

void append_shortest(std::string& out, double x) {
  if (!std::isfinite(x)) {
    out += non_finite(x);
    return;
  }
  char buf[32];  // the longest shortest double, "-2.2250738585072014e-308", has 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, without_negative_zero(x));
  out.append(buf, r.ptr);
}

std::string message_number(double x) { return significant(x, 10); }

std::string significant(double x, int digits) {
  std::string out;
  append_significant(out, x, digits);
  return out;
}

void append_significant(std::string& out, double x, int digits) {
  append_formatted(out, x, std::chars_format::general, std::clamp(digits, 1, 17));
}

std::string fixed(double x, int digits) {
  std::string out;
  append_formatted(out, x, std::chars_format::fixed, std::clamp(digits, 0, 17));
  return out;
}

std::string message_list(std::span<const double> values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ", ";
    out += message_number(values[i]);
  }
  return out + "]";
}

}  // namespace frictionlab::support
