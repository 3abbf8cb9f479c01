#pragma once
// features.json of one run of `frictionlab paper`: the measured features (dynamics/paper/
// run_features.h) and the thresholds that defined them. Non-finite numbers are written as null.

#include "dynamics/paper/run_features.h"
#include "friction/support/json.h"

namespace frictionlab::dynamics::paper {

[[nodiscard]] support::Json features_json(const RunFeatures& f, const FeatureThresholds& th);

}  // namespace frictionlab::dynamics::paper
