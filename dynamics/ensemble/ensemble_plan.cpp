#include "dynamics/ensemble/ensemble_plan.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "dynamics/body/body_scales.h"
#include "dynamics/ensemble/design.h"
#include "dynamics/ensemble/random_stream.h"
#include "dynamics/ensemble/replica.h"
#include "dynamics/ensemble/variant.h"
#include "friction/registry.h"
#include "friction/support/checked_input.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::ensemble {
namespace {

// The design's starts, each a value per varied key.
std::vector<std::vector<double>> draw_starts(const Study& s) {
  const int dims = static_cast<int>(s.vary.size());
  if (s.design == DesignKind::grid) {
    std::vector<std::vector<double>> axes;
    for (const auto& a : s.vary) axes.push_back(a.grid());
    return grid_product(axes);
  }
  // The design's own stream: derive_seed(seed, 0, 0); replicas use (seed, start, r >= 1).
  const std::uint64_t seed = derive_seed(s.seed, 0, 0);
  std::vector<UnitPoint> unit = s.design == DesignKind::random ? random_points(dims, s.points, seed)
                                : s.design == DesignKind::sobol ? sobol_points(dims, s.points)
                                                                : latin_hypercube(dims, s.points, seed);
  for (auto& p : unit)
    for (int d = 0; d < dims; ++d) p[static_cast<std::size_t>(d)] = s.vary[static_cast<std::size_t>(d)].at(p[static_cast<std::size_t>(d)]);
  return unit;
}

std::string hex16(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace

std::uint64_t fnv1a64(std::string_view text, std::uint64_t h) {
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

EnsemblePlan EnsemblePlan::make(const Study& study) {
  EnsemblePlan p;
  p.study_ = std::make_shared<const Study>(study);
  const std::string where = study.file.string() + ": ";
  try {
    bool patch_variants = false;
    for (std::size_t i = 0; i < study.laws.size(); ++i)
      patch_variants = patch_variants || !parse_variant(study.laws[i], "laws[" + std::to_string(i) + "]").patch.empty();
    for (std::size_t i = 0; i < study.set.size(); ++i) {
      const std::string key = study.set[i].substr(0, study.set[i].find('='));
      if (key == "contact.law")
        throw support::invalid_value("set[" + std::to_string(i) + "]", std::string_view(study.set[i]),
                                     "the laws are the study's `laws`");
      if (key == "contact.patch" && patch_variants)
        throw support::invalid_value("set[" + std::to_string(i) + "]", std::string_view(study.set[i]),
                                     "the contact models are the laws' @PATCH suffixes");
    }
    const std::string text = support::read_file(study.scenario, "scenario file");
    try {
      p.document_ = std::make_shared<const ScenarioDocument>(ScenarioDocument::parse(text, study.scenario.string()));
      p.model_ = run_model_from(p.document_->model(study.set));
      if (p.model_ == RunModel::puck)
        p.puck_base_ = std::make_shared<const puck::PuckScenario>(puck::resolve_puck(*p.document_, study.set));
      else
        p.base_ = std::make_shared<const Scenario>(p.document_->resolve(study.set));
    } catch (const std::invalid_argument& e) {
      throw support::invalid_value("scenario (with the study's set)", study.scenario.string(), e.what());
    }
    // The study's `shadow` says which laws the reference's runs evaluate; a scenario's run.shadow
    // would say it a second time, for every law's runs.
    const RunOptions& base_run = p.model_ == RunModel::puck ? p.puck_base_->run : p.base_->run;
    if (!base_run.shadow.empty())
      throw support::invalid_value("scenario (with the study's set)", study.scenario.string(),
                                   "run.shadow is set: in a study the shadow laws are the study's `shadow` key (by "
                                   "default the compared laws, along the reference law's runs)");
    const std::string& resolved = p.model_ == RunModel::puck ? p.puck_base_->resolved_toml : p.base_->resolved_toml;
    p.hash_ = hex16(fnv1a64(resolved, fnv1a64(std::string_view("\0", 1), fnv1a64(study.canonical))));
    if (p.model_ == RunModel::puck) {
      if (study.replicas > 1)
        throw support::invalid_value("replicas.count", static_cast<long long>(study.replicas),
                                     "a puck study has 1: the puck's motion is not chaotic, a replica would repeat its start's run");
    } else {
      p.rate_scale_ = body_scales(p.base_->body, p.base_->contact).rate;
    }

    for (std::size_t i = 0; i < study.laws.size(); ++i) {
      const Variant v = parse_variant(study.laws[i], "laws[" + std::to_string(i) + "]");
      try {
        (void)friction::make_law(v.law);
        if (!v.patch.empty()) {  // the contact model and the keys it needs, on the base start
          std::vector<std::string> o = study.set;
          for (auto& e : variant_overrides(v)) o.push_back(std::move(e));
          (void)p.document_->resolve(o);
        }
      } catch (const std::invalid_argument& e) {
        throw support::invalid_value("laws[" + std::to_string(i) + "]", std::string_view(study.laws[i]), e.what());
      }
    }
    if (study.shadow_compared) {
      const Variant reference = parse_variant(study.laws.front(), "laws[0]");
      for (std::size_t i = 1; i < study.laws.size(); ++i) {
        const Variant v = parse_variant(study.laws[i], "laws[" + std::to_string(i) + "]");
        if (v.patch != reference.patch || v.law == reference.law) continue;
        if (std::find(p.shadow_laws_.begin(), p.shadow_laws_.end(), v.law) == p.shadow_laws_.end())
          p.shadow_laws_.push_back(v.law);
      }
    } else {
      for (std::size_t i = 0; i < study.shadow_laws.size(); ++i) {
        try {
          (void)friction::make_law(study.shadow_laws[i]);
        } catch (const std::invalid_argument& e) {
          throw support::invalid_value("shadow[" + std::to_string(i) + "]", std::string_view(study.shadow_laws[i]), e.what());
        }
        p.shadow_laws_.push_back(study.shadow_laws[i]);
      }
    }
    for (std::size_t i = 0; i < study.vary.size(); ++i)
      p.keys_.push_back(
          VariedKey::parse(study.vary[i].key, "vary[" + std::to_string(i) + "].key", p.model_ == RunModel::puck));
    // Each key at its extremes, the others at their minimum: a key the scenario does not know,
    // or a range it rejects, is an error now rather than a thousand failed runs.
    std::vector<double> lows;
    for (const auto& a : study.vary) lows.push_back(a.min);
    for (std::size_t i = 0; i < study.vary.size(); ++i) {
      for (const double x : {study.vary[i].min, study.vary[i].max}) {
        std::vector<double> v = lows;
        v[i] = x;
        try {
          std::vector<std::string> o = study.set;
          if (p.model_ == RunModel::puck) {
            for (auto& e : puck_start_overrides(p.puck_base_->initial.v, p.keys_, v)) o.push_back(std::move(e));
            (void)puck::resolve_puck(*p.document_, o);
          } else {
            const StartState s = apply_start(p.base_->initial, p.base_->body.inertia, p.keys_, v);
            for (auto& e : start_overrides(s)) o.push_back(std::move(e));
            (void)p.document_->resolve(o);
          }
        } catch (const std::invalid_argument& e) {
          throw support::invalid_value("vary[" + std::to_string(i) + "]", std::string_view(study.vary[i].key),
                                       std::string("at ") + (x == study.vary[i].min ? "min" : "max") + ": " + e.what());
        }
      }
    }
    p.starts_ = draw_starts(study);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + e.what());
  }
  return p;
}

RunId EnsemblePlan::run_id(long index) const {
  RunId id;
  id.law = static_cast<int>(index % laws());
  const long sr = index / laws();
  id.replica = sr % replicas();
  id.start = sr / replicas();
  return id;
}

std::vector<std::string> EnsemblePlan::overrides(const RunId& id) const {
  if (model_ == RunModel::puck) {
    std::vector<std::string> o = study_->set;
    for (auto& e : puck_start_overrides(puck_base_->initial.v, keys_, start_values(id.start))) o.push_back(std::move(e));
    o.push_back("contact.law=" + study_->laws.at(static_cast<std::size_t>(id.law)));
    return o;
  }
  StartState s = apply_start(base_->initial, base_->body.inertia, keys_, start_values(id.start));
  s = perturb_replica(std::move(s), study_->replica_size, rate_scale_, study_->seed, id.start, id.replica);
  std::vector<std::string> o = study_->set;
  for (auto& e : start_overrides(s)) o.push_back(std::move(e));
  for (auto& e : variant_overrides(parse_variant(study_->laws.at(static_cast<std::size_t>(id.law)), "law")))
    o.push_back(std::move(e));
  return o;
}

Scenario EnsemblePlan::scenario(const RunId& id) const { return document_->resolve(overrides(id)); }

puck::PuckScenario EnsemblePlan::puck_scenario(const RunId& id) const {
  return puck::resolve_puck(*document_, overrides(id));
}

Task EnsemblePlan::task(long index) const {
  Task t;
  t.index = index;
  t.start = index / pairs_per_start();
  t.first_replica = 2 * (index % pairs_per_start());
  t.replica_count = std::min(2L, replicas() - t.first_replica);
  return t;
}

}  // namespace frictionlab::dynamics::ensemble
