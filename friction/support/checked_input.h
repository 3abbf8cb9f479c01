#pragma once
// Input whose every read is checked, so that a failed read (EIO, a file of /proc that refuses
// reads, a folder) is an error naming the file and the system's reason, never taken for the end of
// a shorter or empty file:
//
//   read_file    a file read whole (a scenario, a study, runs.csv, a run's summary), where reading
//                through a std::ifstream's rdbuf() puts a read error on the output stream;
//   InputStream  a file or standard input read as a stream (a CSV table), where std::cin, synced
//                with stdio, takes a read error for the end of the input.

#include <array>
#include <filesystem>
#include <istream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <string_view>

namespace frictionlab::support {

/// A file could not be opened or read. A std::invalid_argument (the input the user named is not
/// usable); error_number() is the errno of the failure (ENOENT, EISDIR, EIO, ...).
class InputError : public std::invalid_argument {
 public:
  InputError(const std::string& message, int error_number)
      : std::invalid_argument(message), error_number_(error_number) {}
  [[nodiscard]] int error_number() const noexcept { return error_number_; }

 private:
  int error_number_;
};

/// The whole content of `file`. `what` names it in messages ("scenario file"):
///   "cannot read scenario file 'PATH': No such file or directory"  (it cannot be opened)
///   "scenario file 'PATH' is a folder: give the path of a file"
///   "reading scenario file 'PATH' failed: Input/output error"      (a read failed part-way)
/// Throws InputError.
[[nodiscard]] std::string read_file(const std::filesystem::path& file, std::string_view what);

/// A file ("-": standard input) as a std::istream whose reads go through read(2): a read that fails
/// sets badbit (as std::ifstream's do), and errno keeps the system's reason. Opening it throws
/// InputError as read_file does.
class InputStream : public std::istream {
 public:
  InputStream(const std::filesystem::path& file, std::string_view what);
  ~InputStream() override;
  InputStream(const InputStream&) = delete;
  InputStream& operator=(const InputStream&) = delete;

 private:
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(int fd) : fd_(fd) {}
    [[nodiscard]] int fd() const { return fd_; }

   protected:
    int_type underflow() override;

   private:
    int fd_;
    std::array<char, 1 << 16> data_{};
  };
  Buffer buffer_;
};

}  // namespace frictionlab::support
