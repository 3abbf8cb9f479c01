#include "dynamics/cli/retypable_command.h"

#include <algorithm>
#include <cctype>

namespace frictionlab::cli {
namespace {

std::string shell_word(const std::string& value) {
  const bool plain = !value.empty() && std::all_of(value.begin(), value.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || std::string_view("_./:=,+-@").find(ch) != std::string_view::npos;
  });
  if (plain) return value;
  std::string quoted = "'";
  for (char ch : value) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

}  // namespace

std::string retypable_command(const CLI::App& subcommand, std::initializer_list<std::string_view> omit) {
  std::string line = "frictionlab " + subcommand.get_name();
  for (const CLI::Option* opt : subcommand.get_options()) {
    if (opt->count() == 0 || !opt->nonpositional()) continue;
    const std::string name = opt->get_name();  // the long name when there is one
    if (name == "--help" || std::find(omit.begin(), omit.end(), name) != omit.end()) continue;
    line += " " + name;
    if (opt->get_type_size_max() == 0 || opt->get_expected_max() == 0) continue;  // a flag
    std::string joined;
    for (const std::string& value : opt->results()) joined += (joined.empty() ? "" : ",") + value;
    line += " " + shell_word(joined);
  }
  return line;
}

}  // namespace frictionlab::cli
