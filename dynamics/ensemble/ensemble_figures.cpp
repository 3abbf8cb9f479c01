#include "dynamics/ensemble/ensemble_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "dynamics/ensemble/feature_comparison.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {
namespace {

using support::gnuplot_escaped;
using support::gnuplot_quoted;
using support::gnuplot_text;

constexpr const char* kTerminal = "set encoding utf8\nset terminal png truecolor enhanced size %W%,%H% font 'DejaVuSans,10'";
// Laws in order: black for the reference, then colours and dash types that survive grayscale.
constexpr const char* kColours[] = {"#000000", "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"};
// Outcome classes and their colours (the classes of run_record.h).
const std::vector<std::pair<std::string, std::string>> kClasses = {
    {"pole+", "#4575b4"}, {"pole-", "#d73027"}, {"tilted", "#fee090"}, {"stopped", "#636363"}, {"failed", "#000000"}};
// The puck's (run_record.h: puck_outcome_class).
const std::vector<std::pair<std::string, std::string>> kPuckClasses = {
    {"together", "#1a9850"}, {"slip-first", "#4575b4"}, {"spin-first", "#d73027"}, {"moving", "#fee090"},
    {"rest", "#c2a5cf"},     {"stopped", "#636363"},    {"failed", "#000000"}};
const std::vector<std::pair<CellChange, std::string>> kChanges = {{CellChange::same, "#e0e0e0"},
                                                                  {CellChange::mixed, "#fdae61"},
                                                                  {CellChange::changed, "#d7191c"},
                                                                  {CellChange::chaotic, "#2c7bb6"}};

std::string terminal(int width, int height) {
  std::string t = kTerminal;
  t.replace(t.find("%W%"), 3, std::to_string(width));
  t.replace(t.find("%H%"), 3, std::to_string(height));
  return t;
}

std::string num(double x) {
  std::string s;
  if (std::isnan(x)) return "NaN";
  support::append_shortest(s, x);
  return s;
}

// Cell edges: midpoints between grid values (geometric on a log axis), extended at the ends.
std::vector<double> edges(const std::vector<double>& v, bool log) {
  std::vector<double> e(v.size() + 1);
  const auto mid = [&](double a, double b) { return log ? std::sqrt(a * b) : 0.5 * (a + b); };
  if (v.size() == 1) {
    e[0] = log ? v[0] / 1.1 : v[0] - 0.5;
    e[1] = log ? v[0] * 1.1 : v[0] + 0.5;
    return e;
  }
  for (std::size_t i = 1; i < v.size(); ++i) e[i] = mid(v[i - 1], v[i]);
  e[0] = log ? v[0] * v[0] / e[1] : 2 * v[0] - e[1];
  e[v.size()] = log ? v.back() * v.back() / e[v.size() - 1] : 2 * v.back() - e[v.size() - 1];
  return e;
}

// One map's data: x y xlo xhi ylo yhi value per cell.
std::string map_data(const GridAxes& a, const std::vector<double>& value) {
  const auto ex = edges(a.x, a.x_log);
  const auto ey = edges(a.y, a.y_log);
  std::string s = "# " + a.x_key + " " + a.y_key + " xlo xhi ylo yhi value\n";
  for (std::size_t i = 0; i < a.x.size(); ++i)
    for (std::size_t j = 0; j < a.y.size(); ++j) {
      s += num(a.x[i]) + " " + num(a.y[j]) + " " + num(ex[i]) + " " + num(ex[i + 1]) + " " + num(ey[j]) + " " +
           num(ey[j + 1]) + " " + num(value[i * a.y.size() + j]) + "\n";
    }
  return s;
}

struct Panel {
  std::string title;
  std::string data;  // file name
};

// A multiplot of heat maps, `palette` the palette/cb settings; `title` in gnuplot's enhanced-text
// markup (user text in it escaped), panel titles and axis keys as they are.
std::string map_script(const std::string& stem, const std::string& title, const GridAxes& a, const std::vector<Panel>& panels,
                       const std::string& palette) {
  const int cols = panels.size() <= 1 ? 1 : 2;
  const int rows = static_cast<int>((panels.size() + 1) / 2);
  std::ostringstream s;
  s << "# " << stem << ".png: " << title << ". Regenerate: gnuplot " << stem << ".gp\n"
    << terminal(cols * 620, rows * 430 + 60) << "\nset output " << gnuplot_quoted(stem + ".png") << "\n"
    << "set style fill solid 1.0 noborder\nset datafile missing 'NaN'\nset tics out\nset rmargin 14\n"
    << "set xlabel " << gnuplot_text(a.x_key) << "\nset ylabel " << gnuplot_text(a.y_key) << "\n"
    << (a.x_log ? "set logscale x\n" : "") << (a.y_log ? "set logscale y\n" : "") << palette
    << "set multiplot layout " << rows << "," << cols << " title " << gnuplot_quoted(title) << " font ',12'\n";
  const auto ex = edges(a.x, a.x_log);
  const auto ey = edges(a.y, a.y_log);
  for (const auto& p : panels) {
    const auto [x0, x1] = std::minmax_element(ex.begin(), ex.end());
    const auto [y0, y1] = std::minmax_element(ey.begin(), ey.end());
    s << "set title " << gnuplot_text(p.title) << "\nset xrange [" << num(*x0) << ":" << num(*x1) << "]\nset yrange ["
      << num(*y0) << ":" << num(*y1) << "]\n"
      << "plot " << gnuplot_quoted(p.data) << " using 1:2:3:4:5:6 with boxxyerror lc rgb '#bdbdbd' notitle, \\\n"
      << "     " << gnuplot_quoted(p.data) << " using 1:2:3:4:5:6:7 with boxxyerror lc palette notitle\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

// A discrete palette of `colours` at 0, 1, ..., n-1, labelled.
std::string discrete_palette(const std::vector<std::pair<std::string, std::string>>& named) {
  std::ostringstream s;
  s << "set palette maxcolors " << named.size() << "\nset palette defined (";
  for (std::size_t i = 0; i < named.size(); ++i) s << (i ? ", " : "") << i << " " << gnuplot_quoted(named[i].second);
  s << ")\nset cbrange [-0.5:" << named.size() - 0.5 << "]\nset cbtics (";
  for (std::size_t i = 0; i < named.size(); ++i) s << (i ? ", " : "") << gnuplot_text(named[i].first) << " " << i;
  s << ")\n";
  return s.str();
}

class Writer {
 public:
  Writer(std::filesystem::path dir, bool draw) : dir_(std::move(dir)), draw_(draw) {}
  void data(const std::string& name, const std::string& text) { support::write_file_atomically(dir_ / name, text); }
  void figure(const std::string& stem, const std::string& script) {
    support::write_file_atomically(dir_ / (stem + ".gp"), script);
    if (!draw_) return;
    const support::GnuplotRun run = support::run_gnuplot(dir_, stem + ".gp", stem + ".log");
    if (run.ok) {
      out.drawn.push_back(dir_ / (stem + ".png"));
    } else {
      out.errors.push_back(stem + ".png not drawn: " + run.message);
    }
  }
  FiguresOutcome out;

 private:
  std::filesystem::path dir_;
  bool draw_;
};

void divergence_figure(Writer& w, const std::string& title, const std::vector<std::string>& laws,
                       const std::vector<RunRecord>& rows) {
  // ECDF per law (vs the reference on its replica) and for the floor, over the compared runs.
  std::vector<std::pair<std::string, std::vector<double>>> curves;
  std::vector<long> compared;
  for (std::size_t i = 0; i <= laws.size(); ++i) {
    const bool floor = i == laws.size();
    if (i == 0) continue;
    std::vector<double> t;
    long n = 0;
    for (const auto& r : rows) {
      const bool mine = floor ? (r.law == laws.front() && r.diverge_ref.rfind("replica:", 0) == 0)
                              : (r.law == laws[i] && r.diverge_ref == laws.front());
      if (!mine || std::isnan(r.diverge_horizon)) continue;
      ++n;
      if (!std::isnan(r.t_diverge)) t.push_back(r.t_diverge);
    }
    std::sort(t.begin(), t.end());
    curves.emplace_back(floor ? "floor: " + laws.front() + " vs its other replica" : laws[i] + " vs " + laws.front(), t);
    compared.push_back(n);
  }
  std::ostringstream plot;
  bool any = false;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const auto& [name, t] = curves[c];
    if (t.empty() || compared[c] == 0) continue;
    std::string d = "# t_diverge (s), share of the " + std::to_string(compared[c]) + " compared runs parted by then\n";
    for (std::size_t k = 0; k < t.size(); ++k)
      d += num(t[k]) + " " + num(static_cast<double>(k + 1) / static_cast<double>(compared[c])) + "\n";
    const std::string file = "divergence-" + std::to_string(c) + ".dat";
    w.data(file, d);
    const bool floor = c + 1 == curves.size();
    plot << (any ? ", \\\n     " : "plot ") << gnuplot_quoted(file) << " using 1:2 with steps lw 2 dt "
         << (floor ? 1 : static_cast<int>(c % 4) + 2) << " lc rgb "
         << gnuplot_quoted(floor ? kColours[0] : kColours[(c + 1) % 7]) << " title " << gnuplot_text(name);
    any = true;
  }
  if (!any) return;
  std::ostringstream s;
  s << "# divergence.png: " << title << ": when runs part (|Δγ3| > 0.05). Regenerate: gnuplot divergence.gp\n"
    << terminal(900, 560) << "\nset output 'divergence.png'\nset grid\nset logscale x\n"
    << "set xlabel 'time at which the two runs part: |Δγ_3| > 0.05 (s), log scale'\n"
    << "set ylabel 'share of compared runs parted'\nset yrange [0:1.02]\nset key right bottom opaque box\n"
    << "set title " << gnuplot_text(title + ": divergence times against the chaos floor") << "\n"
    << plot.str() << "\n";
  w.figure("divergence", s.str());
}

// The angle between the axes against time: per law (against the reference on its replica) and
// for the floor, the median and quartiles over the runs compared at each time of kAxisAngleTimes.
void axis_divergence_figure(Writer& w, const std::string& title, const std::vector<std::string>& laws,
                            const std::vector<RunRecord>& rows) {
  std::ostringstream plot;
  bool any = false;
  for (std::size_t i = 1; i <= laws.size(); ++i) {
    const bool floor = i == laws.size();
    std::string d = "# t (s), then the angle between the axes (degrees): 25 %, median, 75 % over the runs, runs\n";
    bool rows_written = false;
    for (std::size_t k = 0; k < kAxisAngleTimes.size(); ++k) {
      std::vector<double> a;
      for (const auto& r : rows) {
        const bool mine = floor ? (r.law == laws.front() && r.diverge_ref.rfind("replica:", 0) == 0)
                                : (r.law == laws[i] && r.diverge_ref == laws.front());
        if (mine && k < r.axis_angle_deg.size() && std::isfinite(r.axis_angle_deg[k])) a.push_back(r.axis_angle_deg[k]);
      }
      if (a.empty()) continue;
      d += num(kAxisAngleTimes[k]) + " " + num(quantile(a, 0.25)) + " " + num(quantile(a, 0.5)) + " " +
           num(quantile(a, 0.75)) + " " + std::to_string(a.size()) + "\n";
      rows_written = true;
    }
    if (!rows_written) continue;
    const std::string file = "axis_divergence-" + std::to_string(i) + ".dat";
    w.data(file, d);
    const std::string colour = gnuplot_quoted(floor ? "#7F7F7F" : kColours[i % 7]);
    const std::string dash = floor ? "1" : std::to_string(static_cast<int>(i % 4) + 2);
    const std::string name = floor ? "floor: " + laws.front() + " vs its other replica" : laws[i] + " vs " + laws.front();
    // Each curve its own point type as well as its colour and dash: the figure reads in grayscale.
    const std::string point = floor ? "1" : std::to_string(4 + 2 * static_cast<int>(i % 5));
    plot << (any ? ", \\\n     " : "plot ") << gnuplot_quoted(file) << " using 1:3 with linespoints lw 2.5 pt " << point
         << " ps 1.1 dt " << dash << " lc rgb " << colour << " title " << gnuplot_text(name + " (median; thin: quartiles)");
    for (const int q : {2, 4}) {
      plot << ", \\\n     " << gnuplot_quoted(file) << " using 1:" << q << " with lines lw 0.8 dt " << dash
           << " lc rgb " << colour << " notitle";
    }
    any = true;
  }
  if (!any) return;
  std::ostringstream s;
  s << "# axis_divergence.png: " << title << ": the angle between the runs' symmetry axes. Regenerate: gnuplot "
    << "axis_divergence.gp\n"
    << terminal(900, 560) << "\nset output 'axis_divergence.png'\nset grid\nset logscale xy\nset format y '10^{%T}'\n"
    << "set xlabel 't (s), log scale'\nset ylabel 'angle between the axes (degrees)'\n"
    << "set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb '#555555'\n"
    << "set key left top opaque box\nset title " << gnuplot_text(title + ": distance from the reference against the chaos floor")
    << "\n" << plot.str() << "\n";
  w.figure("axis_divergence", s.str());
}

// The shadow laws' errors along the reference's runs: per law, the distribution over the runs of
// each run's median |dF| per kN (thick) and of its largest (thin, the same colour and dash).
void shadow_figure(Writer& w, const std::string& title, const std::vector<std::string>& shadow_laws,
                   const std::vector<RunRecord>& rows) {
  std::ostringstream plot;
  bool any = false;
  for (std::size_t l = 0; l < shadow_laws.size(); ++l) {
    std::vector<double> typical;
    std::vector<double> worst;
    for (const auto& r : rows) {
      if (l >= r.shadow.size() || !r.shadow[l].evaluated()) continue;
      if (r.shadow[l].F_median > 0.0) typical.push_back(r.shadow[l].F_median);
      if (r.shadow[l].F_max > 0.0) worst.push_back(r.shadow[l].F_max);
    }
    long runs = 0;
    for (const auto& r : rows) runs += l < r.shadow.size() && r.shadow[l].evaluated() ? 1 : 0;
    if (runs == 0) continue;
    const std::string colour = gnuplot_quoted(kColours[(l + 1) % 7]);
    const std::string dash = std::to_string(static_cast<int>(l % 4) + 1);
    for (const bool thick : {true, false}) {
      std::vector<double>& v = thick ? typical : worst;
      if (v.empty()) continue;
      std::sort(v.begin(), v.end());
      std::string d = std::string("# ") + (thick ? "median" : "largest") + " |dF|/(kN) along a run, share of the " +
                      std::to_string(runs) + " reference runs at or below it\n";
      for (std::size_t k = 0; k < v.size(); ++k)
        d += num(v[k]) + " " + num(static_cast<double>(k + 1) / static_cast<double>(runs)) + "\n";
      const std::string file = "shadow_errors-" + std::to_string(l) + (thick ? "-median" : "-max") + ".dat";
      w.data(file, d);
      plot << (any ? ", \\\n     " : "plot ") << gnuplot_quoted(file) << " using 1:2 with steps lw "
           << (thick ? "2.5" : "1") << " dt " << dash << " lc rgb " << colour << " title "
           << gnuplot_text(shadow_laws[l] + (thick ? ": median along the run" : ": largest along the run"));
      any = true;
    }
  }
  if (!any) return;
  std::ostringstream s;
  s << "# shadow_errors.png: " << title << ": the shadow laws' force error along the reference's runs. Regenerate: "
    << "gnuplot shadow_errors.gp\n"
    << terminal(1150, 560) << "\nset output 'shadow_errors.png'\nset grid\nset logscale x\nset format x '10^{%T}'\n"
    << "set xlabel '|ΔF|/(kN) along a run of the reference law (log scale)'\n"
    << "set ylabel 'share of the reference runs at or below'\nset yrange [0:1.02]\n"
    << "set key outside right top vertical box\n"
    << "set title " << gnuplot_text(title + ": each law's friction force error along the reference's motion") << "\n"
    << plot.str() << "\n";
  w.figure("shadow_errors", s.str());
}

double t_vertical_of(const RunRecord& r) { return r.t_vertical; }
double final_gamma3_of(const RunRecord& r) { return r.final_gamma3; }
double log10_ratio_of(const RunRecord& r) {
  return r.puck.terminal_ratio > 0.0 ? std::log10(r.puck.terminal_ratio) : std::numeric_limits<double>::quiet_NaN();
}
double lateral_mm_of(const RunRecord& r) { return 1e3 * r.puck.path_lateral; }

void map_figures(Writer& w, const std::string& title, const std::vector<std::string>& laws,
                 const std::vector<RunRecord>& rows, const OutcomeMap& m, RunModel model) {
  const GridAxes& a = m.axes;
  const std::string markup = gnuplot_escaped(title);  // the study's name, in the titles' markup
  const auto& classes = model == RunModel::puck ? kPuckClasses : kClasses;
  // Outcome classes.
  {
    std::vector<Panel> panels;
    for (const auto& lm : m.laws) {
      std::vector<double> code(m.cells(), std::numeric_limits<double>::quiet_NaN());
      for (std::size_t c = 0; c < m.cells(); ++c)
        for (std::size_t k = 0; k < classes.size(); ++k)
          if (lm.majority_class[c] == classes[k].first) code[c] = static_cast<double>(k);
      const std::string file = "map-final_class-" + lm.law + ".dat";
      w.data(file, map_data(a, code));
      panels.push_back({lm.law, file});
    }
    w.figure("map-final_class", map_script("map-final_class", markup + ": where the runs end (most replicas)", a, panels,
                                           discrete_palette(classes)));
  }
  // Medians of two features.
  struct Mapped {
    const char* name;
    const char* what;
    double (*value)(const RunRecord&);
    const char* palette;
  };
  const auto draw_medians = [&](const auto& mapped) {
    for (const auto& f : mapped) {
      std::vector<Panel> panels;
      for (const auto& law : laws) {
        const std::string file = std::string("map-") + f.name + "-" + law + ".dat";
        w.data(file, map_data(a, cell_medians(a, law, rows, f.value)));
        panels.push_back({law, file});
      }
      w.figure(std::string("map-") + f.name,
               map_script(std::string("map-") + f.name, markup + ": " + f.what, a, panels, f.palette));
    }
  };
  if (model == RunModel::puck) {
    // The ratio at the first stop on a log scale, 1e-3 .. 1e3 (beyond: saturated); the path's end
    // across the initial velocity, -3 .. 3 mm (the exact law's range on a 2:1 plate; beyond:
    // saturated), one colour scale for every law.
    const Mapped mapped[] = {
        {"log10_terminal_ratio", "log10 U/(a|Ω|) at the first stop (grey: none)", &log10_ratio_of,
         "set palette defined (-3 '#4575b4', 0 '#ffffbf', 3 '#d73027')\nset cbrange [-3:3]\n"},
        {"path_lateral", "end of the path across the initial velocity, mm (to its left; grey: none)", &lateral_mm_of,
         "set palette defined (-3 '#4575b4', 0 '#f7f7f7', 3 '#d73027')\nset cbrange [-3:3]\n"},
    };
    draw_medians(mapped);
  }
  // The time to the vertical on a log colour scale over the values there are (1 to 1000 s if none).
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0.0;
  for (const auto& r : rows)
    if (ended_normally(r) && r.t_vertical > 0.0) {
      lo = std::min(lo, r.t_vertical);
      hi = std::max(hi, r.t_vertical);
    }
  if (!(hi > lo)) {
    lo = 1.0;
    hi = 1000.0;
  }
  const std::string vertical_palette =
      "set palette rgb 33,13,10\nset logscale cb\nset cbrange [" + num(lo) + ":" + num(hi) + "]\nset cblabel 't (s)'\n";
  const Mapped mapped[] = {
      {"t_vertical", "median time to the vertical, s (grey: never)", &t_vertical_of, vertical_palette.c_str()},
      {"final_gamma3", "median final γ_3 (grey: no run ended normally)", &final_gamma3_of,
       "set palette defined (-1 '#d73027', 0 '#ffffbf', 1 '#4575b4')\nset cbrange [-1:1]\n"},
  };
  if (model == RunModel::body) draw_medians(mapped);
  // Where a law changes the outcome.
  if (m.laws.size() > 1) {
    std::vector<Panel> panels;
    std::vector<std::pair<std::string, std::string>> named;
    for (const auto& [c, colour] : kChanges) named.emplace_back(std::string(to_string(c)), colour);
    for (std::size_t l = 1; l < m.laws.size(); ++l) {
      std::vector<double> code(m.cells(), std::numeric_limits<double>::quiet_NaN());
      for (std::size_t c = 0; c < m.cells(); ++c)
        if (m.laws[l].change[c] != CellChange::missing) code[c] = static_cast<double>(m.laws[l].change[c]);
      const std::string file = "map-changes-" + m.laws[l].law + ".dat";
      w.data(file, map_data(a, code));
      const auto n = m.count(l);
      panels.push_back({m.laws[l].law + " vs " + laws.front() + ": changed " + std::to_string(n[2]) + ", mixed " +
                            std::to_string(n[1]) + ", chaotic " + std::to_string(n[3]) + " of " + std::to_string(m.cells()),
                        file});
    }
    w.figure("map-changes", map_script("map-changes", markup + ": where does a law change the outcome class?", a, panels,
                                       discrete_palette(named)));
  }
}

}  // namespace

FiguresOutcome write_figures(const std::filesystem::path& dir, const std::string& title, const std::vector<std::string>& laws,
                             const std::vector<RunRecord>& rows, const std::optional<OutcomeMap>& map, bool draw,
                             RunModel model, const std::vector<std::string>& shadow_laws) {
  const std::filesystem::path figures = dir / "figures";
  std::error_code ec;
  std::filesystem::create_directories(figures, ec);
  if (ec) throw support::OutputError("cannot create '" + figures.string() + "': " + ec.message());
  Writer w(figures, draw);
  if (model == RunModel::body) {
    divergence_figure(w, title, laws, rows);
    axis_divergence_figure(w, title, laws, rows);
  }
  shadow_figure(w, title, shadow_laws, rows);
  if (map) map_figures(w, title, laws, rows, *map, model);
  return w.out;
}

}  // namespace frictionlab::dynamics::ensemble
