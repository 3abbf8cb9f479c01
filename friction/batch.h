#pragma once
// Batch evaluation of friction laws over a CSV table, streamed.
//
// Input: optional blank lines and a UTF-8 byte-order mark, then a header line naming at least the
// columns U, Omega, a, b, psi, N, k (SI units, any order; other columns are passed through
// untouched), then one contact per line; blank lines are skipped. Numbers are C locale decimals
// (a leading '+' allowed); one outside the double range ("1e999", "1e-400") is named as such.
//
// Output: every input column as it was, then a `law` column naming the law by its spec
// (FrictionLaw::spec(), quoted if it holds a comma), then F1, F2, M each in the shortest text that
// reads back to the same double (lossless, never localised; a zero is "0", never "-0",
// support/number_format.h). The columns are the same for one law and for several, so that a
// reader of the output need not know how many were asked for. Rows come in input order; each input
// row gives one output row per law, in the order the laws are given.
//
// Streaming: rows are read, evaluated and written one at a time, so memory does not grow with the
// table. With OnError::stop (the default) nothing reaches `out` unless every row succeeds: rows go
// to an unnamed temporary file (in $TMPDIR, else /tmp), copied to `out` at the end. That evaluates
// each row once, works alike for files and pipes, and keeps the promise for every failure (a bad
// number, a law rejecting an input, a full disk); the price is disk space for one copy of the
// output and no output before the end. With skip or nan rows go straight to `out`.
//
// Errors are one line, naming the input line number (1-based, blank lines counted) and the column:
// std::invalid_argument for bad input, std::runtime_error for a failed read or write.

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "friction/law.h"

namespace frictionlab::friction {

/// The columns every output row ends with, after the input's own (the header's tail).
inline constexpr std::string_view kOutputColumns = "law,F1,F2,M";

/// Splits one CSV line into raw fields (double quotes protect commas; fields are kept verbatim).
[[nodiscard]] std::vector<std::string_view> split_csv_line(std::string_view line);

/// What a row that cannot be evaluated does (a bad number, the wrong number of fields, an input a
/// law rejects; with several laws, per law).
enum class OnError {
  stop,  ///< the whole evaluation fails and nothing is written
  skip,  ///< the row is left out of the output
  nan,   ///< the row is written with F1, F2, M = nan
};

/// "stop", "skip" or "nan"; std::invalid_argument naming the value and the choices otherwise.
[[nodiscard]] OnError parse_on_error(std::string_view text);

struct BatchOptions {
  OnError on_error = OnError::stop;
  /// With skip or nan, called once per bad row with its line number and the reason (one line).
  std::function<void(std::size_t line, const std::string& reason)> on_bad_row;
  /// The input in messages: a read that fails part-way is "reading INPUT_NAME failed: REASON".
  std::string input_name = "the input";
};

struct BatchSummary {
  std::size_t rows = 0;      ///< input rows read (blank lines not counted)
  std::size_t written = 0;   ///< output rows written, header not counted
  std::size_t bad = 0;       ///< output rows skipped or written as nan
};

/// Evaluates every law of `laws` (at least one) on every row of `in`, streaming the table to `out`
/// as described above.
BatchSummary evaluate_csv(const std::vector<const FrictionLaw*>& laws, std::istream& in, std::ostream& out,
                          const BatchOptions& options = {});

/// One law, OnError::stop. Returns the number of rows evaluated.
std::size_t evaluate_csv(const FrictionLaw& law, std::istream& in, std::ostream& out);

/// `text` as one CSV field: as it is, or in double quotes (inner quotes doubled) if it holds a
/// comma, a double quote or a line break, as a law spec with several parameters does.
[[nodiscard]] std::string csv_field(std::string_view text);

/// "F1,F2,M" of one evaluation, each in the shortest round-trip form (support::shortest).
[[nodiscard]] std::string format_forces(const FrictionForces& f);

}  // namespace frictionlab::friction
