// engines_side_by_side: the physics engines side by side on the classical problems of sliding and
// spinning friction (docs/engines.md §6), against the exact law and the closed forms.
//
//   engines_side_by_side --out DIR [--scenarios DIR] [--problems ID,...] [--engines NAME,...]
//                        [--no-scan] [--no-plots]
//
// The four problems (bench/engines/problems.h) are built from the shipped scenarios; each runs in
// frictionlab with `exact` and in every engine this build has (bench/engines/engine_list.h) with
// five settings: the engine's defaults; the torsional coefficient docs/engines.md §4 recommends
// (calibrated to the pure-spin torque of frictionlab's static patch); the same at a 1e-4 s step;
// the same with the engine's own options that bring it closest (bench/engines/engine_list.h
// tuned_engines); and the best of a scan of that coefficient over factors 1/8 .. 8 (not for slide-to-roll, where
// it plays no part). Engines that are not built are named on one line; the rest runs.
//
// Output under DIR: engines.csv (one row per run: the measure, the answer, the settings, the CPU
// time), engines.md (the tables, with the command, machine and date), runs/<engine>/<problem>/
// <setting>.csv (the samples), plots/<problem>.{gp,dat,png}.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bench/accuracy/report.h"
#include "bench/engines/engine_list.h"
#include "bench/engines/frictionlab_runs.h"
#include "bench/engines/measures.h"
#include "bench/engines/problems.h"
#include "friction/support/checked_output.h"
#include "friction/support/gnuplot.h"
#include "friction/support/number_format.h"

namespace fs = std::filesystem;
using namespace frictionlab;
using namespace frictionlab::engines;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Setting {
  std::string name;  ///< "defaults", "calibrated", "calibrated, step 1e-4 s", "best of scan (x2)"
  Friction friction;
  Numerics numerics;
};

