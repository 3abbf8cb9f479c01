#include "dynamics/ensemble/run_record.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "dynamics/ensemble/csv_row.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {
namespace {

const std::vector<std::string> kBefore = {"run", "start", "replica", "law"};
// The body's columns after the varied keys, the axis angles' named by their times.
std::vector<std::string> body_after() {
  std::vector<std::string> c = {
      "reason",     "final_class",  "t_final",       "wall_time",     "steps",           "rhs_calls",
      "t_vertical", "vertical_pole", "plateau_tilt_deg", "t_rest",    "final_gamma3",    "liftoffs",
      "min_n_over_mg", "work_slide", "work_spin",     "spin_reversals", "t_first_reversal", "final_spin_sense",
      "t_diverge",     "diverge_ref", "diverge_horizon", "t_part"};
  for (const double t : kAxisAngleTimes) c.push_back("axis_deg_at_" + support::shortest(t));
  c.push_back("message");
  return c;
}
const std::vector<std::string> kAfter = body_after();
const std::vector<std::string> kAfterPuck = {
    "reason",         "final_class",    "t_final",        "wall_time",            "steps",      "rhs_calls",
    "slip_stop_time", "spin_stop_time", "terminal_ratio", "terminal_ratio_limit", "path_along", "path_lateral",
    "turned",         "work_slide",     "work_spin",      "message"};

const std::vector<std::string>& after_keys(RunModel model) { return model == RunModel::puck ? kAfterPuck : kAfter; }

void integer_field(std::string& row, long x) { row += std::to_string(x); }

long parse_integer(const std::string& field, std::string_view column) {
  long x = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), x);
  if (field.empty() || ec != std::errc() || end != field.data() + field.size())
    throw std::invalid_argument("column " + std::string(column) + " holds '" + field + "', not an integer");
  return x;
}

}  // namespace

std::string outcome_class(std::string_view reason, double final_gamma3, const paper::FeatureThresholds& th) {
  if (reason == RunRecord::kFailed) return "failed";
  if (reason != "t_end" && reason != "rest" && reason != "rolling") return "stopped";
  if (final_gamma3 > th.near_vertical) return "pole+";
  if (final_gamma3 < -th.near_vertical) return "pole-";
  return "tilted";
}

// Within a decade of 1: at the puck's stop thresholds (equal in the scales, dynamics/puck/puck_run.h)
// the ratio is at most 1 when the slip stops first and at least 1 when the spin does; a decade
// away, the other motion still has a decade of speed to lose.
std::string puck_outcome_class(std::string_view reason, double terminal_ratio) {
  if (reason == RunRecord::kFailed) return "failed";
  if (reason == "t_end") return "moving";
  if (reason != "rest") return "stopped";
  if (std::isnan(terminal_ratio)) return "rest";
  if (terminal_ratio < 0.1) return "slip-first";
  if (terminal_ratio > 10.0) return "spin-first";
  return "together";
}

const std::array<const char*, 7>& shadow_column_names() {
  static const std::array<const char*, 7> names = {"F_median", "F_p95", "F_max", "M_median", "M_max", "dE", "failures"};
  return names;
}

std::vector<std::string> run_columns(const std::vector<std::string>& keys, RunModel model,
                                     const std::vector<std::string>& shadow_laws) {
  std::vector<std::string> c = kBefore;
  c.insert(c.end(), keys.begin(), keys.end());
  const auto& after = after_keys(model);
  c.insert(c.end(), after.begin(), after.end() - 1);  // the shadow columns come before the message
  for (const auto& law : shadow_laws)
    for (const char* name : shadow_column_names()) c.push_back("shadow_" + std::string(name) + "[" + law + "]");
  c.push_back(after.back());
  return c;
}

std::string runs_header(const std::vector<std::string>& keys, RunModel model, const std::vector<std::string>& shadow_laws) {
  std::string h;
  for (const auto& c : run_columns(keys, model, shadow_laws)) {
    if (!h.empty()) h.push_back(',');
    append_text_field(h, c);
  }
  return h + "\n";
}

std::string to_csv_row(const RunRecord& r) {
  std::string row;
  row.reserve(256);
  integer_field(row, r.run);
  row.push_back(',');
  integer_field(row, r.start);
  row.push_back(',');
  integer_field(row, r.replica);
  row.push_back(',');
  append_text_field(row, r.law);
  for (const double v : r.values) {
    row.push_back(',');
    append_number_field(row, v);
  }
  const auto num = [&](double x) {
    row.push_back(',');
    append_number_field(row, x);
  };
  const auto integer = [&](long x) {
    row.push_back(',');
    integer_field(row, x);
  };
  const auto text = [&](std::string_view s) {
    row.push_back(',');
    append_text_field(row, s);
  };
  const auto shadow_fields = [&] {
    for (const ShadowColumns& c : r.shadow) {
      for (const double x : {c.F_median, c.F_p95, c.F_max, c.M_median, c.M_max, c.dE}) num(x);
      if (c.evaluated()) {
        integer(c.failures);
      } else {
        row.push_back(',');
      }
    }
  };
  text(r.reason);
  text(r.final_class);
  num(r.t_final);
  num(r.wall_time);
  integer(r.steps);
  integer(r.rhs_calls);
  if (r.model == RunModel::puck) {
    num(r.puck.slip_stop_time);
    num(r.puck.spin_stop_time);
    num(r.puck.terminal_ratio);
    num(r.puck.terminal_ratio_limit);
    num(r.puck.path_along);
    num(r.puck.path_lateral);
    num(r.puck.turned);
    num(r.work_slide);
    num(r.work_spin);
    shadow_fields();
    text(support::one_line(r.message));
    row.push_back('\n');
    return row;
  }
  num(r.t_vertical);
  integer(r.vertical_pole);
  num(r.plateau_tilt_deg);
  num(r.t_rest);
  num(r.final_gamma3);
  integer(r.liftoffs);
  num(r.min_n_over_mg);
  num(r.work_slide);
  num(r.work_spin);
  integer(r.spin_reversals);
  num(r.t_first_reversal);
  integer(r.final_spin_sense);
  num(r.t_diverge);
  text(r.diverge_ref);
  num(r.diverge_horizon);
  num(r.t_part);
  for (std::size_t k = 0; k < kAxisAngleTimes.size(); ++k) num(k < r.axis_angle_deg.size() ? r.axis_angle_deg[k] : kNaN);
  shadow_fields();
  text(support::one_line(r.message));
  row.push_back('\n');
  return row;
}

