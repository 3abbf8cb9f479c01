#include "bench/calibration/calibration_output.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <sstream>

#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace frictionlab::calibration {
namespace fs = std::filesystem;
namespace {

std::string num(double x) { return accuracy::format_number(x); }
std::string g4(double x) { return support::significant(x, 4); }
std::string g3(double x) { return support::significant(x, 3); }

// "Rb = 0.5890 a" or "torsional = 0.5890 k a".
std::string setting(const EngineLaw& law, double c) {
  return law.key + " = " + g4(c) + (law.per_unit_load ? " k a" : " a");
}

std::string terminal_line(const std::string& terminal, int width, int height) {
  const std::string size = std::to_string(width) + "," + std::to_string(height);
  return terminal == "pngcairo" ? "set terminal pngcairo size " + size + " enhanced font 'Sans,11'"
                                : "set terminal png size " + size + " enhanced font 'Sans,10'";
}

void script_head(std::ostream& gp, const std::string& terminal, const std::string& name, int width, int height) {
  gp << "# " << name << ".png from " << name << ".dat, written by `frictionlab calibrate`.\n"
     << "# Redraw: cd into this folder, then `gnuplot " << name << ".gp`.\n"
     << terminal_line(terminal.empty() ? "pngcairo" : terminal, width, height) << '\n'
     << "set output " << support::gnuplot_quoted(name + ".png") << "\nset encoding utf8\n";
}

const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"};

// E(c): one panel per engine law; one curve per pressure (colour) and scope (solid: circle,
// dashed: grid). Data blocks: one per ScanCurve, in result order.
void write_scan_plot(const CalibrationResult& r, const fs::path& plots, const std::string& terminal) {
  std::ostringstream d;
  d << "# c  max|M_law - M_exact|/(kNa); one block per law, pressure, scope (see the script)\n";
  for (const auto& s : r.scans) {
    d << "# " << s.law << ' ' << s.pressure << ' ' << scope_name(s.scope) << '\n';
    for (std::size_t j = 0; j < s.c.size(); ++j) d << g4(s.c[j]) << ' ' << g4(s.max_error_M[j]) << '\n';
    d << "\n\n";
  }
  support::write_file_atomically(plots / "calibration_scan.dat", d.str());

  std::vector<std::string> laws, pressures_seen;
  for (const auto& s : r.scans) {
    if (std::find(laws.begin(), laws.end(), s.law) == laws.end()) laws.push_back(s.law);
    if (std::find(pressures_seen.begin(), pressures_seen.end(), s.pressure) == pressures_seen.end())
      pressures_seen.push_back(s.pressure);
  }
  std::ostringstream gp;
  script_head(gp, terminal, "calibration_scan", 500 * static_cast<int>(laws.size()) + 40, 460);
  gp << "set multiplot layout 1," << laws.size()
     << " title 'Largest torque error over the grid against the coefficient c (solid: circle, dashed: mu in "
     << g3(r.grid.spec().mu_min) << "..1)' font ',12'\n"
     << "set logscale x\nset xlabel 'c  (Rb/a, or torsional/(k a), r\\_spin/(k a))'\n"
     << "set ylabel 'max |ΔM| / (k·N·a)'\nset yrange [0:*]\nset grid\nset key top center\n";
  for (const auto& law : laws) {
    gp << "set title " << support::gnuplot_text(law) << "\nplot ";
    bool first = true;
    for (std::size_t b = 0; b < r.scans.size(); ++b) {
      const auto& s = r.scans[b];
      if (s.law != law) continue;
      const auto colour = static_cast<std::size_t>(
          std::find(pressures_seen.begin(), pressures_seen.end(), s.pressure) - pressures_seen.begin());
      gp << (first ? "" : ", \\\n     ") << "'calibration_scan.dat' index " << b
         << " using 1:2 with lines lw 2 dt " << (s.scope == Scope::circle ? 1 : 2) << " lc rgb '"
         << kColours[colour % 6] << "' title "
         << support::gnuplot_text(s.pressure + (s.scope == Scope::circle ? ", circle" : ", grid"));
      first = false;
    }
    gp << '\n';
  }
  gp << "unset multiplot\n";
  support::write_file_atomically(plots / "calibration_scan.gp", gp.str());
}

// F1 and M on the circle against s: one column per pressure, exact (black) and each engine law at
// its best c for the circle.
void write_forces_plot(const CalibrationResult& r, const fs::path& plots, const std::string& terminal) {
  std::ostringstream d;
  d << "# s  F1/(kN)  M/(kNa); one block per curve (see the script)\n";
  for (const auto& c : r.curves) {
    d << "# " << c.pressure << ' ' << c.label << '\n';
    for (std::size_t i = 0; i < c.F1.size(); ++i)
      d << g4(r.grid.s()[i]) << ' ' << support::significant(c.F1[i], 6) << ' ' << support::significant(c.M[i], 6)
        << '\n';
    d << "\n\n";
  }
  support::write_file_atomically(plots / "calibration_forces.dat", d.str());

  std::vector<std::string> ps;
  for (const auto& c : r.curves)
    if (std::find(ps.begin(), ps.end(), c.pressure) == ps.end()) ps.push_back(c.pressure);
  std::ostringstream gp;
  script_head(gp, terminal, "calibration_forces", 480 * static_cast<int>(ps.size()) + 40, 820);
  gp << "set multiplot layout 2," << ps.size()
     << " title 'Circle (sphere on a plane): exact (black) and the engine laws at their best c for the circle' "
        "font ',12'\n"
     << "set logscale x\nset xlabel 's = U/(a|Ω|)'\nset grid\nset key bottom right font ',9'\n";
  for (const int row : {0, 1}) {
    for (const auto& p : ps) {
      gp << "set title " << support::gnuplot_text("pressure " + p) << "\nset ylabel '"
         << (row == 0 ? "F1/(k·N)" : "M/(k·N·a)") << "'\n"
         << (row == 0 ? "set key bottom right\n" : "set key top right\n") << "plot ";
      bool first = true;
      std::size_t colour = 0;
      for (std::size_t b = 0; b < r.curves.size(); ++b) {
        const auto& c = r.curves[b];
        if (c.pressure != p) continue;
        const bool exact = first;  // the exact law's curve comes first for each pressure
        gp << (first ? "" : ", \\\n     ") << "'calibration_forces.dat' index " << b << " using 1:" << 2 + row
           << " with lines lw " << (exact ? 3 : 2) << " dt " << (exact ? 1 : 1 + colour % 4) << " lc rgb '"
           << (exact ? std::string("black") : std::string(kColours[colour % 6])) << "' title "
           << support::gnuplot_text(c.label);
        if (!exact) ++colour;
        first = false;
      }
      gp << '\n';
    }
  }
  gp << "unset multiplot\n";
  support::write_file_atomically(plots / "calibration_forces.gp", gp.str());
}

}  // namespace

