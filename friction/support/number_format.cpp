#include "friction/support/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace frictionlab::support {
namespace {

// Non-finite values in one spelling (printf and to_chars would write "-nan" for a negative NaN).
const char* non_finite(double x) { return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf"; }

std::string printf_format(double x, int digits, char conversion) {
  if (!std::isfinite(x)) return non_finite(x);
  const char format[] = {'%', '.', '*', conversion, '\0'};
  char buf[400];  // %.17f of 1e308 has 309 digits before the point
  const int n = std::snprintf(buf, sizeof buf, format, std::clamp(digits, 0, 17), x);
  return std::string(buf, static_cast<std::size_t>(std::clamp(n, 0, static_cast<int>(sizeof buf) - 1)));
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
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
}

std::string message_number(double x) { return significant(x, 10); }

std::string significant(double x, int digits) { return printf_format(x, std::max(digits, 1), 'g'); }

std::string fixed(double x, int digits) { return printf_format(x, digits, 'f'); }

std::string message_list(std::span<const double> values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ", ";
    out += message_number(values[i]);
  }
  return out + "]";
}

}  // namespace frictionlab::support
