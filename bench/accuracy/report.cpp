#include "bench/accuracy/report.h"

#include <sys/utsname.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <functional>
#include <mutex>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <thread>

#include "friction/law_spec.h"
#include "friction/support/number_format.h"

namespace frictionlab::accuracy {
namespace {

constexpr std::array<Component, 3> kComponents = {Component::F1, Component::F2, Component::M};

// Short numbers for markdown: 3 significant digits ("n/a" where there is no value).
std::string short_number(double x) { return std::isnan(x) ? "n/a" : support::significant(x, 3); }

std::string percent(double fraction) { return support::fixed(100.0 * fraction, 1) + "%"; }

std::string degrees(double psi) { return support::significant(psi * 180.0 / std::numbers::pi, 4) + "°"; }

// "s=0.0123, μ=0.05, ψ=45°, Ω<0" for markdown, or "" if there is no such point.
std::string where(const Grid& grid, std::size_t i) {
  if (i == kNoIndex) return "";
  const GridPoint p = grid.point(i);
  return "s=" + short_number(p.s) + ", μ=" + short_number(p.mu) + ", ψ=" + degrees(p.psi) +
         (p.sign < 0 ? ", Ω<0" : ", Ω>0");
}

// One column of a summary CSV: its name and how to print it for a scope.
struct Column {
  std::string name;
  std::function<std::string(const ScopeSummary&)> value;
};

// Four columns locating the grid point that `index` picks from a scope.
void add_location(std::vector<Column>& cols, const Grid& grid, const std::string& prefix,
                  std::function<std::size_t(const ScopeSummary&)> index) {
  const auto field = [&grid, index](auto pick) {
    return [&grid, index, pick](const ScopeSummary& sc) -> std::string {
      const std::size_t i = index(sc);
      return i == kNoIndex ? std::string() : pick(grid.point(i));
    };
  };
  cols.push_back({prefix + "_s", field([](const GridPoint& p) { return format_number(p.s); })});
  cols.push_back({prefix + "_mu", field([](const GridPoint& p) { return format_number(p.mu); })});
  cols.push_back({prefix + "_psi", field([](const GridPoint& p) { return format_number(p.psi); })});
  cols.push_back(
      {prefix + "_sign", field([](const GridPoint& p) { return std::to_string(p.sign); })});
}

std::vector<Column> scope_columns(const Grid& grid) {
  std::vector<Column> cols;
  cols.push_back({"points", [](const ScopeSummary& sc) { return std::to_string(sc.points); }});
  for (const Component comp : kComponents) {
    const auto c = static_cast<std::size_t>(comp);
    const std::string n(component_name(comp));
    cols.push_back({"max_err_" + n, [c](const ScopeSummary& sc) { return format_number(sc.error[c].max_abs); }});
    cols.push_back({"rms_err_" + n, [c](const ScopeSummary& sc) { return format_number(sc.error[c].rms); }});
    cols.push_back({"median_err_" + n, [c](const ScopeSummary& sc) { return format_number(sc.error[c].median_abs); }});
    cols.push_back({"p95_err_" + n, [c](const ScopeSummary& sc) { return format_number(sc.error[c].p95_abs); }});
    add_location(cols, grid, "max_err_" + n, [c](const ScopeSummary& sc) { return sc.error[c].max_index; });
    cols.push_back({"nonfinite_" + n, [c](const ScopeSummary& sc) { return std::to_string(sc.error[c].nonfinite); }});
    add_location(cols, grid, "first_nonfinite_" + n,
                 [c](const ScopeSummary& sc) { return sc.error[c].first_nonfinite; });
    cols.push_back({"sign_checked_" + n, [c](const ScopeSummary& sc) { return std::to_string(sc.sign[c].considered); }});
    cols.push_back({"sign_mismatch_frac_" + n, [c](const ScopeSummary& sc) { return format_number(sc.sign[c].mismatch_fraction()); }});
    cols.push_back({"sign_opposite_frac_" + n, [c](const ScopeSummary& sc) { return format_number(sc.sign[c].opposite_fraction()); }});
    cols.push_back({"sign_zero_frac_" + n, [c](const ScopeSummary& sc) { return format_number(sc.sign[c].zero_fraction()); }});
  }
  cols.push_back({"nondissipative_points", [](const ScopeSummary& sc) { return std::to_string(sc.dissipation.violations); }});
  cols.push_back({"worst_dissipation", [](const ScopeSummary& sc) { return format_number(sc.dissipation.worst); }});
  add_location(cols, grid, "worst_dissipation", [](const ScopeSummary& sc) { return sc.dissipation.worst_index; });
  cols.push_back({"singular_points", [](const ScopeSummary& sc) { return std::to_string(sc.singular_points); }});
  add_location(cols, grid, "first_singular", [](const ScopeSummary& sc) { return sc.first_singular; });
  return cols;
}

std::size_t count_poles(const LawSummary& law, Component c, std::size_t imu = kNoIndex) {
  std::size_t n = 0;
  for (const auto& p : law.poles) n += p.component == c && (imu == kNoIndex || p.imu == imu);
  return n;
}

void write_header(std::ostream& out, const std::vector<std::string>& lead,
                  const std::vector<Column>& cols, const std::vector<std::string>& tail) {
  bool first = true;
  const auto put = [&](const std::string& s) {
    out << (first ? "" : ",") << s;
    first = false;
  };
  for (const auto& s : lead) put(s);
  for (const auto& c : cols) put(c.name);
  for (const auto& s : tail) put(s);
  out << '\n';
}

void write_row(std::ostream& out, const std::vector<std::string>& lead,
               const std::vector<Column>& cols, const ScopeSummary& sc,
               const std::vector<std::string>& tail) {
  bool first = true;
  const auto put = [&](const std::string& s) {
    out << (first ? "" : ",") << s;
    first = false;
  };
  for (const auto& s : lead) put(s);
  for (const auto& c : cols) put(c.value(sc));
  for (const auto& s : tail) put(s);
  out << '\n';
}

std::ofstream open_for_writing(const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return out;
}

void close_checked(std::ofstream& out, const std::filesystem::path& path) {
  out.close();
  if (!out) throw std::runtime_error("error while writing " + path.string());
}

template <class Writer>
void write_file(const std::filesystem::path& path, Writer&& writer) {
  auto out = open_for_writing(path);
  writer(out);
  close_checked(out, path);
}

std::string read_cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown CPU";
}

// Markdown table helpers.
void md_row(std::ostream& out, const std::vector<std::string>& cells) {
  out << '|';
  for (const auto& c : cells) out << ' ' << c << " |";
  out << '\n';
}
void md_head(std::ostream& out, const std::vector<std::string>& cells) {
  md_row(out, cells);
  out << '|';
  for (std::size_t i = 0; i < cells.size(); ++i) out << (i == 0 ? "---|" : "---:|");
  out << '\n';
}

std::string max_with_place(const Grid& grid, const ErrorStats& st) {
  if (st.max_index == kNoIndex) return "n/a";
  return short_number(st.max_abs) + " (" + where(grid, st.max_index) + ")";
}

std::string nonfinite_cell(const ScopeSummary& sc) {
  const std::size_t n = sc.error[0].nonfinite + sc.error[1].nonfinite + sc.error[2].nonfinite;
  if (n == 0) return "0";
  return std::to_string(sc.error[0].nonfinite) + "/" + std::to_string(sc.error[1].nonfinite) + "/" +
         std::to_string(sc.error[2].nonfinite);
}

std::string sign_cell(const SignStats& st) {
  std::string s = percent(st.opposite_fraction());
  if (st.zero > 0) s += " (+" + percent(st.zero_fraction()) + " zero)";
  return s;
}

}  // namespace

