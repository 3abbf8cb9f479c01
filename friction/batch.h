#pragma once
// Batch evaluation of a friction law over a CSV table.
//
// Input: a header line naming at least the columns U, Omega, a, b, psi, N, k (SI units, any order;
// other columns are passed through untouched), then one contact per line. Output: every input
// column as it was, then F1, F2, M printed with 17 significant digits (lossless for doubles).

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "friction/law.h"

namespace frictionlab::friction {

/// Splits one CSV line into raw fields (double quotes protect commas; fields are kept verbatim).
[[nodiscard]] std::vector<std::string_view> split_csv_line(std::string_view line);

/// Evaluates `law` on every row of `in` and writes the table to `out`. Nothing is written unless
/// every row is valid: a bad header, a bad number or an input the law rejects throws
/// std::invalid_argument naming the line number (1 = header) and the column.
/// Returns the number of rows evaluated.
std::size_t evaluate_csv(const FrictionLaw& law, std::istream& in, std::ostream& out);

/// "F1,F2,M" of one evaluation, each with 17 significant digits.
[[nodiscard]] std::string format_forces(const FrictionForces& f);

}  // namespace frictionlab::friction
