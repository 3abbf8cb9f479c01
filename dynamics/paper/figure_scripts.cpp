#include "dynamics/paper/figure_scripts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "dynamics/paper/figure_data.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

// libgd's PNG (not pngcairo): no antialiasing, but a third of the file size for these noisy curves.
constexpr const char* kTerminal = "set encoding utf8\nset terminal png truecolor enhanced size 1200,980 font 'DejaVuSans,10'";
constexpr const char* kBand = "set style fill transparent solid 0.15 noborder";
constexpr double kAxisHeadroom = 1.15;  // the capped axes end this factor above the largest cap

enum class Cap { none, force, moment, major, n_over_mg };

struct Panel {
  int lo;             // min column in .dat
  int hi;             // max column
  int mean;           // mean column
  int end;            // column in .end.dat
  const char* label;  // y axis label, with unit
  Cap cap;
  const char* range;  // fixed y range, when not capped
};

constexpr std::array<Panel, 6> kPanels = {{
    {FigureColumns::gamma3_min, FigureColumns::gamma3_max, FigureColumns::gamma3_mean, EndColumns::gamma3, "γ_3 = cos(nutation angle)",
     Cap::none, "[-1.05:1.05]"},
    {FigureColumns::force_min, FigureColumns::force_max, FigureColumns::force_mean, EndColumns::force, "|F|, friction force (N)", Cap::force, ""},
    {FigureColumns::moment_min, FigureColumns::moment_max, FigureColumns::moment_mean, EndColumns::moment, "|M|, friction moment (N mm)",
     Cap::moment, ""},
    {FigureColumns::major_min, FigureColumns::major_max, FigureColumns::major_mean, EndColumns::major, "a, major semi-axis of the patch (mm)",
     Cap::major, ""},
    {FigureColumns::ratio_min, FigureColumns::ratio_max, FigureColumns::ratio_mean, EndColumns::ratio, "b/a, axis ratio of the patch", Cap::none,
     "[0:1.05]"},
    {FigureColumns::n_min, FigureColumns::n_max, FigureColumns::n_mean, EndColumns::n, "N/(m g)", Cap::n_over_mg, ""},
}};

using support::gnuplot_quoted;

std::string title_of(const FigureRun& r) { return r.stopped_early ? r.label + " (" + r.note + ")" : r.label; }

double cap_of(const AxisCaps& c, Cap which) {
  switch (which) {
    case Cap::force: return c.force;
    case Cap::moment: return c.moment;
    case Cap::major: return c.major;
    case Cap::n_over_mg: return c.n_over_mg;
    case Cap::none: break;
  }
  return 0.0;
}

// The top of a capped axis: over the runs that ended normally (all runs if none did).
double axis_top(const FigureGroup& g, Cap which, bool early) {
  double top = 0.0;
  for (const bool normal_only : {true, false}) {
    for (const auto& r : g.runs) {
      if (normal_only && r.stopped_early) continue;
      const double c = cap_of(early ? r.ranges.early : r.ranges.full, which);
      if (std::isfinite(c)) top = std::max(top, c);
    }
    if (top > 0.0) break;
  }
  return top > 0.0 ? kAxisHeadroom * top : 1.0;
}

std::string number(double x) { return support::significant(x, 4); }

// The plot command of one panel: per run a band (min-max per bin) and its mean line, and a cross
// where an early-stopped run stopped.
std::string plot_command(const FigureGroup& g, const std::string& kind, int x_col, int lo, int hi, int mean,
                         int end_x, int end_y, bool with_titles, bool bands) {
  std::string cmd = "plot ";
  for (std::size_t i = 0; i < g.runs.size(); ++i) {
    const FigureRun& r = g.runs[i];
    const std::string colour = gnuplot_quoted(law_colour(r.label, i));
    const std::string data = gnuplot_quoted("data/" + r.stem + "." + kind + ".dat");
    const std::string x = std::to_string(x_col);
    if (i > 0) cmd += ", \\\n     ";
    if (bands && !r.stopped_early)  // a run stopped at a pole has bins of ~1e9 N: no band
      cmd += data + " using " + x + ":" + std::to_string(lo) + ":" + std::to_string(hi) +
             " with filledcurves lc rgb " + colour + " notitle, \\\n     ";
    cmd += data + " using " + x + ":" + std::to_string(mean) + " with lines lw 1.1 lc rgb " + colour +
           (with_titles ? " title " + gnuplot_quoted(title_of(r)) : " notitle");
    if (r.stopped_early) {
      cmd += ", \\\n     " + gnuplot_quoted("data/" + r.stem + ".end.dat") + " using " + std::to_string(end_x) + ":" +
             std::to_string(end_y) + " with points pt 2 ps 2.5 lw 2.5 lc rgb " + colour + " notitle";
    }
  }
  return cmd + "\n";
}

void write_file(const std::filesystem::path& p, const std::string& text) { support::write_file_atomically(p, text); }

