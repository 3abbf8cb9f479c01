#pragma once
// Runs the built `frictionlab` binary through the shell and captures what it prints.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace frictionlab::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// An empty path under the temporary directory, unique to this process: `frictionlab_<tag>_<pid>`.
inline std::filesystem::path fresh_temp_dir(const std::string& tag) {
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

/// Runs `FRICTIONLAB_EXE args` (args are shell words, may include `< file`).
inline CommandResult run_frictionlab(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto err = dir / ("frictionlab_test_err_" + std::to_string(::getpid()));
  const std::string cmd = std::string(FRICTIONLAB_EXE) + " " + args + " 2>" + err.string();
  CommandResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(err);
  std::filesystem::remove(err);
  return r;
}

}  // namespace frictionlab::testing