RunInfo describe_this_run() {
  RunInfo info;
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &utc);
  info.date = buf;
  utsname u{};
  std::string os = "Linux";
  if (uname(&u) == 0) os = std::string(u.sysname) + " " + u.release + " " + u.machine;
  info.machine = read_cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) +
                 " hardware threads, " + os;
  return info;
}

std::string format_number(double x) { return support::significant(x, 10); }

void write_points_csv(std::ostream& out, const Grid& grid, const LawValues& law,
                      const LawValues& reference) {
  out << "s,mu,psi,sign,F1,F2,M,err_F1,err_F2,err_M,dissipation\n";
  std::string row;
  const auto put = [&](double x, bool last = false) {
    support::append_significant(row, x, 10);
    row += last ? '\n' : ',';
  };
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const GridPoint p = grid.point(i);
    row.clear();
    put(p.s);
    put(p.mu);
    put(p.psi);
    row += p.sign < 0 ? "-1," : "1,";
    put(law.F1[i]);
    put(law.F2[i]);
    put(law.M[i]);
    put(law.F1[i] - reference.F1[i]);
    put(law.F2[i] - reference.F2[i]);
    put(law.M[i] - reference.M[i]);
    put(dissipation(law.F1[i], law.M[i], p.s, p.sign), true);
    out << row;
  }
}

