#pragma once
// One job per output folder: a FolderLock claims a folder for this process with flock(2) on
// DIR/.frictionlab.lock, a file that holds the claimant's pid. A second job on the folder (two
// `ensemble --resume` or `paper --resume` started together would both redo the same runs) is
// refused with one line naming the folder and the pid holding it.
//
// The claim ends when the FolderLock dies (the file is removed), and the system ends it when the
// process dies however it dies (SIGKILL, a crash, a lost node): a lock file left behind by a dead
// process is not held, and the next job takes it over without anyone deleting it.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace frictionlab::support {

/// Another process holds the folder: a std::invalid_argument (choose another folder, or wait).
class FolderInUse : public std::invalid_argument {
 public:
  FolderInUse(const std::string& message, long holder) : std::invalid_argument(message), holder_(holder) {}
  /// The holder's pid, as its lock file says (0 if it could not be read).
  [[nodiscard]] long holder() const noexcept { return holder_; }

 private:
  long holder_;
};

class FolderLock {
 public:
  /// The lock file's name in the folder.
  static constexpr const char* kFileName = ".frictionlab.lock";

  /// Creates `dir` if needed and claims it. Throws FolderInUse if another job holds it:
  ///   "OPTION DIR is in use by another frictionlab job (pid 1234; DIR/.frictionlab.lock): wait
  ///    for it to end, or choose another OPTION"
  /// and support::OutputError if the folder or the lock file cannot be created. `option` names
  /// the folder as the user gave it ("--out").
  explicit FolderLock(const std::filesystem::path& dir, const std::string& option = "--out");
  /// Removes the lock file and releases the claim.
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace frictionlab::support
