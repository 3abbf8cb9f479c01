#include "dynamics/ensemble/study.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "dynamics/ensemble/variant.h"
#include "dynamics/io/toml_document.h"
#include "friction/support/checked_input.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {
namespace {

using support::invalid_value;
using support::InvalidValue;

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

[[noreturn]] void wrong_type(const std::string& key, const toml::node& n, const std::string& wanted) {
  throw InvalidValue(key, key + " must be " + wanted + ", got " + type_name(n));
}

// A table of the study: typed reads that remember the keys used, then a check for unknown keys.
class Table {
 public:
  Table(const toml::table* t, std::string prefix) : t_(t), prefix_(std::move(prefix)) {}

  [[nodiscard]] std::string key(const std::string& k) const { return prefix_.empty() ? k : prefix_ + "." + k; }
  bool has(const std::string& k) {
    used_.insert(k);
    return t_ != nullptr && t_->contains(k);
  }
  const toml::node& node(const std::string& k) {
    if (!has(k)) throw InvalidValue(key(k), key(k) + " is required");
    return *t_->get(k);
  }
  double number(const std::string& k) { return as_number(node(k), key(k)); }
  double number(const std::string& k, double fallback) { return has(k) ? number(k) : fallback; }
  long long integer(const std::string& k, long long fallback) {
    if (!has(k)) return fallback;
    const toml::node& n = node(k);
    if (!n.is_integer()) wrong_type(key(k), n, "an integer");
    return *n.value<int64_t>();
  }
  std::string string(const std::string& k, const std::string& fallback) {
    if (!has(k)) return fallback;
    return as_string(node(k), key(k));
  }
  std::string string(const std::string& k) { return as_string(node(k), key(k)); }
  std::vector<std::string> strings(const std::string& k) {
    std::vector<std::string> out;
    if (!has(k)) return out;
    const toml::node& n = node(k);
    const toml::array* a = n.as_array();
    if (!a) wrong_type(key(k), n, "an array of strings");
    for (std::size_t i = 0; i < a->size(); ++i)
      out.push_back(as_string(*a->get(i), key(k) + "[" + std::to_string(i) + "]"));
    return out;
  }
  std::vector<double> numbers(const std::string& k) {
    const toml::node& n = node(k);
    const toml::array* a = n.as_array();
    if (!a) wrong_type(key(k), n, "an array of numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i) out.push_back(as_number(*a->get(i), key(k) + "[" + std::to_string(i) + "]"));
    return out;
  }
  const toml::table* table(const std::string& k) {
    if (!has(k)) return nullptr;
    const toml::node& n = node(k);
    if (!n.is_table()) wrong_type(key(k), n, "a section [" + key(k) + "]");
    return n.as_table();
  }

  void check_no_unknown_keys(const std::vector<std::string>& known) const {
    if (!t_) return;
    for (const auto& [k, v] : *t_) {
      const std::string name(k.str());
      if (used_.count(name)) continue;
      std::string list;
      for (const auto& a : known) list += (list.empty() ? "" : ", ") + a;
      throw InvalidValue(key(name), "unknown key " + key(name) + " (known keys" +
                                        (prefix_.empty() ? "" : " of " + prefix_) + ": " + list + ")");
    }
  }

  static double as_number(const toml::node& n, const std::string& where) {
    double x = 0.0;
    if (n.is_floating_point()) {
      x = *n.value<double>();
    } else if (n.is_integer()) {
      x = static_cast<double>(*n.value<int64_t>());
    } else {
      wrong_type(where, n, "a number");
    }
    if (!std::isfinite(x)) throw invalid_value(where, x, "it must be finite");
    return x;
  }
  static std::string as_string(const toml::node& n, const std::string& where) {
    if (!n.is_string()) wrong_type(where, n, "a string");
    return *n.value<std::string>();
  }

 private:
  const toml::table* t_;
  std::string prefix_;
  std::set<std::string> used_;
};

DesignKind design_kind(const std::string& name) {
  for (const DesignKind k : {DesignKind::grid, DesignKind::random, DesignKind::sobol, DesignKind::lhs})
    if (to_string(k) == name) return k;
  throw invalid_value("design.type", std::string_view(name), "it must be grid, random, sobol or lhs");
}

VariedAxis read_axis(const toml::table* t, const std::string& prefix, DesignKind design) {
  Table axis(t, prefix);
  VariedAxis a;
  a.key = axis.string("key");
  if (a.key.empty()) throw invalid_value(axis.key("key"), std::string_view(a.key), "it must name a scenario key");
  const std::string scale = axis.string("scale", "linear");
  if (scale == "log") {
    a.scale = AxisScale::log;
  } else if (scale != "linear") {
    throw invalid_value(axis.key("scale"), std::string_view(scale), "it must be linear or log");
  }
  const bool explicit_values = axis.has("values");
  if (explicit_values) {
    if (design != DesignKind::grid)
      throw InvalidValue(axis.key("values"), axis.key("values") + " is for grid designs only (design.type = " +
                                                 std::string(to_string(design)) + " samples min to max)");
    if (axis.has("min") || axis.has("max") || axis.has("points"))
      throw InvalidValue(axis.key("values"), axis.key("values") + " replaces min, max and points: give one or the other");
    a.values = axis.numbers("values");
    if (a.values.empty()) throw InvalidValue(axis.key("values"), axis.key("values") + " must list at least one value");
    for (std::size_t i = 1; i < a.values.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (a.values[i] == a.values[j])
          throw invalid_value(axis.key("values") + "[" + std::to_string(i) + "]", a.values[i], "it repeats an earlier value");
    a.min = *std::min_element(a.values.begin(), a.values.end());
    a.max = *std::max_element(a.values.begin(), a.values.end());
  } else {
    a.min = axis.number("min");
    a.max = axis.number("max");
    if (!(a.max > a.min)) throw invalid_value(axis.key("max"), a.max, "it must be > " + axis.key("min") + " = " + support::message_number(a.min));
    if (design == DesignKind::grid) {
      const long long points = axis.integer("points", 0);
      if (!axis.has("points")) throw InvalidValue(axis.key("points"), axis.key("points") + " is required by a grid design (or give values = [...])");
      if (points < 2 || points > 1'000'000)
        throw invalid_value(axis.key("points"), points, "it must be 2 to 1000000 (one value: values = [x])");
      a.points = static_cast<long>(points);
    } else if (axis.has("points")) {
      throw InvalidValue(axis.key("points"), axis.key("points") + " is for grid designs only (design.points gives the number of starts)");
    }
  }
  if (a.scale == AxisScale::log && !(a.min > 0.0))
    throw invalid_value(explicit_values ? axis.key("values") : axis.key("min"), a.min, "a log scale needs values > 0");
  axis.check_no_unknown_keys({"key", "min", "max", "points", "values", "scale"});
  return a;
}

Study build(const toml::table& root, const std::filesystem::path& source, const std::filesystem::path& folder) {
  Study s;
  s.file = source;
  Table top(&root, "");
  s.name = top.string("name", source.stem().string());
  s.description = top.string("description", "");
  const std::string scenario = top.string("scenario");
  if (scenario.empty()) throw InvalidValue("scenario", "scenario must name the base scenario file");
  s.scenario = std::filesystem::path(scenario).is_absolute() ? std::filesystem::path(scenario) : folder / scenario;
  s.laws = top.strings("laws");
  if (!top.has("laws")) throw InvalidValue("laws", "laws is required: the friction laws to compare, the reference first");
  if (s.laws.empty()) throw InvalidValue("laws", "laws must list at least one friction law");
  for (std::size_t i = 0; i < s.laws.size(); ++i) {
    (void)parse_variant(s.laws[i], "laws[" + std::to_string(i) + "]");  // LAW or LAW@PATCH, both parts named
    for (std::size_t j = 0; j < i; ++j)
      if (s.laws[i] == s.laws[j])
        throw invalid_value("laws[" + std::to_string(i) + "]", std::string_view(s.laws[i]), "it repeats laws[" + std::to_string(j) + "]");
  }
  s.set = top.strings("set");
  for (std::size_t i = 0; i < s.set.size(); ++i)
    if (s.set[i].find('=') == std::string::npos || s.set[i].front() == '=')
      throw invalid_value("set[" + std::to_string(i) + "]", std::string_view(s.set[i]),
                          "an override has the form key=value (e.g. run.output_dt=0.01)");
  if (top.has("shadow")) {
    const toml::node& n = top.node("shadow");
    if (n.is_boolean()) {
      s.shadow_compared = *n.value<bool>();
    } else if (n.is_array()) {
      s.shadow_compared = false;
      s.shadow_laws = top.strings("shadow");
      for (std::size_t i = 0; i < s.shadow_laws.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (s.shadow_laws[i] == s.shadow_laws[j])
            throw invalid_value("shadow[" + std::to_string(i) + "]", std::string_view(s.shadow_laws[i]),
                                "it repeats shadow[" + std::to_string(j) + "]");
    } else {
      wrong_type("shadow", n, "true, false or an array of friction-law specs");
    }
  }
  const long long seed = top.integer("seed", 1);
  if (seed < 0) throw invalid_value("seed", seed, "it must be >= 0");
  s.seed = static_cast<std::uint64_t>(seed);

  Table design(top.table("design"), "design");
  s.design = design_kind(design.string("type", "grid"));
  if (s.design == DesignKind::grid) {
    if (design.has("points"))
      throw InvalidValue("design.points", "design.points is for random, sobol and lhs designs (a grid takes each "
                                          "axis's points)");
  } else {
    const long long points = design.integer("points", 0);
    if (!design.has("points")) throw InvalidValue("design.points", "design.points is required by a " + std::string(to_string(s.design)) + " design");
    if (points < 1 || points > 100'000'000) throw invalid_value("design.points", points, "it must be 1 to 100000000");
    s.points = static_cast<long>(points);
  }
  design.check_no_unknown_keys({"type", "points"});

  if (top.has("vary")) {
    const toml::node& n = top.node("vary");
    const toml::array* list = n.as_array();
    if (!list || !list->is_array_of_tables()) wrong_type("vary", n, "an array of tables ([[vary]] sections)");
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string prefix = "vary[" + std::to_string(i) + "]";
      s.vary.push_back(read_axis(list->get(i)->as_table(), prefix, s.design));
      for (std::size_t j = 0; j < i; ++j)
        if (s.vary[j].key == s.vary[i].key)
          throw invalid_value(prefix + ".key", std::string_view(s.vary[i].key), "it repeats vary[" + std::to_string(j) + "].key");
    }
  }
  if (s.design != DesignKind::grid && s.vary.empty())
    throw InvalidValue("design.type", "design.type = " + std::string(to_string(s.design)) +
                                          " needs at least one [[vary]] key (without, the study has one start: use grid)");
  if (s.design == DesignKind::sobol && s.vary.size() > static_cast<std::size_t>(kSobolMaxDimension))
    throw invalid_value("design.type", std::string_view("sobol"), "GSL's Sobol sequence has at most " +
                                                                        std::to_string(kSobolMaxDimension) + " dimensions");

  Table replicas(top.table("replicas"), "replicas");
  const long long count = replicas.integer("count", 1);
  if (count < 1 || count > 1'000'000) throw invalid_value("replicas.count", count, "it must be 1 to 1000000");
  s.replicas = static_cast<long>(count);
  if (s.replicas > 1) {
    s.replica_size = replicas.number("size");
    if (!(s.replica_size > 0.0 && s.replica_size <= 0.1))
      throw invalid_value("replicas.size", s.replica_size, "it must be > 0 and <= 0.1 (a small relative perturbation)");
  } else if (replicas.has("size")) {
    s.replica_size = replicas.number("size");
  }
  replicas.check_no_unknown_keys({"count", "size"});

  Table output(top.table("output"), "output");
  s.trajectory_dt = output.number("trajectory_dt", s.trajectory_dt);
  if (!(s.trajectory_dt > 0.0)) throw invalid_value("output.trajectory_dt", s.trajectory_dt, "it must be > 0 s");
  output.check_no_unknown_keys({"trajectory_dt"});

  top.check_no_unknown_keys({"name", "description", "scenario", "laws", "set", "shadow", "seed", "[design]", "[[vary]]",
                             "[replicas]", "[output]"});
  return s;
}

}  // namespace

double VariedAxis::at(double u) const {
  if (u >= 1.0) return max;
  if (scale == AxisScale::log) return std::exp(std::log(min) + u * (std::log(max) - std::log(min)));
  return min + u * (max - min);
}

std::vector<double> VariedAxis::grid() const {
  if (!values.empty()) return values;
  std::vector<double> out;
  for (long k = 0; k < points; ++k) out.push_back(at(static_cast<double>(k) / static_cast<double>(points - 1)));
  return out;
}

Study parse_study(std::string_view text, const std::filesystem::path& source, const std::filesystem::path& folder) {
  const toml::table root = parse_toml(text, source.string());
  try {
    Study s = build(root, source, folder);
    s.text = std::string(text);
    std::ostringstream canonical;
    canonical << root;
    s.canonical = canonical.str();
    return s;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source.string() + ": " + e.what());
  }
}

Study read_study(const std::filesystem::path& file) {
  return parse_study(support::read_file(file, "study file"), file, file.parent_path());
}

}  // namespace frictionlab::dynamics::ensemble