void write_summary_csv(std::ostream& out, const StudyResult& study) {
  const auto cols = scope_columns(study.grid);
  write_header(out, {"law"}, cols, {"pole_brackets_F1", "pole_brackets_F2", "pole_brackets_M", "eval_seconds"});
  for (const auto& law : study.summaries) {
    write_row(out, {law.law}, cols, law.overall,
              {std::to_string(count_poles(law, Component::F1)), std::to_string(count_poles(law, Component::F2)),
               std::to_string(count_poles(law, Component::M)), format_number(law.seconds)});
  }
}

void write_summary_by_mu_csv(std::ostream& out, const StudyResult& study) {
  const auto cols = scope_columns(study.grid);
  write_header(out, {"law", "mu"}, cols, {"pole_brackets_F1", "pole_brackets_F2", "pole_brackets_M"});
  for (const auto& law : study.summaries) {
    for (std::size_t imu = 0; imu < law.by_mu.size(); ++imu) {
      write_row(out, {law.law, format_number(study.grid.mu()[imu])}, cols, law.by_mu[imu],
                {std::to_string(count_poles(law, Component::F1, imu)),
                 std::to_string(count_poles(law, Component::F2, imu)),
                 std::to_string(count_poles(law, Component::M, imu))});
    }
  }
}

void write_summary_by_region_csv(std::ostream& out, const StudyResult& study) {
  const auto cols = scope_columns(study.grid);
  write_header(out, {"law", "region"}, cols, {});
  for (const auto& law : study.summaries) {
    for (std::size_t r = 0; r < law.by_region.size(); ++r) {
      write_row(out, {law.law, study.regions[r].name}, cols, law.by_region[r], {});
    }
  }
}

void write_poles_csv(std::ostream& out, const Grid& grid, const LawSummary& law) {
  out << "component,mu,psi,s_low,s_high\n";
  for (const auto& p : law.poles) {
    out << component_name(p.component) << ',' << format_number(grid.mu()[p.imu]) << ','
        << format_number(grid.psi()[p.ipsi]) << ',' << format_number(p.s_low) << ','
        << format_number(p.s_high) << '\n';
  }
}

