#include "dynamics/puck/puck_study_report.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <sstream>

#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {
namespace {

using support::gnuplot_quoted;
using support::gnuplot_text;

std::string sig(double x, int digits = 4) { return std::isfinite(x) ? support::significant(x, digits) : "–"; }
std::string csv_number(double x) { return std::isfinite(x) ? support::shortest(x) : ""; }

// What the law predicts at one kappa, in a table cell.
std::string regime_cell(const TerminalRatioAnalysis& a) {
  if (a.regime == "together") return sig(a.attracting.front(), 4) + " (λ " + sig(a.exponents.front(), 2) + ")";
  if (a.regime == "slip-first") return "→ 0";
  if (a.regime == "spin-first") return "→ ∞";
  std::string cell = "depends";
  for (const double r : a.repelling) cell += " (repels at " + sig(r, 3) + ")";
  return cell;
}

std::string today() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
  return buf;
}

const TerminalRatioAnalysis* theory_of(const PuckStudyResults& r, const std::string& law, double kappa) {
  for (const auto& row : r.theory)
    if (row.law == law && row.kappa == kappa) return &row.analysis;
  return nullptr;
}

std::string predicted(const PuckStudyResults& r, const std::string& law, double kappa) {
  const TerminalRatioAnalysis* a = theory_of(r, law, kappa);
  return a ? regime_cell(*a) : "(κ not in --kappas)";
}

std::string report(const PuckStudyResults& r, const std::string& command) {
  std::ostringstream o;
  o << "# The puck study\n\n"
    << "`" << command << "`, " << today() << ", " << support::fixed(r.wall_time, 1) << " s wall. "
    << "Scenarios: `" << r.disk_file.string() << "`, `" << r.ellipse_file.string()
    << "`; every run is its file with the overrides listed in `disk.csv` / `ellipse.csv` "
       "(`frictionlab simulate FILE --set ...` reruns it). The model, the events and the theory: docs/puck.md.\n\n";
  if (!r.unavailable.empty()) {
    o << "Not available in this build (the registry refused the spec; rerun once it has them): ";
    for (std::size_t i = 0; i < r.unavailable.size(); ++i) o << (i ? ", " : "") << "`" << r.unavailable[i] << "`";
    o << ".\n\n";
  }
  // 1. theory
  std::vector<double> kappas;
  for (const auto& row : r.theory)
    if (std::find(kappas.begin(), kappas.end(), row.kappa) == kappas.end()) kappas.push_back(row.kappa);
  o << "## 1. The terminal ratio predicted from each law (circular patch)\n\n"
    << "The ratio r = v/(a ω) obeys d ln r/dt = (k g/v) G(r), G(r) = r μ(r)/κ − f(r) (f = F1/(kN), kN = k·N = k m g, "
       "μ = M/(kNa), κ = I/(m a²)); near the end it settles on a zero r* of G with G' < 0 (slip and spin stop "
       "together), or goes to 0 (the slip stops first) or ∞ (the spin stops first). Each cell: r* with the "
       "exponent λ of the approach (r − r* ∝ v^λ), or → 0, → ∞, or \"depends\" (a repelling zero: the end depends "
       "on the start).\n\n| law |";
  for (const double k : kappas) o << " κ = " << sig(k, 3) << " |";
  o << "\n|---|";
  for (std::size_t i = 0; i < kappas.size(); ++i) o << "---|";
  o << "\n";
  for (const auto& law : r.laws) {
    o << "| `" << law << "` |";
    for (const double k : kappas) o << " " << predicted(r, law, k) << " |";
    o << "\n";
  }
  // 2. disk
  o << "\n## 2. The disk (`puck-disk.toml`, a = " << "5 cm" << ", ω0 = " << sig(r.disk_omega0, 3)
    << " 1/s): stop times and the terminal ratio\n\n"
    << "Rest thresholds lowered to the fraction of √(g a), √(g/a) given by the study (the overrides in "
       "`disk.csv`), so that the ratio has decades of energy to settle in. *ratio at stop*: v/(a|ω|) when the "
       "first of slip and spin stops; *limit*: extrapolated from the last decades of the kinetic energy "
       "(Aitken; – where the ratio does not converge geometrically); *predicted*: section 1.\n\n"
    << "| law | κ | r0 | slip stops (s) | spin stops (s) | ratio at stop | limit | predicted | end |\n"
    << "|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& d : r.disk) {
    const PuckRunSummary& s = d.summary;
    o << "| `" << d.law << "` | " << sig(d.kappa, 3) << " | " << sig(d.start_ratio, 3) << " | "
      << sig(s.slip_stop_time, 6) << " | " << sig(s.spin_stop_time, 6) << " | " << sig(s.terminal_ratio, 4) << " | "
      << sig(s.terminal_ratio_limit, 4) << " | " << predicted(r, d.law, d.kappa) << " | " << to_string(s.reason)
      << " |\n";
  }
  // 3. ellipse
  const EllipseRun* exact = nullptr;
  for (const auto& e : r.ellipse)
    if (e.law == "exact") exact = &e;
  o << "\n## 3. The elliptic puck (`puck-ellipse.toml`): path and stop times\n\n"
    << "*sideways*: the end's distance from the line of the initial velocity (left positive); *from exact*: "
       "the distance between the law's end and the exact law's.\n\n"
    << "| law | slip stops (s) | spin stops (s) | distance (m) | sideways (mm) | from exact (mm) | turned (rad) | end |\n"
    << "|---|---|---|---|---|---|---|---|\n";
  for (const auto& e : r.ellipse) {
    const PuckRunSummary& s = e.summary;
    const double from_exact =
        exact ? (position(s.x_final) - position(exact->summary.x_final)).norm() * 1e3 : std::nan("");
    o << "| `" << e.law << "` | " << sig(s.slip_stop_time, 6) << " | " << sig(s.spin_stop_time, 6) << " | "
      << sig(e.offset.along, 5) << " | " << sig(e.offset.lateral * 1e3, 4) << " | " << sig(from_exact, 3) << " | "
      << sig(heading(s.x_final), 5) << " | " << to_string(s.reason) << " |\n";
  }
  o << "\nFigures: `figures/drift.png`, `figures/regimes.png`, `figures/ratio.png`, `figures/paths.png`.\n";
  return o.str();
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

