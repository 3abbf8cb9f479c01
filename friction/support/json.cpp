#include "friction/support/json.h"

namespace frictionlab::support {

std::string json_text(const Json& value) {
  return value.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace frictionlab::support
