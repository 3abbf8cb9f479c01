#pragma once
// The values every option of every subcommand must have before a command sees them, checked in one
// place (main.cpp installs it on the whole application after the subcommands registered):
//
//   an integer (INT)    decimal digits with an optional sign, within the 64-bit range: CLI11 alone
//                       clamps 99999999999999999999999 to 9223372036854775807, and reads 010 as 8
//                       and 0x10 as 16 (010 is now 10, 0x10 an error);
//   a whole number (UINT)  the same without a sign: CLI11 alone wraps -1 to 18446744073709551615;
//   a number (FLOAT)    a double that the text does not overflow (1e400) or underflow (1e-400,
//                       which CLI11 alone takes as 0): 0, or a magnitude from 2.2e-308 to 1.8e308;
//   text (TEXT)         not empty: an empty --law '' or --out '' is otherwise taken as "not given"
//                       and the default silently used.
//
// A value that breaks its rule is std::invalid_argument "OPTION = 'VALUE' is invalid: RULE"
// (support::invalid_value): one line, exit code 1. Each command still checks its own bounds
// (--threads >= 0, ...).

#include <CLI/CLI.hpp>

namespace frictionlab::cli {

/// Adds the check of its type to every option that takes a value, in `app` and its subcommands.
void check_option_values(CLI::App& app);

/// An integer option (read as long long, so that no value is narrowed by CLI11) for a library
/// that takes an int: std::invalid_argument naming `option` if it does not fit.
[[nodiscard]] int int_option(const char* option, long long value);

}  // namespace frictionlab::cli
