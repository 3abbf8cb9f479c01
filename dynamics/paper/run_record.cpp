#include "dynamics/paper/run_record.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dynamics/body/state.h"
#include "friction/support/checked_input.h"
#include "friction/support/checked_output.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A run's own files: one that cannot be read is a failure of the run's record (std::runtime_error),
// not bad input.
std::string read_text(const std::filesystem::path& path) {
  try {
    return support::read_file(path, "file");
  } catch (const support::InputError& e) {
    throw std::runtime_error(e.what());
  }
}

const support::Json& member(const support::Json& j, const char* key) {
  if (!j.is_object() || !j.contains(key)) throw std::runtime_error(std::string("summary.json: '") + key + "' is missing");
  return j.at(key);
}

double number(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (v.is_null()) return kNaN;
  if (!v.is_number()) throw std::runtime_error(std::string("summary.json: '") + key + "' is not a number");
  return v.get<double>();
}

long integer(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (!v.is_number_integer()) throw std::runtime_error(std::string("summary.json: '") + key + "' is not an integer");
  return v.get<long>();
}

std::string text(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (!v.is_string()) throw std::runtime_error(std::string("summary.json: '") + key + "' is not a string");
  return v.get<std::string>();
}

Eigen::Vector3d vector3(const support::Json& j, const char* key) {
  const support::Json& v = member(j, key);
  if (!v.is_array() || v.size() != 3)
    throw std::runtime_error(std::string("summary.json: '") + key + "' is not 3 numbers");
  Eigen::Vector3d out;
  for (std::size_t i = 0; i < 3; ++i) out[static_cast<Eigen::Index>(i)] = v[i].is_null() ? kNaN : v[i].get<double>();
  return out;
}

double parse_number(std::string_view s, const std::filesystem::path& path) {
  double x = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), x);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size())
    throw std::runtime_error("'" + path.string() + "': '" + std::string(s) + "' is not a number");
  return x;
}

}  // namespace

long thinned_rows(long rows, int every) {
  if (rows <= 0) return 0;
  const long kept = (rows - 1) / every + 1;  // rows 0, every, 2 every, ...
  return (rows - 1) % every == 0 ? kept : kept + 1;  // and the last
}

long thin_csv(const std::filesystem::path& path, int every) {
  const std::string in = read_text(path);
  std::size_t pos = in.find('\n');
  if (pos == std::string::npos) throw std::runtime_error("'" + path.string() + "' has no header line");
  ++pos;
  std::vector<std::string_view> rows;
  while (pos < in.size()) {
    std::size_t end = in.find('\n', pos);
    if (end == std::string::npos) end = in.size() - 1;  // a last line without its newline
    rows.emplace_back(in.data() + pos, end + 1 - pos);
    pos = end + 1;
  }
  if (every <= 1) return static_cast<long>(rows.size());
  std::string out(in.data(), in.find('\n') + 1);
  long kept = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i % static_cast<std::size_t>(every) != 0 && i + 1 != rows.size()) continue;
    out += rows[i];
    ++kept;
  }
  support::write_file_atomically(path, out);
  return kept;
}

long csv_data_rows(const std::filesystem::path& path) {
  std::string text;
  try {
    text = support::read_file(path, "file");
  } catch (const support::InputError&) {
    return -1;
  }
  // Lines as std::getline counts them: a last line without its newline counts too.
  long lines = static_cast<long>(std::count(text.begin(), text.end(), '\n'));
  if (!text.empty() && text.back() != '\n') ++lines;
  return lines > 0 ? lines - 1 : 0;
}

namespace {
constexpr const char* kComparisonHeader = "t,gamma3,gamma3_mean_1s,axis_x,axis_y,axis_z";

std::array<std::vector<double>*, 6> columns_of(ComparisonSeries& s) {
  return {&s.t, &s.gamma3, &s.gamma3_smooth, &s.axis_x, &s.axis_y, &s.axis_z};
}
std::array<const std::vector<double>*, 6> columns_of(const ComparisonSeries& s) {
  return {&s.t, &s.gamma3, &s.gamma3_smooth, &s.axis_x, &s.axis_y, &s.axis_z};
}
}  // namespace

