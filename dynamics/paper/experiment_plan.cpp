#include "dynamics/paper/experiment_plan.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <system_error>

#include "dynamics/io/shipped_data.h"
#include "friction/law_spec.h"
#include "friction/registry.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

void check_names(const std::vector<std::string>& given, const std::vector<std::string>& known, const char* option) {
  if (given.empty()) throw std::invalid_argument(std::string(option) + " is empty: give at least one of " + joined(known));
  std::set<std::string> seen;
  for (const auto& g : given) {
    if (std::find(known.begin(), known.end(), g) == known.end())
      throw std::invalid_argument(std::string(option) + ": unknown name '" + g + "'; known: " + joined(known));
    if (!seen.insert(g).second) throw std::invalid_argument(std::string(option) + ": '" + g + "' is given twice");
  }
}

// Laws are specs (friction/law_spec.h): each must make a law, none twice (two spellings of one
// spec are the same law).
void check_law_specs(const std::vector<std::string>& laws) {
  if (laws.empty()) throw std::invalid_argument("--laws is empty: give at least one law (see `frictionlab laws`)");
  std::vector<std::string> canonical;
  for (const auto& law : laws) {
    try {
      canonical.push_back(friction::canonical_law_spec(law));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--laws: ") + e.what());
    }
    if (std::find(canonical.begin(), canonical.end() - 1, canonical.back()) != canonical.end() - 1)
      throw std::invalid_argument("--laws: '" + law + "' is given twice (the same law as an earlier item)");
  }
}

// Three significant digits: 1e-9 * 0.1 is "1e-10", not "1.0000000000000002e-10".
std::string tolerance(double x) { return support::significant(x, 3); }

}  // namespace

const std::vector<std::string>& known_eggs() {
  static const std::vector<std::string> v = {"egg-printed", "egg-homogeneous"};
  return v;
}

const std::vector<std::string>& known_cases() {
  static const std::vector<std::string> v = {"a", "b", "c"};
  return v;
}

const std::vector<std::string>& default_laws() {
  static const std::vector<std::string> v = {"exact", "pade-reconstructed", "pade-printed", "moller-ellipsoidal"};
  return v;
}

void PlanOptions::validate() const {
  if (out_dir.empty()) throw std::invalid_argument("--out is empty: give an output directory");
  check_law_specs(laws);
  check_names(eggs, known_eggs(), "--eggs");
  check_names(cases, known_cases(), "--cases");
}

std::vector<std::string> split_list(std::string_view list, std::string_view what) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    std::string_view item = list.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (item.empty())
      throw std::invalid_argument(std::string(what) + " = '" + std::string(list) +
                                  "' has an empty item: give names separated by commas");
    out.emplace_back(item);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

std::filesystem::path default_scenario_dir() {
  // The first shipped data folder that has the paper's scenarios; else the last (the build tree's).
  const std::string probe = known_eggs().front() + "-a.toml";
  const std::vector<std::filesystem::path> dirs = shipped_data_dirs();
  std::error_code ec;
  for (const auto& dir : dirs)
    if (std::filesystem::exists(dir / "scenarios" / probe, ec)) return dir / "scenarios";
  return dirs.back() / "scenarios";
}

std::vector<RunSpec> plan_runs(const PlanOptions& options) {
  options.validate();
  for (const auto& o : options.overrides)
    if (o.rfind("contact.law=", 0) == 0)
      throw std::invalid_argument("--set " + o + ": the paper job sets the law of each run; choose laws with --laws");
    else if (o.rfind("run.shadow=", 0) == 0)
      throw std::invalid_argument("--set " + o +
                                  ": the paper job shadows the compared laws along the reference run (--no-shadow: none)");
  const std::vector<std::string> paper_defaults = {"run.output_dt=" + support::shortest(kPaperOutputDt)};
  // Each run's scenario: the group's document with the run's overrides and its law.
  const auto resolve = [](const ScenarioDocument& doc, const RunSpec& r) {
    std::vector<std::string> overrides = r.overrides;
    overrides.push_back("contact.law=" + r.law);
    return std::make_shared<const Scenario>(doc.resolve(overrides));
  };
  std::vector<RunSpec> runs;
  for (const auto& egg : options.eggs) {
    for (const auto& c : options.cases) {
      RunSpec base;
      base.egg = egg;
      base.case_id = c;
      base.scenario_file = options.scenario_dir / (egg + "-" + c + ".toml");
      if (!std::filesystem::exists(base.scenario_file))
        throw std::invalid_argument("scenario file '" + base.scenario_file.string() +
                                    "' does not exist (--scenarios names the folder of <egg>-<case>.toml)");
      const ScenarioDocument doc = ScenarioDocument::read(base.scenario_file);
      base.overrides = paper_defaults;
      base.overrides.insert(base.overrides.end(), options.overrides.begin(), options.overrides.end());
      const std::filesystem::path group_dir = options.out_dir / "runs" / base.group();
      std::shared_ptr<const Scenario> reference;
      // The reference run carries the compared laws as shadow laws (dynamics/core/shadow_laws.h):
      // each law's friction along the reference's own motion.
      std::string shadows;
      for (const auto& law : options.laws) {
        if (friction::canonical_law_spec(law) != kReferenceLaw) shadows += (shadows.empty() ? "[\"" : ", \"") + law + "\"";
      }
      for (const auto& law : options.laws) {
        RunSpec r = base;
        r.law = r.label = law;  // the spec verbatim; its folder a name safe in paths and links
        r.out_dir = group_dir / friction::law_file_stem(r.label);
        if (options.shadow && !shadows.empty() && friction::canonical_law_spec(law) == kReferenceLaw)
          r.overrides.push_back("run.shadow=" + shadows + "]");
        r.scenario = resolve(doc, r);  // throws on a bad --set
        if (friction::canonical_law_spec(law) == kReferenceLaw) reference = r.scenario;
        runs.push_back(std::move(r));
      }
      if (options.baseline && reference) {
        RunSpec r = base;
        r.law = std::string(kReferenceLaw);
        r.baseline = true;
        const std::string abs_tol = tolerance(reference->run.integrator.abs_tol * kBaselineToleranceFactor);
        const std::string rel_tol = tolerance(reference->run.integrator.rel_tol * kBaselineToleranceFactor);
        r.label = r.law + "-tol" + abs_tol;
        r.overrides.push_back("run.abs_tol=" + abs_tol);
        r.overrides.push_back("run.rel_tol=" + rel_tol);
        r.out_dir = group_dir / r.label;
        r.scenario = resolve(doc, r);
        runs.push_back(std::move(r));
      }
    }
  }
  return runs;
}

}  // namespace frictionlab::dynamics::paper