void write_calibration_csv(std::ostream& out, const CalibrationResult& r) {
  out << "law,pressure,scope,exact_spin,closed_form_spin,c_spin,max_F1_spin,max_F2_spin,max_M_spin,rms_M_spin,"
         "c_best,max_F1_best,max_F2_best,max_M_best,rms_M_best,worst_s,worst_mu,worst_psi,worst_sign\n";
  for (const auto& row : r.rows) {
    const auto p = r.grid.point(row.best.worst_M);
    out << row.law << ',' << row.pressure << ',' << scope_name(row.scope) << ',' << num(row.exact_circle_spin)
        << ',' << num(circle_spin_closed_form(row.pressure));
    for (const Errors* e : {&row.at_spin, &row.best}) {
      out << ',' << num(e->c) << ',' << num(e->max[0]) << ',' << num(e->max[1]) << ',' << num(e->max[2]) << ','
          << num(e->rms[2]);
    }
    out << ',' << num(p.s) << ',' << num(p.mu) << ',' << num(p.psi) << ',' << p.sign << '\n';
  }
}

void write_scan_csv(std::ostream& out, const CalibrationResult& r) {
  out << "law,pressure,scope,c,max_err_M\n";
  for (const auto& s : r.scans) {
    for (std::size_t j = 0; j < s.c.size(); ++j) {
      out << s.law << ',' << s.pressure << ',' << scope_name(s.scope) << ',' << num(s.c[j]) << ','
          << num(s.max_error_M[j]) << '\n';
    }
  }
}

void write_curves_csv(std::ostream& out, const CalibrationResult& r) {
  out << "pressure,law,s,F1,M\n";
  for (const auto& c : r.curves) {
    for (std::size_t i = 0; i < c.F1.size(); ++i) {
      out << c.pressure << ',' << c.label << ',' << num(r.grid.s()[i]) << ',' << num(c.F1[i]) << ',' << num(c.M[i])
          << '\n';
    }
  }
}

