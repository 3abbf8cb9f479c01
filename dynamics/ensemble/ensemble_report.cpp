#include "dynamics/ensemble/ensemble_report.h"

#include <sys/utsname.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "dynamics/ensemble/chaos_floor_rule.h"
#include "dynamics/ensemble/cluster_prediction.h"
#include "dynamics/ensemble/progress_meter.h"
#include "dynamics/ensemble/feature_comparison.h"
#include "dynamics/ensemble/outcome_map.h"
#include "dynamics/ensemble/sample_statistics.h"
#include "dynamics/paper/experiment_report.h"
#include "friction/support/checked_input.h"
#include "friction/support/checked_output.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {
namespace {

// Coordination per task assumed in the predictions: rank 0 handles a request and a task's rows in
// well under a millisecond (docs/ensembles.md §6); 1 ms is a generous bound.
constexpr double kPredictionTaskOverhead = 1e-3;

std::string n3(double x) { return std::isnan(x) ? "–" : support::significant(x, 3); }
std::string n4(double x) { return std::isnan(x) ? "–" : support::significant(x, 4); }
std::string p_text(double p) {
  if (std::isnan(p)) return "–";
  if (p < 1e-4) return "<1e-4";
  return support::significant(p, 2);
}
std::string share(long k, long n) { return std::to_string(k) + "/" + std::to_string(n); }
std::string verdict_text(Verdict v) {
  return v == Verdict::changes ? "**changes**" : std::string(to_string(v));
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

std::vector<const RunRecord*> of_law(const std::vector<RunRecord>& rows, const std::string& law) {
  std::vector<const RunRecord*> out;
  for (const auto& r : rows)
    if (r.law == law) out.push_back(&r);
  return out;
}

void study_section(std::ostringstream& s, const EnsemblePlan& plan, const std::vector<RunRecord>& rows,
                   const std::string& command, const std::string& machine) {
  const Study& st = plan.study();
  s << "# Ensemble `" << st.name << "`\n\n";
  if (!st.description.empty()) s << st.description << ".\n\n";
  s << "Study `" << st.file.filename().string() << "` (hash `" << plan.hash() << "`), base scenario `"
    << st.scenario.filename().string() << "`";
  if (!st.set.empty()) {
    s << " with";
    for (const auto& o : st.set) s << " `" << o << "`";
  }
  s << ". Laws, the reference first: ";
  for (std::size_t i = 0; i < st.laws.size(); ++i) s << (i ? ", " : "") << "`" << st.laws[i] << "`";
  s << ". " << plan.starts() << " start" << (plan.starts() == 1 ? "" : "s");
  if (!st.vary.empty()) {
    s << " (" << to_string(st.design) << (st.design == DesignKind::grid ? "" : ", " + std::to_string(st.points) + " points")
      << " over";
    for (std::size_t i = 0; i < st.vary.size(); ++i) {
      const auto& a = st.vary[i];
      s << (i ? "," : "") << " `" << a.key << "` in [" << n4(a.min) << ", " << n4(a.max) << "]"
        << (a.scale == AxisScale::log ? " (log)" : "");
      if (st.design == DesignKind::grid) s << " (" << a.grid().size() << " values)";
    }
    s << ")";
  }
  s << " × " << plan.replicas() << " replica" << (plan.replicas() == 1 ? "" : "s");
  if (plan.replicas() > 1) s << " (perturbation " << n3(st.replica_size) << ")";
  s << " × " << plan.laws() << " law" << (plan.laws() == 1 ? "" : "s") << " = **" << plan.runs() << " runs** ("
    << rows.size() << " in runs.csv).\n\n";
  double cpu = 0.0;
  for (const auto& r : rows) cpu += std::isnan(r.wall_time) ? 0.0 : r.wall_time;
  s << "Made by `" << command << "`; report written " << utc_now() << " on " << machine << ". The runs took "
    << support::fixed(cpu, 0) << " s of one core in all (" << n3(static_cast<double>(rows.size()) / cpu)
    << " runs per second per core).\n\n";
}

void runs_section(std::ostringstream& s, const std::vector<std::string>& laws, const std::vector<RunRecord>& rows,
                  RunModel model) {
  std::set<std::string> reasons;
  for (const auto& r : rows) reasons.insert(r.reason);
  s << "## How the runs ended\n\n| law | runs |";
  for (const auto& reason : reasons) s << " " << reason << " |";
  s << "\n|---|---|";
  for (std::size_t i = 0; i < reasons.size(); ++i) s << "---|";
  s << "\n";
  for (const auto& law : laws) {
    const auto runs = of_law(rows, law);
    std::map<std::string, long> n;
    for (const RunRecord* r : runs) ++n[r->reason];
    s << "| " << law << " | " << runs.size() << " |";
    for (const auto& reason : reasons) s << " " << n[reason] << " |";
    s << "\n";
  }
  if (model == RunModel::puck)
    s << "\n`rest`: slip and spin both stopped (docs/puck.md §1); `t_end`: still moving at run.t_end; `law-pole`: the "
         "law's denominator passed through 0; `max-steps`: the integrator crawled (run.max_steps); `failed`: the run "
         "could not start.\n\n";
  else
    s << "\n`rest`, `rolling`, `t_end`: the run ended as the model intends; `law-pole`: the law's denominator "
         "passed through 0 (the printed Padé law); `max-steps`: the integrator crawled (run.max_steps); "
         "`stagnation`: a bounce reached U = Ω = 0 while unsettled; `chatter`: a law discontinuous at U = 0 (or "
         "Ω = 0) chattered there while the other did not stop; `failed`: the run could not start "
         "(docs/dynamics.md §5).\n\n";

  const auto classes = compare_classes(rows, laws, model);
  std::set<std::string> names;
  for (const auto& c : classes)
    for (const auto& [k, v] : c.counts) names.insert(k);
  s << "## Where the runs end: outcome classes\n\n";
  if (model == RunModel::puck)
    s << "By the ratio U/(a|Ω|) at the first of the two stops: `together` within a decade of 1, `slip-first` "
         "below 0.1, `spin-first` above 10; `moving`: still moving at t_end; `stopped`: stopped early (law-pole, "
         "max-steps, ...). Total variation (TV) and chi-square p against the reference; the floor is zero: the "
         "puck's motion is not chaotic, the same start gives the same run.\n\n| law |";
  else
    s << "`pole+` / `pole-`: ended within 8.1° of the vertical with γ3 → +1 / −1 (the pole at z_lo / z_hi touches); "
         "`tilted`: ended elsewhere; `stopped`: stopped early (law-pole, max-steps, stagnation, chatter, ...). Total variation "
         "(TV) and chi-square p against the reference; the floor: the same between the reference's even and odd "
         "replicas.\n\n| law |";
  for (const auto& k : names) s << " " << k << " |";
  s << " TV | p | floor TV | floor p | verdict |\n|---|";
  for (std::size_t i = 0; i < names.size(); ++i) s << "---|";
  s << "---|---|---|---|---|\n";
  for (const auto& c : classes) {
    s << "| " << c.law << " |";
    for (const auto& k : names) {
      const auto it = c.counts.find(k);
      s << " " << (it == c.counts.end() ? 0 : it->second) << " |";
    }
    s << " " << n3(c.tv) << " | " << p_text(c.p) << " | " << n3(c.floor_tv) << " | " << p_text(c.floor_p) << " | "
      << (c.law == laws.front() ? "reference" : verdict_text(c.verdict)) << " |\n";
  }
  s << "\n";
}

void features_section(std::ostringstream& s, const std::vector<std::string>& laws, const std::vector<RunRecord>& rows,
                      RunModel model) {
  s << "## Does the law change the motion? Features against the chaos floor\n\n"
    << "Per feature, over the runs that ended normally: quantiles (5, 25, 50, 75, 95 %), and the law's "
       "distance to the reference's distribution: Wasserstein-1 (W1, in the feature's unit) and "
       "Kolmogorov–Smirnov (D, asymptotic p with Stephens' effective size). *Floor*: the same distances between "
       "the reference's even- and odd-numbered replicas. A law **changes** the feature when p < "
    << support::significant(kSignificance, 2) << " and W1 > " << support::significant(kFloorFactor, 2)
    << " × floor W1; *within chaos* when neither holds; *unclear* when one does; *negligible* when W1 is at most "
       "the feature's resolution, the smallest difference that means anything for it (given in each heading) "
       "(docs/ensembles.md).\n\n";
  if (floor_is_zero(model))
    s << "The floor is **zero** here: the puck's motion is not chaotic (a start gives the same run, bit for bit), so "
         "the study has no replicas and a law changes a feature when p < "
      << support::significant(kSignificance, 2) << " and W1 exceeds the feature's resolution.\n\n";
  const auto comparisons = compare_features(rows, laws, model);
  std::map<std::string, std::map<std::string, Verdict>> verdicts;
  for (const auto& f : compared_features(model)) {
    s << "### " << f.label << " (`" << f.name << "`" << (f.unit.empty() ? "" : ", " + f.unit) << "; resolution "
      << support::significant(f.resolution, 2) << ")\n\n"
      << "| law | normal | with value | 5 % | 25 % | median | 75 % | 95 % | W1 | D | p | floor W1 | floor D | floor p | "
         "verdict |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& c : comparisons) {
      if (c.feature != f.name) continue;
      const auto& q = c.summary.quantiles;
      const auto& d = c.distances;
      s << "| " << c.law << " | " << share(c.summary.normal, c.summary.runs) << " | " << c.summary.finite;
      for (const double x : q) s << " | " << n4(x);
      s << " | " << n3(d.w1) << " | " << n3(d.ks) << " | " << p_text(d.p) << " | " << n3(d.floor_w1) << " | "
        << n3(d.floor_ks) << " | " << p_text(d.floor_p) << " | "
        << (c.law == laws.front() ? "reference" : verdict_text(d.verdict)) << " |\n";
      verdicts[f.name][c.law] = d.verdict;
    }
    s << "\n";
  }
  if (laws.size() > 1) {
    s << "### Verdicts at a glance\n\n| feature |";
    for (std::size_t i = 1; i < laws.size(); ++i) s << " " << laws[i] << " |";
    s << "\n|---|";
    for (std::size_t i = 1; i < laws.size(); ++i) s << "---|";
    s << "\n";
    for (const auto& c : compare_classes(rows, laws, model))
      if (c.law != laws.front()) verdicts["final_class"][c.law] = c.verdict;
    for (const auto& name : {std::string("final_class")}) {
      s << "| outcome class |";
      for (std::size_t i = 1; i < laws.size(); ++i) s << " " << verdict_text(verdicts[name][laws[i]]) << " |";
      s << "\n";
    }
    for (const auto& f : compared_features(model)) {
      s << "| " << f.name << " |";
      for (std::size_t i = 1; i < laws.size(); ++i) s << " " << verdict_text(verdicts[f.name][laws[i]]) << " |";
      s << "\n";
    }
    s << "\n";
  }
}

void divergence_section(std::ostringstream& s, const std::vector<std::string>& laws, const std::vector<RunRecord>& rows,
                        const std::vector<std::string>& figures) {
  s << "## Divergence times against the floor\n\n"
    << "The first time γ3 of a law's run differs from the reference's on the same replica by more than "
    << support::significant(paper::kDivergenceThreshold, 2)
    << " (compared up to the end of the shorter run); the floor: the reference on replica 2p + 1 against 2p. "
       "Quantiles over the runs that parted; KS and p against the floor's times, unparted runs counted as never.\n\n"
       "| | compared | parted | 5 % | 25 % | median | 75 % | 95 % | median horizon (s) | D vs floor | p |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|\n";
  const auto table = [&](double RunRecord::*time) {
    for (const auto& d : compare_divergence(rows, laws, time)) {
      s << "| " << (d.law == "floor" ? "floor (" + laws.front() + " vs its other replica)" : d.law) << " | "
        << d.compared << " | " << d.parted;
      for (const double x : d.quantiles) s << " | " << n4(x);
      s << " | " << n4(d.median_horizon) << " | " << n3(d.ks) << " | " << p_text(d.p) << " |\n";
    }
    s << "\n";
  };
  table(&RunRecord::t_diverge);
  for (const auto& f : figures)
    if (f == "figures/divergence.png") s << "![divergence times](" << f << ")\n\n";
  s << "The same for the bodies' symmetry axes (world axes, from the pose): the first time they are 1° "
       "apart, which also counts a heading that γ3 does not see (dynamics/paper/divergence.h).\n\n"
       "| | compared | parted | 5 % | 25 % | median | 75 % | 95 % | median horizon (s) | D vs floor | p |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|\n";
  table(&RunRecord::t_part);
  for (const auto& f : figures) {
    if (f == "figures/axis_divergence.png")
      s << "The angle between the axes against time: the median over the compared runs (thick) and its quartiles "
           "(thin), each law's against the floor's.\n\n![the distance between the axes](" << f << ")\n\n";
  }
}

// The shadow laws along the reference's runs (run_record.h: the shadow columns).
void shadow_section(std::ostringstream& s, const std::string& reference, const std::vector<std::string>& shadow_laws,
                    const std::vector<RunRecord>& rows, const std::vector<std::string>& figures) {
  s << "## Each law's friction along the reference's motion\n\n"
    << "Every run of `" << reference
    << "` evaluates these laws at the contact of each state it passes through, without changing the run "
       "(dynamics/core/shadow_laws.h), every contact state weighted by the time spent there. Per run: the median, "
       "95 % and largest |ΔF| per kN (k·N: the friction bound; ΔF the tangential force's error as a vector) and "
       "|ΔM| per kNa, and ΔE, what the law would dissipate along the run minus what the run did, over the run's "
       "friction work W. Over the runs: the median of each run's value, the largest of the largest, and the 5–95 % "
       "range of ΔE/W.\n\n"
       "| law | runs | ΔF/kN median | ΔF/kN 95 % | ΔF/kN worst | ΔM/kNa median | ΔM/kNa worst | ΔE/W median | "
       "ΔE/W 5–95 % | failed states (runs) |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t l = 0; l < shadow_laws.size(); ++l) {
    std::vector<double> f50, f95, m50, rel;
    double f_max = kNaN;
    double m_max = kNaN;
    long runs = 0;
    long failed = 0;
    long failed_runs = 0;
    for (const auto& r : rows) {
      if (l >= r.shadow.size() || !r.shadow[l].evaluated()) continue;
      const ShadowColumns& c = r.shadow[l];
      ++runs;
      failed += c.failures;
      failed_runs += c.failures > 0 ? 1 : 0;
      const auto keep = [](std::vector<double>& v, double x) {
        if (std::isfinite(x)) v.push_back(x);
      };
      keep(f50, c.F_median);
      keep(f95, c.F_p95);
      keep(m50, c.M_median);
      if (std::isfinite(c.F_max)) f_max = std::isnan(f_max) ? c.F_max : std::max(f_max, c.F_max);
      if (std::isfinite(c.M_max)) m_max = std::isnan(m_max) ? c.M_max : std::max(m_max, c.M_max);
      const double work = r.work_slide + r.work_spin;
      if (work > 0.0 && std::isfinite(c.dE)) rel.push_back(c.dE / work);
    }
    const auto percent = [](double x) { return std::isnan(x) ? std::string("–") : support::significant(100.0 * x, 3) + " %"; };
    s << "| " << shadow_laws[l] << " | " << runs << " | " << n3(quantile(f50, 0.5)) << " | " << n3(quantile(f95, 0.5))
      << " | " << n3(f_max) << " | " << n3(quantile(m50, 0.5)) << " | " << n3(m_max) << " | "
      << percent(quantile(rel, 0.5)) << " | " << percent(quantile(rel, 0.05)) << " to " << percent(quantile(rel, 0.95))
      << " | " << failed << " (" << failed_runs << ") |\n";
  }
  s << "\n";
  for (const auto& f : figures)
    if (f == "figures/shadow_errors.png")
      s << "Over the reference's runs: the share of runs whose median (thick) or largest (thin) |ΔF|/(kN) along the "
           "motion is at most the value.\n\n![the force errors along the motion](" << f << ")\n\n";
}

