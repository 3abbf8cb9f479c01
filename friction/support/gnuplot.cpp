#include "friction/support/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

extern char** environ;

namespace frictionlab::support {
namespace {

constexpr const char* kGnuplot = "gnuplot";

struct Spawned {
  int start_error = 0;  // errno of posix_spawnp (ENOENT: not found)
  int status = -1;      // waitpid status
};

// Runs argv[0] (looked up on PATH) in `dir` (empty: here) with stdin from /dev/null and
// stdout + stderr into `output` (opened after the change of directory).
Spawned spawn_and_wait(std::vector<std::string> args, const std::filesystem::path& dir,
                       const std::filesystem::path& output) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!dir.empty()) posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  Spawned s;
  pid_t pid = 0;
  s.start_error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (s.start_error != 0) return s;
  while (::waitpid(pid, &s.status, 0) < 0) {
    if (errno != EINTR) {
      s.status = -1;
      break;
    }
  }
  return s;
}

bool exited_zero(int status) { return status >= 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0; }

}  // namespace

std::string gnuplot_escaped(std::string_view text) {
  // Each character gnuplot's enhanced-text mode reads as markup (`help enhanced`) is preceded by a
  // backslash, so that it is shown as itself.
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (std::string_view("^_@&~{}\\").find(c) != std::string_view::npos) out.push_back('\\');
    out.push_back(c);
  }
  return out;
}

std::string gnuplot_quoted(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    out.push_back(c);
    if (c == '\'') out.push_back('\'');
  }
  return out + "'";
}

std::string gnuplot_text(std::string_view text) { return gnuplot_quoted(gnuplot_escaped(text)); }

std::string gnuplot_label_column_text(std::string_view text) {
  std::string doubled;
  for (const char c : gnuplot_escaped(text)) {
    doubled.push_back(c);
    if (c == '\\') doubled.push_back(c);
  }
  return gnuplot_quoted(doubled);
}

bool gnuplot_has_terminal(std::string_view terminal) {
  const Spawned s = spawn_and_wait({kGnuplot, "-e", "set terminal " + std::string(terminal)}, {}, "/dev/null");
  return s.start_error == 0 && exited_zero(s.status);
}

GnuplotRun run_gnuplot(const std::filesystem::path& dir, const std::filesystem::path& script,
                       const std::filesystem::path& log) {
  GnuplotRun run;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    run.message = "cannot run gnuplot in '" + dir.string() + "': not a folder";
    return run;
  }
  const Spawned s = spawn_and_wait({kGnuplot, script.string()}, dir, log);
  const std::filesystem::path log_path = log.is_absolute() ? log : dir / log;
  if (s.start_error != 0) {
    run.found = s.start_error != ENOENT;
    run.message = run.found ? "cannot start gnuplot: " + std::string(std::strerror(s.start_error))
                            : "gnuplot not found (install gnuplot-nox)";
    return run;
  }
  run.ok = exited_zero(s.status);
  if (run.ok) {
    if (std::filesystem::file_size(log_path, ec) == 0 && !ec) std::filesystem::remove(log_path, ec);
  } else {
    run.message = "gnuplot failed on " + (dir / script).string() + " (see " + log_path.string() + ")";
  }
  return run;
}

std::vector<std::string> run_gnuplot_scripts(const std::filesystem::path& dir,
                                             const std::vector<std::string>& scripts) {
  std::vector<std::string> errors;
  for (const auto& script : scripts) {
    const GnuplotRun run = run_gnuplot(dir, script, std::filesystem::path(script).stem().string() + ".log");
    if (!run.found) {
      errors.push_back(run.message + ": no PNG drawn (the scripts are in " + dir.string() + ")");
      break;
    }
    if (!run.ok) errors.push_back(run.message);
  }
  return errors;
}

}  // namespace frictionlab::support
