#include "dynamics/ensemble/outcome_map.h"

#include <map>

#include "dynamics/ensemble/feature_comparison.h"
#include "dynamics/ensemble/sample_statistics.h"

namespace frictionlab::dynamics::ensemble {

std::string_view to_string(CellChange c) {
  switch (c) {
    case CellChange::same: return "same";
    case CellChange::mixed: return "mixed";
    case CellChange::changed: return "changed";
    case CellChange::chaotic: return "chaotic";
    case CellChange::missing: return "missing";
  }
  return "missing";
}

std::optional<GridAxes> map_axes(const Study& s) {
  if (s.design != DesignKind::grid || s.vary.size() != 2) return std::nullopt;
  GridAxes a;
  a.x_key = s.vary[0].key;
  a.y_key = s.vary[1].key;
  a.x = s.vary[0].grid();
  a.y = s.vary[1].grid();
  a.x_log = s.vary[0].scale == AxisScale::log;
  a.y_log = s.vary[1].scale == AxisScale::log;
  return a;
}

std::vector<long> OutcomeMap::count(std::size_t law) const {
  std::vector<long> n(5, 0);
  for (const CellChange c : laws.at(law).change) ++n[static_cast<std::size_t>(c)];
  return n;
}

OutcomeMap build_outcome_map(const GridAxes& axes, const std::vector<std::string>& laws,
                             const std::vector<RunRecord>& rows) {
  OutcomeMap m;
  m.axes = axes;
  const std::size_t cells = m.cells();
  // classes[law][cell]: the classes of the cell's replicas.
  std::map<std::string, std::vector<std::vector<std::string>>> classes;
  for (const auto& law : laws) classes[law].resize(cells);
  for (const auto& r : rows) {
    const auto it = classes.find(r.law);
    if (it == classes.end() || r.start < 0 || static_cast<std::size_t>(r.start) >= cells) continue;
    it->second[static_cast<std::size_t>(r.start)].push_back(r.final_class);
  }
  const auto& reference = classes[laws.front()];
  for (const auto& law : laws) {
    LawMap lm;
    lm.law = law;
    lm.majority_class.resize(cells);
    lm.change.assign(cells, CellChange::missing);
    const auto& mine = classes[law];
    for (std::size_t c = 0; c < cells; ++c) {
      std::map<std::string, long> n;
      for (const auto& k : mine[c]) ++n[k];
      long best = 0;
      for (const auto& [k, v] : n)
        if (v > best) {
          best = v;
          lm.majority_class[c] = k;
        }
      if (law == laws.front() || mine[c].empty() || reference[c].empty()) continue;
      bool unanimous = true;
      for (const auto& k : reference[c]) unanimous = unanimous && k == reference[c].front();
      if (!unanimous) {
        lm.change[c] = CellChange::chaotic;
        continue;
      }
      long other = 0;
      for (const auto& k : mine[c]) other += k != reference[c].front() ? 1 : 0;
      const long total = static_cast<long>(mine[c].size());
      lm.change[c] = other == 0 ? CellChange::same : 2 * other > total ? CellChange::changed : CellChange::mixed;
    }
    m.laws.push_back(std::move(lm));
  }
  return m;
}

std::vector<double> cell_medians(const GridAxes& axes, const std::string& law, const std::vector<RunRecord>& rows,
                                 double (*value)(const RunRecord&)) {
  const std::size_t cells = axes.x.size() * axes.y.size();
  std::vector<std::vector<double>> v(cells);
  for (const auto& r : rows)
    if (r.law == law && ended_normally(r) && r.start >= 0 && static_cast<std::size_t>(r.start) < cells)
      v[static_cast<std::size_t>(r.start)].push_back(value(r));
  std::vector<double> out(cells);
  for (std::size_t c = 0; c < cells; ++c) out[c] = quantile(v[c], 0.5);
  return out;
}

}  // namespace frictionlab::dynamics::ensemble