void write_tables_markdown(std::ostream& out, const StudyResult& study, const RunInfo& run) {
  const Grid& g = study.grid;
  out << "# Accuracy of the friction laws against `" << study.reference.law << "`\n\n";
  out << "Generated by `" << (run.command.empty() ? "frictionlab accuracy" : run.command) << "`";
  if (!run.date.empty()) out << " on " << run.date;
  if (!run.machine.empty()) out << " (" << run.machine << ")";
  if (run.seconds > 0.0) out << "; evaluation and statistics took " << support::fixed(run.seconds, 2) << " s";
  out << ".\n\n";
  out << "Grid: " << g.s().size() << " slip ratios s = U/(a|Ω|) log-spaced over [" << short_number(g.s().front())
      << ", " << short_number(g.s().back()) << "], " << g.mu().size() << " axis ratios μ = b/a over ["
      << short_number(g.mu().front()) << ", 1], " << g.psi().size()
      << " orientations ψ over [0°, 180°], both signs of Ω: " << g.size()
      << " points per law. Errors are law − exact, per kN = k·N, the friction coefficient times the normal force "
         "(F1, F2), and per kNa = k·N·a (M); max and RMS are "
         "over the points where the law's output is finite (non-finite outputs are counted apart).\n\n";

  out << "## Overall errors\n\n";
  md_head(out, {"law", "max abs err F1 (where)", "RMS F1", "max abs err F2 (where)", "RMS F2",
                "max abs err M (where)", "RMS M", "non-finite F1/F2/M"});
  for (const auto& law : study.summaries) {
    const auto& o = law.overall;
    md_row(out, {"`" + law.law + "`", max_with_place(g, o.error[0]), short_number(o.error[0].rms),
                 max_with_place(g, o.error[1]), short_number(o.error[1].rms),
                 max_with_place(g, o.error[2]), short_number(o.error[2].rms), nonfinite_cell(o)});
  }

  out << "\n## Typical errors (robust to poles)\n\n"
      << "Median and 95th percentile (nearest rank) of |law − exact| over the whole grid: one pole "
         "dominates a max or an RMS, not these.\n\n";
  md_head(out, {"law", "median F1", "p95 F1", "median F2", "p95 F2", "median M", "p95 M"});
  for (const auto& law : study.summaries) {
    const auto& o = law.overall;
    md_row(out, {"`" + law.law + "`", short_number(o.error[0].median_abs), short_number(o.error[0].p95_abs),
                 short_number(o.error[1].median_abs), short_number(o.error[1].p95_abs),
                 short_number(o.error[2].median_abs), short_number(o.error[2].p95_abs)});
  }

  out << "\n## Overall physics checks\n\n";
  out << "Non-dissipative: F1 s + M sign(Ω) < 0 (per kN a|Ω|). Wrong sign: the law's sign is "
         "opposite to exact's where |exact| > "
      << short_number(kSignThreshold) << " (a zero output where exact is not zero is counted apart). "
      << "Singular: an output non-finite or larger than " << short_number(kSingularMagnitude)
      << " in size. Pole brackets: grid intervals of s where a denominator changes sign (known for "
         "the printed Padé laws only), per component F1/F2/M.\n\n";
  md_head(out, {"law", "non-dissipative points", "worst F1 s + M sgn Ω (where)", "F2 wrong sign Ω<0",
                "F2 wrong sign Ω>0", "M wrong sign Ω<0", "M wrong sign Ω>0", "singular points",
                "pole brackets F1/F2/M"});
  const std::size_t neg = 3, pos = 4;  // study_regions(): Omega < 0, Omega > 0
  for (const auto& law : study.summaries) {
    const auto& o = law.overall;
    const std::string worst = o.dissipation.violations == 0
                                  ? "—"
                                  : short_number(o.dissipation.worst) + " (" + where(g, o.dissipation.worst_index) + ")";
    const std::string poles = law.has_denominators
                                  ? std::to_string(count_poles(law, Component::F1)) + "/" +
                                        std::to_string(count_poles(law, Component::F2)) + "/" +
                                        std::to_string(count_poles(law, Component::M))
                                  : "n/a";
    md_row(out, {"`" + law.law + "`",
                 std::to_string(o.dissipation.violations) + " (" +
                     percent(static_cast<double>(o.dissipation.violations) / static_cast<double>(o.points)) + ")",
                 worst, sign_cell(law.by_region[neg].sign[1]), sign_cell(law.by_region[pos].sign[1]),
                 sign_cell(law.by_region[neg].sign[2]), sign_cell(law.by_region[pos].sign[2]),
                 std::to_string(o.singular_points), poles});
  }

  out << "\n## Best law by region (smallest RMS error; max error in brackets)\n\n";
  md_head(out, {"region", "F1", "F2", "M"});
  for (std::size_t r = 0; r < study.regions.size(); ++r) {
    std::vector<std::string> cells = {study.regions[r].name + " (" + study.regions[r].label + ")"};
    for (std::size_t c = 0; c < 3; ++c) {
      const LawSummary* best = nullptr;
      for (const auto& law : study.summaries) {
        const auto& e = law.by_region[r].error[c];
        if (std::isnan(e.rms) || e.nonfinite > 0) continue;
        if (!best || e.rms < best->by_region[r].error[c].rms) best = &law;
      }
      cells.push_back(best ? "`" + best->law + "` " + short_number(best->by_region[r].error[c].rms) + " (" +
                                 short_number(best->by_region[r].error[c].max_abs) + ")"
                           : "n/a");
    }
    md_row(out, cells);
  }
  out << "\n(Laws with a non-finite output in a region are not ranked there.)\n";

  out << "\n## Errors by region\n\n";
  md_head(out, {"law", "region", "max F1", "RMS F1", "max F2", "RMS F2", "max M", "RMS M",
                "non-dissipative", "F2 wrong sign", "M wrong sign", "singular"});
  for (const auto& law : study.summaries) {
    for (std::size_t r = 0; r < study.regions.size(); ++r) {
      const auto& sc = law.by_region[r];
      md_row(out, {"`" + law.law + "`", study.regions[r].name, short_number(sc.error[0].max_abs),
                   short_number(sc.error[0].rms), short_number(sc.error[1].max_abs),
                   short_number(sc.error[1].rms), short_number(sc.error[2].max_abs),
                   short_number(sc.error[2].rms), std::to_string(sc.dissipation.violations),
                   sign_cell(sc.sign[1]), sign_cell(sc.sign[2]), std::to_string(sc.singular_points)});
    }
  }

  out << "\n## Errors by axis ratio μ\n";
  for (const auto& law : study.summaries) {
    out << "\n### `" << law.law << "`";
    if (!law.description.empty()) out << ": " << law.description;
    out << "\n\n";
    md_head(out, {"μ", "max F1", "RMS F1", "max F2", "RMS F2", "max M", "RMS M", "non-finite",
                  "non-dissipative", "F2 wrong sign", "M wrong sign", "singular", "pole brackets F2/M"});
    for (std::size_t imu = 0; imu < law.by_mu.size(); ++imu) {
      const auto& sc = law.by_mu[imu];
      md_row(out, {short_number(g.mu()[imu]), short_number(sc.error[0].max_abs), short_number(sc.error[0].rms),
                   short_number(sc.error[1].max_abs), short_number(sc.error[1].rms),
                   short_number(sc.error[2].max_abs), short_number(sc.error[2].rms), nonfinite_cell(sc),
                   std::to_string(sc.dissipation.violations), sign_cell(sc.sign[1]), sign_cell(sc.sign[2]),
                   std::to_string(sc.singular_points),
                   law.has_denominators ? std::to_string(count_poles(law, Component::F2, imu)) + "/" +
                                              std::to_string(count_poles(law, Component::M, imu))
                                        : "n/a"});
    }
  }
}

