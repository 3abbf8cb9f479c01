#include "dynamics/ensemble/run_model.h"

#include "friction/support/errors.h"

namespace frictionlab::dynamics::ensemble {

std::string_view to_string(RunModel m) { return m == RunModel::puck ? "puck" : "body"; }

RunModel run_model_from(std::string_view name) {
  if (name == "body") return RunModel::body;
  if (name == "puck") return RunModel::puck;
  throw support::invalid_value("model", name, "it must be \"body\" or \"puck\"");
}

}  // namespace frictionlab::dynamics::ensemble
