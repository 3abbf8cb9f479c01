// Rows of runs.csv (dynamics/ensemble/run_record.h, dynamics/ensemble/csv_row.h).

#include "dynamics/ensemble/run_record.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynamics/ensemble/csv_row.h"

namespace frictionlab::dynamics::ensemble {
namespace run_record_test {

TEST(EnsembleCsvRow, FieldsWithCommasQuotesAndLineBreaksAreQuoted) {
  std::string row;
  append_text_field(row, "plain");
  row += ',';
  append_text_field(row, "a,b");
  row += ',';
  append_text_field(row, "say \"hi\"");
  row += ',';
  append_text_field(row, "two\nlines");
  EXPECT_EQ(row, "plain,\"a,b\",\"say \"\"hi\"\"\",\"two\nlines\"");
  EXPECT_EQ(split_csv_line("plain,\"a,b\",\"say \"\"hi\"\"\",,x"),
            (std::vector<std::string>{"plain", "a,b", "say \"hi\"", "", "x"}));
  EXPECT_THROW((void)split_csv_line("a,\"open"), std::invalid_argument);
}

TEST(EnsembleCsvRow, NumbersRoundTripAndNaNIsEmpty) {
  for (const double x : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23}) {
    std::string f;
    append_number_field(f, x);
    EXPECT_EQ(parse_number_field(f, "x"), x) << f;
  }
  std::string f;
  append_number_field(f, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(f, "");
  EXPECT_TRUE(std::isnan(parse_number_field("", "x")));
  EXPECT_THROW((void)parse_number_field("1.5x", "t_final"), std::invalid_argument);
}

TEST(EnsembleRunRecord, ARowReadsBackAsTheSameRecord) {
  RunRecord r;
  r.run = 12;
  r.start = 3;
  r.replica = 1;
  r.law = "exact:pressure=uniform,x";  // a law spec with a comma survives the CSV
  r.values = {0.97, 100.0};
  r.reason = "law-pole";
  r.final_class = "stopped";
  r.t_final = 0.3162729541;
  r.wall_time = 0.01;
  r.steps = 261;
  r.rhs_calls = 8272;
  r.t_vertical = 4.66;
  r.vertical_pole = -1;
  r.plateau_tilt_deg = 121.8;
  r.final_gamma3 = -0.993;
  r.liftoffs = 338;
  r.min_n_over_mg = 0.0;
  r.work_slide = 247.4;
  r.work_spin = -0.0137;
  r.spin_reversals = 3;
  r.t_first_reversal = 1.25;
  r.final_spin_sense = -1;
  r.diverge_ref = "replica:0";
  r.diverge_horizon = 0.31;
  r.t_part = 0.27;
  r.axis_angle_deg = {1e-9, 0.5, std::nan(""), std::nan(""), std::nan(""), std::nan(""), std::nan(""), std::nan(""),
                      std::nan("")};
  r.message = "the denominator of F2 passes through 0, \"here\"";
  const std::string row = to_csv_row(r);
  EXPECT_EQ(row.back(), '\n');
  EXPECT_EQ(std::count(row.begin(), row.end(), '\n'), 1);
  const RunRecord b = parse_run_row(std::string_view(row).substr(0, row.size() - 1), 2);
  EXPECT_EQ(to_csv_row(b), row);
  EXPECT_EQ(b.law, r.law);
  EXPECT_EQ(b.values, r.values);
  EXPECT_TRUE(std::isnan(b.t_rest));
  EXPECT_TRUE(std::isnan(b.t_diverge));
  EXPECT_EQ(b.message, r.message);
  EXPECT_EQ(b.spin_reversals, 3);
  EXPECT_EQ(b.t_first_reversal, 1.25);
  EXPECT_EQ(b.final_spin_sense, -1);
  EXPECT_EQ(b.t_part, 0.27);
  ASSERT_EQ(b.axis_angle_deg.size(), kAxisAngleTimes.size());
  EXPECT_EQ(b.axis_angle_deg[1], 0.5);
  EXPECT_TRUE(std::isnan(b.axis_angle_deg[2]));
  EXPECT_EQ(run_index_of_row(row), 12);
  EXPECT_THROW((void)parse_run_row("1,2,3", 2), std::invalid_argument);
  EXPECT_EQ(runs_header({"initial.gamma3"}).rfind("run,start,replica,law,initial.gamma3,reason,", 0), 0u);
  EXPECT_EQ(run_columns({"k"}).size(), 4u + 1u + 23u + kAxisAngleTimes.size());
  EXPECT_NE(runs_header({"k"}).find(",t_part,axis_deg_at_0.1,axis_deg_at_0.3,axis_deg_at_1,"), std::string::npos);
}

TEST(EnsembleRunRecord, OutcomeClassesFollowTheEndAndTheFinalTilt) {
  EXPECT_EQ(outcome_class("rest", 0.995), "pole+");
  EXPECT_EQ(outcome_class("rolling", -0.9999), "pole-");
  EXPECT_EQ(outcome_class("t_end", 0.5), "tilted");
  EXPECT_EQ(outcome_class("t_end", 0.99), "tilted") << "within 8.1 deg means > 0.99";
  EXPECT_EQ(outcome_class("law-pole", 0.999), "stopped");
  EXPECT_EQ(outcome_class("max-steps", 0.0), "stopped");
  EXPECT_EQ(outcome_class("failed", std::nan("")), "failed");
}

TEST(EnsembleRunRecord, APuckRowHasThePuckColumnsAndReadsBack) {
  RunRecord r;
  r.model = RunModel::puck;
  r.run = 5;
  r.law = "exact";
  r.values = {0.25};
  r.reason = "rest";
  r.final_class = "together";
  r.t_final = 0.52;
  r.wall_time = 0.001;
  r.steps = 90;
  r.rhs_calls = 1200;
  r.puck.slip_stop_time = 0.5211;
  r.puck.spin_stop_time = 0.5216;
  r.puck.terminal_ratio = 0.8165;
  r.puck.path_along = 0.232;
  r.puck.path_lateral = -0.001;
  r.puck.turned = 8.59;
  r.work_slide = 0.05;
  r.work_spin = 0.015;
  const std::string row = to_csv_row(r);
  // run, start, replica, law, one key, then the puck's 16 columns.
  EXPECT_EQ(split_csv_line(row.substr(0, row.size() - 1)).size(), 4u + 1u + 16u);
  EXPECT_EQ(run_columns({"k"}, RunModel::puck).size(), 4u + 1u + 16u);
  const RunRecord b = parse_run_row(std::string_view(row).substr(0, row.size() - 1), 1, RunModel::puck);
  EXPECT_EQ(b.model, RunModel::puck);
  EXPECT_EQ(to_csv_row(b), row);
  EXPECT_TRUE(std::isnan(b.puck.terminal_ratio_limit)) << "empty reads back as missing";
  EXPECT_THROW((void)parse_run_row(std::string_view(row).substr(0, row.size() - 1), 1), std::invalid_argument)
      << "a puck row is not a body row";
  EXPECT_EQ(runs_header({"k"}, RunModel::puck).find("t_vertical"), std::string::npos);
}

TEST(EnsembleRunRecord, PuckOutcomeClassesFollowTheRatioAtTheFirstStop) {
  EXPECT_EQ(puck_outcome_class("rest", 0.8165), "together");
  EXPECT_EQ(puck_outcome_class("rest", 0.1), "together") << "a decade below 1 is still together";
  EXPECT_EQ(puck_outcome_class("rest", 0.0999), "slip-first");
  EXPECT_EQ(puck_outcome_class("rest", 10.0), "together");
  EXPECT_EQ(puck_outcome_class("rest", 10.01), "spin-first");
  EXPECT_EQ(puck_outcome_class("rest", std::nan("")), "rest");
  EXPECT_EQ(puck_outcome_class("t_end", 1.0), "moving");
  EXPECT_EQ(puck_outcome_class("law-pole", 1.0), "stopped");
  EXPECT_EQ(puck_outcome_class("failed", std::nan("")), "failed");
}

}  // namespace
}  // namespace frictionlab::dynamics::ensemble
