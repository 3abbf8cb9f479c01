#pragma once
// Runs the built `frictionlab` binary as a user does and captures what it prints: through the
// shell (run_frictionlab), under a file-size limit (run_frictionlab_with_file_limit), or stopped
// by a signal once it is under way (run_frictionlab_signalled).

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

namespace frictionlab::testing {

struct CommandResult {
  int exit_code = -1;  ///< -1 if it did not exit normally
  int signal = 0;      ///< the signal that killed it, if one did
  std::string out;     ///< stdout
  std::string err;     ///< stderr
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// An empty path under the temporary directory, unique to this process: `frictionlab_<tag>_<pid>`.
inline std::filesystem::path fresh_temp_dir(const std::string& tag) {
  const auto dir = std::filesystem::temp_directory_path() / ("frictionlab_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

/// Runs `FRICTIONLAB_EXE args` (args are shell words, may include `< file`), in the folder
/// `cwd` if one is given (else in the test's own).
inline CommandResult run_frictionlab(const std::string& args, const std::filesystem::path& cwd = {}) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto err = dir / ("frictionlab_test_err_" + std::to_string(::getpid()));
  const std::string cd = cwd.empty() ? std::string() : "cd '" + cwd.string() + "' && ";
  const std::string cmd = cd + std::string(FRICTIONLAB_EXE) + " " + args + " 2>" + err.string();
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

namespace detail {

// Starts `exec FRICTIONLAB_EXE args >out 2>err` in a child shell after `setup` ran in the child
// (which may change limits or signal dispositions: both survive exec). Returns the child's pid.
inline pid_t spawn_frictionlab(const std::string& args, const std::filesystem::path& out,
                               const std::filesystem::path& err, const std::function<void()>& setup) {
  const std::string cmd =
      "exec " + std::string(FRICTIONLAB_EXE) + " " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    setup();
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

inline CommandResult wait_for(pid_t pid, const std::filesystem::path& out, const std::filesystem::path& err) {
  CommandResult r;
  int status = 0;
  if (pid > 0 && ::waitpid(pid, &status, 0) == pid) {
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  }
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// Not run_frictionlab's file: a test may run a command while a spawned one runs.
inline std::filesystem::path capture_file(const char* what) {
  return std::filesystem::temp_directory_path() /
         ("frictionlab_test_spawned_" + std::string(what) + "_" + std::to_string(::getpid()));
}

}  // namespace detail

/// Runs `FRICTIONLAB_EXE args` with no file allowed to grow beyond `bytes` (RLIMIT_FSIZE, as
/// `ulimit -f` sets it; SIGXFSZ keeps its default action, so the program must deal with it).
/// Its stdout and stderr are captured in files under the same limit (they stay far below it).
inline CommandResult run_frictionlab_with_file_limit(const std::string& args, rlim_t bytes) {
  const auto out = detail::capture_file("out");
  const auto err = detail::capture_file("err");
  const pid_t pid = detail::spawn_frictionlab(args, out, err, [bytes] {
    const rlimit limit{bytes, bytes};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  });
  return detail::wait_for(pid, out, err);
}

/// Starts `FRICTIONLAB_EXE args`, waits until `ready()` is true (polled every 10 ms, at most
/// `timeout`), sends `signal`, and waits for the end. If `ready()` never held, the signal is
/// sent at the timeout anyway (and the test will see a run that did not start).
inline CommandResult run_frictionlab_signalled(const std::string& args, int signal, const std::function<bool()>& ready,
                                               std::chrono::milliseconds timeout = std::chrono::seconds(20)) {
  const auto out = detail::capture_file("out");
  const auto err = detail::capture_file("err");
  const pid_t pid = detail::spawn_frictionlab(args, out, err, [] {});
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (!ready() && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(pid, signal);
  return detail::wait_for(pid, out, err);
}

}  // namespace frictionlab::testing
