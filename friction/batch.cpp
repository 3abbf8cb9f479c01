#include "friction/batch.h"

#include <stdlib.h>  // mkstemp
#include <unistd.h>  // close, unlink

#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <optional>
#include <span>
#include <ostream>
#include <stdexcept>

#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

constexpr std::array<std::string_view, 7> kInputColumns = {"U", "Omega", "a", "b", "psi", "N", "k"};
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string at_line(std::size_t line) { return "input line " + std::to_string(line) + ": "; }

// A bad row: its message names the column; the caller adds the line.
struct RowError {
  std::string message;
};

double parse_number(std::string_view field, std::string_view column) {
  const auto text = trim(field);
  double value = 0.0;
  const auto* first = text.data();
  const auto* last = text.data() + text.size();
  // from_chars does not take a leading '+' (nor, after it, a sign).
  const bool plus = !text.empty() && *first == '+';
  if (plus) ++first;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  const bool signed_twice = plus && first != last && *first == '-';
  if (!text.empty() && ec == std::errc() && ptr == last && !signed_twice) return value;  // the common case
  const std::string quoted = "column " + std::string(column) + " = '" + std::string(text) + "'";
  if (!text.empty() && ptr == last && ec == std::errc::result_out_of_range && !signed_twice) {
    // from_chars reports overflow and underflow to zero alike; strtod tells them apart.
    const std::string copy(text);
    const double approx = std::strtod(copy.c_str(), nullptr);
    throw RowError{quoted + " is out of the range of a double (" +
                   (std::isinf(approx) ? "magnitude above " + support::shortest(std::numeric_limits<double>::max())
                                       : "nonzero, magnitude below " +
                                             support::shortest(std::numeric_limits<double>::denorm_min())) +
                   ")"};
  }
  throw RowError{quoted + " is not a number"};
}

void split_into(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t start = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == ',' && !quoted) {
      fields.push_back(line.substr(start, i - start));
      start = i + 1;
    }
  }
  fields.push_back(line.substr(start));
}

void append_forces(std::string& out, const FrictionForces& f) {
  support::append_shortest(out, f.F1);
  out += ',';
  support::append_shortest(out, f.F2);
  out += ',';
  support::append_shortest(out, f.M);
}

[[noreturn]] void write_failed(int err) {
  std::string msg = "cannot write the output";
  if (err != 0) msg += std::string(": ") + std::strerror(err);
  throw std::runtime_error(msg);
}

// Writes `text` to `out`; a failed write throws std::runtime_error (with errno's reason if the
// stream's device set one).
void write_checked(std::ostream& out, std::string_view text) {
  errno = 0;
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) write_failed(errno);
}

void flush_checked(std::ostream& out) {
  errno = 0;
  out.flush();
  if (!out) write_failed(errno);
}

// An unnamed temporary file (created in the temporary directory and unlinked at once, so that
// nothing is left behind whatever happens), written and then read back.
class Spool {
 public:
  Spool() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path();
    std::string name = (dir / "frictionlab-batch-XXXXXX").string();
    const int fd = ::mkstemp(name.data());
    if (fd < 0) {
      throw std::runtime_error("cannot create a temporary file in " + dir.string() + ": " + std::strerror(errno));
    }
    file_.open(name, std::ios::in | std::ios::out | std::ios::trunc | std::ios::binary);
    ::close(fd);
    ::unlink(name.c_str());
    if (!file_) throw std::runtime_error("cannot open the temporary file " + name);
  }
  std::ostream& stream() { return file_; }

  // Copies everything written to `out`.
  void copy_to(std::ostream& out) {
    flush_checked(file_);
    file_.seekg(0);
    std::array<char, 1 << 16> buf{};
    while (file_.read(buf.data(), buf.size()) || file_.gcount() > 0) {
      write_checked(out, std::string_view(buf.data(), static_cast<std::size_t>(file_.gcount())));
    }
    if (file_.bad()) throw std::runtime_error("cannot read back the temporary file");
  }

 private:
  std::fstream file_;
};

