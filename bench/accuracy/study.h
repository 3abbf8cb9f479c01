#pragma once
// The accuracy study: every law against the exact one on the study grid.
//
// run_study() evaluates the registry's reference law (friction::reference_law_name(), "exact") and
// each law at every grid point (in parallel over mu), then summarises each law overall and per mu
// slice: error statistics of F1/(kN), F2/(kN), M/(kNa), sign checks, dissipation, singular points
// and (for laws that declare poles) pole brackets. Writing the results is report.h's and plots.h's
// job.

#include <array>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/accuracy/consistency.h"
#include "bench/accuracy/error_stats.h"
#include "bench/accuracy/evaluation.h"
#include "bench/accuracy/grid.h"
#include "bench/accuracy/singularity.h"

namespace frictionlab::accuracy {

/// Laws the registry marks slow (friction::LawInfo::slow, e.g. the 2-D GSL cross-check of `exact`,
/// ~10-30 ms per call) are run only by name, on at most this many points (about a minute on two
/// cores).
inline constexpr std::size_t kSlowLawMaxPoints = 5000;

struct StudyOptions {
  GridSpec grid;                   ///< the grid (defaults: 200 s x 20 mu x 25 psi x 2 signs)
  std::vector<std::string> laws;   ///< law specs to compare with the reference; empty: default_laws()
  std::string reference;           ///< the reference's spec (e.g. exact:pressure=uniform); empty: the
                                   ///< registry's reference law (friction::reference_law_name())
  std::size_t threads = 0;         ///< worker threads, 0: one per hardware thread
  std::ostream* progress = nullptr;  ///< one line per evaluated law, if given
};

/// Every registered law except the reference and the slow ones (registry facts), in registry order.
[[nodiscard]] std::vector<std::string> default_laws();

/// Checks the law names (std::invalid_argument naming an unknown law, a repeated one, or a slow
/// law on a grid larger than kSlowLawMaxPoints).
void check_laws(const std::vector<std::string>& laws, const Grid& grid);

/// Statistics of one law over one set of points (the whole grid or one mu slice). Every index in
/// it is a grid index (Grid::point gives the location).
struct ScopeSummary {
  std::size_t points = 0;
  std::array<ErrorStats, 3> error;  ///< F1, F2, M (see Component)
  std::array<SignStats, 3> sign;    ///< F1, F2, M against the reference's signs
  DissipationStats dissipation;     ///< F1 s + M sign(Omega) < 0
  std::size_t singular_points = 0;  ///< is_singular() points
  std::size_t first_singular = kNoIndex;
};

/// Summarises `law` against `reference` over the grid points numbered in `indices`.
[[nodiscard]] ScopeSummary summarize(const Grid& grid, const LawValues& law,
                                     const LawValues& reference,
                                     const std::vector<std::size_t>& indices);

/// Regions of the grid summarised beside the mu slices: three bands of slip ratio (spin-dominated,
/// comparable, slip-dominated) and the two signs of Omega.
struct Region {
  std::string name;   ///< e.g. "s < 0.1", "Omega < 0"
  std::string label;  ///< a few words for tables
  std::vector<std::size_t> indices;
};
/// Edges of the slip-ratio bands: s < 0.1, 0.1 <= s <= 10, s > 10.
inline constexpr double kSlowBandEdge = 0.1;
inline constexpr double kFastBandEdge = 10.0;
[[nodiscard]] std::vector<Region> study_regions(const Grid& grid);

struct LawSummary {
  std::string law;
  std::string description;         ///< the registry's one-line summary
  ScopeSummary overall;
  std::vector<ScopeSummary> by_mu;  ///< one per grid mu
  std::vector<ScopeSummary> by_region;  ///< one per study_regions() entry
  bool has_denominators = false;    ///< the law declares poles (known_denominators(law) exists)
  std::vector<PoleBracket> poles;   ///< sign changes of its denominators on the grid
  double seconds = 0.0;             ///< wall time of its evaluation on the grid
};

struct StudyResult {
  Grid grid;
  LawValues reference;                ///< the reference law's values; reference.law is its name
  double reference_seconds = 0.0;
  std::vector<Region> regions;        ///< study_regions(grid)
  std::vector<LawValues> values;      ///< one per law, in the order of the options
  std::vector<LawSummary> summaries;  ///< one per law, same order
};

/// Runs the study. Throws std::invalid_argument on bad options (grid or law names).
[[nodiscard]] StudyResult run_study(const StudyOptions& options);

}  // namespace frictionlab::accuracy