RunRecord parse_run_row(std::string_view line, std::size_t key_count, RunModel model, std::size_t shadow_count) {
  const std::vector<std::string> f = split_csv_line(line);
  const std::size_t expected =
      kBefore.size() + key_count + after_keys(model).size() + shadow_count * shadow_column_names().size();
  if (f.size() != expected)
    throw std::invalid_argument("a row of runs.csv has " + std::to_string(f.size()) + " fields, not " +
                                std::to_string(expected));
  RunRecord r;
  std::size_t i = 0;
  r.run = parse_integer(f[i++], "run");
  r.start = parse_integer(f[i++], "start");
  r.replica = parse_integer(f[i++], "replica");
  r.law = f[i++];
  for (std::size_t k = 0; k < key_count; ++k) r.values.push_back(parse_number_field(f[i++], "of a varied key"));
  r.reason = f[i++];
  r.final_class = f[i++];
  r.t_final = parse_number_field(f[i++], "t_final");
  r.wall_time = parse_number_field(f[i++], "wall_time");
  r.steps = parse_integer(f[i++], "steps");
  r.rhs_calls = parse_integer(f[i++], "rhs_calls");
  r.model = model;
  const auto shadow_fields = [&] {
    for (std::size_t l = 0; l < shadow_count; ++l) {
      ShadowColumns c;
      for (double* x : {&c.F_median, &c.F_p95, &c.F_max, &c.M_median, &c.M_max, &c.dE})
        *x = parse_number_field(f[i++], "of a shadow law");
      const std::string& failures = f[i++];
      c.failures = failures.empty() ? -1 : parse_integer(failures, "shadow_failures");
      r.shadow.push_back(c);
    }
  };
  if (model == RunModel::puck) {
    r.puck.slip_stop_time = parse_number_field(f[i++], "slip_stop_time");
    r.puck.spin_stop_time = parse_number_field(f[i++], "spin_stop_time");
    r.puck.terminal_ratio = parse_number_field(f[i++], "terminal_ratio");
    r.puck.terminal_ratio_limit = parse_number_field(f[i++], "terminal_ratio_limit");
    r.puck.path_along = parse_number_field(f[i++], "path_along");
    r.puck.path_lateral = parse_number_field(f[i++], "path_lateral");
    r.puck.turned = parse_number_field(f[i++], "turned");
    r.work_slide = parse_number_field(f[i++], "work_slide");
    r.work_spin = parse_number_field(f[i++], "work_spin");
    shadow_fields();
    r.message = f[i++];
    return r;
  }
  r.t_vertical = parse_number_field(f[i++], "t_vertical");
  r.vertical_pole = static_cast<int>(parse_integer(f[i++], "vertical_pole"));
  r.plateau_tilt_deg = parse_number_field(f[i++], "plateau_tilt_deg");
  r.t_rest = parse_number_field(f[i++], "t_rest");
  r.final_gamma3 = parse_number_field(f[i++], "final_gamma3");
  r.liftoffs = parse_integer(f[i++], "liftoffs");
  r.min_n_over_mg = parse_number_field(f[i++], "min_n_over_mg");
  r.work_slide = parse_number_field(f[i++], "work_slide");
  r.work_spin = parse_number_field(f[i++], "work_spin");
  r.spin_reversals = parse_integer(f[i++], "spin_reversals");
  r.t_first_reversal = parse_number_field(f[i++], "t_first_reversal");
  r.final_spin_sense = static_cast<int>(parse_integer(f[i++], "final_spin_sense"));
  r.t_diverge = parse_number_field(f[i++], "t_diverge");
  r.diverge_ref = f[i++];
  r.diverge_horizon = parse_number_field(f[i++], "diverge_horizon");
  r.t_part = parse_number_field(f[i++], "t_part");
  for (std::size_t k = 0; k < kAxisAngleTimes.size(); ++k)
    r.axis_angle_deg.push_back(parse_number_field(f[i++], "axis_deg_at"));
  shadow_fields();
  r.message = f[i++];
  return r;
}

long run_index_of_row(std::string_view line) {
  long x = -1;
  const auto comma = line.find(',');
  const std::string_view first = line.substr(0, comma);
  const auto [end, ec] = std::from_chars(first.data(), first.data() + first.size(), x);
  if (first.empty() || ec != std::errc() || end != first.data() + first.size() || x < 0) return -1;
  return x;
}

}  // namespace frictionlab::dynamics::ensemble
