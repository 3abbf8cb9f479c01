#include "friction/support/checked_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <utility>

namespace frictionlab::support {
namespace {

std::string reason(int error_number) { return error_number != 0 ? std::strerror(error_number) : "unknown error"; }

// Writes all of [data, data + size) to fd, retrying after signals. Returns 0 or the errno;
// `done` (if given) receives the bytes that were written.
int write_all(int fd, const char* data, std::size_t size, std::size_t* done = nullptr) {
  std::size_t written = 0;
  int error_number = 0;
  while (written < size) {
    const ssize_t n = ::write(fd, data + written, size - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      error_number = errno;
      break;
    }
    if (n == 0) {
      error_number = EIO;  // a file never accepts nothing without an error
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  if (done) *done = written;
  return error_number;
}

}  // namespace

RecordFile::RecordFile(const std::filesystem::path& path, std::size_t buffer_bytes)
    : RecordFile(path, OpenMode::truncate, buffer_bytes) {}

RecordFile::RecordFile(const std::filesystem::path& path, OpenMode mode, std::size_t buffer_bytes)
    : path_(path), capacity_(buffer_bytes > 0 ? buffer_bytes : kDefaultBuffer) {
  const int how = mode == OpenMode::append ? O_APPEND : O_TRUNC;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | how | O_CLOEXEC, 0666);
  if (fd_ < 0) throw OutputError("cannot write '" + path.string() + "': " + reason(errno));
  if (mode == OpenMode::append) {
    const off_t end = ::lseek(fd_, 0, SEEK_END);
    if (end < 0) {
      const int error_number = errno;
      ::close(std::exchange(fd_, -1));
      throw OutputError("cannot append to '" + path.string() + "': " + reason(error_number));
    }
    base_ = static_cast<std::uint64_t>(end);
  }
  buffer_.reserve(capacity_);
}

RecordFile::~RecordFile() {
  if (fd_ < 0) return;
  if (failure_.empty() && !buffer_.empty()) {
    // Best effort: keep the buffered whole records, or none of them.
    if (write_all(fd_, buffer_.data(), buffer_.size()) != 0) (void)::ftruncate(fd_, static_cast<off_t>(base_ + written_));
  }
  ::close(fd_);
}

void RecordFile::throw_if_failed() const {
  if (!failure_.empty()) throw OutputError(failure_);
}

void RecordFile::fail(const std::string& what, int error_number) {
  failure_ = what + " '" + path_.string() + "' failed: " + reason(error_number);
  throw OutputError(failure_);
}

void RecordFile::append(std::string_view record) {
  throw_if_failed();
  if (fd_ < 0) throw OutputError("'" + path_.string() + "' is already closed");
  if (limit_ > 0 && size() + record.size() > limit_)
    throw SizeLimitReached("'" + path_.string() + "' holds " + std::to_string(size()) + " bytes; the next record (" +
                           std::to_string(record.size()) + " bytes) would take it past its limit of " +
                           std::to_string(limit_) + " bytes");
  if (!buffer_.empty() && buffer_.size() + record.size() > capacity_) flush();
  buffer_.append(record);
  record_ends_.push_back(buffer_.size());
}

void RecordFile::flush() {
  throw_if_failed();
  if (fd_ < 0 || buffer_.empty()) return;
  std::size_t done = 0;
  const int error_number = write_all(fd_, buffer_.data(), buffer_.size(), &done);
  if (error_number != 0) {
    // Part of the buffer may have reached the file: keep the whole records among it, cut the rest.
    const auto whole = std::upper_bound(record_ends_.begin(), record_ends_.end(), done);
    written_ += whole == record_ends_.begin() ? 0 : *(whole - 1);
    (void)::ftruncate(fd_, static_cast<off_t>(base_ + written_));
    buffer_.clear();
    record_ends_.clear();
    fail("writing", error_number);
  }
  written_ += buffer_.size();
  buffer_.clear();
  record_ends_.clear();
}

void RecordFile::close() {
  if (fd_ < 0) {
    throw_if_failed();
    return;
  }
  try {
    flush();
  } catch (const OutputError&) {
    ::close(std::exchange(fd_, -1));
    throw;
  }
  if (::close(std::exchange(fd_, -1)) != 0) fail("closing", errno);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  static std::atomic<unsigned long> counter{0};
  const std::filesystem::path temporary =
      path.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
  const auto fail = [&](int error_number) {
    ::unlink(temporary.c_str());
    throw OutputError("cannot write '" + path.string() + "': " + reason(error_number));
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw OutputError("cannot write '" + path.string() + "': " + reason(errno));
  const int write_error = write_all(fd, content.data(), content.size());
  const int close_result = ::close(fd);
  if (write_error != 0) fail(write_error);
  if (close_result != 0) fail(errno);
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail(errno);
}

void finish_standard_output() {
  // std::cout writes through stdout (synchronised with stdio): a failed write or flush shows as a
  // bad stream, with errno still telling why; stdio's own state is checked after.
  errno = 0;
  std::cout.flush();
  bool failed = !std::cout;
  int error_number = failed ? errno : 0;
  errno = 0;
  if (std::fflush(stdout) != 0) {
    failed = true;
    if (error_number == 0) error_number = errno;
  }
  failed = failed || std::ferror(stdout);
  // Closing reports what a flush cannot (e.g. a network file system); stdout already closed by
  // the caller of the program (EBADF) is not an error of ours.
  errno = 0;
  if (std::fclose(stdout) != 0 && errno != EBADF) {
    failed = true;
    if (error_number == 0) error_number = errno;
  }
  if (failed)
    throw OutputError("writing to standard output failed" + (error_number != 0 ? ": " + reason(error_number) : ""));
}

}  // namespace frictionlab::support
