// The figures' gnuplot scripts (dynamics/paper/figure_scripts.h), read as text: what each panel
// draws, in which style and on which axis.

#include "dynamics/paper/figure_scripts.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace frictionlab::dynamics::paper {
namespace figure_scripts_test {

namespace fs = std::filesystem;

FigureRun run(const std::string& label, bool baseline = false, const std::string& stop = "") {
  FigureRun r;
  r.label = label;
  r.stem = "g-" + label;
  r.baseline = baseline;
  r.stopped_early = !stop.empty();
  r.stop = stop;
  r.ranges.full = {2.0, 30.0, 10.0, 1.5};
  r.ranges.early = {2.0, 30.0, 10.0, 1.5};
  return r;
}

// Case a: the printed law stops at 0.3163 s; case b: at 3.875 s.
std::vector<FigureGroup> two_cases() {
  FigureGroup a{"egg-printed", "a", "case a", {}};
  a.runs = {run("exact"), run("pade-reconstructed"), run("pade-printed", false, "law-pole at t = 0.3163 s"),
            run("moller-ellipsoidal"), run("exact-tol1e-10", true)};
  FigureGroup b = a;
  b.case_id = "b";
  b.description = "case b";
  b.runs[2].stop = "law-pole at t = 3.875 s";
  return {a, b};
}

struct Scripts {
  fs::path dir;
  std::vector<std::string> names;
  Scripts() : dir(fs::temp_directory_path() / ("frictionlab_figure_scripts_" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    names = write_figure_scripts(dir, two_cases());
  }
  ~Scripts() { fs::remove_all(dir); }
  [[nodiscard]] std::string text(const std::string& name) const {
    std::ifstream in(dir / name);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

// The plot commands of a script (each from "plot " to the end of its last continued line), with the
// settings that precede each.
struct Panel {
  std::string settings;
  std::string plot;
};
std::vector<Panel> panels(const std::string& script) {
  std::vector<Panel> out;
  std::string settings;
  std::size_t pos = 0;
  while (pos < script.size()) {
    std::size_t end = script.find('\n', pos);
    if (end == std::string::npos) end = script.size();
    std::string line = script.substr(pos, end - pos);
    pos = end + 1;
    if (line.rfind("plot ", 0) == 0) {
      std::string plot = line;
      while (!plot.empty() && plot.back() == '\\' && pos < script.size()) {
        end = script.find('\n', pos);
        if (end == std::string::npos) end = script.size();
        plot += "\n" + script.substr(pos, end - pos);
        pos = end + 1;
      }
      out.push_back({settings, plot});
      settings.clear();
    } else {
      settings += line + "\n";
    }
  }
  return out;
}

// The elements of a plot command (separated by ", \").
std::vector<std::string> elements(const std::string& plot) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t sep = plot.find(", \\\n", start);
    out.push_back(plot.substr(start, sep == std::string::npos ? std::string::npos : sep - start));
    if (sep == std::string::npos) return out;
    start = sep + 4;
  }
}

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

TEST(PaperFigureScripts, OneScriptPerFigure) {
  const Scripts s;
  EXPECT_EQ(s.names, (std::vector<std::string>{"fig2-egg-printed.gp", "fig3-egg-printed-a.gp", "fig3-egg-printed-a-early.gp",
                                               "fig3-egg-printed-b.gp", "fig3-egg-printed-b-early.gp"}));
}

TEST(PaperFigureScripts, TheBaselineIsDrawnAndNamedInTheKey) {
  const Scripts s;
  for (const std::string name : {"fig2-egg-printed.gp", "fig3-egg-printed-a.gp", "fig3-egg-printed-a-early.gp"}) {
    const std::string text = s.text(name);
    EXPECT_TRUE(has(text, "data/g-exact-tol1e-10.")) << name;
    EXPECT_TRUE(std::regex_search(text, std::regex("title '[^']*exact-tol1e-10[^']*baseline"))) << name;
  }
}

// Grayscale keeps dash patterns, not colours: within a figure no two runs share one.
TEST(PaperFigureScripts, EveryRunOfAFigureHasItsOwnDashPattern) {
  const Scripts s;
  for (const auto& name : s.names) {
    for (const auto& panel : panels(s.text(name))) {
      std::set<std::string> dashes;
      int lines = 0;
      for (const auto& e : elements(panel.plot)) {
        if (!has(e, "with lines")) continue;
        ++lines;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(e, m, std::regex(" dt (\\S+)"))) << name << ": " << e;
        dashes.insert(m[1]);
      }
      // fig. 3 draws the quantiles as thin lines (two per run that ended normally, in its dash).
      EXPECT_EQ(lines, has(name, "fig3") ? 5 + 2 * 4 : 5) << name;
      EXPECT_EQ(dashes.size(), 5u) << name << ": " << panel.plot;
    }
  }
}

// fig. 2 has a panel per case: each marks where the printed law stopped in THAT case, and the key
// (drawn once) gives no time.
TEST(PaperFigureScripts, EachPanelMarksItsOwnEarlyStops) {
  const Scripts s;
  const auto fig2 = panels(s.text("fig2-egg-printed.gp"));
  ASSERT_EQ(fig2.size(), 2u);
  EXPECT_TRUE(has(fig2[0].plot, "law-pole at t = 0.3163 s")) << fig2[0].plot;
  EXPECT_FALSE(has(fig2[0].plot, "3.875")) << fig2[0].plot;
  EXPECT_TRUE(has(fig2[1].plot, "law-pole at t = 3.875 s")) << fig2[1].plot;
  EXPECT_FALSE(has(fig2[1].plot, "0.3163")) << fig2[1].plot;
  for (const auto& panel : fig2)
    for (const auto& e : elements(panel.plot))
      if (has(e, " title ")) {
        EXPECT_FALSE(std::regex_search(e, std::regex("title '[^']*[0-9] s"))) << e;
      }
  // fig. 3: every panel marks the stop with a cross; its reason and time are said once, in the key.
  const std::string text3 = s.text("fig3-egg-printed-b.gp");
  const auto fig3 = panels(text3);
  ASSERT_EQ(fig3.size(), 6u);
  for (const auto& panel : fig3) {
    EXPECT_TRUE(has(panel.plot, "data/g-pade-printed.end.dat")) << panel.plot;
    EXPECT_FALSE(has(panel.plot, "with labels")) << panel.plot;
  }
  EXPECT_TRUE(has(fig3[0].plot, "title 'pade-printed (× = law-pole at t = 3.875 s)'")) << fig3[0].plot;
  std::size_t said = 0;
  for (std::size_t pos = text3.find("3.875 s"); pos != std::string::npos; pos = text3.find("3.875 s", pos + 1)) ++said;
  EXPECT_EQ(said, 1u);
}

// |F|, |M| and N/(m g) are dominated by impacts: log axes. The 5-95 % quantiles are thin lines
// (no filled band) drawn before every mean line.
TEST(PaperFigureScripts, ImpactQuantitiesOnLogAxesAndQuantileLinesBeneathTheMeans) {
  const Scripts s;
  const auto fig3 = panels(s.text("fig3-egg-printed-a.gp"));
  ASSERT_EQ(fig3.size(), 6u);
  const std::vector<bool> log_axis = {false, true, true, false, false, true};  // gamma3, |F|, |M|, a, b/a, N
  const std::vector<int> band_lo = {FigureColumns::gamma3_lo, FigureColumns::force_lo, FigureColumns::moment_lo,
                                    FigureColumns::major_lo,  FigureColumns::ratio_lo, FigureColumns::n_lo};
  for (std::size_t p = 0; p < fig3.size(); ++p) {
    EXPECT_EQ(has("\n" + fig3[p].settings, "\nset logscale y\n"), log_axis[p]) << p << ": " << fig3[p].settings;
    EXPECT_EQ(has("\n" + fig3[p].settings, "\nunset logscale y\n"), !log_axis[p]) << p << ": " << fig3[p].settings;
    bool mean_seen = false;
    int quantile_lines = 0;
    for (const auto& e : elements(fig3[p].plot)) {
      EXPECT_FALSE(has(e, "filledcurves")) << e;
      if (!has(e, "with lines")) continue;
      if (!has(e, "lw 0.5")) {
        mean_seen = true;
        continue;
      }
      ++quantile_lines;
      EXPECT_FALSE(mean_seen) << "a quantile line drawn over a mean: " << e;
      if (quantile_lines % 2 == 1) {
        EXPECT_TRUE(has(e, "$" + std::to_string(band_lo[p]) + ",")) << p << ": " << e;
      }
    }
    EXPECT_EQ(quantile_lines, 8) << p;  // two for every run but the one stopped early
  }
}

// Law specs, names, descriptions and stop reasons are shown as they are: their '_' (r_spin,
// max_steps) would otherwise be typeset as a subscript by the enhanced-text terminals. The key and
// the titles escape them once (support::gnuplot_text); the stop labels, read through a `using`
// column, twice (support::gnuplot_label_column_text).
TEST(PaperFigureScripts, UserTextIsEscapedForEnhancedText) {
  FigureGroup g{"egg_x", "a", "omega_3 = 100", {}};
  g.runs = {run("exact"), run("decoupled:r_spin=0", false, "max_steps at t = 1 s")};
  const fs::path dir = fs::temp_directory_path() / ("frictionlab_figure_text_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto names = write_figure_scripts(dir, {g});
  ASSERT_FALSE(names.empty());
  for (const auto& name : names) {
    std::ifstream in(dir / name);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (has(name, "fig2")) {
      EXPECT_TRUE(has(text, "title 'decoupled:r\\_spin=0 (× = stop)'")) << name << "\n" << text;
      EXPECT_TRUE(has(text, ":('decoupled:r\\\\_spin=0: max\\\\_steps at t = 1 s') with labels")) << name;
    } else {
      EXPECT_TRUE(has(text, "title 'decoupled:r\\_spin=0 (× = max\\_steps at t = 1 s)'")) << name << "\n" << text;
    }
    EXPECT_TRUE(has(text, "egg\\_x")) << name;
    EXPECT_TRUE(has(text, "omega\\_3 = 100")) << name;
    // No title holds an unescaped '_' (file names do, and must: they are not text).
    const std::regex title("title '((?:[^']|'')*)'");
    for (auto m = std::sregex_iterator(text.begin(), text.end(), title); m != std::sregex_iterator(); ++m)
      EXPECT_FALSE(std::regex_search((*m)[1].str(), std::regex("(^|[^\\\\])_"))) << name << ": " << m->str();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
