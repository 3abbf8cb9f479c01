#include "dynamics/tippe_top/tippe_top_study_report.h"

#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <sstream>

#include "dynamics/tippe_top/tippe_top_observables.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::tippe_top {
namespace {

using support::gnuplot_quoted;
using support::gnuplot_text;

std::string sig(double x, int digits = 4) { return std::isfinite(x) ? support::significant(x, digits) : "–"; }
std::string csv_number(double x) { return std::isfinite(x) ? support::shortest(x) : ""; }

std::string today() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
  return buf;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

std::string report(const TippeTopStudyResults& r, const std::string& command) {
  std::ostringstream o;
  o << "# The tippe-top study\n\n"
    << "`" << command << "`, " << today() << ", " << support::fixed(r.wall_time, 1) << " s wall. Scenario: `"
    << r.scenario.string() << "`; every run is that file with the overrides in `runs.csv` (`frictionlab simulate "
       "FILE --set ...` reruns it). The model, the source and the checks: docs/tippe-top.md.\n\n";
  if (!r.unavailable.empty()) {
    o << "Not available in this build (the registry refused the spec): ";
    for (std::size_t i = 0; i < r.unavailable.size(); ++i) o << (i ? ", " : "") << "`" << r.unavailable[i] << "`";
    o << ".\n\n";
  }
  o << "*horizontal*: γ3 first below 0; *inverted*: γ3 first below " << sig(kInvertedGamma3, 2)
    << " (the inversion time); *min γ3*: the lowest γ3 and when; *end*: the reason and time the run ended, γ3 "
       "there; *E rise*: the largest rise of the total energy over its running minimum, / E(0) (0 for a "
       "dissipative law, up to the integration error); *balance*: max |E + W − E(0)|/E(0); *Jellett*: "
       "max |L·r − L·r(0)|/|L·r(0)|; *identity*: max |L·r − L·r(0) + ∫ M γ·r dt|/|L·r(0)| (trapezoids over the "
       "samples; 0 up to integration and quadrature error for every law).\n\n"
    << "| law | horizontal (s) | inverted (s) | min γ3 (at s) | end | γ3 at end | E rise | balance | Jellett | "
       "identity | steps |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& run : r.runs) {
    const RunSummary& s = run.summary;
    o << "| `" << run.law << "` | " << sig(run.horizontal_time, 5) << " | " << sig(run.inversion_time, 5) << " | "
      << sig(run.min_gamma3, 4) << " (" << sig(run.min_gamma3_time, 4) << ") | " << to_string(s.reason) << " at "
      << sig(s.t_final, 5) << " s | " << sig(run.final_gamma3, 4) << " | " << sig(run.max_energy_rise, 2) << " | "
      << sig(run.energy_balance_error, 2) << " | " << sig(run.max_jellett_change, 3) << " | "
      << sig(run.jellett_identity_error, 2) << " | " << s.steps << " |\n";
  }
  o << "\nMessages of runs that did not end at rest or t_end:\n\n";
  bool any = false;
  for (const auto& run : r.runs) {
    const RunSummary& s = run.summary;
    if (s.reason == Termination::rest || s.reason == Termination::t_end) continue;
    any = true;
    o << "* `" << run.law << "`: " << to_string(s.reason) << ": " << s.message << "\n";
  }
  if (!any) o << "* none\n";
  o << "\nFigures: `figures/gamma3.png`, `figures/jellett.png`.\n";
  return o.str();
}

void write_table(const TippeTopStudyResults& r, const std::filesystem::path& out) {
  std::ostringstream t;
  t << "law,reason,t_final,horizontal_time,inversion_time,min_gamma3,min_gamma3_time,final_gamma3,"
       "max_energy_rise,energy_balance_error,jellett0,max_jellett_change,jellett_identity_error,slide_work,"
       "spin_work,steps,wall_time,overrides\n";
  for (const auto& run : r.runs) {
    const RunSummary& s = run.summary;
    t << run.law << "," << to_string(s.reason) << "," << csv_number(s.t_final) << "," << csv_number(run.horizontal_time)
      << "," << csv_number(run.inversion_time) << "," << csv_number(run.min_gamma3) << ","
      << csv_number(run.min_gamma3_time) << "," << csv_number(run.final_gamma3) << ","
      << csv_number(run.max_energy_rise) << "," << csv_number(run.energy_balance_error) << ","
      << csv_number(run.jellett0) << "," << csv_number(run.max_jellett_change) << ","
      << csv_number(run.jellett_identity_error) << "," << csv_number(slide_work(s.x_final)) << ","
      << csv_number(spin_work(s.x_final)) << "," << s.steps << "," << csv_number(s.wall_time) << ",\""
      << joined(run.overrides) << "\"\n";
  }
  support::write_file_atomically(out / "runs.csv", t.str());
}