void write_tables(const PuckStudyResults& r, const std::filesystem::path& out) {
  std::ostringstream t;
  t << "law,kappa,regime,attracting,exponent,repelling,small_ratio_slope,large_ratio_limit\n";
  for (const auto& row : r.theory) {
    const auto& a = row.analysis;
    t << row.law << "," << csv_number(row.kappa) << "," << a.regime << ","
      << (a.attracting.empty() ? "" : csv_number(a.attracting.front())) << ","
      << (a.exponents.empty() ? "" : csv_number(a.exponents.front())) << ","
      << (a.repelling.empty() ? "" : csv_number(a.repelling.front())) << "," << csv_number(a.small_slope) << ","
      << csv_number(a.large_limit) << "\n";
  }
  support::write_file_atomically(out / "theory.csv", t.str());
  std::ostringstream d;
  d << "law,kappa,start_ratio,reason,slip_stop_time,spin_stop_time,terminal_ratio,terminal_ratio_limit,steps,overrides\n";
  for (const auto& x : r.disk) {
    const auto& s = x.summary;
    d << x.law << "," << csv_number(x.kappa) << "," << csv_number(x.start_ratio) << "," << to_string(s.reason) << ","
      << csv_number(s.slip_stop_time) << "," << csv_number(s.spin_stop_time) << "," << csv_number(s.terminal_ratio)
      << "," << csv_number(s.terminal_ratio_limit) << "," << s.steps << ",\"" << joined(x.overrides) << "\"\n";
  }
  support::write_file_atomically(out / "disk.csv", d.str());
  std::ostringstream e;
  e << "law,reason,slip_stop_time,spin_stop_time,x,y,along,lateral,heading,steps,overrides\n";
  for (const auto& x : r.ellipse) {
    const auto& s = x.summary;
    e << x.law << "," << to_string(s.reason) << "," << csv_number(s.slip_stop_time) << ","
      << csv_number(s.spin_stop_time) << "," << csv_number(position(s.x_final).x()) << ","
      << csv_number(position(s.x_final).y()) << "," << csv_number(x.offset.along) << "," << csv_number(x.offset.lateral)
      << "," << csv_number(heading(s.x_final)) << "," << s.steps << ",\"" << joined(x.overrides) << "\"\n";
  }
  support::write_file_atomically(out / "ellipse.csv", e.str());
}

