#include "arguments.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace frictionlab::python {
namespace {

std::string quoted(std::string_view name) { return "'" + std::string(name) + "'"; }

// CPython's list of names: 'a'; 'a' and 'b'; 'a', 'b', and 'c'.
std::string name_list(const std::vector<std::string_view>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += i + 1 == names.size() ? (names.size() > 2 ? ", and " : " and ") : ", ";
    text += quoted(names[i]);
  }
  return text;
}

bool same_ignoring_case(std::string_view x, std::string_view y) {
  return std::equal(x.begin(), x.end(), y.begin(), y.end(), [](char p, char q) {
    return std::tolower(static_cast<unsigned char>(p)) == std::tolower(static_cast<unsigned char>(q));
  });
}

}  // namespace

void bind_arguments(std::string_view function, std::span<const char* const> names, const py::args& args,
                    const py::kwargs& kwargs, std::span<py::handle> out) {
  const std::size_t n = names.size();
  const auto f = [&] { return std::string(function) + "()"; };  // built for a message only
  if (args.size() > n) {
    // Counting self, as Python does for a method.
    const std::size_t takes = n + 1;
    const std::size_t given = args.size() + 1;
    throw py::type_error(f() + " takes " + std::to_string(takes) + " positional argument" + (takes == 1 ? "" : "s") +
                         " but " + std::to_string(given) + (given == 1 ? " was" : " were") + " given");
  }
  for (std::size_t i = 0; i < args.size(); ++i) out[i] = args[i];
  for (const auto& [key, value] : kwargs) {
    const std::string k = py::str(key);
    const auto at = std::find_if(names.begin(), names.end(), [&](const char* name) { return k == name; });
    if (at == names.end()) {
      std::string message = f() + " got an unexpected keyword argument " + quoted(k);
      // Python 3.12's hint, for the likely slip: the right name in the wrong case.
      for (const char* name : names) {
        if (same_ignoring_case(k, name)) message += ". Did you mean " + quoted(name) + "?";
      }
      throw py::type_error(message);
    }
    const auto i = static_cast<std::size_t>(at - names.begin());
    if (out[i]) throw py::type_error(f() + " got multiple values for argument " + quoted(k));
    out[i] = value;
  }
  std::vector<std::string_view> missing;
  for (std::size_t i = 0; i < n; ++i) {
    if (!out[i]) missing.emplace_back(names[i]);
  }
  if (!missing.empty()) {
    throw py::type_error(f() + " missing " + std::to_string(missing.size()) + " required positional argument" +
                         (missing.size() == 1 ? "" : "s") + ": " + name_list(missing));
  }
}

}  // namespace frictionlab::python
