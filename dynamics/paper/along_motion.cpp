#include "dynamics/paper/along_motion.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "dynamics/core/motion_phase.h"
#include "dynamics/paper/divergence.h"
#include "dynamics/paper/figure_data.h"
#include "dynamics/paper/figure_scripts.h"
#include "dynamics/paper/run_record.h"
#include "friction/registry.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

constexpr double kHigh = 0.95;
constexpr double kDegree = 180.0 / std::numbers::pi;
// The outputs of figure (a), in shadow.csv's order per law, and their axis labels.
const std::vector<std::string> kOutputs = {"dF1", "dF2", "dM", "dP"};
const std::vector<std::string> kOutputLabels = {"|ΔF_1| / kN", "|ΔF_2| / kN", "|ΔM| / kNa", "|ΔP|, W"};
// Shading of the phases (motion_phase.h codes), grey levels that leave the lines legible.
const std::map<int, std::string> kPhaseShade = {{static_cast<int>(MotionPhase::airborne), "#D4D4D4"},
                                                {static_cast<int>(MotionPhase::bouncing), "#D4D4D4"},
                                                {static_cast<int>(MotionPhase::rolling_spin), "#EDEDED"},
                                                {static_cast<int>(MotionPhase::near_rest), "#BDBDBD"}};

std::string num(double x, int digits = 3) { return support::significant(support::without_negative_zero(x), digits); }

// One CSV header line split into fields (RFC 4180 quotes).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

struct ShadowTable {
  std::vector<std::string> laws;               // in column order
  std::vector<std::vector<double>> columns;    // by shadow.csv column
  std::map<std::string, std::size_t> index;    // column name -> position
};

ShadowTable read_shadow_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read '" + file.string() + "'");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("'" + file.string() + "' is empty");
  ShadowTable t;
  const std::vector<std::string> names = csv_fields(line);
  t.columns.resize(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    t.index[names[i]] = i;
    if (names[i].rfind("dF1[", 0) == 0 && names[i].back() == ']') t.laws.push_back(names[i].substr(4, names[i].size() - 5));
  }
  for (const char* needed : {"t", "phase"}) {
    if (!t.index.count(needed)) throw std::runtime_error("'" + file.string() + "' has no column " + needed);
  }
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (!std::getline(row, cell, ',')) throw std::runtime_error("'" + file.string() + "': a short row");
      t.columns[i].push_back(cell == "nan" || cell == "-nan" ? kNaN : std::stod(cell));
    }
  }
  return t;
}

// The law specs of a .shadow.dat from its header line ("# t phase dF1[LAW]:med ...").
std::vector<std::string> shadow_data_laws(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::istringstream words(line);
  std::vector<std::string> laws;
  for (std::string w; words >> w;) {
    if (w.rfind("dF1[", 0) == 0 && w.size() > 9 && w.compare(w.size() - 5, 5, "]:med") == 0)
      laws.push_back(w.substr(4, w.size() - 9));
  }
  return laws;
}

std::string shadow_data_name(const std::string& stem) { return stem + ".shadow.dat"; }
std::string divergence_data_name(const std::string& group) { return group + ".divergence.dat"; }

const RunResult* find_run(const std::vector<const RunResult*>& group, bool baseline, const std::string& law = "") {
  for (const RunResult* r : group) {
    if (r->spec.baseline != baseline) continue;
    if (baseline || (law.empty() ? friction::canonical_law_spec(r->spec.law) == kReferenceLaw : r->spec.law == law))
      return r;
  }
  return nullptr;
}

std::string terminal(int height) {
  return "set encoding utf8\nset terminal pngcairo enhanced size 1200," + std::to_string(height) +
         " font 'DejaVuSans,10'\n";
}

std::string case_title(const RunResult& ref) {
  return ref.spec.egg + ", case " + ref.spec.case_id;
}