ComparisonSeries thin_series(const ComparisonSeries& full, int every) {
  ComparisonSeries s;
  const auto from = columns_of(full);
  const auto to = columns_of(s);
  const std::size_t n = full.t.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i % static_cast<std::size_t>(every) != 0 && i + 1 != n) continue;
    for (std::size_t c = 0; c < from.size(); ++c) to[c]->push_back((*from[c])[i]);
  }
  return s;
}

void write_comparison_series(const std::filesystem::path& path, const ComparisonSeries& s) {
  std::string out = std::string(kComparisonHeader) + "\n";
  const auto columns = columns_of(s);
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) out += ',';
      support::append_shortest(out, (*columns[c])[i]);
    }
    out += '\n';
  }
  support::write_file_atomically(path, out);
}

ComparisonSeries read_comparison_series(const std::filesystem::path& path) {
  const std::string in = read_text(path);
  std::istringstream lines(in);
  std::string line;
  if (!std::getline(lines, line) || line != kComparisonHeader)
    throw std::runtime_error("'" + path.string() + "' does not begin with the header " + kComparisonHeader);
  ComparisonSeries s;
  const auto columns = columns_of(s);
  while (std::getline(lines, line)) {
    const std::string_view row(line);
    std::size_t start = 0;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::size_t end = c + 1 < columns.size() ? row.find(',', start) : row.size();
      if (end == std::string_view::npos || (c + 1 == columns.size() && row.find(',', start) != std::string_view::npos))
        throw std::runtime_error("'" + path.string() + "': a row without " + std::to_string(columns.size()) + " numbers");
      columns[c]->push_back(parse_number(row.substr(start, end - start), path));
      start = end + 1;
    }
  }
  if (s.t.empty()) throw std::runtime_error("'" + path.string() + "' has no rows");
  return s;
}

std::optional<Termination> termination_named(std::string_view name) {
  for (int i = 0; i <= static_cast<int>(Termination::flat_face); ++i) {
    const auto t = static_cast<Termination>(i);
    if (to_string(t) == name) return t;
  }
  return std::nullopt;
}

RunSummary summary_from_json(const support::Json& j, double weight) {
  RunSummary s;
  const support::Json& term = member(j, "termination");
  const std::string reason = text(term, "reason");
  const auto t = termination_named(reason);
  if (!t) throw std::runtime_error("summary.json: termination reason '" + reason + "' is unknown");
  s.reason = *t;
  s.message = text(term, "message");
  s.rule = text(term, "rule");
  s.t_final = number(j, "final_time");
  s.steps = integer(j, "steps");
  s.rejected_steps = integer(j, "rejected_steps");
  s.rhs_calls = integer(j, "rhs_calls");
  s.samples = integer(j, "samples");
  s.sample_rhs_calls = integer(j, "sample_rhs_calls");
  s.hermite_samples = integer(j, "hermite_samples");
  s.wall_time = number(j, "wall_time_s");
  s.liftoffs = integer(j, "liftoffs");
  s.landings = integer(j, "landings");
  s.min_normal_force = number(j, "min_N_over_mg") * weight;
  s.initial_energy = number(j, "initial_energy");
  s.final_energy = number(j, "final_energy");
  s.max_gamma_drift = number(j, "max_gamma_drift");
  const support::Json& x = member(j, "final_state");
  s.x_final = make_state(vector3(x, "v"), vector3(x, "omega"), vector3(x, "gamma"), number(x, "eps"));
  slide_work(s.x_final) = number(j, "work_sliding");
  spin_work(s.x_final) = number(j, "work_spinning");
  return s;
}

support::Json read_json_file(const std::filesystem::path& path) {
  const std::string text_in = read_text(path);
  try {
    return support::Json::parse(text_in);
  } catch (const std::exception& e) {
    throw std::runtime_error("'" + path.string() + "' is not valid JSON: " + e.what());
  }
}

}  // namespace frictionlab::dynamics::paper
