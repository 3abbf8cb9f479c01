#include "dynamics/io/shipped_data.h"

#include <algorithm>
#include <stdexcept>
#include <system_error>

#ifndef FRICTIONLAB_SOURCE_DIR
#define FRICTIONLAB_SOURCE_DIR "."
#endif
// The installed data relative to the installed command's folder (set by CMake from the install
// layout: bin/frictionlab -> share/frictionlab).
#ifndef FRICTIONLAB_DATA_DIR_FROM_BINDIR
#define FRICTIONLAB_DATA_DIR_FROM_BINDIR "../share/frictionlab"
#endif

namespace frictionlab::dynamics {

std::vector<std::filesystem::path> shipped_data_dirs() {
  std::vector<std::filesystem::path> dirs = {"data"};
  // An installed command must not depend on the source tree it was built from: its data is
  // installed beside it. The running program's own path is /proc/self/exe (Linux).
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back((exe.parent_path() / FRICTIONLAB_DATA_DIR_FROM_BINDIR).lexically_normal());
  const std::filesystem::path source = std::filesystem::path(FRICTIONLAB_SOURCE_DIR) / "data";
  if (std::find(dirs.begin(), dirs.end(), source) == dirs.end()) dirs.push_back(source);
  return dirs;
}

std::filesystem::path find_shipped_file(const std::string& given, std::string_view kind, std::string_view what) {
  std::error_code ec;
  const std::filesystem::path path(given);
  if (given.empty() || std::filesystem::exists(path, ec) || given.find('/') != std::string::npos) return path;
  std::string searched;
  for (const auto& dir : shipped_data_dirs()) {
    const std::filesystem::path folder = dir / kind;
    for (const std::string& name : {given, given + ".toml"}) {
      if (std::filesystem::is_regular_file(folder / name, ec)) return folder / name;
    }
    searched += (searched.empty() ? "" : ", ") + folder.string();
  }
  throw std::invalid_argument(std::string(what) + " '" + given + "' not found: no file '" + given +
                              "' here, and no " + given + " or " + given + ".toml in " + searched);
}

}  // namespace frictionlab::dynamics
