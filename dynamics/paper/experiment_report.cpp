#include "dynamics/paper/experiment_report.h"

#include <sys/utsname.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>

#include "dynamics/paper/figure_data.h"
#include "dynamics/body/state.h"
#include "friction/support/checked_output.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

// ---- numbers and cells ----------------------------------------------------------------------

// Table cells: `digits` significant digits; "–" where there is no value.
std::string num(double x, int digits = 4) { return std::isfinite(x) ? support::significant(x, digits) : "–"; }
// `digits` after the point; "–" where there is no value.
std::string fixed_num(double x, int digits) { return std::isfinite(x) ? support::fixed(x, digits) : "–"; }
// A difference, with its sign always written ("+49.13", "-0.5167").
std::string signed_num(double x, int digits = 4) {
  if (!std::isfinite(x)) return "–";
  return (std::signbit(x) ? "" : "+") + support::significant(x, digits);
}

// CSV: 10 significant digits; empty where there is no value.
std::string csv_num(double x) { return std::isfinite(x) ? support::significant(x, 10) : ""; }

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string md_cell(std::string s) {
  for (std::size_t p = 0; (p = s.find('|', p)) != std::string::npos; p += 2) s.replace(p, 1, "\\|");
  return s;
}

// ---- facts of a run ------------------------------------------------------------------------

double work_sliding(const RunResult& r) { return r.executed ? slide_work(r.summary.x_final) : kNaN; }
double work_spinning(const RunResult& r) { return r.executed ? spin_work(r.summary.x_final) : kNaN; }
double min_n_over_mg(const RunResult& r) { return r.executed ? r.summary.min_normal_force / r.weight : kNaN; }

std::string reason(const RunResult& r) {
  return r.executed ? std::string(to_string(r.summary.reason)) : std::string("not run");
}

bool is_reference(const RunResult& r) { return !r.spec.baseline && r.spec.law == kReferenceLaw; }

const RunResult* reference_of(const std::vector<RunResult>& results, const RunResult& r) {
  for (const auto& x : results)
    if (x.spec.group() == r.spec.group() && is_reference(x) && x.executed) return &x;
  return nullptr;
}

// The run of `law` (not the baseline) in the same (egg, case) as `r`.
const RunResult* same_case_run(const std::vector<RunResult>& results, const RunResult& r, std::string_view law) {
  for (const auto& x : results)
    if (x.executed && !x.spec.baseline && x.spec.group() == r.spec.group() && x.spec.law == law) return &x;
  return nullptr;
}

// ---- cells of the behaviour table ----------------------------------------------------------

std::string pole_text(int pole) { return pole > 0 ? "+1" : (pole < 0 ? "-1" : "–"); }

std::string vertical_cell(const RunFeatures& f) {
  if (!f.vertical.reached) return "–";
  return num(f.vertical.t_reached) + " (" + pole_text(f.vertical.pole) + (f.vertical.left ? "" : ", final") + ")";
}

std::string duration_cell(const VerticalEpisode& e, double t_final) {
  if (!e.reached) return "–";
  return e.left ? num(e.duration(t_final)) : "to end";
}

std::string plateau_cell(const Plateau& p) {
  if (!p.found) return "–";
  return fixed_num(p.gamma3, 3) + " (" + fixed_num(p.tilt_deg(), 1) + "°)";
}

std::string held_cell(const Plateau& p) {
  if (!p.found) return "–";
  return num(p.duration()) + (p.lasts_to_end ? " (end)" : "");
}

std::string divergence_cell(const Divergence& d) { return d.found ? num(d.t) : ">" + num(d.horizon); }

std::string spin_share_cell(const RunResult& r) {
  const double ws = work_sliding(r);
  const double wp = work_spinning(r);
  return fixed_num(100.0 * wp / (ws + wp), 0) + " %";
}

// ---- the CSV tables ------------------------------------------------------------------------