struct Row {
  std::string engine;   ///< "MuJoCo 2.2.2", "frictionlab"
  std::string problem;  ///< Problem::id
  Setting setting;
  Run run;
  Measure measure;
  double answer = kNaN;
  double cpu_s = 0.0;
  std::string ended;    ///< frictionlab's termination, else empty
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

std::string g4(double x) { return std::isnan(x) ? "—" : support::significant(x, 4); }

// |value - answer| / |answer|; infinity for a value never reached.
double relative_error(double value, double answer) {
  return std::isnan(value) ? std::numeric_limits<double>::infinity() : std::abs(value - answer) / std::abs(answer);
}

// A measure for the table: "never" for NaN, "→ ∞" and "→ 0" for the puck's ratio when one motion
// stopped long before the other.
std::string shown_value(const std::string& problem, double x) {
  if (std::isnan(x)) return "never";
  if (problem == "puck" && x > 1e3) return "→ ∞";
  if (problem == "puck" && x < 1e-3) return "→ 0";
  return g4(x);
}

std::string slug(std::string s) {
  for (char& c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  }
  return s;
}

void write_samples(const fs::path& file, const std::vector<Sample>& samples) {
  std::string csv = "t,x,y,z,vx,vy,vz,omega_x,omega_y,omega_z,qw,qx,qy,qz,gamma3,N\n";
  for (const Sample& s : samples) {
    support::append_shortest(csv, s.t);
    for (const double x : s.com) (csv += ','), support::append_shortest(csv, x);
    for (const double x : s.v) (csv += ','), support::append_shortest(csv, x);
    for (const double x : s.omega) (csv += ','), support::append_shortest(csv, x);
    for (const double x : s.orientation) (csv += ','), support::append_shortest(csv, x);
    csv += ',';
    support::append_shortest(csv, axis_vertical(s.orientation));
    csv += ',';
    support::append_shortest(csv, s.normal_force);
    csv += '\n';
  }
  fs::create_directories(file.parent_path());
  support::write_file_atomically(file, csv);
}

Row run_engine(const Engine& engine, const Problem& p, const Setting& setting) {
  RunSpec spec = p.spec;
  spec.friction = setting.friction;
  spec.friction.k = p.spec.friction.k;
  const double g = spec.numerics.g;
  spec.numerics = setting.numerics;
  spec.numerics.g = g;
  // The sphere problems start at rest on the plane except for their velocities: a soft contact
  // first finds its depth (0.2 s); the tilted tippe top and the disk start as they are.
  if (p.id == "spin-down" || p.id == "slide-to-roll") spec.numerics.settle_time = 0.2;
  Row r;
  r.engine = engine.name() + " " + engine.version();
  r.problem = p.id;
  r.setting = setting;
  r.answer = p.answer;
  const double c0 = cpu_seconds();
  try {
    r.run = engine.run(spec);
  } catch (const std::runtime_error& e) {
    // The engine gave up (e.g. MuJoCo's "simulation is unstable"): a result of the comparison,
    // recorded as the row's outcome; bad input (std::invalid_argument) still ends the program.
    r.cpu_s = cpu_seconds() - c0;
    r.measure.value = kNaN;
    r.measure.time = kNaN;
    r.measure.detail = std::string("the engine failed: ") + e.what();
    return r;
  }
  r.cpu_s = cpu_seconds() - c0;
  r.measure = measure(p, r.run.samples);
  return r;
}

// The plotted quantity of a problem's sample.
double plotted(const Problem& p, const Sample& s) {
  if (p.id == "spin-down") return s.omega[2];
  if (p.id == "puck") return std::hypot(s.v[0], s.v[1]) / (p.patch_radius * std::abs(s.omega[2]));
  if (p.id == "tippe-top") return axis_vertical(s.orientation);
  return std::hypot(s.v[0], s.v[1]);
}

std::string plotted_label(const Problem& p) {
  if (p.id == "spin-down") return "ω_z (1/s)";
  if (p.id == "puck") return "v/(a ω)";
  if (p.id == "tippe-top") return "γ_3 (axis . e_z)";
  return "|v| (m/s)";
}

void write_plot(const fs::path& dir, const Problem& p, const std::vector<const Row*>& rows, bool draw) {
  std::ostringstream dat, gp;
  dat << "# " << p.title << ": t and " << plotted_label(p) << ", one block per run (see the script)\n";
  for (const Row* r : rows) {
    dat << "# " << r->engine << ", " << r->setting.name << '\n';
    for (const Sample& s : r->run.samples) dat << support::significant(s.t, 8) << ' ' << support::significant(plotted(p, s), 6) << '\n';
    dat << "\n\n";
  }
  const std::string stem = p.id;
  support::write_file_atomically(dir / (stem + ".dat"), dat.str());
  const char* colours[] = {"black", "#D55E00", "#0072B2", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"};
  gp << "# " << stem << ".png from " << stem << ".dat, written by engines_side_by_side.\n"
     << "# Redraw: cd into this folder, then `gnuplot " << stem << ".gp`.\n"
     << "set terminal pngcairo size 1000,560 enhanced font 'Sans,11'\nset output " << support::gnuplot_quoted(stem + ".png") << '\n'
     << "set encoding utf8\nset grid\nset key outside right top\nset xlabel 't (s)'\n"
     << "set ylabel " << support::gnuplot_quoted(plotted_label(p)) << '\n'
     << "set title " << support::gnuplot_text(p.title + ": " + p.quantity + ", answer " + g4(p.answer)) << '\n';
  if (p.id == "puck") gp << "set logscale y\nset yrange [0.1:100]\nset xrange [0:0.8]\n";
  gp << "plot ";
  std::vector<std::string> engines;  // one colour per engine, dashed for its defaults
  for (const Row* r : rows) {
    if (std::find(engines.begin(), engines.end(), r->engine) == engines.end()) engines.push_back(r->engine);
  }
  for (std::size_t b = 0; b < rows.size(); ++b) {
    const auto colour = static_cast<std::size_t>(
        std::find(engines.begin(), engines.end(), rows[b]->engine) - engines.begin());
    const bool ref = rows[b]->engine == "frictionlab";
    const bool dashed = rows[b]->setting.name == "defaults";
    gp << (b ? ", \\\n     " : "") << support::gnuplot_quoted(stem + ".dat") << " index " << b << " using 1:2 with lines lw " << (ref ? 3 : 2)
       << " dt " << (dashed ? 2 : 1) << " lc rgb '" << colours[colour % 7] << "' title "
       << support::gnuplot_text(rows[b]->engine + ", " + rows[b]->setting.name);
  }
  gp << '\n';
  support::write_file_atomically(dir / (stem + ".gp"), gp.str());
  if (draw) {
    const auto r = support::run_gnuplot(dir, stem + ".gp", stem + ".log");
    if (!r.ok) std::cerr << "engines: warning: gnuplot: " << r.message << std::endl;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The physics engines side by side on the classical problems of sliding and spinning friction"};
  std::string out, scenarios = "data/scenarios";
  std::vector<std::string> only_problems, only_engines;
  bool no_scan = false, no_plots = false;
  app.add_option("--out", out, "output folder")->required();
  app.add_option("--scenarios", scenarios, "the folder of the shipped scenarios")->capture_default_str();
  app.add_option("--problems", only_problems, "only these problems (spin-down,puck,tippe-top,slide-to-roll)")
      ->delimiter(',');
  app.add_option("--engines", only_engines, "only these engines (MuJoCo,Bullet,ODE)")->delimiter(',');
  app.add_flag("--no-scan", no_scan, "skip the scan of the torsional coefficient");
  app.add_flag("--no-plots", no_plots, "do not run gnuplot");
  CLI11_PARSE(app, argc, argv);

  try {
    std::ostringstream command;
    for (int i = 0; i < argc; ++i) command << (i ? " " : "") << (i == 0 ? "engines_side_by_side" : argv[i]);
    const auto wall0 = std::chrono::steady_clock::now();
    std::vector<Problem> problems = make_problems(scenarios);
    if (!only_problems.empty()) {
      for (const auto& id : only_problems) {
        if (std::none_of(problems.begin(), problems.end(), [&](const Problem& p) { return p.id == id; }))
          throw std::invalid_argument("--problems: '" + id + "' is not a problem (spin-down, puck, tippe-top, slide-to-roll)");
      }
      std::erase_if(problems, [&](const Problem& p) {
        return std::find(only_problems.begin(), only_problems.end(), p.id) == only_problems.end();
      });
    }
    auto engines = built_engines();
    const auto tuned = tuned_engines();
    if (!only_engines.empty()) {
      std::erase_if(engines, [&](const auto& e) {
        return std::find(only_engines.begin(), only_engines.end(), e->name()) == only_engines.end();
      });
    }
    const auto missing = missing_engines();
    if (!missing.empty()) {
      std::string line = "engines: not built (package not installed): ";
      for (std::size_t i = 0; i < missing.size(); ++i) line += (i ? ", " : "") + missing[i];
      std::cerr << line << "; running the others" << std::endl;
    }
    const fs::path dir(out);
    fs::create_directories(dir / "plots");

    std::vector<Row> rows;
    for (Problem& p : problems) {
      // frictionlab with the scenario's exact law first: the tippe top's answer is its run.
      Row f;
      f.engine = "frictionlab";
      f.problem = p.id;
      f.setting.name = p.law;
      const double c0 = cpu_seconds();
      FrictionlabRun fr = run_frictionlab(p, p.law, dir / "runs" / "frictionlab" / p.id);
      f.cpu_s = cpu_seconds() - c0;
      f.run = std::move(fr.run);
      f.ended = fr.ended;
      f.measure = measure(p, f.run.samples);
      if (std::isnan(p.answer)) p.answer = f.measure.value;
      f.answer = p.answer;
      std::cerr << "engines: " << p.id << ": frictionlab " << p.law << ": " << g4(f.measure.value) << " (answer " << g4(p.answer)
                << "), " << f.ended << std::endl;
      rows.push_back(std::move(f));

      for (const auto& engine : engines) {
        const double k = p.spec.friction.k;
        const Friction cal = engine->calibrated(k, p.spin_c, p.patch_radius);
        std::vector<Setting> settings = {{"defaults", engine->defaults(k), {}}, {"calibrated", cal, {}}};
        Setting fine{"calibrated, step 1e-4 s", cal, {}};
        fine.numerics.timestep = 1e-4;
        settings.push_back(fine);
        const auto report = [&](const Row& r) {
          std::cerr << "engines: " << p.id << ": " << r.engine << ", " << r.setting.name << ": " << g4(r.measure.value)
                    << " (" << g4(r.cpu_s) << " s CPU)" << std::endl;
        };
        for (const Setting& s : settings) {
          rows.push_back(run_engine(*engine, p, s));
          report(rows.back());
        }
        // The engine's own options that this study found bring it closest, with the calibration.
        for (const auto& variant : tuned) {
          if (variant.engine->name() != engine->name()) continue;
          rows.push_back(run_engine(*variant.engine, p, {"calibrated, " + variant.label, cal, {}}));
          report(rows.back());
        }
        if (!no_scan && p.id != "slide-to-roll") {
          Row best;
          double best_error = std::numeric_limits<double>::infinity();
          for (const double factor : {0.125, 0.25, 0.5, 0.7071, 1.4142, 2.0, 4.0, 8.0}) {
            Setting s{"", cal, {}};
            s.friction.torsional = cal.torsional * factor;
            s.name = "best of scan (" + g4(factor) + " × calibrated)";
            Row r = run_engine(*engine, p, s);
            const double e = relative_error(r.measure.value, p.answer);
            if (e < best_error) {
              best_error = e;
              best = std::move(r);
            }
          }
          // The calibrated run (factor 1) is a candidate too.
          const Row& calibrated_row = *std::find_if(rows.rbegin(), rows.rend(), [&](const Row& r) {
            return r.engine == engine->name() + " " + engine->version() && r.problem == p.id &&
                   r.setting.name == "calibrated";
          });
          if (relative_error(calibrated_row.measure.value, p.answer) <= best_error) {
            best = calibrated_row;
            best.setting.name = "best of scan (1 × calibrated)";
          }
          std::cerr << "engines: " << p.id << ": " << best.engine << ", " << best.setting.name << ": "
                    << g4(best.measure.value) << std::endl;
          rows.push_back(std::move(best));
        }
      }
    }

    // The samples of every run kept, the CSV and the tables.
    for (const Row& r : rows) {
      if (r.engine == "frictionlab") continue;  // its run folder has trajectory.csv
      write_samples(dir / "runs" / slug(r.engine) / r.problem / (slug(r.setting.name) + ".csv"), r.run.samples);
    }
    std::string csv =
        "engine,problem,setting,torsional,rolling,timestep,iterations,value,answer,relative_error,time,cpu_s,detail,notes\n";
    const auto quoted = [](const std::string& s) {
      std::string q = "\"";
      for (const char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
      return q + "\"";
    };
    for (const Row& r : rows) {
      csv += quoted(r.engine) + ',' + r.problem + ',' + quoted(r.setting.name) + ',' + support::shortest(r.setting.friction.torsional) +
             ',' + support::shortest(r.setting.friction.rolling) + ',' + support::shortest(r.run.timestep) + ',' +
             std::to_string(r.run.iterations) + ',' + support::shortest(r.measure.value) + ',' + support::shortest(r.answer) +
             ',' + support::shortest(relative_error(r.measure.value, r.answer)) + ',' + support::shortest(r.measure.time) +
             ',' + support::shortest(r.cpu_s) + ',' + quoted(r.measure.detail + (r.ended.empty() ? "" : "; " + r.ended)) +
             ',' + quoted(r.run.notes) + '\n';
    }
    support::write_file_atomically(dir / "engines.csv", csv);

    const auto info = accuracy::describe_this_run();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    std::ostringstream md;
    md << "<!-- written by `" << command.str() << "` -->\n\n"
       << "Made by `" << command.str() << "` on " << info.date << " (" << info.machine << "), " << g4(wall)
       << " s in all.\n";
    for (const Problem& p : problems) {
      md << "\n**" << p.title << "** (" << p.scenario.filename().string() << "; patch radius a = " << g4(p.patch_radius)
         << " m, pure spin c = " << g4(p.spin_c) << "). Measured: " << p.quantity << ". Answer: " << g4(p.answer) << ", "
         << p.answer_source << ".\n\n"
         << "| run | setting | torsional | step (s) | measured | error | also | CPU (s) |\n"
         << "|---|---|---|---|---|---|---|---|\n";
      for (const Row& r : rows) {
        if (r.problem != p.id) continue;
        const double e = relative_error(r.measure.value, r.answer);
        md << "| " << r.engine << " | " << r.setting.name << " | "
           << (r.engine == "frictionlab" ? "—" : g4(r.setting.friction.torsional)) << " | "
           << (r.engine == "frictionlab" ? "adaptive" : g4(r.run.timestep)) << " | "
           << shown_value(p.id, r.measure.value) << " | "
           << (std::isinf(e) || (p.id == "puck" && (r.measure.value > 1e3 || r.measure.value < 1e-3)) ? "—" : support::significant(100.0 * e, 2) + " %") << " | " << r.measure.detail
           << (r.ended.empty() ? "" : "; " + r.ended) << " | " << g4(r.cpu_s) << " |\n";
      }
    }
    md << "\nEach engine's settings (Run::notes):\n\n";
    std::vector<std::string> seen;
    for (const Row& r : rows) {
      if (r.engine == "frictionlab" || std::find(seen.begin(), seen.end(), r.engine) != seen.end()) continue;
      seen.push_back(r.engine);
      md << "* " << r.engine << ": " << r.run.notes << '\n';
    }
    support::write_file_atomically(dir / "engines.md", md.str());

    for (const Problem& p : problems) {
      std::vector<const Row*> plotted_rows;
      for (const Row& r : rows) {
        if (r.problem == p.id && (r.engine == "frictionlab" || r.setting.name == "defaults" || r.setting.name == "calibrated"))
          plotted_rows.push_back(&r);
      }
      write_plot(dir / "plots", p, plotted_rows, !no_plots);
    }
    std::cout << md.str();
    support::finish_standard_output();
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "engines_side_by_side: error: " << e.what() << std::endl;
    return 1;
  }
}
