// mujoco_side_by_side: a sphere that slides and spins on a plane, run in MuJoCo (condim 4, elliptic
// cone) and in frictionlab with the `exact` and `mujoco-elliptic` laws, from one scenario file;
// writes the slip and spin histories, a table and a figure (docs/engines.md §4).
//
//   mujoco_side_by_side SCENARIO --out DIR [--set KEY=VALUE]... [--torsional T] [--laws SPEC,...]
//                       [--timestep DT] [--solref-timeconst TC] [--impratio R] [--no-plots]
//
// The sphere (radius, mass, inertia), k, g, the initial velocities, t_end and output_dt are the
// scenario's (its body must be the `sphere` preset standing upright: gamma = (0, 0, 1)). MuJoCo's
// torsional coefficient is --torsional, by default the Hertz pure-spin calibration at the static
// load, T = (3 pi/16) k a0 (to 4 digits) with a0 = sqrt(2 |eps0| R) the static patch radius (docs/engines.md §3);
// the same T is given to frictionlab's `mujoco-elliptic:torsional=T`.
//
// Output under DIR: mujoco/sphere.xml (the model), mujoco/trajectory.csv, frictionlab/<law>/ (each
// run: trajectory.csv, summary.json, scenario.toml), side_by_side.md (the table, with the command,
// machine and date), plots/side_by_side.{gp,dat,png}.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/accuracy/report.h"
#include "bench/mujoco/mujoco_sphere.h"
#include "dynamics/body/equations_of_motion.h"  // the body's Sample and Observer
#include "dynamics/core/observer.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"
#include "friction/registry.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace fs = std::filesystem;
using namespace frictionlab;

namespace {

struct History {
  std::string label;
  std::vector<double> t, U, Omega, N;
  std::string ended;  // how the run ended
};

// Collects t, U, Omega, N of every frictionlab sample.
class Recorder final : public dynamics::Observer {
 public:
  explicit Recorder(History& h) : h_(h) {}
  void sample(const dynamics::Sample& s) override {
    h_.t.push_back(s.t);
    h_.U.push_back(s.contact.U);
    h_.Omega.push_back(s.contact.Omega);
    h_.N.push_back(s.contact.N);
  }

 private:
  History& h_;
};

// Linear interpolation of y(t) at `at` (NaN past the end of the run).
double at_time(const std::vector<double>& t, const std::vector<double>& y, double at) {
  if (t.empty() || at > t.back() + 1e-12) return std::numeric_limits<double>::quiet_NaN();
  const auto it = std::lower_bound(t.begin(), t.end(), at);
  if (it == t.begin()) return y.front();
  if (it == t.end()) return y.back();
  const auto j = static_cast<std::size_t>(it - t.begin());
  const double w = (at - t[j - 1]) / (t[j] - t[j - 1]);
  return y[j - 1] + w * (y[j] - y[j - 1]);
}

// The first time y falls below `fraction` of its start (NaN if never).
double time_below(const std::vector<double>& t, const std::vector<double>& y, double fraction) {
  const double y0 = std::abs(y.front());
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::abs(y[i]) < fraction * y0) return t[i];
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::string g4(double x) { return std::isnan(x) ? "—" : support::significant(x, 4); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"A sphere sliding and spinning on a plane: MuJoCo (condim 4, elliptic cone) beside frictionlab"};
  std::string scenario_file, out;
  std::vector<std::string> sets, laws;
  double torsional = 0.0, timestep = 1e-4, solref_timeconst = 0.02, impratio = 1.0;
  bool no_plots = false;
  app.add_option("scenario", scenario_file, "scenario file (a `sphere` body)")->required();
  app.add_option("--out", out, "output folder")->required();
  app.add_option("--set", sets, "override a scenario key (repeatable)");
  app.add_option("--torsional", torsional, "MuJoCo's torsional coefficient, m (default: (3 pi/16) k a0)");
  app.add_option("--laws", laws, "frictionlab laws (default: exact and mujoco-elliptic with the same torsional)")
      ->delimiter(',');
  app.add_option("--timestep", timestep, "MuJoCo's time step, s")->capture_default_str();
  app.add_option("--solref-timeconst", solref_timeconst, "MuJoCo's solref time constant, s")->capture_default_str();
  app.add_option("--impratio", impratio, "MuJoCo's impratio")->capture_default_str();
  app.add_flag("--no-plots", no_plots, "do not run gnuplot");
  CLI11_PARSE(app, argc, argv);