std::string behaviour_csv_row(const RunResult& r) {
  const RunFeatures& f = r.features;
  const Plateau& p = f.plateau;
  const RunSummary& s = r.summary;
  std::ostringstream row;
  row << r.spec.egg << ',' << r.spec.case_id << ',' << csv_text(r.spec.law) << ',' << csv_text(r.spec.label) << ','
      << (r.spec.baseline ? 1 : 0) << ',' << reason(r) << ',' << csv_text(r.executed ? s.message : "") << ','
      << csv_num(r.executed ? s.t_final : kNaN) << ',' << (r.executed ? s.steps : 0) << ','
      << (r.executed ? s.rejected_steps : 0) << ',' << (r.executed ? s.rhs_calls : 0) << ','
      << csv_num(r.executed ? s.wall_time : kNaN) << ',' << (r.executed ? s.liftoffs : 0) << ','
      << csv_num(min_n_over_mg(r)) << ',' << csv_num(work_sliding(r)) << ',' << csv_num(work_spinning(r)) << ','
      << csv_num(f.vertical.t_reached) << ',' << f.vertical.pole << ',' << (f.vertical.left ? 1 : 0) << ','
      << csv_num(f.vertical.duration(f.t_final)) << ',' << csv_num(f.near_vertical.duration(f.t_final)) << ','
      << csv_num(p.t_start) << ',' << csv_num(p.gamma3) << ',' << csv_num(p.found ? p.tilt_deg() : kNaN) << ','
      << csv_num(p.found ? p.tilt_time() : kNaN) << ',' << csv_num(p.found ? p.duration() : kNaN) << ','
      << csv_num(f.gamma3_final) << ',' << csv_num(f.gamma3_final_mean) << ',' << csv_num(f.kinetic_final) << ','
      << csv_num(f.descent_oscillation) << ',' << f.sampled_liftoffs << ',' << f.sampled_liftoffs_before_plateau
      << ',' << csv_text(r.error) << '\n';
  return row.str();
}

// One row per run.
std::string behaviour_csv(const std::vector<RunResult>& results) {
  std::string csv =
      "egg,case,law,label,baseline,reason,message,t_final_s,steps,rejected_steps,rhs_calls,wall_time_s,liftoffs,"
      "min_N_over_mg,work_sliding_J,work_spinning_J,t_vertical_s,vertical_pole,vertical_left,vertical_spin_s,"
      "near_vertical_s,plateau_t_start_s,plateau_gamma3,plateau_tilt_deg,tilt_time_s,plateau_duration_s,"
      "gamma3_final,gamma3_final_mean,kinetic_final_J,descent_oscillation,sampled_liftoffs,"
      "sampled_liftoffs_before_plateau,error\n";
  for (const auto& r : results) csv += behaviour_csv_row(r);
  return csv;
}

// One row per compared run.
std::string comparison_csv(const std::vector<LawComparison>& comparisons) {
  std::ostringstream csv;
  csv << "egg,case,law,label,threshold,divergence_t_s,divergence_smooth_t_s,compared_up_to_s,"
         "stagnation_difference_s,final_gamma3_difference,final_tilt_difference_deg,work_sliding_J,work_spinning_J,"
         "wall_time_s,rhs_calls\n";
  for (const auto& c : comparisons) {
    const RunResult& r = *c.run;
    csv << r.spec.egg << ',' << r.spec.case_id << ',' << csv_text(r.spec.law) << ',' << csv_text(r.spec.label) << ','
        << csv_num(kDivergenceThreshold) << ',' << csv_num(c.raw.found ? c.raw.t : kNaN) << ','
        << csv_num(c.smooth.found ? c.smooth.t : kNaN) << ',' << csv_num(c.raw.horizon) << ','
        << csv_num(c.stagnation_difference) << ',' << csv_num(c.final_gamma3_difference) << ','
        << csv_num(c.final_tilt_difference_deg) << ',' << csv_num(work_sliding(r)) << ',' << csv_num(work_spinning(r))
        << ',' << csv_num(r.summary.wall_time) << ',' << r.summary.rhs_calls << '\n';
  }
  return csv.str();
}

// One row per claim, egg and law.
std::string narrative_csv(const std::vector<NarrativeVerdicts>& verdicts) {
  std::ostringstream csv;
  csv << "egg,law,claim_id,claim,verdict,evidence\n";
  for (const auto& v : verdicts)
    for (const auto& c : v.checks)
      csv << v.egg << ',' << v.law << ',' << c.id << ',' << csv_text(c.claim) << ',' << to_string(c.verdict) << ','
          << csv_text(c.evidence) << '\n';
  return csv.str();
}

