// `frictionlab friction`: evaluate one law at one contact, or over a CSV table read from stdin.

#include <array>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <unistd.h>

#include "dynamics/cli/commands.h"
#include "friction/batch.h"
#include "friction/registry.h"

namespace frictionlab::cli {
namespace {

struct FrictionOptions {
  std::string law = "exact";
  std::array<std::optional<double>, 7> value;  // U, Omega, a, b, psi, N, k
};

constexpr std::array<const char*, 7> kNames = {"U", "Omega", "a", "b", "psi", "N", "k"};
constexpr std::array<const char*, 7> kHelp = {
    "slip speed of the patch centre, m/s (>= 0)", "spin about the upward normal, 1/s",
    "major semi-axis, m (> 0)", "minor semi-axis, m (0 < b <= a)",
    "angle from the slip direction to the major axis, rad", "normal force, N (>= 0)",
    "friction coefficient (>= 0)"};

void run(const FrictionOptions& opt) {
  const auto law = friction::make_law(opt.law);
  std::size_t given = 0;
  for (const auto& v : opt.value) given += v.has_value();
  if (given == 0) {
    if (isatty(STDIN_FILENO)) {
      throw std::invalid_argument(
          "no contact given: pass --U --Omega --a --b --psi --N --k, or pipe a CSV table on stdin");
    }
    friction::evaluate_csv(*law, std::cin, std::cout);
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
  std::cout << friction::format_forces(law->evaluate(in)) << '\n';
}

}  // namespace

void register_friction_command(CLI::App& app) {
  auto opt = std::make_shared<FrictionOptions>();
  auto* cmd = app.add_subcommand(
      "friction",
      "Evaluate a friction law: prints F1,F2,M (N, N, N m) for one contact, or, with no contact\n"
      "options, reads a CSV table with columns U,Omega,a,b,psi,N,k on stdin and writes it back\n"
      "with F1,F2,M appended");
  cmd->add_option("--law", opt->law, "law name (see `frictionlab laws`)")->capture_default_str();
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    cmd->add_option(std::string("--") + kNames[i], opt->value[i], kHelp[i]);
  }
  cmd->callback([opt] { run(*opt); });
}

}  // namespace frictionlab::cli
