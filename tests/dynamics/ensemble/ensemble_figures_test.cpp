// The ensemble's figure scripts (dynamics/ensemble/ensemble_figures.h), read as text: what the
// user typed (the study's name, the varied keys, law specs) reaches every title, key entry and
// axis label escaped for gnuplot's enhanced text, where '_' is a subscript.

#include "dynamics/ensemble/ensemble_figures.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace frictionlab::dynamics::ensemble {
namespace ensemble_figures_test {

namespace fs = std::filesystem;

TEST(EnsembleFigures, UserTextIsEscapedForEnhancedText) {
  const std::vector<std::string> laws = {"exact", "decoupled:r_spin=0"};
  OutcomeMap map;
  map.axes = {"initial.omega_3", "contact.k", {1.0, 2.0}, {0.1, 0.2}, false, false};
  for (const auto& law : laws)
    map.laws.push_back({law, std::vector<std::string>(4, "pole+"),
                        std::vector<CellChange>(4, law == laws.front() ? CellChange::missing : CellChange::changed)});
  std::vector<RunRecord> rows;
  for (long start = 0; start < 4; ++start)
    for (long replica = 0; replica < 2; ++replica)
      for (const auto& law : laws) {
        RunRecord r;
        r.start = start;
        r.replica = replica;
        r.law = law;
        r.reason = "rest";
        r.final_class = "pole+";
        r.t_vertical = 1.0 + start;
        r.final_gamma3 = 0.9;
        r.diverge_ref = law == laws.front() ? "replica:" + std::to_string(1 - replica) : laws.front();
        r.diverge_horizon = 10.0;
        r.t_diverge = 2.0 + replica;
        rows.push_back(r);
      }
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_ensemble_figures_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  (void)write_figures(dir, "study_x", laws, rows, map, /*draw=*/false);
  int scripts = 0;
  // Every quoted text after title, xlabel, ylabel, or in the colour bar's tic labels.
  const std::regex shown("(title|xlabel|ylabel|cbtics \\(|, ) '((?:[^']|'')*)'");
  for (const auto& entry : fs::directory_iterator(dir / "figures")) {
    if (entry.path().extension() != ".gp") continue;
    ++scripts;
    std::ifstream in(entry.path());
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string name = entry.path().filename().string();
    EXPECT_NE(text.find("study\\_x"), std::string::npos) << name << "\n" << text;
    for (auto m = std::sregex_iterator(text.begin(), text.end(), shown); m != std::sregex_iterator(); ++m)
      for (const char* raw : {"study_x", "r_spin", "omega_3"})
        EXPECT_EQ((*m)[2].str().find(raw), std::string::npos) << name << ": " << m->str();
    if (name == "divergence.gp") {
      EXPECT_NE(text.find("title 'decoupled:r\\_spin=0 vs exact'"), std::string::npos) << text;
    }
    if (name.rfind("map-", 0) == 0) {
      EXPECT_NE(text.find("set xlabel 'initial.omega\\_3'"), std::string::npos) << name << "\n" << text;
      EXPECT_NE(text.find("set title 'decoupled:r\\_spin=0"), std::string::npos) << name << "\n" << text;
    }
  }
  EXPECT_GE(scripts, 3);  // divergence, the final classes, the changes (and the medians)
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
