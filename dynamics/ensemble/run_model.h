#pragma once
// Which model the runs of a study integrate: the base scenario's top-level `model`
// (dynamics/body/scenario.h): "body" (a body of revolution on a Hertz plane: the egg, the tippe top)
// or "puck" (the sliding-spinning puck, dynamics/puck/). Each model has its own per-run features
// and so its own columns of runs.csv (dynamics/ensemble/run_record.h) and its own compared
// features (dynamics/ensemble/feature_comparison.h); the rest of the ensemble is the same.

#include <string_view>

namespace frictionlab::dynamics::ensemble {

enum class RunModel { body, puck };

/// "body", "puck".
[[nodiscard]] std::string_view to_string(RunModel m);
/// The model of a scenario's `model` value ("body" or "puck"); another is std::invalid_argument
/// naming the key `model` and the rule.
[[nodiscard]] RunModel run_model_from(std::string_view name);

}  // namespace frictionlab::dynamics::ensemble
