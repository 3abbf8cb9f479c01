#pragma once
// Reading runs.csv in the command's tests: its rows without the wall_time column (the one column
// that differs between two runs of the same ensemble).

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dynamics/ensemble/csv_row.h"
#include "tests/cli/cli_runner.h"

namespace frictionlab::testing {

/// The header and rows of runs.csv, each row's wall_time field emptied; rows in file order.
inline std::vector<std::string> runs_without_wall_time(const std::filesystem::path& file) {
  std::istringstream in(slurp(file));
  std::string line;
  std::vector<std::string> out;
  std::size_t wall = std::string::npos;
  while (std::getline(in, line)) {
    auto f = dynamics::ensemble::split_csv_line(line);
    if (wall == std::string::npos) wall = static_cast<std::size_t>(std::find(f.begin(), f.end(), "wall_time") - f.begin());
    if (wall < f.size()) f[wall].clear();
    std::string joined;
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (i) joined += ',';
      dynamics::ensemble::append_text_field(joined, f[i]);
    }
    out.push_back(joined);
  }
  return out;
}

/// Rows (without the header) by their run index (the first field), as written.
inline std::map<long, std::string> rows_by_run(const std::filesystem::path& file) {
  std::istringstream in(slurp(file));
  std::string line;
  std::getline(in, line);
  std::map<long, std::string> out;
  while (std::getline(in, line)) out.emplace(std::stol(line.substr(0, line.find(','))), line);
  return out;
}

}  // namespace frictionlab::testing