void map_section(std::ostringstream& s, const OutcomeMap& m, const std::vector<std::string>& figures) {
  s << "## Maps over `" << m.axes.x_key << "` × `" << m.axes.y_key << "`\n\n"
    << "Per cell (one start, its replicas) and law but the reference: *chaotic* where the reference's own "
       "replicas end in different classes, *changed* where more than half of the law's replicas end elsewhere than "
       "the reference's unanimous class, *mixed* where some do, *same* where none does.\n\n"
       "| law | same | mixed | changed | chaotic | cells |\n|---|---|---|---|---|---|\n";
  for (std::size_t l = 1; l < m.laws.size(); ++l) {
    const auto n = m.count(l);
    s << "| " << m.laws[l].law << " | " << n[0] << " | " << n[1] << " | **" << n[2] << "** | " << n[3] << " | "
      << m.cells() << " |\n";
  }
  s << "\n";
  for (const auto& f : figures)
    if (f.rfind("figures/map-", 0) == 0) s << "![" << f.substr(8, f.size() - 12) << "](" << f << ")\n\n";
}

void cost_section(std::ostringstream& s, const std::vector<std::string>& laws, const std::vector<RunRecord>& rows) {
  s << "## Cost\n\nWall time of each run on one core (scenario, integration, features; no trajectory written), "
       "RHS calls of the integrator and of the samples.\n\n"
       "| law | runs | median wall (s) | mean wall (s) | max wall (s) | total (s) | median RHS calls | ns per RHS call |\n"
       "|---|---|---|---|---|---|---|---|\n";
  for (const auto& law : laws) {
    std::vector<double> wall;
    std::vector<double> calls;
    double total = 0.0;
    double total_calls = 0.0;
    for (const RunRecord* r : of_law(rows, law)) {
      if (std::isnan(r->wall_time)) continue;
      wall.push_back(r->wall_time);
      calls.push_back(static_cast<double>(r->rhs_calls));
      total += r->wall_time;
      total_calls += static_cast<double>(r->rhs_calls);
    }
    s << "| " << law << " | " << wall.size() << " | " << n3(quantile(wall, 0.5)) << " | "
      << n3(wall.empty() ? kNaN : total / static_cast<double>(wall.size())) << " | " << n3(quantile(wall, 1.0)) << " | "
      << support::fixed(total, 1) << " | " << n3(quantile(calls, 0.5)) << " | "
      << (total_calls > 0 ? support::fixed(1e9 * total / total_calls, 0) : "–") << " |\n";
  }
  const std::vector<double> tasks = task_costs(rows);
  s << "\n**Predicted wall time on P cores** (dynamics/ensemble/cluster_prediction.h): the " << tasks.size()
    << " tasks (a start, a pair of replicas, every law) handed out in plan order to the first free core, each "
       "costing its runs' wall times above plus "
    << support::significant(1e3 * kPredictionTaskOverhead, 2)
    << " ms of coordination; one worker per core as fast as this one; start-up and I/O not counted.\n\n"
       "| cores | 1 | 2 | 64 | 1024 |\n|---|---|---|---|---|\n| wall time |";
  for (const long p : {1L, 2L, 64L, 1024L})
    s << " " << ProgressMeter::duration(predicted_wall_time(tasks, p, kPredictionTaskOverhead)) << " |";
  s << "\n\n";
}

}  // namespace