void write_readme(std::ostream& out, const StudyResult& study, const RunInfo& run, const StudyFiles& files) {
  out << "# Accuracy study output\n\n"
      << "Produced by `" << (run.command.empty() ? "frictionlab accuracy" : run.command) << "`"
      << (run.date.empty() ? "" : " on " + run.date) << ". Every law is compared with `"
      << study.reference.law << "` at " << study.grid.size()
      << " dimensionless contacts: a = 1 m, b = μ m, U = s m/s, Ω = ±1 1/s, N = 1 N, k = 1, so F1 and F2 are in "
         "units of kN = k·N (the friction coefficient times the normal force), M in units of kNa = k·N·a and the "
         "power F1 U + M Ω in units of kN a|Ω|.\n\n"
      << "Numbers have 10 significant digits; non-finite values are written nan, inf, -inf.\n\n"
      << "## Files\n\n"
      << (files.point_tables ? "* `points/<law>.csv`" : "* `points/<law>.csv` (not written by this run: add `--points`)")
      << ": one row per grid point (the reference too, as `points/" << study.reference.law
      << ".csv`, with zero errors). Columns:\n"
      << "  `s` = U/(a|Ω|); `mu` = b/a; `psi` (rad) from the slip direction to the major axis; "
         "`sign` of Ω (−1 or 1);\n"
      << "  `F1`, `F2` (per kN), `M` (per kNa) of the law; `err_F1`, `err_F2`, `err_M` = law − exact;\n"
      << "  `dissipation` = F1 s + M sign (per kN a|Ω|; < 0 means the law feeds energy in).\n"
      << "  Rows run with s fastest, then sign, then psi, then mu.\n"
      << "* `summary.csv`: one row per law over the whole grid; `summary_by_mu.csv`: one row per law and μ "
         "(column `mu`); `summary_by_region.csv`: one row per law and region (column `region`: "
         "`s < 0.1`, `0.1 <= s <= 10`, `s > 10`, `Omega < 0`, `Omega > 0`). Columns, for X in F1, F2, M:\n"
      << "  `points`; `max_err_X`, `rms_err_X`, `median_err_X`, `p95_err_X`: max, root mean square, "
         "median and 95th percentile (nearest rank) of |law − exact| over points where the law is finite;\n"
      << "  `max_err_X_s`, `_mu`, `_psi`, `_sign`: where the max occurs (first such point);\n"
      << "  `nonfinite_X`: points where the law's X is NaN or ±inf, `first_nonfinite_X_s/_mu/_psi/_sign` the first;\n"
      << "  `sign_checked_X`: points where |exact X| > " << short_number(kSignThreshold)
      << " (and the law finite); `sign_mismatch_frac_X`: fraction of those with sign(law) ≠ sign(exact), "
         "split into `sign_opposite_frac_X` (opposite sign) and `sign_zero_frac_X` (law exactly 0);\n"
      << "  `nondissipative_points`: points with F1 s + M sign < 0; `worst_dissipation` the most negative value "
         "(0 if none) and `worst_dissipation_s/_mu/_psi/_sign` where;\n"
      << "  `singular_points`: points with an output non-finite or larger than " << short_number(kSingularMagnitude)
      << " in size, `first_singular_s/_mu/_psi/_sign` the first;\n"
      << "  `pole_brackets_F1/_F2/_M` (summary and by-mu files): grid intervals of s where that output's "
         "denominator changes sign (laws with known denominators: the printed Padé laws; 0 otherwise);\n"
      << "  `eval_seconds` (summary.csv): wall time of the law's evaluation on the grid.\n"
      << "* `singular/<law>.csv` (laws with known denominators): one row per pole bracket: `component`, "
         "`mu`, `psi`, and the nodes `s_low`, `s_high` between which the denominator changes sign.\n"
      << "* `accuracy_tables.md`: the tables in markdown.\n"
      << "* `plots/*.gp`, `plots/*.dat`, `plots/*.png`: gnuplot scripts, their data and the figures; "
         "rerun a figure with `cd plots && gnuplot NAME.gp`.\n";
}