  try {
    std::ostringstream command;
    for (int i = 0; i < argc; ++i) command << (i ? " " : "") << (i == 0 ? "mujoco_side_by_side" : argv[i]);
    const auto doc = dynamics::ScenarioDocument::read(scenario_file);
    const dynamics::Scenario base = doc.resolve(sets);
    if (base.body_spec.preset != "sphere" || !base.body_spec.radius) {
      throw std::invalid_argument("body.preset = '" + base.body_spec.preset +
                                  "' is invalid here: the side by side needs a `sphere` body");
    }
    if ((base.initial.gamma - Eigen::Vector3d::UnitZ()).norm() > 1e-12) {
      throw std::invalid_argument("initial.gamma is invalid here: the side by side needs [0, 0, 1]");
    }
    const double R = *base.body_spec.radius;
    const double weight = base.body.mass * base.contact.g;
    const double a0 = std::sqrt(2.0 * -base.contact.static_height(weight) * R);
    // Rounded to 4 digits, the value both MuJoCo and the law spec then carry (short in labels).
    if (torsional == 0.0) torsional = std::stod(support::significant(3.0 * std::numbers::pi / 16.0 * base.contact.k * a0, 4));
    if (laws.empty()) laws = {"exact", "mujoco-elliptic:torsional=" + support::shortest(torsional)};

    const fs::path dir(out);
    fs::create_directories(dir / "mujoco");
    fs::create_directories(dir / "plots");

    mujoco_side::SphereSpec spec;
    spec.R = R;
    spec.mass = base.body.mass;
    if (!base.body.axisymmetric)
      throw std::invalid_argument("body.inertia is invalid here: the side by side needs the sphere's centre of mass at "
                                  "its centre and J = diag(A, A, C)");
    spec.A = base.body.axisymmetric->A;
    spec.C = base.body.axisymmetric->C;
    spec.g = base.contact.g;
    spec.k = base.contact.k;
    spec.torsional = torsional;
    for (int i = 0; i < 3; ++i) {
      spec.v0[i] = base.initial.v[i];
      spec.omega0[i] = base.initial.omega[i];
    }
    spec.t_end = base.run.t_end;
    spec.output_dt = base.run.output_dt;
    spec.timestep = timestep;
    spec.solref_timeconst = solref_timeconst;
    spec.impratio = impratio;
    std::cerr << "side by side: MuJoCo " << mujoco_side::mujoco_version() << ", torsional = " << torsional
              << " m, a0 = " << a0 << " m" << std::endl;
    const auto samples = mujoco_side::run_sphere(spec, dir / "mujoco" / "sphere.xml");

    std::vector<History> runs;
    History mj{"MuJoCo " + mujoco_side::mujoco_version() + " (condim 4, elliptic)", {}, {}, {}, {}, "t_end"};
    {
      std::ostringstream csv;
      csv << "t,U,Omega,v1,v2,v3,omega1,omega2,omega3,N,Ft,tau,depth\n";
      for (const auto& s : samples) {
        mj.t.push_back(s.t);
        mj.U.push_back(s.U);
        mj.Omega.push_back(s.Omega);
        mj.N.push_back(s.N);
        csv << support::shortest(s.t) << ',' << support::shortest(s.U) << ',' << support::shortest(s.Omega);
        for (const double x : s.v) csv << ',' << support::shortest(x);
        for (const double x : s.omega) csv << ',' << support::shortest(x);
        csv << ',' << support::shortest(s.N) << ',' << support::shortest(s.Ft) << ',' << support::shortest(s.tau)
            << ',' << support::shortest(s.depth) << '\n';
      }
      support::write_file_atomically(dir / "mujoco" / "trajectory.csv", csv.str());
    }
    runs.push_back(mj);

    for (const auto& law : laws) {
      auto overrides = sets;
      overrides.push_back("contact.law=" + law);
      const dynamics::Scenario s = doc.resolve(overrides);
      History h{"frictionlab " + law, {}, {}, {}, {}, ""};
      Recorder rec(h);
      const auto run = dynamics::run_scenario(s, dir / "frictionlab" / friction::law_file_stem(law), &rec);
      h.ended = std::string(dynamics::to_string(run.summary.reason)) + " at " + g4(run.summary.t_final) + " s";
      std::cerr << "side by side: " << law << " ended " << h.ended << std::endl;
      runs.push_back(std::move(h));
    }

    // The table.
    const auto info = accuracy::describe_this_run();
    std::ostringstream md;
    md << "<!-- written by `" << command.str() << "` -->\n\n"
       << "Made by `" << command.str() << "` on " << info.date << " (" << info.machine << "). Sphere R = " << g4(R)
       << " m, m = " << g4(base.body.mass) << " kg, k = " << g4(base.contact.k) << ", static patch a0 = " << g4(a0)
       << " m, MuJoCo torsional = " << g4(torsional) << " m, timestep " << g4(timestep) << " s, solref ("
       << g4(solref_timeconst) << ", 1), impratio " << g4(impratio) << ".\n\n"
       << "| run | U falls below 1% of U0 at (s) | Omega below 1% of Omega0 at (s) |";
    const std::vector<double> times = {0.01, 0.03, 0.1, 0.3, 1.0, 3.0};
    for (const double t : times) md << " U, Omega at " << g4(t) << " s |";
    md << " run ended |\n|---|---|---|";
    for (std::size_t i = 0; i < times.size(); ++i) md << "---|";
    md << "---|\n";
    for (const auto& h : runs) {
      md << "| " << h.label << " | " << g4(time_below(h.t, h.U, 0.01)) << " | " << g4(time_below(h.t, h.Omega, 0.01))
         << " |";
      for (const double t : times) md << ' ' << g4(at_time(h.t, h.U, t)) << ", " << g4(at_time(h.t, h.Omega, t)) << " |";
      md << ' ' << h.ended << " |\n";
    }
    support::write_file_atomically(dir / "side_by_side.md", md.str());

    // The figure: U(t) over the slip phase, Omega(t) over the whole run, N(t).
    std::ostringstream dat;
    dat << "# t  U  Omega  N; one block per run (see the script)\n";
    for (const auto& h : runs) {
      dat << "# " << h.label << '\n';
      for (std::size_t i = 0; i < h.t.size(); ++i) {
        dat << support::significant(h.t[i], 8) << ' ' << support::significant(h.U[i], 6) << ' '
            << support::significant(h.Omega[i], 6) << ' ' << support::significant(h.N[i], 6) << '\n';
      }
      dat << "\n\n";
    }
    support::write_file_atomically(dir / "plots" / "side_by_side.dat", dat.str());
    double t_slip = 0.0;
    for (const auto& h : runs) {
      const double ts = time_below(h.t, h.U, 0.01);
      t_slip = std::max(t_slip, std::isnan(ts) ? base.run.t_end : ts);
    }
    const char* colours[] = {"black", "#D55E00", "#0072B2", "#009E73", "#CC79A7"};
    std::ostringstream gp;
    gp << "# side_by_side.png from side_by_side.dat, written by mujoco_side_by_side.\n"
       << "# Redraw: cd into this folder, then `gnuplot side_by_side.gp`.\n"
       << "set terminal pngcairo size 1500,460 enhanced font 'Sans,11'\nset output 'side_by_side.png'\n"
       << "set encoding utf8\nset grid\nset xlabel 't (s)'\n"
       << "set multiplot layout 1,3 title " << support::gnuplot_text(
              "Sphere R = " + g4(R) + " m sliding and spinning: MuJoCo against frictionlab (torsional = " +
              g4(torsional) + " m)") << " font ',12'\n";
    const auto panel = [&](const std::string& title, int column, double xmax, const std::string& ylabel) {
      gp << "set title " << support::gnuplot_text(title) << "\nset ylabel " << support::gnuplot_text(ylabel)
         << "\nset xrange [0:" << g4(xmax) << "]\nplot ";
      for (std::size_t b = 0; b < runs.size(); ++b) {
        gp << (b ? ", \\\n     " : "") << "'side_by_side.dat' index " << b << " using 1:" << column
           << " with lines lw " << (b == 0 ? 3 : 2) << " dt " << 1 + b % 4 << " lc rgb '" << colours[b % 5]
           << "' title " << support::gnuplot_text(runs[b].label);
      }
      gp << '\n';
    };
    panel("slip speed of the contact point", 2, std::min(base.run.t_end, 1.5 * t_slip), "U (m/s)");
    panel("spin about the vertical", 3, base.run.t_end, "Ω (1/s)");
    panel("normal force", 4, std::min(base.run.t_end, 1.5 * t_slip), "N (N)");
    gp << "unset multiplot\n";
    support::write_file_atomically(dir / "plots" / "side_by_side.gp", gp.str());
    if (!no_plots) {
      const auto r = support::run_gnuplot(dir / "plots", "side_by_side.gp", "side_by_side.log");
      if (!r.ok) std::cerr << "side by side: warning: gnuplot: " << r.message << std::endl;
    }
    std::cout << md.str();
    support::finish_standard_output();
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "mujoco_side_by_side: error: " << e.what() << std::endl;
    return 1;
  }
}
