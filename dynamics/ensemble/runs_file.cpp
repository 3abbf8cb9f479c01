#include "dynamics/ensemble/runs_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "friction/support/checked_input.h"

namespace frictionlab::dynamics::ensemble {
ExistingRuns read_existing_runs(const std::filesystem::path& file, const std::string& header, long runs) {
  ExistingRuns e;
  const std::string text = support::read_file(file, "runs file");
  if (text.empty()) return e;
  if (text.compare(0, header.size(), header) != 0)
    throw std::invalid_argument(file.string() + " has another header than this study's runs.csv: it was written by "
                                "another study or version (use another --out)");
  std::size_t pos = header.size();
  std::size_t line_number = 1;
  while (pos < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) {
      // A row cut by a kill mid-write: it was not finished; drop it.
      std::filesystem::resize_file(file, pos);
      e.cut_partial_row = true;
      break;
    }
    const std::string_view line(text.data() + pos, end - pos);
    const long run = run_index_of_row(line);
    if (run < 0 || run >= runs)
      throw std::invalid_argument(file.string() + ":" + std::to_string(line_number) + ": not a row of this study's runs (run index " +
                                  std::to_string(run) + " of " + std::to_string(runs) + ")");
    e.done.insert(run);
    ++e.rows;
    pos = end + 1;
  }
  return e;
}

RunsWriter::RunsWriter(const std::filesystem::path& file, const std::string& header, bool resume)
    : file_(file, resume ? support::RecordFile::OpenMode::append : support::RecordFile::OpenMode::truncate, 1 << 14) {
  if (!resume || std::filesystem::file_size(file) == 0) {
    file_.append(header);
    file_.flush();
  }
}

void RunsWriter::write(const RunRecord& r) {
  file_.append(to_csv_row(r));
  file_.flush();
}

void RunsWriter::close() { file_.close(); }

void sort_runs_file(const std::filesystem::path& file) {
  const std::string text = support::read_file(file, "runs file");
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) return;
  std::map<long, std::string_view> rows;
  std::size_t pos = header_end + 1;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + pos, end - pos);
    rows.emplace(run_index_of_row(line), line);  // keeps the first of duplicates
    pos = end + 1;
  }
  std::string out(text, 0, header_end + 1);
  out.reserve(text.size());
  for (const auto& [run, line] : rows) out.append(line).push_back('\n');
  support::write_file_atomically(file, out);
}

}  // namespace frictionlab::dynamics::ensemble
