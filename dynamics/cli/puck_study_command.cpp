// `frictionlab puck-study --out DIR [--laws SPEC,...] [--scenarios DIR] [--no-plots]`: every friction
// law on the sliding-spinning puck (docs/puck.md §4, dynamics/puck/puck_study.h): the terminal
// regimes predicted from each law, the disk's stop times and terminal ratio, the elliptic puck's
// path; report, tables and figures under DIR.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "dynamics/cli/commands.h"
#include "dynamics/cli/retypable_command.h"
#include "dynamics/paper/experiment_plan.h"
#include "dynamics/puck/puck_study.h"
#include "dynamics/puck/puck_study_report.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

struct PuckStudyCommandOptions {
  std::string out;
  std::string laws;  // a list of specs (friction/law_spec.h), empty: the study's default
  std::string scenarios;
  bool no_plots = false;
};

void run(const PuckStudyCommandOptions& opt, const std::string& command) {
  if (opt.out.empty()) throw std::invalid_argument("--out is empty: name the output folder");
  dynamics::puck::PuckStudyOptions so;
  if (!opt.laws.empty()) so.laws = friction::split_law_list(opt.laws);
  so.scenario_dir = opt.scenarios.empty() ? dynamics::paper::default_scenario_dir() : std::filesystem::path(opt.scenarios);
  const dynamics::puck::PuckStudyResults results = dynamics::puck::run_puck_study(so);
  const std::vector<std::string> problems = dynamics::puck::write_puck_study(results, opt.out, command, !opt.no_plots);
  for (const auto& p : problems) std::cerr << "frictionlab: puck-study: " << p << std::endl;
  std::cout << "puck-study: " << results.laws.size() << " laws, " << results.disk.size() + results.ellipse.size()
            << " runs in " << support::fixed(results.wall_time, 1) << " s; wrote "
            << (std::filesystem::path(opt.out) / "puck-study.md").string() << std::endl;
}

}  // namespace

void register_puck_study_command(CLI::App& app) {
  auto opt = std::make_shared<PuckStudyCommandOptions>();
  auto* cmd = app.add_subcommand("puck-study",
                                 "Every friction law on the sliding-spinning puck: terminal regimes from the law, the\n"
                                 "disk's stop times and terminal ratio, the elliptic puck's path (docs/puck.md); ~3.3 MB");
  cmd->add_option("--out", opt->out, "output folder (created; existing files are replaced)")->required();
  cmd->add_option("--laws", opt->laws,
                  "law specs, separated by ';' or ',' (default: every registered law, and exact:pressure=uniform, "
                  "exact:pressure=punch where the registry has them)");
  cmd->add_option("--scenarios", opt->scenarios, "folder of puck-disk.toml and puck-ellipse.toml (default: the shipped ones)");
  cmd->add_flag("--no-plots", opt->no_plots, "write the gnuplot data and scripts but do not run gnuplot");
  cmd->callback([opt, cmd] { run(*opt, retypable_command(*cmd)); });
}

}  // namespace frictionlab::cli
