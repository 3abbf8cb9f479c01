#include "dynamics/paper/figure_scripts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "dynamics/paper/figure_data.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

using support::gnuplot_label_column_text;
using support::gnuplot_quoted;
using support::gnuplot_text;

// pngcairo draws dash patterns (libgd's png draws every line solid).
constexpr const char* kFig3Terminal =
    "set encoding utf8\nset terminal pngcairo enhanced size 1200,1000 font 'DejaVuSans,10'";
constexpr const char* kFig2Terminal =
    "set encoding utf8\nset terminal pngcairo enhanced size 1800,660 font 'DejaVuSans,11'";
// The key, across the top of the figure (drawn with the first panel).
constexpr const char* kKey =
    "set key at screen 0.5,0.955 center top vertical font ',10' samplen 4 spacing 1.05\n";
constexpr const char* kFig2Key =
    "set key at screen 0.5,0.905 center top horizontal maxcols 5 font ',10' samplen 4 spacing 1.1 width -3\n";
constexpr const char* kBand = "set style fill transparent solid 0.13 noborder";
// Values outside an axis are drawn at its edge (a log axis cannot show the zeros of a body in the
// air; a stop beyond the axis is still marked).
constexpr const char* kClip = "clip(y, lo, hi) = y < lo ? lo : (y > hi ? hi : y)";
constexpr double kLinearHeadroom = 1.05;  // a linear capped axis ends this factor above the cap
constexpr double kLogHeadroom = 1.5;      // a log axis ends this factor above the cap ...
constexpr double kLogDecades = 4.0;       // ... and spans this many decades

enum class Cap { none, force, moment, major, n_over_mg };
enum class Axis { fixed, linear, log };

struct Panel {
  int lo;             // band bottom column in .dat
  int hi;             // band top column
  int mean;           // line column
  int end;            // column in .end.dat
  const char* label;  // y axis label, with unit
  Axis axis;
  Cap cap;
  double fixed_lo, fixed_hi;  // the range of a fixed axis
};

constexpr std::array<Panel, 6> kPanels = {{
    {FigureColumns::gamma3_lo, FigureColumns::gamma3_hi, FigureColumns::gamma3_mean, EndColumns::gamma3,
     "γ_3 = cos(nutation angle)", Axis::fixed, Cap::none, -1.05, 1.05},
    {FigureColumns::force_lo, FigureColumns::force_hi, FigureColumns::force_mean, EndColumns::force,
     "|F|, friction force (N), 2-s mean, log scale", Axis::log, Cap::force, 0, 0},
    {FigureColumns::moment_lo, FigureColumns::moment_hi, FigureColumns::moment_mean, EndColumns::moment,
     "|M|, friction moment (N mm), 2-s mean, log scale", Axis::log, Cap::moment, 0, 0},
    {FigureColumns::major_lo, FigureColumns::major_hi, FigureColumns::major_mean, EndColumns::major,
     "a, major semi-axis (mm), 2-s mean", Axis::linear, Cap::major, 0, 0},
    {FigureColumns::ratio_lo, FigureColumns::ratio_hi, FigureColumns::ratio_mean, EndColumns::ratio,
     "b/a, axis ratio of the patch", Axis::fixed, Cap::none, 0.0, 1.05},
    {FigureColumns::n_lo, FigureColumns::n_hi, FigureColumns::n_mean, EndColumns::n, "N/(m g), 2-s mean, log scale",
     Axis::log, Cap::n_over_mg, 0, 0},
}};

// Eight patterns that stay apart in grayscale: solid, dashed, dotted, dash-dot, long dashes (the
// fifth run: with the four default laws, the baseline), dash-dot-dot, dot-long dash, long
// dash-three dots.
constexpr std::array<const char*, 8> kDashes = {"1", "2", "3", "4", "(28,7)", "5", "(4,6,16,6)", "(16,5,3,5,3,5,3,5)"};

std::string number(double x) { return support::significant(x, 4); }

// Key entries stay short: a panel of fig. 2 is a third of the width, and the key must fit in it.
// A run's key entry; with `stop`, an early stop's reason and time too (fig. 3: its one label).
std::string title_of(const FigureRun& r, bool stop = false) {
  std::string t = r.label;
  if (r.baseline) t += " (baseline)";
  if (r.stopped_early) t += stop ? " (× = " + r.stop + ")" : " (× = stop)";
  return t;
}

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

// The largest cap of the runs that ended normally (of all runs if none did); 1 if none is positive.
double largest_cap(const FigureGroup& g, Cap which, bool early) {
  double top = 0.0;
  for (const bool normal_only : {true, false}) {
    for (const auto& r : g.runs) {
      if (normal_only && r.stopped_early) continue;
      const double c = cap_of(early ? r.ranges.early : r.ranges.full, which);
      if (std::isfinite(c)) top = std::max(top, c);
    }
    if (top > 0.0) break;
  }
  return top > 0.0 ? top : 1.0;
}

struct Range {
  double lo, hi;
};

