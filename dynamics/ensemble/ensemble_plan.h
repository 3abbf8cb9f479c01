#pragma once
// Every run of a study: (start x replica x law), numbered, with its scenario, and grouped into
// tasks. The base scenario is read once; each run's scenario is the base resolved with, in order,
// the study's `set`, the start's varied keys (dynamics/ensemble/varied_key.h), the replica's
// perturbed initial vectors (dynamics/ensemble/replica.h) and contact.law = the law (with its
// contact model, contact.patch, for a variant `LAW@PATCH`: dynamics/ensemble/variant.h).
//
// Run index  i = (start * replicas + replica) * laws + law. It identifies a run within a study;
// the study's hash identifies the study, so that `--resume` refuses a folder made by another one:
// FNV-1a 64 of the study as parsed and of the base scenario as resolved with the study's `set`
// (both written back as TOML: a changed value changes the hash, a reworded comment does not).
//
// Tasks: a task is one start and one pair of replicas (2p, 2p + 1) with every law — the runs
// that are compared along the trajectory: each law against the reference law on the same replica
// (the law's divergence time), and the reference on replica 2p + 1 against the reference on 2p
// (the chaos floor's divergence time). The reference runs first; its trajectory is kept in
// memory only while the task runs, so memory does not grow with the number of runs
// (docs/ensembles.md §2). A study with one replica has tasks of one replica.
//
// The model is the base scenario's (dynamics/ensemble/run_model.h). A puck scenario's runs are its
// file resolved with the study's `set`, the start's keys (varied_key.h: puck_start_overrides) and
// the law; a puck study has one replica (the puck's motion is not chaotic: a replica would repeat
// its start's run, so its floor is zero, dynamics/ensemble/feature_comparison.h).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/ensemble/run_model.h"
#include "dynamics/ensemble/study.h"
#include "dynamics/ensemble/varied_key.h"
#include "dynamics/puck/puck_scenario.h"
#include "dynamics/body/scenario.h"

namespace frictionlab::dynamics::ensemble {

struct RunId {
  long start = 0;
  long replica = 0;
  int law = 0;  ///< index into Study::laws (0: the reference)
};

/// A start and its replicas `first_replica` .. `first_replica + replica_count - 1`, every law.
struct Task {
  long index = 0;
  long start = 0;
  long first_replica = 0;
  long replica_count = 1;  ///< 1 or 2
};

class EnsemblePlan {
 public:
  /// Reads the base scenario, resolves it with the study's `set`, draws the design, and checks
  /// the varied keys (each at its extremes) and the laws, so that a bad study fails before
  /// anything runs (std::invalid_argument naming the study file and its key).
  static EnsemblePlan make(const Study& study);

  [[nodiscard]] const Study& study() const { return *study_; }
  [[nodiscard]] long starts() const { return static_cast<long>(starts_.size()); }
  [[nodiscard]] long replicas() const { return study_->replicas; }
  [[nodiscard]] int laws() const { return static_cast<int>(study_->laws.size()); }
  [[nodiscard]] long runs() const { return starts() * replicas() * laws(); }
  [[nodiscard]] long run_index(const RunId& id) const { return (id.start * replicas() + id.replica) * laws() + id.law; }
  [[nodiscard]] RunId run_id(long index) const;

  /// The varied keys' values of a start (before any replica's perturbation), in the study's order.
  [[nodiscard]] const std::vector<double>& start_values(long start) const {
    return starts_.at(static_cast<std::size_t>(start));
  }
  /// The overrides that make run `id` from the base scenario file (see the header comment).
  [[nodiscard]] std::vector<std::string> overrides(const RunId& id) const;
  /// The run's scenario, resolved (throws std::invalid_argument if this start's values make an
  /// invalid scenario: the run is then recorded as failed).
  [[nodiscard]] Scenario scenario(const RunId& id) const;
  /// The same for a puck study (model() == RunModel::puck).
  [[nodiscard]] puck::PuckScenario puck_scenario(const RunId& id) const;
  /// The model every run of the study integrates.
  [[nodiscard]] RunModel model() const { return model_; }
  /// The laws the reference law's runs evaluate along their motion (dynamics/core/shadow_laws.h;
  /// runs.csv's shadow columns are named by them): the study's `shadow` list, or by default the
  /// law of every compared variant under the reference's contact model (a variant under another
  /// model has another contact to evaluate at: its runs are compared by their trajectories only),
  /// each once, the reference's own law left out.
  [[nodiscard]] const std::vector<std::string>& shadow_laws() const { return shadow_laws_; }

  [[nodiscard]] long tasks() const { return starts() * pairs_per_start(); }
  [[nodiscard]] Task task(long index) const;
  [[nodiscard]] long pairs_per_start() const { return (replicas() + 1) / 2; }

  /// 16 hexadecimal digits: FNV-1a 64 of Study::canonical, a NUL, the resolved base scenario.
  [[nodiscard]] const std::string& hash() const { return hash_; }
  /// The base scenario resolved with the study's `set` (its law as the file says); a body study's.
  [[nodiscard]] const Scenario& base() const { return *base_; }

 private:
  std::shared_ptr<const Study> study_;
  std::shared_ptr<const ScenarioDocument> document_;
  std::shared_ptr<const Scenario> base_;                  // model body
  std::shared_ptr<const puck::PuckScenario> puck_base_;   // model puck
  RunModel model_ = RunModel::body;
  std::vector<VariedKey> keys_;
  std::vector<std::string> shadow_laws_;
  std::vector<std::vector<double>> starts_;
  double rate_scale_ = 0.0;
  std::string hash_;
};

/// FNV-1a 64 of `text`, continuing from `h` (the offset basis by default).
[[nodiscard]] std::uint64_t fnv1a64(std::string_view text, std::uint64_t h = 0xcbf29ce484222325ULL);

}  // namespace frictionlab::dynamics::ensemble
