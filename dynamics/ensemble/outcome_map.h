#pragma once
// Maps over the starts of a study whose design is a grid of exactly two varied keys: per cell (one
// start, all its replicas) and law, the median of a feature, the outcome class most replicas end
// in, and whether the law's outcome differs from the reference's beyond the reference's own
// disagreement:
//
//   chaotic  the reference law's replicas of the cell end in different classes: the outcome is
//            decided by chaos, and no law can be said to change it there;
//   same     the reference's replicas agree on a class, and every replica of the law ends in it;
//   mixed    some but at most half of the law's replicas end elsewhere;
//   changed  more than half of the law's replicas end in another class than the reference's
//            unanimous one (with two replicas: both).
//
// Cells are ordered as the starts: start = i * ny + j, i along the first key (x), j the second (y).

#include <optional>
#include <string>
#include <vector>

#include "dynamics/ensemble/run_record.h"
#include "dynamics/ensemble/study.h"

namespace frictionlab::dynamics::ensemble {

enum class CellChange { same, mixed, changed, chaotic, missing };

/// "same", "mixed", "changed", "chaotic", "missing".
[[nodiscard]] std::string_view to_string(CellChange c);

struct GridAxes {
  std::string x_key;
  std::string y_key;
  std::vector<double> x;  ///< the first key's grid values
  std::vector<double> y;  ///< the second key's
  bool x_log = false;
  bool y_log = false;
};

/// The grid of a study with two varied keys on a grid design, or nothing.
[[nodiscard]] std::optional<GridAxes> map_axes(const Study& s);

struct LawMap {
  std::string law;
  std::vector<std::string> majority_class;  ///< per cell ("" without runs)
  std::vector<CellChange> change;           ///< per cell, against the reference (the reference: missing)
};

struct OutcomeMap {
  GridAxes axes;
  std::vector<LawMap> laws;  ///< the study's laws, the reference first

  [[nodiscard]] std::size_t cells() const { return axes.x.size() * axes.y.size(); }
  /// Cells of `law` (index into laws) in each CellChange.
  [[nodiscard]] std::vector<long> count(std::size_t law) const;
};

/// The map of a study's rows (`laws` as in the study, the reference first).
[[nodiscard]] OutcomeMap build_outcome_map(const GridAxes& axes, const std::vector<std::string>& laws,
                                           const std::vector<RunRecord>& rows);

/// The per-cell median over the replicas of `value` for the runs of `law` that ended normally
/// (NaN where none has a finite value).
[[nodiscard]] std::vector<double> cell_medians(const GridAxes& axes, const std::string& law,
                                               const std::vector<RunRecord>& rows,
                                               double (*value)(const RunRecord&));

}  // namespace frictionlab::dynamics::ensemble