std::vector<RunRecord> read_runs(const std::filesystem::path& runs_csv, std::size_t key_count, RunModel model,
                                 std::size_t shadow_count) {
  std::istringstream in(support::read_file(runs_csv, "runs file"));
  std::string line;
  std::getline(in, line);  // header
  std::vector<RunRecord> rows;
  long number = 1;
  while (std::getline(in, line)) {
    ++number;
    try {
      rows.push_back(parse_run_row(line, key_count, model, shadow_count));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(runs_csv.string() + ":" + std::to_string(number) + ": " + e.what());
    }
  }
  return rows;
}

std::string machine_description() {
  std::string model;
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpu, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  utsname u{};
  uname(&u);
  return (model.empty() ? std::string("unknown CPU") : model) + " (" + std::to_string(std::thread::hardware_concurrency()) +
         " cores), " + u.sysname + " " + u.release;
}

std::string report_markdown(const EnsemblePlan& plan, const std::vector<RunRecord>& rows, const std::string& command,
                            const std::string& machine, const std::vector<std::string>& figures) {
  const auto& laws = plan.study().laws;
  const RunModel model = plan.model();
  std::ostringstream s;
  study_section(s, plan, rows, command, machine);
  runs_section(s, laws, rows, model);
  features_section(s, laws, rows, model);
  // The puck's runs are compared by their features, not along the trajectory.
  if (laws.size() > 1 && model == RunModel::body) divergence_section(s, laws, rows, figures);
  if (!plan.shadow_laws().empty()) shadow_section(s, laws.front(), plan.shadow_laws(), rows, figures);
  if (const auto axes = map_axes(plan.study())) map_section(s, build_outcome_map(*axes, laws, rows), figures);
  cost_section(s, laws, rows);
  return s.str();
}

