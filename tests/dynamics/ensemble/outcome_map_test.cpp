// Maps over a grid of starts (dynamics/ensemble/outcome_map.h).

#include "dynamics/ensemble/outcome_map.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frictionlab::dynamics::ensemble {
namespace outcome_map_test {

RunRecord run(long start, long replica, const std::string& law, const std::string& cls, double t_vertical = std::nan("")) {
  RunRecord r;
  r.start = start;
  r.replica = replica;
  r.law = law;
  r.final_class = cls;
  r.reason = cls == "stopped" ? "law-pole" : "rest";
  r.t_vertical = t_vertical;
  return r;
}

TEST(EnsembleOutcomeMap, CellsAreSameMixedChangedOrChaotic) {
  GridAxes a;
  a.x_key = "initial.gamma3";
  a.y_key = "initial.omega3";
  a.x = {0.1, 0.5};
  a.y = {10.0, 20.0};
  // Cells: start = i * 2 + j. Two replicas each.
  const std::vector<RunRecord> rows = {
      run(0, 0, "exact", "pole+"), run(0, 1, "exact", "pole+"), run(0, 0, "law", "pole+"), run(0, 1, "law", "pole+"),
      run(1, 0, "exact", "pole+"), run(1, 1, "exact", "pole-"), run(1, 0, "law", "pole+"), run(1, 1, "law", "pole+"),
      run(2, 0, "exact", "pole+"), run(2, 1, "exact", "pole+"), run(2, 0, "law", "stopped"), run(2, 1, "law", "pole-"),
      run(3, 0, "exact", "tilted"), run(3, 1, "exact", "tilted"), run(3, 0, "law", "tilted"), run(3, 1, "law", "pole-"),
  };
  const OutcomeMap m = build_outcome_map(a, {"exact", "law"}, rows);
  ASSERT_EQ(m.cells(), 4u);
  ASSERT_EQ(m.laws.size(), 2u);
  EXPECT_EQ(m.laws[1].change, (std::vector<CellChange>{CellChange::same, CellChange::chaotic, CellChange::changed,
                                                       CellChange::mixed}));
  EXPECT_EQ(m.laws[0].change, std::vector<CellChange>(4, CellChange::missing)) << "the reference is not compared";
  EXPECT_EQ(m.laws[0].majority_class[3], "tilted");
  EXPECT_EQ(m.count(1), (std::vector<long>{1, 1, 1, 1, 0}));
}

TEST(EnsembleOutcomeMap, MediansOverTheReplicasThatEndedNormally) {
  GridAxes a;
  a.x = {0.0};
  a.y = {1.0, 2.0};
  const std::vector<RunRecord> rows = {run(0, 0, "exact", "pole+", 3.0), run(0, 1, "exact", "pole+", 5.0),
                                       run(1, 0, "exact", "stopped", 1.0), run(1, 1, "exact", "pole+")};
  const auto m = cell_medians(a, "exact", rows, [](const RunRecord& r) { return r.t_vertical; });
  EXPECT_EQ(m[0], 4.0);
  EXPECT_TRUE(std::isnan(m[1])) << "the stopped run does not count; the other has no value";
}

TEST(EnsembleOutcomeMap, OnlyGridsOfTwoKeysAreMapped) {
  Study s;
  s.design = DesignKind::grid;
  s.vary = {VariedAxis{.key = "a", .min = 0, .max = 1, .points = 3, .values = {}, .scale = AxisScale::linear},
            VariedAxis{.key = "b", .min = 1, .max = 100, .points = 3, .values = {}, .scale = AxisScale::log}};
  const auto axes = map_axes(s);
  ASSERT_TRUE(axes.has_value());
  EXPECT_EQ(axes->x, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_TRUE(axes->y_log);
  s.design = DesignKind::lhs;
  EXPECT_FALSE(map_axes(s).has_value());
  s.design = DesignKind::grid;
  s.vary.pop_back();
  EXPECT_FALSE(map_axes(s).has_value());
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
