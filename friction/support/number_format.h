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
// Non-finite values print the same everywhere: "nan", "inf", "-inf" (never "-nan"). No text is a
// negative zero: -0.0, and a negative value that rounds to zero at the precision asked for, print
// as "0" ("0.00"). Every file these functions write is read by people or plotted: CSV tables and
// trajectories, reports, figure data, messages. There the sign of a zero is arithmetic residue
// (F1 = -0 at pure spin, a velocity component that cancels) that reads as a negative number, while
// "0" reads back to a double equal to it (-0.0 == 0.0). What must come back bit for bit, a
// scenario written beside its run, is written by the TOML writer, not here.

#include <span>
#include <string>

namespace frictionlab::support {

/// Shortest round-trip text (std::to_chars): 0.1 -> "0.1", 1e-300 -> "1e-300"; it reads back to the
/// same bits, but for -0.0, which prints "0" (above).
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
/// `x`, but +0.0 for -0.0: the value that shortest(x) reads back as. For in-memory copies of what a
/// file holds (Python's trajectory columns equal trajectory.csv bit for bit).
[[nodiscard]] constexpr double without_negative_zero(double x) { return x == 0.0 ? 0.0 : x; }
/// "[a, b, c]" with message numbers.
[[nodiscard]] std::string message_list(std::span<const double> values);

}  // namespace frictionlab::support
