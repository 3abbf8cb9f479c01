#include "friction/support/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "friction/support/checked_output.h"

namespace frictionlab::support {
namespace {

// The pid a lock file holds (0 if none can be read: the holder has not written it yet).
long holder_of(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return 0;
  char* end = nullptr;
  const long pid = std::strtol(text, &end, 10);
  return end != text && pid > 0 ? pid : 0;
}

// Whether `fd` is still the file at `path`: a holder that released the lock has removed the file
// it locked, and a lock on that removed file claims nothing.
bool still_linked(int fd, const std::filesystem::path& path) {
  struct stat open_file {};
  struct stat named {};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 && open_file.st_dev == named.st_dev &&
         open_file.st_ino == named.st_ino;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& dir, const std::string& option) : path_(dir / kFileName) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw OutputError("cannot create the output folder '" + dir.string() + "': " + ec.message());
  for (;;) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw OutputError("cannot create the lock file '" + path_.string() + "': " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const long holder = holder_of(fd);
      ::close(fd);
      if (error != EWOULDBLOCK)
        throw OutputError("cannot lock '" + path_.string() + "': " + std::strerror(error));
      throw FolderInUse(option + " " + dir.string() + " is in use by another frictionlab job (" +
                            (holder > 0 ? "pid " + std::to_string(holder) : std::string("pid not yet written")) +
                            "; " + path_.string() + "): wait for it to end, or choose another " + option,
                        holder);
    }
    if (!still_linked(fd, path_)) {  // taken from a holder that just released it: try the new file
      ::close(fd);
      continue;
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
      const int error = errno;
      ::unlink(path_.c_str());
      ::close(fd);
      throw OutputError("cannot write the lock file '" + path_.string() + "': " + std::strerror(error));
    }
    fd_ = fd;
    return;
  }
}

FolderLock::~FolderLock() {
  // Removed while still locked, so that no other job can lock this file after it is released.
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace frictionlab::support
