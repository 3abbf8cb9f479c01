#include "bench/accuracy/plots.h"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <memory>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "bench/accuracy/report.h"
#include "friction/registry.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::accuracy {
namespace fs = std::filesystem;
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;

// Categories of the singularity map (the colours of singular_<law>.png).
enum Category : int {
  kRegular = 0,
  kF2Negative = 1,
  kMNegative = 2,
  kBothNegative = 3,
  kF1Negative = 4,
  kSingular = 5,
};

int category(std::uint8_t bits) {
  if (bits & kSingularValue) return kSingular;
  if (bits & kF1DenominatorNegative) return kF1Negative;
  const bool f2 = bits & kF2DenominatorNegative;
  const bool m = bits & kMDenominatorNegative;
  return f2 && m ? kBothNegative : m ? kMNegative : f2 ? kF2Negative : kRegular;
}

// Axis ranges, labels and plot coordinates: 4 significant digits.
std::string g(double x) { return support::significant(x, 4); }

// Every script and data file is written whole or not at all (support/checked_output.h).
void write_text(const fs::path& path, const std::ostringstream& text) {
  support::write_file_atomically(path, text.str());
}

// Grid nodes nearest to `wanted`, without repeats, in grid order.
std::vector<std::size_t> pick_mu(const Grid& grid, std::initializer_list<double> wanted) {
  std::vector<std::size_t> out;
  for (const double w : wanted) {
    const std::size_t i = grid.nearest_mu(w);
    if (std::find(out.begin(), out.end(), i) == out.end()) out.push_back(i);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string terminal_line(const std::string& terminal, int width, int height) {
  if (terminal == "pngcairo") {
    return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
           " enhanced font 'Sans,11'";
  }
  return "set terminal png size " + std::to_string(width) + "," + std::to_string(height) +
         " enhanced font 'Sans,10'";
}

// The header every script shares: terminal, output, and a note on how it was made.
void script_head(std::ostream& gp, const std::string& terminal, const std::string& name, int width,
                 int height) {
  gp << "# " << name << ".png from " << name << ".dat, written by `frictionlab accuracy`.\n"
     << "# Redraw: cd into this folder, then `gnuplot " << name << ".gp`.\n"
     << terminal_line(terminal.empty() ? "pngcairo" : terminal, width, height) << '\n'
     << "set output " << support::gnuplot_quoted(name + ".png") << "\n"
     << "set encoding utf8\n";
}

std::string heat_data(const StudyResult& study, const LawValues& law,
                      const std::vector<std::size_t>& mus) {
  const Grid& grid = study.grid;
  const std::array<const std::vector<double>*, 3> lv = {&law.F1, &law.F2, &law.M};
  const std::array<const std::vector<double>*, 3> rv = {&study.reference.F1, &study.reference.F2,
                                                        &study.reference.M};
  std::ostringstream d;
  d << "# log10(s)  psi_deg  log10|err F1|  log10|err F2|  log10|err M|   (max over sign Omega,"
       " clamped to [" << kHeatFloor << ", " << kHeatCeiling << "]; NaN: non-finite)\n";
  for (std::size_t k = 0; k < mus.size(); ++k) {
    d << "# index " << k << ": mu = " << g(grid.mu()[mus[k]]) << '\n';
    for (std::size_t ipsi = 0; ipsi < grid.psi().size(); ++ipsi) {
      for (std::size_t is = 0; is < grid.s().size(); ++is) {
        d << g(std::log10(grid.s()[is])) << ' ' << g(grid.psi()[ipsi] * kDeg);
        for (std::size_t c = 0; c < 3; ++c) {
          double e = 0.0;
          for (std::size_t isign = 0; isign < Grid::kSigns.size(); ++isign) {
            const std::size_t i = grid.index(mus[k], ipsi, isign, is);
            const double v = (*lv[c])[i];
            e = std::isfinite(v) ? std::max(e, std::abs(v - (*rv[c])[i])) : kNaN;
            if (std::isnan(e)) break;
          }
          d << ' ' << (std::isnan(e) ? "NaN" : g(std::log10(std::clamp(e, kHeatFloor, kHeatCeiling))));
        }
        d << '\n';
      }
      d << '\n';
    }
    d << '\n';
  }
  return d.str();
}

std::string log_cbtics(int lo, int hi) {
  std::string t = "set cbtics (";
  for (int e = lo; e <= hi; ++e) {
    t += (e == lo ? "" : ", ") + std::string("\"10^{") + std::to_string(e) + "}\" " + std::to_string(e);
  }
  return t + ")";
}

void write_heat(const StudyResult& study, const LawValues& law, const fs::path& plots,
                const std::string& terminal, std::vector<fs::path>& scripts) {
  const auto mus = pick_mu(study.grid, {0.05, 0.5, 1.0});
  const std::string name = "heat_" + friction::law_file_stem(law.law);
  support::write_file_atomically(plots / (name + ".dat"), heat_data(study, law, mus));
  std::ostringstream gp;
  script_head(gp, terminal, name, 1500, 400 * static_cast<int>(mus.size()) + 60);
  const int lo = static_cast<int>(std::round(std::log10(kHeatFloor)));
  const int hi = static_cast<int>(std::round(std::log10(kHeatCeiling)));
  gp << "set multiplot layout " << mus.size() << ",3 title "
     << support::gnuplot_text(law.law + " against exact: |law − exact| (max over sign Ω); F1, F2 per k·N, "
                                        "M per k·N·a; white: non-finite")
     << " font ',13'\n"
     << "set xlabel 'log_{10} s,  s = U/(a|Ω|)'\nset ylabel 'ψ (deg)'\n"
     << "set xrange [" << g(std::log10(study.grid.s().front())) << ":" << g(std::log10(study.grid.s().back()))
     << "]\nset yrange [0:180]\nset ytics 0,45,180\n"
     << "set cbrange [" << lo << ":" << hi << "]\n" << log_cbtics(lo, hi) << '\n'
     << "set palette defined (0 '#0d0887', 1 '#6a00a8', 2 '#b12a90', 3 '#e16462', 4 '#fca636', 5 '#f0f921')\n"
     << "set tics out\n";
  const char* comp[] = {"F1/(k·N)", "F2/(k·N)", "M/(k·N·a)"};
  for (std::size_t k = 0; k < mus.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      gp << "set title " << support::gnuplot_quoted("|Δ" + std::string(comp[c]) + "|,  μ = " + g(study.grid.mu()[mus[k]]))
         << "\n"
         << "plot " << support::gnuplot_quoted(name + ".dat") << " index " << k << " using 1:2:" << 3 + c
         << " with image notitle\n";
    }
  }
  gp << "unset multiplot\n";
  write_text(plots / (name + ".gp"), gp);
  scripts.push_back(plots / (name + ".gp"));
}

bool needs_singularity_map(const LawSummary& sum) {
  return sum.overall.singular_points > 0 || !sum.poles.empty();
}

void write_singular(const StudyResult& study, const LawValues& law, const LawSummary& sum,
                    const fs::path& plots, const std::string& terminal, std::vector<fs::path>& scripts) {
  const Grid& grid = study.grid;
  const auto den = known_denominators(law.law);
  const auto map = singularity_map(grid, law, den);
  const auto mus = pick_mu(grid, {0.05, 0.1, 0.25, 0.5, 0.75, 0.95});
  const std::string name = "singular_" + friction::law_file_stem(law.law);
  {
    std::ostringstream d;
    d << "# log10(s)  psi_deg  category (0 regular, 1 F2 denominator < 0, 2 M denominator < 0, 3 both,"
         " 4 F1 denominator < 0, 5 |output| > " << kSingularMagnitude << " or non-finite at either sign)\n";
    for (std::size_t k = 0; k < mus.size(); ++k) {
      d << "# index " << k << ": mu = " << g(grid.mu()[mus[k]]) << '\n';
      for (std::size_t ipsi = 0; ipsi < grid.psi().size(); ++ipsi) {
        for (std::size_t is = 0; is < grid.s().size(); ++is) {
          const auto bits = map[(mus[k] * grid.psi().size() + ipsi) * grid.s().size() + is];
          d << g(std::log10(grid.s()[is])) << ' ' << g(grid.psi()[ipsi] * kDeg) << ' '
            << category(bits) << '\n';
        }
        d << '\n';
      }
      d << '\n';
    }
    write_text(plots / (name + ".dat"), d);
  }
  std::ostringstream gp;
  const std::size_t rows = (mus.size() + 2) / 3;
  script_head(gp, terminal, name, 1500, 430 * static_cast<int>(rows) + 60);
  // Two title lines: gnuplot_text strings joined by gnuplot's string operator '.' around "\n".
  const std::string line1 =
      law.law + ": where it is singular" +
      (sum.has_denominators ? " (sign of each denominator of eq. (8): a colour change along s is a real pole)" : "");
  const std::string line2 = "black: an output non-finite or > " + support::significant(kSingularMagnitude, 6) +
                            " in size (F1, F2 per k·N, M per k·N·a) at either sign of Ω";
  gp << "set multiplot layout " << rows << ",3 title " << support::gnuplot_text(line1) << ".\"\\n\"."
     << support::gnuplot_text(line2) << " font ',13'\n"
     << "set xlabel 'log_{10} s,  s = U/(a|Ω|)'\nset ylabel 'ψ (deg)'\n"
     << "set xrange [" << g(std::log10(grid.s().front())) << ":" << g(std::log10(grid.s().back()))
     << "]\nset yrange [0:180]\nset ytics 0,45,180\nset tics out\n"
     << "set cbrange [-0.5:5.5]\n"
     << "set palette defined (-0.5 'white', 0.5 'white', 0.5 '#9ecae1', 1.5 '#9ecae1', 1.5 '#fdae6b', "
        "2.5 '#fdae6b', 2.5 '#c994c7', 3.5 '#c994c7', 3.5 '#74c476', 4.5 '#74c476', 4.5 'black', 5.5 'black')\n"
     << "set cbtics ('regular' 0, 'F2 den<0' 1, 'M den<0' 2, 'F2,M den<0' 3, 'F1 den<0' 4, "
        "'|out|>" << kSingularMagnitude << "' 5) font ',9'\n"
     << "set rmargin 9\n";
  for (std::size_t k = 0; k < mus.size(); ++k) {
    gp << "set title " << support::gnuplot_quoted("μ = " + g(grid.mu()[mus[k]])) << "\n"
       << "plot " << support::gnuplot_quoted(name + ".dat") << " index " << k << " using 1:2:3 with image notitle\n";
  }
  gp << "unset multiplot\n";
  write_text(plots / (name + ".gp"), gp);
  scripts.push_back(plots / (name + ".gp"));
}

void write_curves(const StudyResult& study, const CurveCase& cc, const fs::path& plots,
                  const std::string& terminal, std::vector<fs::path>& scripts) {
  std::vector<std::string> names = {study.reference.law};
  for (const auto& v : study.values) {
    if (v.law != study.reference.law) names.push_back(v.law);
  }
  std::vector<std::unique_ptr<friction::FrictionLaw>> laws;
  for (const auto& n : names) laws.push_back(friction::make_law(n));
  const auto& s = study.grid.s();
  const std::string name = "curves_" + cc.tag;

  // values[sign][law][component][is]
  std::array<std::vector<std::array<std::vector<double>, 3>>, 2> values;
  for (std::size_t isign = 0; isign < 2; ++isign) {
    values[isign].resize(laws.size());
    for (std::size_t j = 0; j < laws.size(); ++j) {
      for (auto& comp : values[isign][j]) comp.resize(s.size());
      for (std::size_t is = 0; is < s.size(); ++is) {
        const auto f = laws[j]->evaluate(to_contact({s[is], cc.mu, cc.psi, Grid::kSigns[isign]}));
        values[isign][j][0][is] = f.F1;
        values[isign][j][1][is] = f.F2;
        values[isign][j][2][is] = f.M;
      }
    }
  }
  {
    std::ostringstream d;
    d << "# mu = " << g(cc.mu) << ", psi = " << g(cc.psi * kDeg) << " deg; index 0: Omega < 0, index 1: Omega > 0\n"
      << "# columns: s, then F1/(kN) F2/(kN) M/(kNa) of each law:";
    for (const auto& n : names) d << ' ' << n;
    d << '\n';
    for (std::size_t isign = 0; isign < 2; ++isign) {
      for (std::size_t is = 0; is < s.size(); ++is) {
        d << format_number(s[is]);
        for (std::size_t j = 0; j < laws.size(); ++j) {
          for (std::size_t c = 0; c < 3; ++c) {
            const double v = values[isign][j][c][is];
            d << ' ' << (std::isfinite(v) ? format_number(v) : "NaN");
          }
        }
        d << '\n';
      }
      d << "\n\n";
    }
    write_text(plots / (name + ".dat"), d);
  }
  std::ostringstream gp;
  script_head(gp, terminal, name, 1500, 950);
  gp << "set multiplot layout 2,3 title "
     << support::gnuplot_quoted("F1, F2, M against s at μ = " + g(cc.mu) + ", ψ = " + g(cc.psi * kDeg) +
                                "° (top: Ω > 0, bottom: Ω < 0); the y range follows exact, curves that leave it "
                                "are off scale")
     << " font ',13'\n"
     << "set logscale x\nset format x '10^{%L}'\nset xlabel 's = U/(a|Ω|)'\nset grid\n"
     << "set key right bottom font ',9' spacing 1.1\n";
  const char* comp[] = {"F1/(k·N)", "F2/(k·N)", "M/(k·N·a)"};
  for (const std::size_t isign : {std::size_t{1}, std::size_t{0}}) {
    for (std::size_t c = 0; c < 3; ++c) {
      // y range: the exact curve's range, widened so that a sound law's curve fits.
      const auto& ex = values[isign][0][c];
      const auto [lo_it, hi_it] = std::minmax_element(ex.begin(), ex.end());
      const double span = std::max(*hi_it - *lo_it, 0.1);
      gp << "set title " << support::gnuplot_quoted(std::string(comp[c]) + ",  Ω " + (isign == 1 ? "> 0" : "< 0"))
         << "\nset ylabel " << support::gnuplot_quoted(comp[c]) << "\n"
         << "set yrange [" << g(*lo_it - 0.5 * span) << ":" << g(*hi_it + 0.5 * span) << "]\n"
         << (c == 0 ? "set key\n" : "unset key\n") << "plot ";
      for (std::size_t j = 0; j < names.size(); ++j) {
        const std::size_t col = 2 + 3 * j + c;
        gp << (j == 0 ? "" : ", \\\n     ") << support::gnuplot_quoted(name + ".dat") << " index " << isign
           << " using 1:" << col << " with lines "
           << (j == 0 ? "lc rgb 'black' lw 3" : "lw 2 dt " + std::to_string(1 + (j - 1) % 5) + " lc " + std::to_string(j))
           << " title " << support::gnuplot_text(names[j]);
      }
      gp << '\n';
    }
  }
  gp << "unset multiplot\n";
  write_text(plots / (name + ".gp"), gp);
  scripts.push_back(plots / (name + ".gp"));
}

}  // namespace