std::string end_of(const RunResult& r) {
  return std::string(to_string(r.summary.reason)) + " at t = " + num(r.summary.t_final, 4) + " s";
}

// Figure (a): the shadow errors along the reference run.
std::string shadow_script(const RunResult& ref, const std::string& stem, const std::vector<std::string>& laws,
                          const std::filesystem::path& data_file) {
  // The phase shading: contiguous bins of one dominant phase, read back from the data.
  std::ifstream in(data_file);
  std::string line;
  std::getline(in, line);
  std::vector<std::pair<double, int>> bins;  // bin centre, phase
  std::vector<double> ranges(kOutputs.size(), 0.0);  // the largest value of each panel
  while (std::getline(in, line)) {
    std::istringstream row(line);
    double t = 0.0, phase = 0.0;
    row >> t >> phase;
    bins.emplace_back(t, static_cast<int>(phase));
    for (std::size_t c = 0; row; ++c) {
      std::string cell;
      if (!(row >> cell)) break;
      const double v = cell == "NaN" ? 0.0 : std::stod(cell);
      if (std::isfinite(v)) ranges[(c / 2) % kOutputs.size()] = std::max(ranges[(c / 2) % kOutputs.size()], v);
    }
  }
  const double t_end = ref.summary.t_final;
  const double half = bins.size() > 1 ? 0.5 * (bins[1].first - bins[0].first) : 0.5 * t_end;
  std::ostringstream s;
  s << terminal(1200) << "set output " << support::gnuplot_quoted("shadow-" + ref.spec.group() + ".png") << "\n";
  s << "set multiplot layout 4,1 margins 0.08,0.97,0.06,0.9 spacing 0,0.04 title "
    << support::gnuplot_text(case_title(ref) + ": each law's friction minus " + ref.spec.law + "'s at the " +
                             ref.spec.law + " run's own contacts (it ends " + end_of(ref) + ")")
    << " font ',12'\n";
  s << "set xrange [0:" << support::shortest(t_end) << "]\nset logscale y\nset format y '10^{%T}'\n"
    << "set grid ytics lc rgb '#C8C8C8'\nset lmargin 12\nset rmargin 4\n";
  int object = 1;
  for (std::size_t i = 0; i < bins.size();) {
    std::size_t j = i;
    while (j + 1 < bins.size() && bins[j + 1].second == bins[i].second) ++j;
    if (const auto shade = kPhaseShade.find(bins[i].second); shade != kPhaseShade.end()) {
      s << "set object " << object++ << " rect from " << support::shortest(std::max(0.0, bins[i].first - half))
        << ", graph 0 to " << support::shortest(bins[j].first + half) << ", graph 1 behind fc rgb '"
        << shade->second << "' fs solid 1.0 noborder\n";
    }
    i = j + 1;
  }
  const std::string data = support::gnuplot_quoted("data/" + shadow_data_name(stem));
  for (std::size_t k = 0; k < kOutputs.size(); ++k) {
    s << "set ylabel " << support::gnuplot_quoted(kOutputLabels[k]) << "\n";
    s << (k == 0 ? "set key at screen 0.5, screen 0.945 center top horizontal font ',10' samplen 4 width -2\n"
                 : "unset key\n");
    if (k + 1 == kOutputs.size()) {
      s << "set xlabel " << support::gnuplot_quoted("t, s      (shading: white sliding · light grey rolling with spin · "
                                                    "grey bouncing or in the air · dark grey near rest)")
        << "\n";
    } else {
      s << "unset xlabel\n";
    }
    // Eight decades below the largest value drawn: the approach to rest takes every error to 0.
    const double top = ranges[k];
    if (top > 0.0) {
      s << "set yrange [" << support::shortest(top * 1e-8) << ":" << support::shortest(top * 3.0) << "]\n";
    } else {
      s << "set yrange [*:*]\n";
    }
    s << "plot ";
    for (std::size_t l = 0; l < laws.size(); ++l) {
      FigureRun run;
      run.label = laws[l];
      const LineStyle style = line_style(run, l + 1);  // index 0 is the reference's own style
      const std::size_t median = 3 + 8 * l + 2 * k;  // gnuplot columns: t, phase, then 8 per law
      if (l > 0) s << ", \\\n     ";
      s << data << " using 1:" << median << " with lines lw 2 dt " << style.dash << " lc rgb '" << style.colour
        << "' title " << support::gnuplot_text(laws[l] + " (median; thin: 95 %)") << ", \\\n     " << data
        << " using 1:" << median + 1 << " with lines lw 0.7 dt " << style.dash << " lc rgb '" << style.colour
        << "' notitle";
    }
    s << "\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

// Figure (b): distances from the reference against the chaos floor's.
std::string divergence_script(const RunResult& ref, const std::vector<const RunResult*>& laws,
                              const RunResult* floor, const std::string& data_name) {
  std::ostringstream s;
  s << terminal(640) << "set output " << support::gnuplot_quoted("divergence-" + ref.spec.group() + ".png") << "\n";
  s << "set title " << support::gnuplot_text(case_title(ref) + ": angle between each run's symmetry axis and the " +
                                             ref.spec.law + " run's (world axes)")
    << "\n";
  // Log time: the laws part within seconds, the runs last minutes.
  const double first = ref.t.size() > 1 ? ref.t[1] : 0.01;
  s << "set logscale xy\nset format y '10^{%T}'\nset yrange [1e-10:300]\nset xrange [" << support::shortest(first)
    << ":" << support::shortest(std::max(ref.summary.t_final, 2.0 * first)) << "]\nset xlabel 't, s'\n"
    << "set ylabel 'angle between the axes, degrees'\nset grid xtics ytics lc rgb '#C8C8C8'\n"
    << "set key bottom right font ',10' samplen 4 box opaque\n"
    << "set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead dt 3 lc rgb '#555555'\n"
    << "set label 1 '1°: parted' at graph 0.01, first 1.6 left font ',9' tc rgb '#555555'\n";
  const std::string data = support::gnuplot_quoted("data/" + data_name);
  s << "plot ";
  int column = 2;
  if (floor) {
    s << data << " using 1:" << column++ << " with lines lw 2.5 dt 1 lc rgb '#9A9A9A' title "
      << support::gnuplot_text("chaos floor: " + floor->spec.label + " against " + ref.spec.law);
  }
  for (std::size_t l = 0; l < laws.size(); ++l) {
    FigureRun run;
    run.label = laws[l]->spec.label;
    const LineStyle style = line_style(run, l + 1);
    if (floor || l > 0) s << ", \\\n     ";
    s << data << " using 1:" << column++ << " with lines lw 1.6 dt " << style.dash << " lc rgb '" << style.colour
      << "' title " << support::gnuplot_text(laws[l]->spec.label);
  }
  s << "\n";
  return s.str();
}

// The distance series of the figure's data: on the reference's grid, NaN past a run's end.
void write_divergence_data(const std::filesystem::path& file, const RunResult& ref,
                           const std::vector<DistanceSeries>& series) {
  std::string out = "# t, then the angle (degrees) from the reference run: the floor (if any), then each law\n";
  for (std::size_t i = 0; i < ref.t.size(); ++i) {
    support::append_shortest(out, ref.t[i]);
    for (const DistanceSeries& d : series) {
      out += ' ';
      out += i < d.angle.size() ? support::shortest(d.angle[i] * kDegree) : std::string("NaN");
    }
    out += '\n';
  }
  support::write_file_atomically(file, out);
}

std::string parting_text(double t, const RunResult& run) {
  if (!std::isnan(t)) return num(t, 3) + " s";
  return run.ended_normally() ? "not by " + num(run.summary.t_final, 4) + " s"
                              : "– (its run stopped at " + num(run.summary.t_final, 4) + " s: " +
                                    std::string(to_string(run.summary.reason)) + ")";
}

// One law's row of the table (c).
std::string table_row(const RunResult& run, const support::Json* stats, double run_work, const DistanceSeries& d,
                      const std::string& floor_text) {
  std::ostringstream row;
  row << "| `" << run.spec.label << "` | ";
  if (stats) {
    const auto& contact = (*stats)["errors"]["contact"];
    const auto value = [](const support::Json& v) { return v.is_number() ? num(v.get<double>()) : std::string("–"); };
    const double dE = (*stats)["difference_J"].get<double>();
    row << value(contact["F"]["median"]) << " | " << value(contact["F"]["p95"]) << " | " << value(contact["F"]["max"])
        << " | " << value(contact["M"]["median"]) << " | " << value(contact["M"]["max"]) << " | " << num(dE) << " ("
        << num(100.0 * dE / run_work, 2) << " %) | " << (*stats)["failures"].get<long>() << " | ";
  } else {
    row << "– | – | – | – | – | – | – | ";
  }
  row << parting_text(parting_time(d), run) << " | "
      << floor_text << " |\n";
  return row.str();
}

}  // namespace

void write_shadow_figure_data(const std::filesystem::path& shadow_csv, const std::filesystem::path& dir,
                              const std::string& stem) {
  const ShadowTable table = read_shadow_csv(shadow_csv);
  const std::vector<double>& t = table.columns[table.index.at("t")];
  const std::vector<double>& phase = table.columns[table.index.at("phase")];
  std::string out = "# t phase";
  for (const std::string& law : table.laws) {
    for (const std::string& o : kOutputs) out += " " + o + "[" + law + "]:med " + o + "[" + law + "]:p95";
  }
  out += "\n";
  const double t_end = t.empty() ? 0.0 : t.back();
  const double width = t_end / kShadowBins;
  std::size_t row = 0;
  for (int b = 0; b < kShadowBins && width > 0.0; ++b) {
    const double hi = (b + 1 == kShadowBins) ? std::numeric_limits<double>::infinity() : (b + 1) * width;
    std::size_t end = row;
    while (end < t.size() && t[end] < hi) ++end;
    std::map<int, int> phases;
    for (std::size_t i = row; i < end; ++i) ++phases[static_cast<int>(phase[i])];
    const int dominant = phases.empty() ? 0
                                        : std::max_element(phases.begin(), phases.end(), [](const auto& x, const auto& y) {
                                            return x.second < y.second;
                                          })->first;
    support::append_shortest(out, (b + 0.5) * width);
    out += " " + std::to_string(dominant);
    for (const std::string& law : table.laws) {
      for (const std::string& o : kOutputs) {
        const std::vector<double>& c = table.columns[table.index.at(o + "[" + law + "]")];
        std::vector<double> values;
        for (std::size_t i = row; i < end; ++i) {
          if (phase[i] != static_cast<int>(MotionPhase::airborne) && std::isfinite(c[i])) values.push_back(std::abs(c[i]));
        }
        for (const double q : {0.5, kHigh}) {
          out += ' ';
          out += values.empty() ? std::string("NaN") : support::shortest(quantile(values, q));
        }
      }
    }
    out += '\n';
    row = end;
  }
  std::filesystem::create_directories(dir);
  support::write_file_atomically(dir / shadow_data_name(stem), out);
}

AlongMotion write_along_motion(const std::filesystem::path& plots_dir, const std::vector<RunResult>& results) {
  AlongMotion out;
  std::vector<std::vector<const RunResult*>> groups;
  for (const RunResult& r : results) {
    if (!r.executed) continue;
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const auto& g) { return g.front()->spec.group() == r.spec.group(); });
    if (it == groups.end()) {
      groups.push_back({&r});
    } else {
      it->push_back(&r);
    }
  }
  std::ostringstream report;
  report << "## The error along the motion\n\n"
         << "Each compared law evaluated at the `" << kReferenceLaw
         << "` run's own contact states (its shadow laws: `shadow.csv` beside it, statistics in its "
            "`summary.json`), and each law's own run against the `"
         << kReferenceLaw
         << "` run. Errors: `|ΔF|` is the tangential force's error as a vector per `kN` (`k·N`, the friction "
            "coefficient times the normal force), `|ΔM|` the moment's per `kNa` (ΔF/kN and ΔM/kNa in the tables); typical (median) and "
            "worst (95 % and largest) over the contact states of the run, weighted by time. `ΔE`: the energy "
            "the law would have dissipated more along the same path (share of the run's friction work). Parts: "
            "when its symmetry axis is first 1° from the `"
         << kReferenceLaw << "` run's, against when the chaos floor's is (the reference rerun with tolerances ×0.1).\n\n";
  for (const auto& group : groups) {
    const RunResult* ref = find_run(group, false);
    if (!ref) continue;
    const RunResult* floor = find_run(group, true);
    std::vector<const RunResult*> laws;
    for (const RunResult* r : group) {
      if (!r->spec.baseline && r != ref) laws.push_back(r);
    }
    const std::string stem = plot_data_stem(ref->spec);
    // (b): the distances.
    std::vector<DistanceSeries> series;
    const DistanceSeries floor_d = floor ? axis_distance(ref->t, ref->axis, floor->t, floor->axis) : DistanceSeries{};
    if (floor) series.push_back(floor_d);
    for (const RunResult* r : laws) series.push_back(axis_distance(ref->t, ref->axis, r->t, r->axis));
    const std::string data_name = divergence_data_name(ref->spec.group());
    write_divergence_data(plots_dir / "data" / data_name, *ref, series);
    const std::string divergence = "divergence-" + ref->spec.group() + ".gp";
    support::write_file_atomically(plots_dir / divergence, divergence_script(*ref, laws, floor, data_name));
    // (a): from the reference's binned shadow data, when it has one.
    const std::filesystem::path shadow_data = plots_dir / "data" / shadow_data_name(stem);
    if (std::filesystem::exists(shadow_data)) {
      const std::string name = "shadow-" + ref->spec.group() + ".gp";
      support::write_file_atomically(plots_dir / name, shadow_script(*ref, stem, shadow_data_laws(shadow_data), shadow_data));
      out.scripts.push_back(name);
    }
    out.scripts.push_back(divergence);
    // (c): the table.
    support::Json summary;
    try {
      summary = read_json_file(ref->spec.out_dir / "summary.json");
    } catch (const std::exception&) {
      summary = support::Json::object();
    }
    const bool shadowed = summary.contains("shadow");
    const double run_work = shadowed ? summary["shadow"]["run_work_J"].get<double>() : kNaN;
    const std::string floor_text = floor ? parting_text(parting_time(floor_d), *floor) : "– (no floor: --no-baseline)";
    report << "### " << case_title(*ref) << " (the `" << kReferenceLaw << "` run: " << end_of(*ref) << ")\n\n"
           << "| law | ΔF/kN median | 95 % | max | ΔM/kNa median | max | ΔE, J | failures | parts at | "
              "floor parts at |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t l = 0; l < laws.size(); ++l) {
      const support::Json* stats = nullptr;
      if (shadowed) {
        for (const auto& entry : summary["shadow"]["laws"]) {
          if (entry["law"] == laws[l]->spec.law) stats = &entry;
        }
      }
      report << table_row(*laws[l], stats, run_work, series[l + (floor ? 1 : 0)], floor_text);
    }
    report << "\n";
    if (std::filesystem::exists(shadow_data)) report << "![the error along the motion](plots/shadow-" << ref->spec.group() << ".png)\n";
    report << "![distance from the reference against the chaos floor](plots/divergence-" << ref->spec.group()
           << ".png)\n\n";
  }
  out.report = report.str();
  return out;
}

}  // namespace frictionlab::dynamics::paper
