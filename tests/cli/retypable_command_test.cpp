#include "dynamics/cli/retypable_command.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace frictionlab::cli {
namespace retypable_command_test {

struct Parsed {
  CLI::App app{"test"};
  CLI::App* cmd = nullptr;
  std::string out, laws;
  std::vector<std::string> list;
  int threads = 0, points = 7;
  bool no_plots = false;

  explicit Parsed(std::vector<std::string> args) {
    cmd = app.add_subcommand("study", "a study");
    cmd->add_option("--out", out)->required();
    cmd->add_option("--laws", laws);
    cmd->add_option("--list", list)->delimiter(',');
    cmd->add_option("--points", points);
    cmd->add_option("--threads", threads);
    cmd->add_flag("--no-plots", no_plots);
    args.insert(args.begin(), "frictionlab");
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    app.parse(static_cast<int>(argv.size()), argv.data());
  }
};

TEST(CliRetypableCommand, GivenOptionsOnlyUnderTheirLongNamesInDeclaredOrder) {
  Parsed p({"study", "--no-plots", "--points", "9", "--out", "results/x"});
  EXPECT_EQ(retypable_command(*p.cmd), "frictionlab study --out results/x --points 9 --no-plots");
}

TEST(CliRetypableCommand, ListsAreJoinedAndShellCharactersQuoted) {
  Parsed p({"study", "--out", "my dir", "--list", "exact,pade-printed", "--laws", "exact;ellipsoidal:Rb=0.1"});
  EXPECT_EQ(retypable_command(*p.cmd),
            "frictionlab study --out 'my dir' --laws 'exact;ellipsoidal:Rb=0.1' --list exact,pade-printed");
}

TEST(CliRetypableCommand, OmittedOptionsStayOut) {
  Parsed p({"study", "--out", "o", "--threads", "2"});
  EXPECT_EQ(retypable_command(*p.cmd, {"--threads"}), "frictionlab study --out o");
  EXPECT_EQ(retypable_command(*p.cmd), "frictionlab study --out o --threads 2");
}

}  // namespace
}  // namespace frictionlab::cli