void write_calibration_markdown(std::ostream& out, const CalibrationResult& r, const accuracy::RunInfo& run) {
  const auto& spec = r.grid.spec();
  out << "<!-- written by `" << run.command << "`, " << run.date << ", " << run.machine << " -->\n\n"
      << "Made by `" << run.command << "` on " << run.date << " (" << run.machine << "; "
      << support::fixed(run.seconds, 1) << " s). Grid: " << spec.s_points << " slip ratios s in ["
      << g3(spec.s_min) << ", " << g3(spec.s_max) << "], " << spec.mu_points << " axis ratios mu in ["
      << g3(spec.mu_min) << ", 1], " << spec.psi_points
      << " orientations, both signs of Omega. Errors per kN = k·N, the friction coefficient times the normal "
         "force (F1, F2), and per kNa = k·N·a (M); c is the pure-spin "
         "torque per kNa the coefficient gives.\n\n";
  for (const Scope scope : {Scope::circle, Scope::grid}) {
    out << (scope == Scope::circle ? "**Circle** (mu = 1: a sphere on a plane)"
                                   : "**Whole grid** (mu in [" + g3(spec.mu_min) + ", 1], all psi)")
        << "\n\n| engine law | pressure | matched at pure spin | max abs dM | max abs dF1 | best for max abs dM "
           "| max abs dM | max abs dF1 | rms dM | max abs dF2 | largest dM at (s, mu, psi) |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& row : r.rows) {
      if (row.scope != scope) continue;
      const EngineLaw& law = engine_law(row.law);
      const auto p = r.grid.point(row.best.worst_M);
      out << "| `" << row.law << "` | " << row.pressure << " | " << setting(law, row.at_spin.c) << " | "
          << g3(row.at_spin.max[2]) << " | " << g3(row.at_spin.max[0]) << " | " << setting(law, row.best.c) << " | "
          << g3(row.best.max[2]) << " | " << g3(row.best.max[0]) << " | " << g3(row.best.rms[2]) << " | "
          << g3(row.best.max[1]) << " | (" << g3(p.s) << ", " << g3(p.mu) << ", "
          << g3(p.psi * 180.0 / std::numbers::pi) << "°) |\n";
    }
    out << '\n';
  }
}

void write_calibration_files(const CalibrationResult& result, const fs::path& dir, const accuracy::RunInfo& run) {
  fs::create_directories(dir);
  const auto put = [&](const char* name, auto&& writer) {
    std::ostringstream s;
    writer(s);
    support::write_file_atomically(dir / name, s.str());
  };
  put("calibration.csv", [&](std::ostream& o) { write_calibration_csv(o, result); });
  put("scan.csv", [&](std::ostream& o) { write_scan_csv(o, result); });
  put("curves.csv", [&](std::ostream& o) { write_curves_csv(o, result); });
  put("calibration_tables.md", [&](std::ostream& o) { write_calibration_markdown(o, result, run); });
}

std::vector<fs::path> write_calibration_plots(const CalibrationResult& result, const fs::path& dir, bool draw,
                                              std::ostream* progress) {
  const fs::path plots = dir / "plots";
  fs::create_directories(plots);
  std::string terminal;
  for (const char* t : {"pngcairo", "png"}) {
    if (support::gnuplot_has_terminal(t)) {
      terminal = t;
      break;
    }
  }
  write_scan_plot(result, plots, terminal);
  write_forces_plot(result, plots, terminal);
  std::vector<fs::path> drawn;
  if (!draw) return drawn;
  if (terminal.empty()) {
    if (progress) *progress << "calibrate: warning: gnuplot (with a png terminal) not found; figures not drawn\n";
    return drawn;
  }
  for (const char* name : {"calibration_scan", "calibration_forces"}) {
    const std::string stem(name);
    const auto run = support::run_gnuplot(plots, stem + ".gp", stem + ".log");
    if (run.ok && fs::exists(plots / (stem + ".png"))) {
      drawn.push_back(plots / (stem + ".png"));
    } else if (progress) {
      *progress << "calibrate: warning: gnuplot failed on " << stem << ".gp (see " << stem << ".log)\n";
    }
  }
  return drawn;
}

}  // namespace frictionlab::calibration
