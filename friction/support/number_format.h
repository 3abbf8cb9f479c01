#pragma once
// How numbers become text, in one place:
//
//   shortest(x)        the shortest text that reads back to the same double (data files: CSV,
//                      TOML, plot data; what a rerun must read back bit for bit);
//   message_number(x)  10 significant digits (error and progress messages: enough to see a value,
//                      short enough to read);
//   significant(x, n)  n significant digits (%.<n>g: tables, labels);
//   fixed(x, n)        n digits after the point (%.<n>f: wall times, percentages).
//
// Non-finite values print the same everywhere: "nan", "inf", "-inf" (never "-nan").

#include <span>
#include <string>

namespace frictionlab::support {

/// Shortest round-trip text (std::to_chars): 0.1 -> "0.1", 1e-300 -> "1e-300".
[[nodiscard]] std::string shortest(double x);
/// Appends shortest(x) to `out` without a temporary (the CSV writers' inner loop).
void append_shortest(std::string& out, double x);
/// 10 significant digits, for messages.
[[nodiscard]] std::string message_number(double x);
/// `digits` significant digits (1 to 17), as printf's %.<digits>g (but never localised).
[[nodiscard]] std::string significant(double x, int digits);
/// Appends significant(x, digits) to `out` without a temporary (bulk tables).
void append_significant(std::string& out, double x, int digits);
/// `digits` digits after the decimal point (0 to 17), as printf's %.<digits>f (never localised).
[[nodiscard]] std::string fixed(double x, int digits);
/// "[a, b, c]" with message numbers.
[[nodiscard]] std::string message_list(std::span<const double> values);

}  // namespace frictionlab::support