// A read that failed is not the end of the table. The stream keeps no reason: errno, cleared before
// each read, holds the system's (EIO, ...).
void check_read(const std::istream& in, const std::string& name) {
  if (in.bad()) {
    throw std::runtime_error("reading " + name + " failed" +
                             (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
  }
}

// Rows evaluated per call of a law.
constexpr std::size_t kChunkRows = 256;

}  // namespace

std::vector<std::string_view> split_csv_line(std::string_view line) {
  std::vector<std::string_view> fields;
  split_into(line, fields);
  return fields;
}

OnError parse_on_error(std::string_view text) {
  if (text == "stop") return OnError::stop;
  if (text == "skip") return OnError::skip;
  if (text == "nan") return OnError::nan;
  throw std::invalid_argument("--on-error = '" + std::string(text) + "' is not a choice: use stop, skip or nan");
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

std::string format_forces(const FrictionForces& f) {
  std::string s;
  append_forces(s, f);
  return s;
}

BatchSummary evaluate_csv(const std::vector<const FrictionLaw*>& laws, std::istream& in, std::ostream& out,
                          const BatchOptions& options) {
  if (laws.empty()) throw std::invalid_argument("no friction law given");
  // A message about a row names the law only when there are several (one law: the message is the
  // law's own, as a single evaluation gives it).
  const bool several = laws.size() > 1;
  // The law column's field per law, made once: the row loop allocates nothing.
  std::vector<std::string> law_field;
  for (const FrictionLaw* l : laws) law_field.push_back("," + csv_field(l->spec()));

  // The header: the first line that is not blank, after an optional byte-order mark.
  std::string header;
  std::size_t number = 0;
  bool found = false;
  for (errno = 0; std::getline(in, header); errno = 0) {
    ++number;
    if (number == 1 && std::string_view(header).substr(0, kByteOrderMark.size()) == kByteOrderMark) {
      header.erase(0, kByteOrderMark.size());
    }
    if (!header.empty() && header.back() == '\r') header.pop_back();
    if (!trim(header).empty()) {
      found = true;
      break;
    }
  }
  check_read(in, options.input_name);
  if (!found) throw std::invalid_argument("input is empty: expected a CSV header");
  const std::size_t header_line = number;
  const auto names = split_csv_line(header);
  std::array<std::size_t, kInputColumns.size()> column{};
  for (std::size_t c = 0; c < kInputColumns.size(); ++c) {
    std::size_t found_at = names.size();
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (trim(names[i]) != kInputColumns[c]) continue;
      if (found_at != names.size()) {
        throw std::invalid_argument(at_line(header_line) + "column " + std::string(kInputColumns[c]) +
                                    " appears twice in the header");
      }
      found_at = i;
    }
    if (found_at == names.size()) {
      throw std::invalid_argument(at_line(header_line) + "the header lacks column " +
                                  std::string(kInputColumns[c]) + " (required: U,Omega,a,b,psi,N,k in any order)");
    }
    column[c] = found_at;
  }

  std::optional<Spool> spool;
  if (options.on_error == OnError::stop) spool.emplace();
  std::ostream& dest = spool ? spool->stream() : out;
  write_checked(dest, header + "," + std::string(kOutputColumns) + "\n");

  BatchSummary summary;
  // Reused for every row: the loop allocates nothing once they have grown to the longest row.
  std::string line;
  std::string row;
  std::vector<std::string_view> fields;
  const auto bad_row = [&](std::size_t line_number, const std::string& reason, const FrictionLaw* law) {
    if (options.on_error == OnError::stop) throw std::invalid_argument(at_line(line_number) + reason);
    ++summary.bad;
    if (options.on_bad_row) options.on_bad_row(line_number, reason);
    if (options.on_error == OnError::skip) return;
    for (std::size_t i = 0; i < laws.size(); ++i) {
      if (law && laws[i] != law) continue;
      row.assign(line);
      row += law_field[i];
      row += ",nan,nan,nan\n";
      write_checked(dest, row);
      ++summary.written;
    }
  };
  // Rows are read into a chunk and each law evaluates the chunk in one call (the law's batch
  // evaluation, FrictionLaw::evaluate of spans); a row the law rejects is reported and the batch
  // goes on after it. Output keeps the input's order: a chunk is written before a row that cannot
  // be parsed is reported.
  struct Pending {
    std::size_t number = 0;
    std::string line;
  };
  // Reused chunk after chunk (their strings keep their capacity).
  std::vector<Pending> pending(kChunkRows);
  std::vector<ContactInput> inputs;
  inputs.reserve(kChunkRows);
  std::vector<std::vector<FrictionForces>> forces(laws.size());
  std::vector<std::vector<std::string>> rejected(laws.size());  // per law and row: why, or empty
  const auto flush = [&] {
    const std::size_t n = inputs.size();
    for (std::size_t i = 0; i < laws.size(); ++i) {
      forces[i].resize(n);
      rejected[i].assign(n, std::string());
      const std::span<const ContactInput> all(inputs);
      const std::span<FrictionForces> results(forces[i]);
      for (std::size_t start = 0; start < n;) {
        try {
          laws[i]->evaluate(all.subspan(start), results.subspan(start));
          break;
        } catch (const BatchError& e) {
          try {
            std::rethrow_exception(e.cause());  // only a rejected input is a bad row
          } catch (const std::invalid_argument&) {
          }
          const std::size_t j = start + e.index();
          rejected[i][j] = e.cause_message();
          start = j + 1;
        }
      }
    }
    for (std::size_t j = 0; j < n; ++j) {
      line.assign(pending[j].line);
      for (std::size_t i = 0; i < laws.size(); ++i) {
        if (!rejected[i][j].empty()) {
          bad_row(pending[j].number, (several ? std::string(laws[i]->spec()) + ": " : std::string()) + rejected[i][j],
                  laws[i]);
          continue;
        }
        row.assign(line);
        row += law_field[i];
        row += ',';
        append_forces(row, forces[i][j]);
        row += '\n';
        write_checked(dest, row);
        ++summary.written;
      }
    }
    inputs.clear();
  };
  std::string parsed_line;
  const auto parse_error = [&](std::size_t line_number, const std::string& reason) {
    parsed_line.assign(line);
    flush();  // the rows before it first
    line.assign(parsed_line);
    bad_row(line_number, reason, nullptr);
  };
  for (errno = 0; std::getline(in, line); errno = 0) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;
    ++summary.rows;
    split_into(line, fields);
    if (fields.size() != names.size()) {
      parse_error(number, "has " + std::to_string(fields.size()) + " fields, the header has " + std::to_string(names.size()));
      continue;
    }
    std::array<double, kInputColumns.size()> v{};
    try {
      for (std::size_t c = 0; c < v.size(); ++c) v[c] = parse_number(fields[column[c]], kInputColumns[c]);
    } catch (const RowError& e) {
      parse_error(number, e.message);
      continue;
    }
    pending[inputs.size()].number = number;
    pending[inputs.size()].line.assign(line);
    inputs.push_back(ContactInput{v[0], v[1], v[2], v[3], v[4], v[5], v[6]});
    if (inputs.size() == kChunkRows) flush();
  }
  flush();
  check_read(in, options.input_name);
  if (spool) spool->copy_to(out);
  flush_checked(out);
  return summary;
}

std::size_t evaluate_csv(const FrictionLaw& law, std::istream& in, std::ostream& out) {
  return evaluate_csv(std::vector<const FrictionLaw*>{&law}, in, out).rows;
}

}  // namespace frictionlab::friction
