// frictionlab: exact and approximate laws of coupled dry friction, and the dynamics they drive.
//
// Exit codes, for every subcommand: 0 done; 1 an error (bad input, CLI11's parse errors included,
// or output that could not be written), reported as one line `frictionlab: error: ...` on stderr;
// a subcommand may add its own (3: `simulate` stopped early, `paper` incomplete). --help prints
// help and exits 0; --version prints `frictionlab VERSION` (the CMake project's) and exits 0.

#include <algorithm>
#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/cli/commands.h"
#include "dynamics/cli/option_values.h"
#include "friction/support/checked_output.h"
#include "friction/support/errors.h"
#include "friction/reference_laws.h"

namespace {

void report(std::string_view message) {
  std::cerr << "frictionlab: error: " << frictionlab::support::one_line(message) << std::endl;
}

// Levenshtein distance, for "did you mean".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// What an option of the parsed subcommand expects, in words ("a number"); empty if unknown.
std::string expected_value(CLI::App& app, const std::string& option) {
  for (CLI::App* sub : app.get_subcommands()) {
    if (const CLI::Option* o = sub->get_option_no_throw(option)) {
      const std::string type = o->get_type_name();
      if (type == "FLOAT") return "a number";
      if (type == "INT") return "an integer";
      if (type == "UINT") return "a whole number >= 0";
      return type.empty() ? "" : "of type " + type;
    }
  }
  return "";
}

// CLI11's message, reworded where it can say more: "Could not convert: --U = abc" names the
// value but not what was wanted.
std::string parse_error_message(CLI::App& app, const CLI::ParseError& e) {
  const std::string message = e.what();
  constexpr std::string_view kConvert = "Could not convert: ";
  if (message.rfind(kConvert, 0) == 0) {
    const std::string rest = message.substr(kConvert.size());
    const auto eq = rest.find(" = ");
    if (eq != std::string::npos) {
      const std::string option = rest.substr(0, eq);
      const std::string wanted = expected_value(app, option);
      if (!wanted.empty())
        return frictionlab::support::invalid_value(option, std::string_view(rest.substr(eq + 3)), "it must be " + wanted)
                   .what();
    }
  }
  return message + " (see --help)";
}

// CLI11 takes an unknown first word for a stray argument; say what it is and what would do.
void check_subcommand(CLI::App& app, int argc, char** argv) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  if (argc < 2) throw std::invalid_argument("a subcommand is required: " + list + " (see frictionlab --help)");
  const std::string_view first = argv[1];
  if (first.empty() || first.front() == '-' || std::find(names.begin(), names.end(), first) != names.end()) return;
  std::string message = "unknown subcommand '" + std::string(first) + "'; the subcommands are " + list;
  const auto nearest = std::min_element(names.begin(), names.end(), [&](const auto& a, const auto& b) {
    return edit_distance(first, a) < edit_distance(first, b);
  });
  if (nearest != names.end() && edit_distance(first, *nearest) <= 2) message += " (did you mean '" + *nearest + "'?)";
  throw std::invalid_argument(message);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"frictionlab: exact vs approximate coupled dry friction (sliding + spinning)\n"
               "over an elliptic Hertz contact patch, at a point and along a motion."};
  app.require_subcommand(1);
  frictionlab::friction::register_reference_laws();  // exact-reference (GSL), in the command
  app.set_version_flag("--version", std::string("frictionlab ") + FRICTIONLAB_VERSION,
                       "Print `frictionlab VERSION` and exit");
  frictionlab::cli::register_laws_command(app);
  frictionlab::cli::register_friction_command(app);
  frictionlab::cli::register_simulate_command(app);
  frictionlab::cli::register_accuracy_command(app);
  frictionlab::cli::register_paper_command(app);
  frictionlab::cli::register_ensemble_command(app);
  frictionlab::cli::register_calibrate_command(app);
  frictionlab::cli::register_puck_study_command(app);
  frictionlab::cli::register_tippe_top_command(app);
  frictionlab::cli::check_option_values(app);  // after every option exists
  // A file-size limit (ulimit -f) is then an error of the write that hits it, reported like a
  // full disk, instead of a signal that kills the process mid-row.
  std::signal(SIGXFSZ, SIG_IGN);

  int code = 0;
  try {
    check_subcommand(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    code = app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    code = app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    code = app.exit(e);
  } catch (const CLI::RuntimeError& e) {
    code = e.get_exit_code();  // a subcommand's own exit code (3: stopped early); it said why
  } catch (const CLI::ParseError& e) {
    report(parse_error_message(app, e));
    code = 1;
  } catch (const std::exception& e) {
    report(e.what());
    code = 1;
  }
  try {
    frictionlab::support::finish_standard_output();
  } catch (const std::exception& e) {
    if (code != 1) report(e.what());  // one line: the first error is the one to fix
    code = 1;
  }
  return code;
}