std::vector<CurveCase> curve_cases() {
  constexpr double pi = std::numbers::pi;
  return {{0.5, pi / 4.0, "mu0.5_psi45"}, {0.1, pi / 3.0, "mu0.1_psi60"}};
}

std::string detect_gnuplot_terminal() {
  for (const char* terminal : {"pngcairo", "png"})
    if (support::gnuplot_has_terminal(terminal)) return terminal;
  return "";
}

PlotReport write_plots(const StudyResult& study, const fs::path& dir, const PlotOptions& options,
                       std::ostream* progress) {
  PlotReport rep;
  const fs::path plots = dir / "plots";
  fs::create_directories(plots);
  rep.terminal = detect_gnuplot_terminal();

  for (std::size_t j = 0; j < study.values.size(); ++j) {
    write_heat(study, study.values[j], plots, rep.terminal, rep.scripts);
    if (needs_singularity_map(study.summaries[j])) {
      write_singular(study, study.values[j], study.summaries[j], plots, rep.terminal, rep.scripts);
    }
  }
  for (const auto& cc : curve_cases()) write_curves(study, cc, plots, rep.terminal, rep.scripts);

  if (!options.draw) return rep;
  if (rep.terminal.empty()) {
    if (progress) {
      *progress << "accuracy: warning: gnuplot (with a png terminal) not found; the CSV files and "
                   "the scripts in " << plots.string() << " are written, the figures are not" << std::endl;
    }
    return rep;
  }
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  const auto work = [&] {
    for (std::size_t k = next++; k < rep.scripts.size(); k = next++) {
      const fs::path& script = rep.scripts[k];
      // gnuplot's messages go to NAME.log, kept only if it wrote any.
      fs::path png = script, log = script;
      png.replace_extension(".png");
      log.replace_extension(".log");
      const bool ok = support::run_gnuplot(plots, script.filename(), log.filename()).ok && fs::exists(png);
      const std::lock_guard lock(mutex);
      if (ok) {
        rep.figures.push_back(png);
      } else {
        rep.failures.push_back(script.filename().string() + " (see " + log.filename().string() + ")");
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < worker_count(0, rep.scripts.size()); ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  std::sort(rep.figures.begin(), rep.figures.end());
  if (progress) {
    *progress << "accuracy: gnuplot (" << rep.terminal << ") drew " << rep.figures.size() << " of "
              << rep.scripts.size() << " figures in " << plots.string();
    if (!rep.failures.empty()) {
      *progress << "; warning: failed on";
      for (const auto& f : rep.failures) *progress << ' ' << f;
    }
    *progress << std::endl;
  }
  return rep;
}

}  // namespace frictionlab::accuracy