ReportOutcome write_report(const EnsemblePlan& plan, const std::filesystem::path& dir, const std::string& command,
                           bool draw) {
  const auto rows = read_runs(dir / "runs.csv", plan.study().vary.size(), plan.model(), plan.shadow_laws().size());
  std::optional<OutcomeMap> map;
  if (const auto axes = map_axes(plan.study())) map = build_outcome_map(*axes, plan.study().laws, rows);
  ReportOutcome out;
  out.figures = write_figures(dir, plan.study().name, plan.study().laws, rows, map, draw, plan.model(), plan.shadow_laws());
  // Link the figures that exist (drawn now, or by an earlier run of gnuplot).
  std::vector<std::string> links;
  const bool puck = plan.model() == RunModel::puck;
  const std::vector<std::string> entries =
      puck ? std::vector<std::string>{"shadow_errors", "map-final_class", "map-log10_terminal_ratio", "map-path_lateral",
                                      "map-changes"}
           : std::vector<std::string>{"divergence", "axis_divergence", "shadow_errors", "map-final_class",
                                      "map-t_vertical", "map-final_gamma3", "map-changes"};
  for (const auto& entry : entries) {
    const std::string f = std::string("figures/") + entry + ".png";
    if (std::filesystem::exists(dir / f)) links.push_back(f);
  }
  out.report = dir / "report.md";
  support::write_file_atomically(out.report, report_markdown(plan, rows, command, machine_description(), links));
  return out;
}

}  // namespace frictionlab::dynamics::ensemble