// ---- the sections of experiments.md ---------------------------------------------------------

// The first lines of the report of an interrupted job: what ran, what did not, how to finish.
std::string interrupted_banner(const std::vector<RunResult>& results, const ReportContext& context) {
  if (!context.interrupted) return "";
  int ended = 0, stopped = 0, not_started = 0;
  for (const auto& r : results) {
    if (!r.executed) {
      ++not_started;
    } else if (r.summary.reason == Termination::interrupted) {
      ++stopped;
    } else {
      ++ended;
    }
  }
  return "> **INTERRUPTED**: this job was stopped before it finished (Ctrl-C, SIGTERM or SIGHUP). Of its " +
         std::to_string(results.size()) + " runs: ran to their end " + std::to_string(ended) +
         ", stopped part way (reason `interrupted`) " + std::to_string(stopped) + ", never started " +
         std::to_string(not_started) +
         ". The tables and figures cover what ran; a claim on a run stopped part way is n/a. `" + context.command +
         " --resume` finishes the job, keeping the runs that are complete.\n\n";
}

std::string resumed_note(const std::vector<RunResult>& results) {
  const auto kept = std::count_if(results.begin(), results.end(), [](const RunResult& r) { return r.resumed; });
  if (kept == 0) return "";
  return "* resumed (`--resume`): " + std::to_string(kept) + " of " + std::to_string(results.size()) +
         " runs kept from an earlier job, not rerun (their wall times and RHS calls are that job's)\n";
}

std::string report_header(const std::vector<RunResult>& results, const ReportContext& context) {
  std::ostringstream md;
  md << interrupted_banner(results, context)
     << "# The paper's experiments (Munitsyna 2013, section 2): generated report\n\n"
     << "Written by `frictionlab paper`; docs/experiments.md explains every column and rule.\n\n"
     << "* command: `" << context.command << "`\n"
     << "* started: " << context.date << "\n"
     << "* machine: " << context.machine << "\n"
     << "* worker threads: " << context.jobs << "; whole job: " << fixed_num(context.wall_time, 1) << " s wall\n"
     << resumed_note(results)
     << "* runs: `runs/<egg>-<case>/<law>/` (trajectory.csv, summary.json, scenario.toml, features.json, "
        "gamma3.csv); figures and their gnuplot scripts: `plots/`\n\n";
  return md.str();
}

std::string behaviour_row(const RunResult& r) {
  if (!r.executed) return "| " + r.name() + " | not run: " + md_cell(r.error) + " |||||||||||||\n";
  const RunFeatures& f = r.features;
  const Plateau& p = f.plateau;
  std::ostringstream md;
  md << "| " << r.name() << " | " << reason(r) << " | " << num(r.summary.t_final) << " | " << vertical_cell(f) << " | "
     << duration_cell(f.vertical, f.t_final) << " | " << duration_cell(f.near_vertical, f.t_final) << " | "
     << plateau_cell(p) << " | " << (p.found ? num(p.tilt_time()) : "–") << " | " << held_cell(p) << " | "
     << fixed_num(f.gamma3_final_mean, 3) << " | " << r.summary.liftoffs << " | " << fixed_num(min_n_over_mg(r), 3)
     << " | " << fixed_num(work_sliding(r), 1) << " | " << fixed_num(work_spinning(r), 1) << " |\n";
  return md.str();
}

// The runs that did not end as the model intends, each with its reason and message.
std::string early_stops(const std::vector<RunResult>& results) {
  std::string md;
  for (const auto& r : results) {
    if (r.executed && r.ended_normally() && r.error.empty()) continue;
    if (md.empty()) md = "Runs that stopped early or failed:\n\n";
    md += "* " + r.name() + ": " + describe(r) + "\n";
  }
  return md.empty() ? md : md + "\n";
}

