#include "friction/batch.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace frictionlab::friction {
namespace {

constexpr std::array<std::string_view, 7> kInputColumns = {"U", "Omega", "a", "b", "psi", "N", "k"};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string at_line(std::size_t line) { return "input line " + std::to_string(line) + ": "; }

double parse_number(std::string_view field, std::size_t line, std::string_view column) {
  const auto text = trim(field);
  double value = 0.0;
  const auto* first = text.data();
  const auto* last = text.data() + text.size();
  if (!text.empty() && *first == '+') ++first;  // from_chars does not take a leading '+'
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (text.empty() || ec != std::errc() || ptr != last) {
    throw std::invalid_argument(at_line(line) + "column " + std::string(column) + " = '" +
                                std::string(text) + "' is not a number");
  }
  return value;
}

void append_double(std::string& out, double v) {
  char buf[32];
  const int n = std::snprintf(buf, sizeof buf, "%.17g", v);
  out.append(buf, static_cast<std::size_t>(n));
}

}  // namespace

std::vector<std::string_view> split_csv_line(std::string_view line) {
  std::vector<std::string_view> fields;
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
  return fields;
}

std::string format_forces(const FrictionForces& f) {
  std::string s;
  append_double(s, f.F1);
  s += ',';
  append_double(s, f.F2);
  s += ',';
  append_double(s, f.M);
  return s;
}

std::size_t evaluate_csv(const FrictionLaw& law, std::istream& in, std::ostream& out) {
  std::string header;
  if (!std::getline(in, header)) throw std::invalid_argument("input is empty: expected a CSV header");
  if (!header.empty() && header.back() == '\r') header.pop_back();
  const auto names = split_csv_line(header);

  std::array<std::size_t, kInputColumns.size()> column{};
  for (std::size_t c = 0; c < kInputColumns.size(); ++c) {
    std::size_t found = names.size();
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (trim(names[i]) != kInputColumns[c]) continue;
      if (found != names.size()) {
        throw std::invalid_argument(at_line(1) + "column " + std::string(kInputColumns[c]) +
                                    " appears twice in the header");
      }
      found = i;
    }
    if (found == names.size()) {
      throw std::invalid_argument(at_line(1) + "the header lacks column " +
                                  std::string(kInputColumns[c]) +
                                  " (required: U,Omega,a,b,psi,N,k in any order)");
    }
    column[c] = found;
  }

  std::string table = header + ",F1,F2,M\n";  // written only once every row has succeeded
  std::size_t rows = 0;
  std::string line;
  for (std::size_t number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;
    const auto fields = split_csv_line(line);
    if (fields.size() != names.size()) {
      throw std::invalid_argument(at_line(number) + "has " + std::to_string(fields.size()) +
                                  " fields, the header has " + std::to_string(names.size()));
    }
    std::array<double, kInputColumns.size()> v{};
    for (std::size_t c = 0; c < v.size(); ++c) v[c] = parse_number(fields[column[c]], number, kInputColumns[c]);
    const ContactInput input{v[0], v[1], v[2], v[3], v[4], v[5], v[6]};
    FrictionForces forces;
    try {
      forces = law.evaluate(input);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(at_line(number) + e.what());
    }
    table += line;
    table += ',';
    table += format_forces(forces);
    table += '\n';
    ++rows;
  }
  out << table;
  out.flush();
  return rows;
}

}  // namespace frictionlab::friction
