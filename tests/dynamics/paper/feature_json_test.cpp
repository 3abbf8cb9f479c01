// features.json (dynamics/paper/feature_json.h): every feature reads back to the same double.

#include "dynamics/paper/feature_json.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frictionlab::dynamics::paper {
namespace feature_json_test {

// Equal as doubles, NaN equal to NaN.
void expect_same(double a, double b, const char* what) {
  if (std::isnan(a)) {
    EXPECT_TRUE(std::isnan(b)) << what;
  } else {
    EXPECT_EQ(a, b) << what;
  }
}

TEST(PaperFeatureJson, EveryFeatureReadsBackBitForBit) {
  RunFeatures f;
  f.t_final = 173.09999999999999;
  f.gamma3_initial = 0.97;
  f.gamma3_final = -0.99199614983550331;
  f.gamma3_final_mean = -0.1 / 3.0;
  f.kinetic_final = 1.2857069046e-2;
  f.max_abs_gamma3 = 0.99999;
  f.first_move = -1;
  f.t_first_move = 0.01;
  f.vertical = {true, 4.66, 1, true, 7.0 / 3.0};
  f.near_vertical = {true, 3.0, 1, false, kNaN};
  f.plateau.found = true;
  f.plateau.t_from = 7.0;
  f.plateau.t_start = 26.59;
  f.plateau.gamma3 = -0.52712345678901234;
  f.plateau.t_end = kNaN;
  f.plateau.lasts_to_end = true;
  f.rise_extreme = kNaN;
  f.descent_oscillation = 1e-300;
  f.sampled_liftoffs = 2724;
  f.sampled_liftoffs_before_plateau = 58;
  f.last_sampled_liftoff = 299.5;

  // Through the text, as --resume reads it.
  const RunFeatures g =
      features_from_json(support::Json::parse(support::json_text(features_json(f, FeatureThresholds{}))));
  expect_same(g.t_final, f.t_final, "t_final");
  expect_same(g.gamma3_initial, f.gamma3_initial, "gamma3_initial");
  expect_same(g.gamma3_final, f.gamma3_final, "gamma3_final");
  expect_same(g.gamma3_final_mean, f.gamma3_final_mean, "gamma3_final_mean");
  expect_same(g.kinetic_final, f.kinetic_final, "kinetic_final");
  expect_same(g.max_abs_gamma3, f.max_abs_gamma3, "max_abs_gamma3");
  EXPECT_EQ(g.first_move, f.first_move);
  expect_same(g.t_first_move, f.t_first_move, "t_first_move");
  for (const auto& [a, b] : {std::pair{&g.vertical, &f.vertical}, std::pair{&g.near_vertical, &f.near_vertical}}) {
    EXPECT_EQ(a->reached, b->reached);
    expect_same(a->t_reached, b->t_reached, "t_reached");
    EXPECT_EQ(a->pole, b->pole);
    EXPECT_EQ(a->left, b->left);
    expect_same(a->t_left, b->t_left, "t_left");
  }
  EXPECT_EQ(g.plateau.found, f.plateau.found);
  expect_same(g.plateau.t_from, f.plateau.t_from, "plateau.t_from");
  expect_same(g.plateau.t_start, f.plateau.t_start, "plateau.t_start");
  expect_same(g.plateau.gamma3, f.plateau.gamma3, "plateau.gamma3");
  expect_same(g.plateau.t_end, f.plateau.t_end, "plateau.t_end");
  EXPECT_EQ(g.plateau.lasts_to_end, f.plateau.lasts_to_end);
  expect_same(g.rise_extreme, f.rise_extreme, "rise_extreme");
  expect_same(g.descent_oscillation, f.descent_oscillation, "descent_oscillation");
  EXPECT_EQ(g.sampled_liftoffs, f.sampled_liftoffs);
  EXPECT_EQ(g.sampled_liftoffs_before_plateau, f.sampled_liftoffs_before_plateau);
  expect_same(g.last_sampled_liftoff, f.last_sampled_liftoff, "last_sampled_liftoff");
}

TEST(PaperFeatureJson, AMissingOrMistypedKeyIsNamed) {
  support::Json j = features_json(RunFeatures{}, FeatureThresholds{});
  j.erase("plateau");
  try {
    (void)features_from_json(j);
    ADD_FAILURE() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'plateau'"), std::string::npos) << e.what();
  }
  j = features_json(RunFeatures{}, FeatureThresholds{});
  j["sampled_liftoffs"] = "many";
  EXPECT_THROW((void)features_from_json(j), std::runtime_error);
}

}  // namespace
}  // namespace frictionlab::dynamics::paper