std::string behaviour_section(const std::vector<RunResult>& results) {
  std::string md =
      "## Runs and behaviour\n\n"
      "Times in s. *vertical*: first `|gamma3| > 0.999` (pole; *final* = only in the final position); *spin*: "
      "from then until the 1-s mean of `|gamma3|` falls below 0.99; *near*: the same from the first `|gamma3| > "
      "0.99`; *plateau*: `gamma3` (tilt of the axis from the upward vertical) where the fast tilt ends, *tilt*: how "
      "long the tilt took, *held*: how long its 5-s mean stays within ±0.05; *final γ3*: mean over the last second; "
      "*lift-offs*: counted at every step; `W`: work against sliding / spinning friction (J).\n\n"
      "| run | end | t end | vertical | spin | near | plateau | tilt | held | final γ3 | lift-offs | min N/mg | "
      "W slide | W spin |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : results) md += behaviour_row(r);
  return md + "\n" + early_stops(results);
}

// The eggs of `verdicts`, in order of appearance.
std::vector<std::string> eggs_of(const std::vector<NarrativeVerdicts>& verdicts) {
  std::vector<std::string> eggs;
  for (const auto& v : verdicts)
    if (std::find(eggs.begin(), eggs.end(), v.egg) == eggs.end()) eggs.push_back(v.egg);
  return eggs;
}

// One row per claim (in the order of the first law that has it), one column per law.
std::string verdict_table(const std::vector<const NarrativeVerdicts*>& of_egg) {
  std::ostringstream md;
  md << "| claim |";
  for (const auto* v : of_egg) md << " " << v->law << " |";
  md << "\n|---|";
  for (std::size_t i = 0; i < of_egg.size(); ++i) md << "---|";
  md << "\n";
  std::vector<std::pair<std::string, std::string>> claims;
  for (const auto* v : of_egg)
    for (const auto& c : v->checks)
      if (std::none_of(claims.begin(), claims.end(), [&](const auto& x) { return x.first == c.id; }))
        claims.emplace_back(c.id, c.claim);
  for (const auto& [id, text] : claims) {
    md << "| " << id << ": " << md_cell(text) << " |";
    for (const auto* v : of_egg) {
      const auto it = std::find_if(v->checks.begin(), v->checks.end(), [&](const auto& c) { return c.id == id; });
      md << " " << (it == v->checks.end() ? std::string("–") : std::string(to_string(it->verdict))) << " |";
    }
    md << "\n";
  }
  return md.str() + "\n";
}

std::string evidence_details(const std::string& egg, const std::vector<const NarrativeVerdicts*>& of_egg) {
  std::ostringstream md;
  for (const auto* v : of_egg) {
    md << "<details><summary>" << egg << ", " << v->law << ": evidence</summary>\n\n";
    for (const auto& c : v->checks)
      md << "* **" << c.id << "** (" << to_string(c.verdict) << ") " << c.claim << ": " << c.evidence << "\n";
    md << "\n</details>\n\n";
  }
  return md.str();
}

std::string narrative_section(const std::vector<NarrativeVerdicts>& verdicts) {
  std::string md =
      "## The paper's narrative\n\n"
      "Rules: *quickly*/*briefly* = within 10 % of the run; *much longer* = at least 2x; *the same angle* = within "
      "5°; *oscillates* (b) = peak-to-peak of `gamma3` about its 1-s mean after the plateau at least 2x case a's; "
      "*a series of lift-offs* = at least 2 seen in the 100-Hz samples before the plateau. *partly*: holds only "
      "in a weaker reading (given in the evidence); *n/a*: the run stopped before it could show the feature. The "
      "`" + std::string(kReferenceLaw) + "-tol…` column is the reference law with tolerances x0.1: where its verdict "
      "differs from the reference's, chance (the chaotic bouncing phase) decides the claim.\n\n";
  for (const auto& egg : eggs_of(verdicts)) {
    std::vector<const NarrativeVerdicts*> of_egg;
    for (const auto& v : verdicts)
      if (v.egg == egg) of_egg.push_back(&v);
    md += "### " + egg + "\n\n" + verdict_table(of_egg) + evidence_details(egg, of_egg);
  }
  return md;
}