Range axis_range(const FigureGroup& g, const Panel& p, bool early) {
  switch (p.axis) {
    case Axis::fixed: return {p.fixed_lo, p.fixed_hi};
    case Axis::linear: return {0.0, kLinearHeadroom * largest_cap(g, p.cap, early)};
    case Axis::log: {
      const double top = kLogHeadroom * largest_cap(g, p.cap, early);
      return {top * std::pow(10.0, -kLogDecades), top};
    }
  }
  return {0.0, 1.0};
}

std::string clipped(int column, const Range& r) {
  return "(clip($" + std::to_string(column) + ", " + number(r.lo) + ", " + number(r.hi) + "))";
}

struct Columns {
  int x, lo, hi, mean, end_x, end_y;
};

// Where the label of a stop goes: to the right of its cross, or to its left (near the right edge).
enum class LabelSide { right, left };

// Stops in the right part of a time axis ending at `t_axis` are labelled on their left.
LabelSide side_on_time_axis(const FigureRun& r, double t_axis) {
  return r.t_final > 0.6 * t_axis ? LabelSide::left : LabelSide::right;
}

// How a panel draws the 5-95 % quantiles and where it says why a run stopped early.
struct PanelStyle {
  bool quantile_lines = false;  ///< thin lines in the run's colour and dash instead of filled bands
  bool stop_labels = true;      ///< a label beside each stop's cross (else the key says it, once)
};

// The plot command of one panel: the bands (or quantile lines) of every run first, then the mean
// lines, then a cross (and a label) where each early-stopped run stopped.
std::string plot_command(const FigureGroup& g, const std::string& kind, const Columns& c, const Range& y,
                         bool with_titles, const std::function<LabelSide(const FigureRun&)>& label_side,
                         const PanelStyle& panel_style = {}) {
  std::vector<std::string> bands, lines, stops;
  const std::string x = std::to_string(c.x);
  for (std::size_t i = 0; i < g.runs.size(); ++i) {
    const FigureRun& r = g.runs[i];
    const LineStyle style = line_style(r, i);
    const std::string colour = gnuplot_quoted(style.colour);
    const std::string data = gnuplot_quoted("data/" + r.stem + "." + kind + ".dat");
    if (!r.stopped_early && !panel_style.quantile_lines) {  // near a pole the bins are meaningless: no band
      bands.push_back(data + " using " + x + ":" + clipped(c.lo, y) + ":" + clipped(c.hi, y) +
                      " with filledcurves lc rgb " + colour + " notitle");
    } else if (!r.stopped_early) {
      for (const int q : {c.lo, c.hi}) {
        bands.push_back(data + " using " + x + ":" + clipped(q, y) + " with lines lw 0.5 dt " + style.dash +
                        " lc rgb " + colour + " notitle");
      }
    }
    lines.push_back(data + " using " + x + ":" + clipped(c.mean, y) + " with lines lw " +
                    (i == 0 ? "1.8" : "1.6") + " dt " + style.dash + " lc rgb " + colour +
                    (with_titles ? " title " + gnuplot_text(title_of(r, !panel_style.stop_labels)) : " notitle"));
    if (r.stopped_early) {
      const std::string end = gnuplot_quoted("data/" + r.stem + ".end.dat") + " using " + std::to_string(c.end_x) + ":" +
                              clipped(c.end_y, y);
      stops.push_back(end + " with points pt 2 ps 2.5 lw 2 lc rgb " + colour + " notitle");
      if (!panel_style.stop_labels) continue;
      const bool left = label_side(r) == LabelSide::left;
      stops.push_back(end + ":(" + gnuplot_label_column_text(r.label + ": " + r.stop) + ") with labels " +
                      (left ? "right offset -1.5,0.8" : "left offset 1.5,0.8") + " font ',9' tc rgb " + colour +
                      " notitle");
    }
  }
  std::string cmd = "plot ";
  bool first = true;
  for (const auto* list : {&bands, &lines, &stops}) {
    for (const auto& e : *list) {
      cmd += (first ? "" : ", \\\n     ") + e;
      first = false;
    }
  }
  return cmd + "\n";
}

std::string axis_settings(const Panel& panel, const Range& y) {
  std::string s = "set ylabel " + gnuplot_quoted(panel.label) + "\n";
  s += panel.axis == Axis::log ? "set logscale y\n" : "unset logscale y\n";
  return s + "set yrange [" + number(y.lo) + ":" + number(y.hi) + "]\n";
}

// fig. 3: six panels of one case, whose impacts spread the quantiles over decades: thin quantile
// lines (a filled band there covers the means), and the early stops said once, in the key.
const PanelStyle kFig3Style{true, false};

