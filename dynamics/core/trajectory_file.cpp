#include "dynamics/core/trajectory_file.h"

#include "friction/support/errors.h"

namespace frictionlab::dynamics {

std::string trajectory_file_header(std::span<const std::string_view> columns) {
  std::string header;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    header += columns[i];
    header += i + 1 < columns.size() ? ',' : '\n';
  }
  return header;
}

TrajectoryFile::TrajectoryFile(const std::filesystem::path& file, std::string_view header, std::uint64_t max_bytes)
    : file_(file) {
  if (max_bytes > 0 && header.size() > max_bytes)
    throw support::invalid_value("run.max_output_bytes", static_cast<long long>(max_bytes),
                                 "it must hold at least the header of trajectory.csv (" +
                                     std::to_string(header.size()) + " bytes)");
  file_.set_size_limit(max_bytes);
  file_.append(header);
}

void TrajectoryFile::append(std::string_view row) {
  try {
    file_.append(row);
  } catch (const support::OutputError& e) {
    throw OutputFailure(e.what());
  } catch (const support::SizeLimitReached& e) {
    throw OutputLimitReached(std::string(e.what()) + " (run.max_output_bytes: raise it, or run.output_dt)");
  }
}

void TrajectoryFile::close() {
  try {
    file_.close();
  } catch (const support::OutputError& e) {
    throw OutputFailure(e.what());
  }
}

}  // namespace frictionlab::dynamics