std::string fig3(const FigureGroup& g, bool early) {
  const std::string kind = early ? "early" : "full";
  const std::string stem = "fig3-" + g.egg + "-" + g.case_id + (early ? "-early" : "");
  std::ostringstream s;
  s << "# " << stem << ".png: the paper's fig. 3 quantities against time, " << g.egg << ", case " << g.case_id
    << (early ? " (first seconds)" : "") << ".\n# Lines: the mean of each time bin (data/*." << kind << ".dat)"
    << (early ? "" : "; bands: its min-max") << "; the axes of |F|, |M|, a, N/(m g) end 15 % above the largest bin mean,\n"
    << "# cutting the bands of the bouncing phases. Regenerate: gnuplot " << stem << ".gp\n"
    << kTerminal << "\nset output " << gnuplot_quoted(stem + ".png") << "\n"
    << kBand << "\nset grid\nset xlabel 't (s)'\nset datafile missing 'NaN'\n";
  if (early) s << "set xrange [0:" << kEarlyWindow << "]\n";
  s << "set multiplot layout 3,2 margins 0.07,0.98,0.05,0.895 spacing 0.08,0.07 title "
    << gnuplot_quoted(g.egg + ", case " + g.case_id + ": " + g.description +
              (early ? " (first " + std::to_string(static_cast<int>(kEarlyWindow)) + " s)" : ""))
    << " font ',13'\n";
  for (std::size_t p = 0; p < kPanels.size(); ++p) {
    const Panel& panel = kPanels[p];
    if (p == 0) {
      s << "set key at screen 0.5,0.958 center top vertical font ',10' samplen 2 spacing 0.9\n";
    } else {
      s << "unset key\n";
    }
    if (panel.cap == Cap::none) {
      s << "set ylabel " << gnuplot_quoted(panel.label) << "\nset yrange " << panel.range << "\n";
    } else {
      s << "set ylabel " << gnuplot_quoted(std::string(panel.label)) << "\nset yrange [0:"
        << number(axis_top(g, panel.cap, early)) << "]\n";
    }
    s << plot_command(g, kind, FigureColumns::t, panel.lo, panel.hi, panel.mean, EndColumns::t, panel.end, p == 0,
                      !early);
  }
  s << "unset multiplot\n";
  return s.str();
}

std::string fig2(const std::string& egg, const std::vector<const FigureGroup*>& groups) {
  const std::string stem = "fig2-" + egg;
  std::ostringstream s;
  s << "# " << stem << ".png: the paper's fig. 2, gamma3 against |omega|^2, " << egg
    << ", one panel per case.\n# Bands: min-max of gamma3 in each time bin, at the bin's mean |omega|^2 "
       "(data/*.full.dat). Regenerate: gnuplot "
    << stem << ".gp\n"
    << "set encoding utf8\nset terminal png truecolor enhanced size 1800,620 font 'DejaVuSans,11'\nset output "
    << gnuplot_quoted(stem + ".png")
    << "\n"
    << kBand << "\nset grid\n"
    << "set logscale x\nset format x '10^{%T}'\nset xlabel '|ω|^2 (1/s^2), log scale; time runs right to left'\n"
    << "set ylabel 'γ_3 = cos(nutation angle)'\nset yrange [-1.05:1.05]\n"
    << "set multiplot layout 1," << groups.size() << " margins 0.05,0.98,0.13,0.76 spacing 0.05,0 title "
    << gnuplot_quoted(egg + ": the paper's fig. 2") << " font ',13'\n";
  for (const FigureGroup* g : groups) {
    s << "set title " << gnuplot_quoted("case " + g->case_id + ": " + g->description) << "\n";
    if (g == groups.front()) {
      s << "set key at screen 0.5,0.9 center top vertical font ',10' samplen 2 spacing 0.9\n";
    } else {
      s << "unset key\n";
    }
    s << plot_command(*g, "full", FigureColumns::omega_sq, FigureColumns::gamma3_min, FigureColumns::gamma3_max,
                      FigureColumns::gamma3_mean, EndColumns::omega_sq, EndColumns::gamma3, g == groups.front(), true);
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace

std::string law_colour(const std::string& law, std::size_t index) {
  static const std::map<std::string, std::string> fixed = {
      {"exact", "#000000"},          {"pade-reconstructed", "#0072B2"}, {"pade-printed", "#D55E00"},
      {"moller-ellipsoidal", "#009E73"}, {"coulomb-decoupled", "#CC79A7"}, {"pade-printed-minor", "#E69F00"},
      {"exact-reference", "#56B4E9"},
  };
  if (const auto it = fixed.find(law); it != fixed.end()) return it->second;
  static const std::array<const char*, 4> others = {"#999999", "#F0E442", "#882255", "#44AA99"};
  return others[index % others.size()];
}

std::vector<std::string> write_figure_scripts(const std::filesystem::path& plots_dir,
                                              const std::vector<FigureGroup>& groups) {
  std::filesystem::create_directories(plots_dir);
  std::vector<std::string> scripts;
  std::vector<std::string> eggs;
  for (const auto& g : groups)
    if (std::find(eggs.begin(), eggs.end(), g.egg) == eggs.end()) eggs.push_back(g.egg);
  for (const auto& egg : eggs) {
    std::vector<const FigureGroup*> of_egg;
    for (const auto& g : groups)
      if (g.egg == egg) of_egg.push_back(&g);
    const std::string name = "fig2-" + egg + ".gp";
    write_file(plots_dir / name, fig2(egg, of_egg));
    scripts.push_back(name);
    for (const FigureGroup* g : of_egg) {
      for (const bool early : {false, true}) {
        const std::string n3 = "fig3-" + g->egg + "-" + g->case_id + (early ? "-early" : "") + ".gp";
        write_file(plots_dir / n3, fig3(*g, early));
        scripts.push_back(n3);
      }
    }
  }
  return scripts;
}

std::vector<std::string> render_figures(const std::filesystem::path& plots_dir, const std::vector<std::string>& scripts) {
  std::vector<std::string> errors;
  for (const auto& script : scripts) {
    const support::GnuplotRun run =
        support::run_gnuplot(plots_dir, script, std::filesystem::path(script).stem().string() + ".log");
    if (!run.found) {
      errors.push_back(run.message + ": no PNG drawn (the scripts are in " + plots_dir.string() + ")");
      break;
    }
    if (!run.ok) errors.push_back(run.message);
  }
  return errors;
}

}  // namespace frictionlab::dynamics::paper