std::string trajectory_error_row(const RunResult& r, const std::vector<LawComparison>& comparisons) {
  const std::string works = fixed_num(work_sliding(r), 1) + " | " + fixed_num(work_spinning(r), 1) + " | " +
                            spin_share_cell(r) + " | " + fixed_num(r.summary.wall_time, 2) + " | " +
                            std::to_string(r.summary.rhs_calls) + " |\n";
  const std::string final_g3 = fixed_num(r.features.gamma3_final_mean, 3);
  if (is_reference(r))
    return "| " + r.spec.group() + " | **" + r.spec.label + "** | – | – | – | " + final_g3 + " | – | " + works;
  const auto it = std::find_if(comparisons.begin(), comparisons.end(), [&](const auto& c) { return c.run == &r; });
  if (it == comparisons.end()) return "";
  return "| " + r.spec.group() + " | " + r.spec.label + (r.ended_normally() ? "" : " (" + reason(r) + ")") + " | " +
         divergence_cell(it->raw) + " | " + divergence_cell(it->smooth) + " | " +
         signed_num(it->stagnation_difference) + " | " + final_g3 + " | " +
         fixed_num(it->final_tilt_difference_deg, 1) + " | " + works;
}

std::string trajectory_error_section(const std::vector<RunResult>& results,
                                     const std::vector<LawComparison>& comparisons) {
  const std::string ref(kReferenceLaw);
  std::string md =
      "## Trajectory error against `" + ref + "`\n\n"
      "*first |Δγ3| > 0.05*: first time the `gamma3` of the two runs differ by more than " +
      num(kDivergenceThreshold) + " (compared every " + num(kComparisonEvery * kPaperOutputDt) +
      " s, gamma3.csv), *1-s mean*: the same for their 1-s moving averages (nutation removed; computed from every "
      "sample); `>T` = never up to T (the end of the shorter run). *Δ t stag*: difference in the time the "
      "contact reaches the stagnation region (rest or rolling). *Δ tilt*: difference in the final tilt of the "
      "axis. The `" + ref + "-tol…` row is the reference law rerun with tolerances x0.1: how early "
      "two equally exact runs part (the motion is chaotic in its bouncing phases).\n\n"
      "| case | law | first \\|Δγ3\\| > 0.05 (s) | 1-s mean (s) | Δ t stag (s) | final γ3 | Δ tilt (°) | W slide (J) "
      "| W spin (J) | spin share | wall (s) | RHS calls |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : results)
    if (r.executed) md += trajectory_error_row(r, comparisons);
  return md + "\n";
}

// Wall time per right-hand-side evaluation (integrator's and samples'), ns.
double ns_per_rhs_call(const RunSummary& s) {
  return 1e9 * s.wall_time / static_cast<double>(std::max(1L, s.rhs_calls + s.sample_rhs_calls));
}

std::string cost_row(const RunResult& r, const std::vector<RunResult>& results) {
  const RunResult* other = same_case_run(results, r, kCostComparisonLaw);
  const RunSummary& s = r.summary;
  const double ratio = other ? s.wall_time / other->summary.wall_time : kNaN;
  const double per_call_ratio = other ? ns_per_rhs_call(s) / ns_per_rhs_call(other->summary) : kNaN;
  const double ms_per_simulated_s = 1e3 * s.wall_time / s.t_final;
  std::ostringstream md;
  md << "| " << r.spec.egg << " | " << r.spec.label << " | " << reason(r) << " | " << num(s.t_final) << " | " << s.steps
     << " | " << s.rhs_calls << " + " << s.sample_rhs_calls << " | " << fixed_num(s.wall_time, 3) << " | "
     << fixed_num(ns_per_rhs_call(s), 0) << " | " << fixed_num(ms_per_simulated_s, 2) << " | " << fixed_num(ratio, 2)
     << " | " << fixed_num(per_call_ratio, 2) << " |\n";
  return md.str();
}

std::string cost_section(const std::vector<RunResult>& results, int jobs) {
  const std::string other(kCostComparisonLaw);
  std::string md = "## Cost of case a to the stagnation region, per law\n\n"
                   "Wall time as measured inside each run (integration and CSV output), with " +
                   std::to_string(jobs) +
                   " runs in parallel. *RHS calls*: the integrator's + the samples'; *ns/RHS*: wall time per "
                   "right-hand-side evaluation; *ms per s*: wall time per simulated second; *ratio*: wall time over "
                   "`" + other + "`'s for the same egg (the target: `exact` within " + num(kCostTarget, 2) +
                   "x; the runs end at different times, the motion being chaotic, so *per call*, the same ratio per "
                   "RHS evaluation, is the fairer measure of the law's cost).\n\n"
                   "| egg | law | end | t end (s) | steps | RHS calls | wall (s) | ns/RHS | ms per s | ratio | per call |\n"
                   "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : results)
    if (r.executed && r.spec.case_id == "a") md += cost_row(r, results);
  return md + "\n";
}

