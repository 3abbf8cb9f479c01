// `frictionlab friction`: evaluate one or more laws at one contact, or over a CSV table read from a
// file or from stdin (friction/batch.h: streamed; a `law` column however many laws; --on-error).

#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/cli/commands.h"
#include "friction/batch.h"
#include "friction/registry.h"
#include "friction/support/checked_input.h"

namespace frictionlab::cli {
namespace {

struct FrictionOptions {
  std::string laws = friction::reference_law_name();
  std::array<std::optional<double>, 7> value;  // U, Omega, a, b, psi, N, k
  std::string input;                           // --input
  std::string input_positional;                // INPUT
  std::string on_error = "stop";
};

constexpr std::array<const char*, 7> kNames = {"U", "Omega", "a", "b", "psi", "N", "k"};
constexpr std::array<const char*, 7> kHelp = {
    "slip speed of the patch centre, m/s (>= 0)", "spin about the upward normal, 1/s",
    "major semi-axis, m (> 0)", "minor semi-axis, m (0 < b <= a)",
    "angle from the slip direction to the major axis, rad", "normal force, N (>= 0)",
    "friction coefficient (>= 0)"};
// Bad rows reported one line each on stderr (with --on-error skip or nan), then a count.
constexpr std::size_t kMaxWarnings = 20;

// The laws of a list of specs (friction/law_spec.h: separated by ';', or by ',' where the next
// item is not KEY=VALUE), in its order; a bad spec, or one law given twice (even under two
// spellings of its spec), throws.
std::vector<std::unique_ptr<friction::FrictionLaw>> make_laws(const std::string& list) {
  std::vector<std::unique_ptr<friction::FrictionLaw>> laws;
  std::vector<std::string> canonical;
  for (const auto& spec : friction::split_law_list(list)) {
    const std::string c = friction::canonical_law_spec(spec);
    for (std::size_t i = 0; i < canonical.size(); ++i) {
      if (canonical[i] != c) continue;
      throw std::invalid_argument(spec == laws[i]->spec()
                                      ? "--law: law '" + spec + "' is listed twice"
                                      : "--law: '" + spec + "' is the same law as '" + std::string(laws[i]->spec()) +
                                            "', listed before it");
    }
    laws.push_back(friction::make_law(spec));
    canonical.push_back(c);
  }
  return laws;
}

// Writes `text` to stdout and flushes it: a failed write (a full disk, a closed pipe) throws.
void write_stdout(const std::string& text) {
  errno = 0;
  std::cout << text << std::flush;
  if (!std::cout) {
    throw std::runtime_error(std::string("cannot write the output") + (errno ? std::string(": ") + std::strerror(errno) : ""));
  }
}

void run_table(const std::vector<const friction::FrictionLaw*>& laws, const std::string& path,
               friction::OnError on_error) {
  friction::BatchOptions options;
  options.on_error = on_error;
  std::size_t shown = 0;
  const char* what = on_error == friction::OnError::skip ? " (row skipped)" : " (written as nan)";
  options.on_bad_row = [&](std::size_t line, const std::string& reason) {
    if (shown++ < kMaxWarnings) {
      std::cerr << "frictionlab: warning: input line " << line << ": " << reason << what << '\n';
    }
  };
  std::error_code ec;
  if (path != "-" && std::filesystem::is_directory(path, ec))
    throw std::invalid_argument("the input " + path + " is a directory");
  // Read through read(2), stdin too: std::cin, synced with stdio, takes a read error for the end
  // of the table (support/checked_input.h).
  std::unique_ptr<support::InputStream> in;
  try {
    in = std::make_unique<support::InputStream>(path, "input");
  } catch (const support::InputError& e) {
    throw std::invalid_argument("cannot open the input " + path + ": " + std::strerror(e.error_number()));
  }
  options.input_name = path == "-" ? "standard input" : "the input '" + path + "'";
  const friction::BatchSummary summary = friction::evaluate_csv(laws, *in, std::cout, options);
  if (summary.bad > kMaxWarnings) {
    std::cerr << "frictionlab: warning: " << summary.bad << " bad rows in all (the first " << kMaxWarnings
              << " shown above)\n";
  }
}

void run(const FrictionOptions& opt) {
  const auto made = make_laws(opt.laws);
  std::vector<const friction::FrictionLaw*> laws;
  for (const auto& law : made) laws.push_back(law.get());
  const friction::OnError on_error = friction::parse_on_error(opt.on_error);
  if (!opt.input.empty() && !opt.input_positional.empty()) {
    throw std::invalid_argument("the input is given twice (--input " + opt.input + " and " + opt.input_positional +
                                "): give one table");
  }
  const std::string path = !opt.input.empty() ? opt.input : opt.input_positional;
  std::size_t given = 0;
  for (const auto& v : opt.value) given += v.has_value();
  if (given > 0 && !path.empty()) {
    throw std::invalid_argument("give either one contact (--U ... --k) or an input table, not both");
  }
  if (given == 0) {
    if (path.empty() && isatty(STDIN_FILENO)) {
      throw std::invalid_argument(
          "no contact given: pass --U --Omega --a --b --psi --N --k, an input file, or pipe a CSV table on stdin");
    }
    run_table(laws, path.empty() ? "-" : path, on_error);
    return;
  }
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (!opt.value[i]) {
      throw std::invalid_argument(std::string("--") + kNames[i] +
                                  " is missing: a single contact needs all of --U --Omega --a --b --psi --N --k");
    }
  }
  const friction::ContactInput in{*opt.value[0], *opt.value[1], *opt.value[2], *opt.value[3],
                                  *opt.value[4], *opt.value[5], *opt.value[6]};
  // The table's own columns, with a header, for one law as for several (friction/batch.h).
  std::string text = std::string(friction::kOutputColumns) + '\n';
  for (const auto* law : laws)
    text += friction::csv_field(law->spec()) + ',' + friction::format_forces(law->evaluate(in)) + '\n';
  write_stdout(text);
}

}  // namespace

