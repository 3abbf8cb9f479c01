#pragma once
// The puck study (`frictionlab puck-study`, docs/puck.md §4): every friction law on the sliding-
// spinning puck, against the law's own prediction and against each other.
//
//   theory   for each law and inertia ratio kappa: the terminal regime of a circular patch and its
//            ratio r*, with the exponent lambda of the approach (dynamics/puck/terminal_ratio.h);
//            and the drift G(r) at kappa = 1/2 (for a figure);
//   disk     puck-disk.toml for each law, inertia ratio (run_kappas) and starting ratio v/(a omega)
//            (start_ratios, at omega0 of the file): the stop times of slip and spin, the terminal
//            ratio measured at the first stop and extrapolated from the energy decades, and the
//            ratio against the kinetic energy (for a figure). The rest thresholds are lowered to
//            `threshold_fraction` of the scales so that the ratio has decades to converge in;
//   ellipse  puck-ellipse.toml for each law: stop times, the path (its sideways deviation from the
//            line of the initial velocity, where it ends against the exact law's end), the angle
//            turned.
// Every run is its scenario file with overrides (recorded), so `frictionlab simulate FILE --set ...`
// reruns it. The laws are specs given to friction::make_law; a spec the registry refuses (a
// pressure model not yet registered) is listed as unavailable and skipped.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/puck/puck_run.h"
#include "dynamics/puck/puck_summary_json.h"
#include "dynamics/puck/terminal_ratio.h"

namespace frictionlab::dynamics::puck {

struct PuckStudyOptions {
  std::filesystem::path scenario_dir;  ///< holds puck-disk.toml and puck-ellipse.toml
  std::vector<std::string> laws;       ///< law specs; empty: default_study_laws()
  std::vector<double> kappas = {0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7, 0.8, 1.0, 1.5};
  std::vector<double> run_kappas = {0.3, 0.5, 1.0};
  std::vector<double> start_ratios = {0.25, 4.0};
  double threshold_fraction = 1e-6;  ///< run.rest_slip_speed / sqrt(g a) and run.rest_spin / sqrt(g/a)

  void validate() const;  ///< std::invalid_argument naming the option
};

/// Every registered law that is not slow (friction/registry.h), then the pressure-model specs exact:pressure=uniform and
/// exact:pressure=punch where the registry accepts them; those it refuses go to `unavailable`.
[[nodiscard]] std::vector<std::string> default_study_laws(std::vector<std::string>* unavailable = nullptr);

struct TheoryRow {
  std::string law;
  double kappa = 0.0;
  TerminalRatioAnalysis analysis;
};

struct DiskRun {
  std::string law;
  double kappa = 0.0;
  double start_ratio = 0.0;
  std::vector<std::string> overrides;  ///< on puck-disk.toml
  PuckRunSummary summary;
  /// (kinetic energy / initial, U/(a|Omega|)) while both motions go on: samples and decades.
  std::vector<std::pair<double, double>> ratio_curve;
};

struct EllipseRun {
  std::string law;
  std::vector<std::string> overrides;  ///< on puck-ellipse.toml
  PuckRunSummary summary;
  PathOffset offset;                   ///< of the end from the line of the initial velocity
  std::vector<Eigen::Vector2d> path;   ///< the centre at the samples
};

struct PuckStudyResults {
  std::vector<std::string> laws;         ///< studied
  std::vector<std::string> unavailable;  ///< refused by the registry
  std::vector<TheoryRow> theory;
  /// G(r) at kappa = 1/2 per law: (r, G) on a logarithmic grid.
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> drift;
  std::vector<DiskRun> disk;
  std::vector<EllipseRun> ellipse;
  std::filesystem::path disk_file, ellipse_file;
  double disk_omega0 = 0.0;  ///< omega0 of puck-disk.toml
  double wall_time = 0.0;    ///< s
};

/// Runs the study. Throws std::invalid_argument for bad options, a missing scenario file or a law
/// spec that is refused when given explicitly.
[[nodiscard]] PuckStudyResults run_puck_study(const PuckStudyOptions& options);

}  // namespace frictionlab::dynamics::puck