std::string figures_section(const ReportContext& context) {
  std::string md = "## Figures\n\n";
  for (const auto& f : context.figures) md += "* [plots/" + f + "](plots/" + f + ")\n";
  for (const auto& e : context.figure_errors) md += "* not drawn: " + e + "\n";
  return md;
}

}  // namespace

std::vector<LawComparison> compare_runs(const std::vector<RunResult>& results, double threshold) {
  std::vector<LawComparison> out;
  for (const auto& r : results) {
    if (!r.executed || is_reference(r)) continue;
    const RunResult* ref = reference_of(results, r);
    if (ref == nullptr) continue;
    LawComparison c;
    c.run = &r;
    c.reference = ref;
    const double dt = ref->t.size() > 1 ? ref->t[1] - ref->t[0] : 1.0;
    c.raw = first_divergence(ref->t, ref->gamma3, r.t, r.gamma3, threshold, dt);
    c.smooth = first_divergence(ref->t, ref->gamma3_smooth, r.t, r.gamma3_smooth, threshold, dt);
    if (r.stagnated() && ref->stagnated()) c.stagnation_difference = r.summary.t_final - ref->summary.t_final;
    c.final_gamma3_difference = r.features.gamma3_final_mean - ref->features.gamma3_final_mean;
    c.final_tilt_difference_deg = tilt_difference_deg(r.features.gamma3_final_mean, ref->features.gamma3_final_mean);
    out.push_back(c);
  }
  return out;
}

std::vector<NarrativeVerdicts> judge_narrative(const std::vector<RunResult>& results, const NarrativeRules& rules) {
  std::vector<std::pair<std::string, std::string>> keys;  // (egg, label) in order of appearance
  for (const auto& r : results) {
    const auto key = std::make_pair(r.spec.egg, r.spec.label);
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  }
  std::vector<NarrativeVerdicts> out;
  for (const auto& [egg, label] : keys) {
    CaseRuns runs;
    for (const auto& r : results) {
      if (r.spec.egg != egg || r.spec.label != label) continue;
      if (r.spec.case_id == "a") runs.a = &r;
      if (r.spec.case_id == "b") runs.b = &r;
      if (r.spec.case_id == "c") runs.c = &r;
    }
    out.push_back({egg, label, check_narrative(runs, rules)});
  }
  return out;
}

std::string machine_description() {
  std::string out;
  utsname u{};
  if (uname(&u) == 0) out = std::string(u.sysname) + " " + u.release + " " + u.machine;
  std::ifstream cpu("/proc/cpuinfo");
  for (std::string line; std::getline(cpu, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) out += ", " + line.substr(line.find_first_not_of(' ', colon + 1));
      break;
    }
  }
  out += " (" + std::to_string(std::thread::hardware_concurrency()) + " logical cores)";
  return out;
}

std::string report_markdown(const std::vector<RunResult>& results, const std::vector<LawComparison>& comparisons,
                            const std::vector<NarrativeVerdicts>& verdicts, const ReportContext& context) {
  return report_header(results, context) + behaviour_section(results) + narrative_section(verdicts) +
         trajectory_error_section(results, comparisons) + context.along_motion + cost_section(results, context.jobs) +
         figures_section(context);
}

void write_report(const std::filesystem::path& out_dir, const std::vector<RunResult>& results,
                  const std::vector<LawComparison>& comparisons, const std::vector<NarrativeVerdicts>& verdicts,
                  const ReportContext& context) {
  std::filesystem::create_directories(out_dir);
  support::write_file_atomically(out_dir / "behaviour.csv", behaviour_csv(results));
  support::write_file_atomically(out_dir / "comparison.csv", comparison_csv(comparisons));
  support::write_file_atomically(out_dir / "narrative.csv", narrative_csv(verdicts));
  support::write_file_atomically(out_dir / "experiments.md", report_markdown(results, comparisons, verdicts, context));
}

}  // namespace frictionlab::dynamics::paper