constexpr const char* kTerminal = "set encoding utf8\nset terminal pngcairo enhanced size 1100,700 font 'DejaVuSans,11'";
constexpr std::array<const char*, 10> kColours = {"#000000", "#d62728", "#1f77b4", "#2ca02c", "#9467bd",
                                                  "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f"};
constexpr std::array<const char*, 8> kDashes = {"1", "2", "3", "4", "(28,7)", "5", "(4,6,16,6)", "(16,5,3,5,3,5,3,5)"};

std::string style(std::size_t i) {
  return std::string(" lw 1.4 dt ") + kDashes[i % kDashes.size()] + " lc rgb " + gnuplot_quoted(kColours[i % kColours.size()]);
}

std::string g7(double x) { return std::isfinite(x) ? support::significant(x, 7) : "NaN"; }

std::vector<std::string> write_figures(const TippeTopStudyResults& r, const std::filesystem::path& dir) {
  const std::filesystem::path data = dir / "data";
  std::filesystem::create_directories(data);
  std::string gamma_plot = "plot ", jellett_plot = "plot ";
  for (std::size_t i = 0; i < r.runs.size(); ++i) {
    const auto& run = r.runs[i];
    std::ostringstream f;
    for (std::size_t j = 0; j < run.gamma3_curve.size(); ++j)
      f << g7(run.gamma3_curve[j].first) << " " << g7(run.gamma3_curve[j].second) << " "
        << g7(run.jellett_curve[j].second) << "\n";
    const std::string name = "run-" + std::to_string(i) + ".dat";
    support::write_file_atomically(data / name, f.str());
    const std::string sep = i ? ", \\\n     " : "";
    gamma_plot += sep + gnuplot_quoted("data/" + name) + " using 1:2 with lines" + style(i) + " title " + gnuplot_text(run.law);
    jellett_plot += sep + gnuplot_quoted("data/" + name) + " using 1:3 with lines" + style(i) + " title " + gnuplot_text(run.law);
  }
  std::ostringstream g;
  g << "# gamma3 against time for every law (docs/tippe-top.md).\n"
    << kTerminal << "\nset output 'gamma3.png'\nset grid\nset key outside right font ',10'\nset yrange [-1.05:1.05]\n"
    << "set xlabel 't (s)'\nset ylabel 'γ_3 (+1: on the near pole, −1: inverted)'\n"
    << "set title 'Tippe top (Leine and Glocker 2003): γ_3 against time'\n"
    << "set arrow from graph 0, first " << g7(kInvertedGamma3) << " to graph 1, first " << g7(kInvertedGamma3)
    << " nohead dt 3 lc rgb '#888888'\n"
    << gamma_plot << "\n";
  support::write_file_atomically(dir / "gamma3.gp", g.str());
  std::ostringstream j;
  j << "# Jellett's quantity L.r / L.r(0) against time (docs/tippe-top.md): 1 without a spin moment.\n"
    << kTerminal << "\nset output 'jellett.png'\nset grid\nset key outside right font ',10'\n"
    << "set xlabel 't (s)'\nset ylabel 'L·r / L·r(0)'\n"
    << "set title 'Jellett''s quantity: conserved without a spin moment, changed by −∫ M γ·r dt with one'\n"
    << jellett_plot << "\n";
  support::write_file_atomically(dir / "jellett.gp", j.str());
  return support::run_gnuplot_scripts(dir, {"gamma3.gp", "jellett.gp"});
}

}  // namespace

std::vector<std::string> write_tippe_top_study(const TippeTopStudyResults& results, const std::filesystem::path& out,
                                               const std::string& command, bool plots) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw support::OutputError("cannot create the output folder '" + out.string() + "': " + ec.message());
  write_table(results, out);
  support::write_file_atomically(out / "tippe-top.md", report(results, command));
  if (!plots) return {};
  return write_figures(results, out / "figures");
}

}  // namespace frictionlab::dynamics::tippe_top
