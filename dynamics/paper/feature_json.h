#pragma once
// features.json of one run of `frictionlab paper`: the measured features (dynamics/paper/
// run_features.h) and the thresholds that defined them. Non-finite numbers are written as null.

#include <ostream>

#include "dynamics/paper/run_features.h"

namespace frictionlab::dynamics::paper {

void write_features_json(std::ostream& out, const RunFeatures& f, const FeatureThresholds& th);

}  // namespace frictionlab::dynamics::paper
