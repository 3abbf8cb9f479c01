#pragma once
// Where the command finds the data frictionlab ships (data/scenarios/, data/studies/), so that
// `frictionlab simulate sphere-sliding` works from any folder:
//
//   1. data/ under the working directory (a checkout);
//   2. the installed data beside the command: <bindir>/../share/frictionlab (from the install
//      layout, /proc/self/exe locating the command);
//   3. the source tree's data/ the command was built from (a build tree).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::dynamics {

/// The folders that may hold the shipped data, in the order they are searched (see above).
[[nodiscard]] std::vector<std::filesystem::path> shipped_data_dirs();

/// The file a user named on the command line, `kind` being the data folder it belongs to
/// ("scenarios", "studies"): `given` itself if it exists (an explicit path wins); else, for a
/// bare name (no '/'), the first of NAME and NAME.toml in each shipped_data_dirs()/KIND; else
/// `given` unchanged (a path with a folder that does not exist: reading it says so). A bare name
/// found nowhere is std::invalid_argument naming the folders searched:
///   "scenario 'x' not found: no file 'x' here, and no x or x.toml in data/scenarios, ..."
[[nodiscard]] std::filesystem::path find_shipped_file(const std::string& given, std::string_view kind,
                                                      std::string_view what);

}  // namespace frictionlab::dynamics
