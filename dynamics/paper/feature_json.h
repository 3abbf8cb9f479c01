#pragma once
// features.json of one run of `frictionlab paper`: the measured features (dynamics/paper/
// run_features.h) and the thresholds that defined them. Non-finite numbers are written as null;
// numbers read back to the same doubles, so that a job resumed from the files (--resume) judges
// exactly what the first job measured.

#include "dynamics/paper/run_features.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics::paper {

[[nodiscard]] support::Json features_json(const RunFeatures& f, const FeatureThresholds& th);

/// The features of a features.json (null: NaN). std::runtime_error naming the key if one is
/// missing or of the wrong type.
[[nodiscard]] RunFeatures features_from_json(const support::Json& j);

}  // namespace frictionlab::dynamics::paper