void register_friction_command(CLI::App& app) {
  auto opt = std::make_shared<FrictionOptions>();
  auto* cmd = app.add_subcommand(
      "friction",
      "Evaluate friction laws: prints a CSV table law,F1,F2,M (F1, F2 in N, M in N m), with its\n"
      "header, one row per law, for one contact; or, with no contact options, reads a CSV table with\n"
      "columns U,Omega,a,b,psi,N,k (any order, other columns passed through; blank lines and a UTF-8\n"
      "byte-order mark are accepted) from INPUT, or from stdin if INPUT is '-' or absent, and writes\n"
      "it back with law,F1,F2,M appended. The columns are the same for one law and for several. Rows\n"
      "are streamed in input order; each input row gives one row per law, in the order of --law. With\n"
      "--on-error stop nothing is written unless every row succeeds (the table is spooled to a\n"
      "temporary file, then copied to stdout)");
  cmd->add_option("--law", opt->laws,
                  "law spec (NAME or NAME:KEY=VALUE[,KEY=VALUE], see `frictionlab laws`), or several separated "
                  "by ';' or by ','")
      ->capture_default_str();
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    cmd->add_option(std::string("--") + kNames[i], opt->value[i], kHelp[i]);
  }
  cmd->add_option("INPUT", opt->input_positional, "CSV table to evaluate ('-': stdin)");
  cmd->add_option("--input", opt->input, "CSV table to evaluate ('-': stdin), as INPUT");
  cmd->add_option("--on-error", opt->on_error,
                  "a row that cannot be evaluated: stop (nothing is written), skip (left out, warned on stderr) "
                  "or nan (written with F1,F2,M = nan, warned on stderr)")
      ->capture_default_str();
  cmd->callback([opt] { run(*opt); });
}

}  // namespace frictionlab::cli
