#include "dynamics/core/output_limit.h"

#include <cmath>
#include <string>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {

double planned_output_bytes(double t_end, double output_dt, std::size_t header_bytes, std::size_t min_row_bytes) {
  const double rows = std::floor(t_end / output_dt) + 1.0;
  return static_cast<double>(header_bytes) + rows * static_cast<double>(min_row_bytes);
}

void check_planned_output(double t_end, double output_dt, long max_output_bytes, std::size_t header_bytes,
                          std::size_t min_row_bytes, std::string_view file) {
  const double planned = planned_output_bytes(t_end, output_dt, header_bytes, min_row_bytes);
  if (planned <= static_cast<double>(max_output_bytes)) return;
  throw support::invalid_value(
      "run.output_dt", output_dt,
      "run.t_end/run.output_dt = " + support::message_number(t_end / output_dt) + " rows of at least " +
          std::to_string(min_row_bytes) + " bytes make " + std::string(file) + " at least " +
          support::message_number(planned) + " bytes, more than run.max_output_bytes = " +
          std::to_string(max_output_bytes) + " (raise run.output_dt, or run.max_output_bytes if you mean it)");
}

}  // namespace frictionlab::dynamics
