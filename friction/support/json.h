#pragma once
// JSON documents (summary.json, features.json): nlohmann::json, with one way of writing them.

#include <string>

#include <nlohmann/json.hpp>

namespace frictionlab::support {

/// A JSON value whose objects keep their keys in the order they were added, so that files read in
/// the order their documentation lists them.
using Json = nlohmann::ordered_json;

/// The text of `value`: 2-space indent and a final newline. Non-finite numbers are written as
/// null (JSON has no inf or nan); invalid UTF-8 in strings (a file name in another encoding) is
/// replaced by U+FFFD instead of failing.
[[nodiscard]] std::string json_text(const Json& value);

}  // namespace frictionlab::support