void write_study_files(const StudyResult& study, const std::filesystem::path& dir,
                       const RunInfo& run, std::ostream* progress, const StudyFiles& files) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const auto t0 = std::chrono::steady_clock::now();

  // The per-point tables, when asked for, are the bulk of the output (18-26 MB per law on the
  // default grid): written in parallel, one law per worker.
  std::vector<std::pair<fs::path, std::function<void(std::ostream&)>>> jobs;
  if (files.point_tables) {
    fs::create_directories(dir / "points");
    jobs.emplace_back(dir / "points" / (friction::law_file_stem(study.reference.law) + ".csv"),
                      [&](std::ostream& out) { write_points_csv(out, study.grid, study.reference, study.reference); });
    for (const auto& values : study.values) {
      jobs.emplace_back(dir / "points" / (friction::law_file_stem(values.law) + ".csv"),
                        [&study, &values](std::ostream& out) { write_points_csv(out, study.grid, values, study.reference); });
    }
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    for (std::size_t j = next++; j < jobs.size(); j = next++) {
      try {
        write_file(jobs[j].first, jobs[j].second);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < worker_count(0, jobs.size()); ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);

  write_file(dir / "summary.csv", [&](std::ostream& out) { write_summary_csv(out, study); });
  write_file(dir / "summary_by_mu.csv", [&](std::ostream& out) { write_summary_by_mu_csv(out, study); });
  write_file(dir / "summary_by_region.csv",
             [&](std::ostream& out) { write_summary_by_region_csv(out, study); });
  for (const auto& law : study.summaries) {
    if (!law.has_denominators) continue;
    fs::create_directories(dir / "singular");
    write_file(dir / "singular" / (friction::law_file_stem(law.law) + ".csv"),
               [&](std::ostream& out) { write_poles_csv(out, study.grid, law); });
  }
  write_file(dir / "accuracy_tables.md", [&](std::ostream& out) { write_tables_markdown(out, study, run); });
  write_file(dir / "README.md", [&](std::ostream& out) { write_readme(out, study, run, files); });
  if (progress) {
    *progress << "accuracy: wrote "
              << (jobs.empty() ? std::string("the summaries (no per-point tables: --points writes them)")
                               : std::to_string(jobs.size()) + " point tables and the summaries")
              << " to " << dir.string() << " in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s"
              << std::endl;
  }
}

}  // namespace frictionlab::accuracy
