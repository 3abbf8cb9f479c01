// `frictionlab tippe-top --out DIR [--laws SPEC,...] [--scenario FILE] [--max-steps N] [--no-plots]`:
// the tippe top with every friction law (docs/tippe-top.md, dynamics/tippe_top/tippe_top_study.h):
// gamma3 against time, inversion times, energy and Jellett checks; report, table and figures in DIR.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "dynamics/cli/commands.h"
#include "dynamics/cli/retypable_command.h"
#include "dynamics/paper/experiment_plan.h"
#include "dynamics/io/shipped_data.h"
#include "dynamics/tippe_top/tippe_top_study.h"
#include "dynamics/tippe_top/tippe_top_study_report.h"
#include "friction/support/number_format.h"

namespace frictionlab::cli {
namespace {

struct TippeTopCommandOptions {
  std::string out;
  std::string laws;  // a list of specs (friction/law_spec.h), empty: the study's default
  std::string scenario;
  long max_steps = dynamics::tippe_top::TippeTopStudyOptions{}.max_steps;
  bool no_plots = false;
};

void run(const TippeTopCommandOptions& opt, const std::string& command) {
  if (opt.out.empty()) throw std::invalid_argument("--out is empty: name the output folder");
  dynamics::tippe_top::TippeTopStudyOptions so;
  if (!opt.laws.empty()) so.laws = friction::split_law_list(opt.laws);
  so.max_steps = opt.max_steps;
  so.scenario = opt.scenario.empty() ? dynamics::paper::default_scenario_dir() / "tippe-top.toml"
                                     : dynamics::find_shipped_file(opt.scenario, "scenarios", "scenario");
  const auto results = dynamics::tippe_top::run_tippe_top_study(so);
  const auto problems = dynamics::tippe_top::write_tippe_top_study(results, opt.out, command, !opt.no_plots);
  for (const auto& p : problems) std::cerr << "frictionlab: tippe-top: " << p << std::endl;
  std::cout << "tippe-top: " << results.runs.size() << " laws in " << support::fixed(results.wall_time, 1)
            << " s; wrote " << (std::filesystem::path(opt.out) / "tippe-top.md").string() << std::endl;
}

}  // namespace

void register_tippe_top_command(CLI::App& app) {
  auto opt = std::make_shared<TippeTopCommandOptions>();
  auto* cmd = app.add_subcommand("tippe-top",
                                 "The tippe top with every friction law: gamma3 against time, inversion times, energy\n"
                                 "and Jellett's quantity (docs/tippe-top.md); ~0.4 MB");
  cmd->add_option("--out", opt->out, "output folder (created; existing files are replaced)")->required();
  cmd->add_option("--laws", opt->laws,
                  "law specs, separated by ';' or ',' (default: every registered law that is not slow, and decoupled, "
                  "decoupled:r_spin=0 where the registry has them)");
  cmd->add_option("--scenario", opt->scenario,
                  "the tippe-top scenario: a file, or a shipped scenario's name (default: the shipped tippe-top.toml)");
  cmd->add_option("--max-steps", opt->max_steps,
                  "accepted steps allowed per run (a bound; a chattering law ends 'chatter' first, docs/dynamics.md §5)");
  cmd->add_flag("--no-plots", opt->no_plots, "write the gnuplot data and scripts but do not run gnuplot");
  cmd->callback([opt, cmd] { run(*opt, retypable_command(*cmd)); });
}

}  // namespace frictionlab::cli