// Figures --------------------------------------------------------------------------------------

constexpr const char* kTerminal = "set encoding utf8\nset terminal pngcairo enhanced size 1000,700 font 'DejaVuSans,11'";
constexpr std::array<const char*, 10> kColours = {"#000000", "#d62728", "#1f77b4", "#2ca02c", "#9467bd",
                                                  "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f"};
constexpr std::array<const char*, 8> kDashes = {"1", "2", "3", "4", "(28,7)", "5", "(4,6,16,6)", "(16,5,3,5,3,5,3,5)"};

std::string style(std::size_t i) {
  return std::string(" lw 1.6 dt ") + kDashes[i % kDashes.size()] + " lc rgb " + gnuplot_quoted(kColours[i % kColours.size()]);
}

std::string g7(double x) { return std::isfinite(x) ? support::significant(x, 7) : "NaN"; }

std::vector<std::string> write_figures(const PuckStudyResults& r, const std::filesystem::path& dir) {
  const std::filesystem::path data = dir / "data";
  std::filesystem::create_directories(data);
  std::vector<std::string> scripts;
  const auto law_index = [&](const std::string& law) {
    return static_cast<std::size_t>(std::find(r.laws.begin(), r.laws.end(), law) - r.laws.begin());
  };
  // drift
  {
    std::string plot = "plot 0 with lines lc rgb '#aaaaaa' notitle";
    for (std::size_t i = 0; i < r.drift.size(); ++i) {
      std::ostringstream f;
      for (const auto& [x, g] : r.drift[i].second) f << g7(x) << " " << g7(g) << "\n";
      const std::string name = "drift-" + std::to_string(i) + ".dat";
      support::write_file_atomically(data / name, f.str());
      plot += ", \\\n     " + gnuplot_quoted("data/" + name) + " using 1:2 with lines" + style(i) + " title " +
              gnuplot_text(r.drift[i].first);
    }
    std::ostringstream s;
    s << "# The drift G(r) of the ratio r = v/(a omega) at kappa = I/(m a^2) = 1/2 (docs/puck.md §3).\n"
      << kTerminal << "\nset output 'drift.png'\nset logscale x\nset xrange [0.01:100]\nset yrange [-1.2:0.6]\n"
      << "set grid\nset key bottom left font ',10'\nset xlabel 'r = v/(a |ω|)'\n"
      << "set ylabel 'G(r) = r μ(r)/κ − f(r), κ = 1/2'\n"
      << "set title 'd ln r/dt = (k g/v) G(r): r settles where G falls through 0'\n"
      << plot << "\n";
    support::write_file_atomically(dir / "drift.gp", s.str());
    scripts.push_back("drift.gp");
  }
  // regimes
  {
    std::string plot = "plot ";
    for (std::size_t i = 0; i < r.laws.size(); ++i) {
      std::ostringstream f;
      for (const auto& row : r.theory)
        if (row.law == r.laws[i]) f << g7(row.kappa) << " " << g7(row.analysis.attracting.empty() ? std::nan("") : row.analysis.attracting.front()) << "\n";
      const std::string name = "regimes-" + std::to_string(i) + ".dat";
      support::write_file_atomically(data / name, f.str());
      plot += std::string(i ? ", \\\n     " : "") + gnuplot_quoted("data/" + name) + " using 1:2 with linespoints pt " +
              std::to_string(4 + i) + style(i) + " title " + gnuplot_text(r.laws[i]);
    }
    std::ostringstream s;
    s << "# The terminal ratio r* against the inertia ratio kappa (circular patch; gaps: no finite r*).\n"
      << kTerminal << "\nset output 'regimes.png'\nset grid\nset key top right font ',10'\n"
      << "set xlabel 'κ = I/(m a^2)'\nset ylabel 'terminal ratio r* = v/(a ω)'\nset logscale y\n"
      << "set title 'Slip and spin stop together only where a finite r* exists'\n"
      << plot << "\n";
    support::write_file_atomically(dir / "regimes.gp", s.str());
    scripts.push_back("regimes.gp");
  }
  // ratio against energy at kappa = 1/2
  {
    std::string plot = "plot ";
    bool first = true;
    int n = 0;
    for (const auto& d : r.disk) {
      if (d.kappa != 0.5) continue;
      std::ostringstream f;
      for (const auto& [e, q] : d.ratio_curve) f << g7(e) << " " << g7(q) << "\n";
      const std::string name = "ratio-" + std::to_string(n++) + ".dat";
      support::write_file_atomically(data / name, f.str());
      const std::size_t i = law_index(d.law);
      const bool titled = d.start_ratio == r.disk.front().start_ratio;
      plot += std::string(first ? "" : ", \\\n     ") + gnuplot_quoted("data/" + name) + " using 1:2 with lines" + style(i) +
              (titled ? " title " + gnuplot_text(d.law) : " notitle");
      first = false;
    }
    if (n > 0) {
      std::ostringstream s;
      s << "# The disk's ratio v/(a omega) against its kinetic energy (kappa = 1/2), from two starting ratios.\n"
        << kTerminal << "\nset output 'ratio.png'\nset logscale x\nset logscale y\nset xrange [1:1e-12]\n"
        << "set yrange [0.01:10]\nset grid\nset key outside right font ',10'\n"
        << "set xlabel 'kinetic energy / initial (the motion runs right)'\nset ylabel 'v/(a |ω|)'\n"
        << "set title 'Disk, κ = 1/2: where the ratio goes as both motions die out'\n"
        << plot << "\n";
      support::write_file_atomically(dir / "ratio.gp", s.str());
      scripts.push_back("ratio.gp");
    }
  }
  // elliptic paths
  {
    std::string plot = "plot ";
    for (std::size_t i = 0; i < r.ellipse.size(); ++i) {
      std::ostringstream f;
      for (const auto& p : r.ellipse[i].path) f << g7(p.x()) << " " << g7(p.y() * 1e3) << "\n";
      const std::string name = "path-" + std::to_string(i) + ".dat";
      support::write_file_atomically(data / name, f.str());
      plot += std::string(i ? ", \\\n     " : "") + gnuplot_quoted("data/" + name) + " using 1:2 with lines" +
              style(law_index(r.ellipse[i].law)) + " title " + gnuplot_text(r.ellipse[i].law);
    }
    std::ostringstream s;
    s << "# The paths of the elliptic puck (puck-ellipse.toml); sideways axis magnified.\n"
      << kTerminal << "\nset output 'paths.png'\nset grid\nset key top left font ',10'\n"
      << "set xlabel 'x (m), along the initial velocity'\nset ylabel 'y (mm), sideways'\n"
      << "set title 'Elliptic puck (2:1): F2 bends the path'\n"
      << plot << "\n";
    support::write_file_atomically(dir / "paths.gp", s.str());
    scripts.push_back("paths.gp");
  }
  return support::run_gnuplot_scripts(dir, scripts);
}

}  // namespace

std::vector<std::string> write_puck_study(const PuckStudyResults& results, const std::filesystem::path& out,
                                          const std::string& command, bool plots) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw support::OutputError("cannot create the output folder '" + out.string() + "': " + ec.message());
  write_tables(results, out);
  support::write_file_atomically(out / "puck-study.md", report(results, command));
  if (!plots) return {};
  return write_figures(results, out / "figures");
}

}  // namespace frictionlab::dynamics::puck