std::string fig3(const FigureGroup& g, bool early) {
  const std::string kind = early ? "early" : "full";
  const std::string stem = "fig3-" + g.egg + "-" + g.case_id + (early ? "-early" : "");
  std::ostringstream s;
  s << "# " << stem << ".png: the paper's fig. 3 quantities against time, " << g.egg << ", case " << g.case_id
    << (early ? " (first seconds)" : "") << ".\n"
    << "# Lines: means (gamma3, b/a: of each time bin; |F|, |M|, a, N: over 2 s around it) from data/*." << kind
    << ".dat; thin lines: 5-95 % quantiles.\n# Regenerate: gnuplot " << stem << ".gp\n"
    << kFig3Terminal << "\nset output " << gnuplot_quoted(stem + ".png") << "\n"
    << kBand << "\n" << kClip << "\nset grid\nset xlabel 't (s)'\nset format y '%g'\nset datafile missing 'NaN'\n";
  if (early) s << "set xrange [0:" << kEarlyWindow << "]\n";
  double t_axis = early ? kEarlyWindow : 0.0;
  if (!early)
    for (const auto& r : g.runs) t_axis = std::max(t_axis, r.t_final);
  const auto label_side = [t_axis](const FigureRun& r) { return side_on_time_axis(r, t_axis); };
  s << "set multiplot layout 3,2 margins 0.07,0.98,0.05,0.83 spacing 0.08,0.07 title "
    << gnuplot_text(g.egg + ", case " + g.case_id + ": " + g.description +
                      (early ? " (first " + std::to_string(static_cast<int>(kEarlyWindow)) + " s)" : ""))
    << " font ',13'\n";
  for (std::size_t p = 0; p < kPanels.size(); ++p) {
    const Panel& panel = kPanels[p];
    s << (p == 0 ? kKey : "unset key\n");
    const Range y = axis_range(g, panel, early);
    s << axis_settings(panel, y)
      << plot_command(g, kind, {FigureColumns::t, panel.lo, panel.hi, panel.mean, EndColumns::t, panel.end}, y, p == 0,
                      label_side, kFig3Style);
  }
  s << "unset multiplot\n";
  return s.str();
}

std::string fig2(const std::string& egg, const std::vector<const FigureGroup*>& groups) {
  const std::string stem = "fig2-" + egg;
  const Range y{-1.05, 1.05};
  std::ostringstream s;
  s << "# " << stem << ".png: the paper's fig. 2, gamma3 against |omega|^2, " << egg << ", one panel per case.\n"
    << "# Lines: the mean gamma3 of each time bin at the bin's mean |omega|^2; bands: 5-95 % quantiles of gamma3\n"
    << "# (data/*.full.dat). Regenerate: gnuplot " << stem << ".gp\n"
    << kFig2Terminal << "\nset output " << gnuplot_quoted(stem + ".png") << "\n"
    << kBand << "\n" << kClip << "\nset grid\nset datafile missing 'NaN'\n"
    << "set logscale x\nset format x '10^{%T}'\nset xlabel '|ω|^2 (1/s^2), log scale; time runs right to left'\n"
    << "set ylabel 'γ_3 = cos(nutation angle)'\nset yrange [-1.05:1.05]\n"
    << "set multiplot layout 1," << groups.size() << " margins 0.05,0.98,0.12,0.74 spacing 0.05,0 title "
    << gnuplot_text(egg + ": the paper's fig. 2") << " font ',13'\n";
  for (const FigureGroup* g : groups) {
    s << "set title " << gnuplot_text("case " + g->case_id + ": " + g->description) << "\n";
    s << (g == groups.front() ? kFig2Key : "unset key\n");
    s << plot_command(*g, "full",
                      {FigureColumns::omega_sq, FigureColumns::gamma3_lo, FigureColumns::gamma3_hi,
                       FigureColumns::gamma3_mean, EndColumns::omega_sq, EndColumns::gamma3},
                      y, g == groups.front(), [](const FigureRun&) { return LabelSide::left; });
  }
  s << "unset multiplot\n";
  return s.str();
}

std::string law_colour(const std::string& law, std::size_t index) {
  // Okabe-Ito colours, one per registered law.
  static const std::map<std::string, std::string> fixed = {
      {"exact", "#000000"},           {"pade-reconstructed", "#0072B2"}, {"pade-printed", "#D55E00"},
      {"moller-ellipsoidal", "#009E73"}, {"coulomb-decoupled", "#CC79A7"}, {"pade-printed-minor", "#E69F00"},
      {"exact-reference", "#56B4E9"},
  };
  if (const auto it = fixed.find(law); it != fixed.end()) return it->second;
  static const std::array<const char*, 4> others = {"#999999", "#F0E442", "#882255", "#44AA99"};
  return others[index % others.size()];
}

}  // namespace

LineStyle line_style(const FigureRun& run, std::size_t index) {
  return {run.baseline ? std::string("#7F7F7F") : law_colour(run.label, index), kDashes[index % kDashes.size()]};
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
    support::write_file_atomically(plots_dir / name, fig2(egg, of_egg));
    scripts.push_back(name);
    for (const FigureGroup* g : of_egg) {
      for (const bool early : {false, true}) {
        const std::string n3 = "fig3-" + g->egg + "-" + g->case_id + (early ? "-early" : "") + ".gp";
        support::write_file_atomically(plots_dir / n3, fig3(*g, early));
        scripts.push_back(n3);
      }
    }
  }
  return scripts;
}

}  // namespace frictionlab::dynamics::paper
