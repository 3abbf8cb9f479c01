#pragma once
// Output whose every write and close is checked, and which stays valid when a write fails (a full
// disk, a file-size limit, /dev/full):
//
//   RecordFile             a file of records (CSV rows): a failed write is rolled back to the
//                          last whole record, so the file never ends in half a row; an optional
//                          size limit refuses the record that would pass it;
//   write_file_atomically  a small file (summary.json, scenario.toml) written to a temporary
//                          file beside it and renamed over it: it is either whole or absent;
//   finish_standard_output flushes and closes stdout and says if that failed.
//
// Failures throw OutputError naming the file and the system's reason.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::support {

/// A write, flush or close failed.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A record refused because the file would grow past its size limit (RecordFile::set_size_limit).
/// Not a failure: the file holds every record before it and can still be closed.
class SizeLimitReached : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file written as a sequence of whole records. Records are buffered; if a write fails (part of
/// the buffer may have reached the file) the file is cut back to the end of the last whole record
/// that reached it, and it stays failed (every later call throws the same OutputError). Not
/// thread-safe.
class RecordFile {
 public:
  /// truncate: the file starts empty; append: records go after what it holds (a job resumed).
  enum class OpenMode { truncate, append };

  /// Creates or truncates `path`. Throws OutputError if it cannot be opened for writing.
  explicit RecordFile(const std::filesystem::path& path, std::size_t buffer_bytes = kDefaultBuffer);
  /// Creates `path` or opens it in `mode`; a failed write is rolled back to the last whole record
  /// this object wrote, never into what the file held before.
  RecordFile(const std::filesystem::path& path, OpenMode mode, std::size_t buffer_bytes = kDefaultBuffer);
  /// Closes the file; errors are lost (call close() to see them).
  ~RecordFile();
  RecordFile(const RecordFile&) = delete;
  RecordFile& operator=(const RecordFile&) = delete;

  /// Appends one whole record (its own line ending included). Throws OutputError, or
  /// SizeLimitReached (the record is not taken) if size() would pass the size limit.
  void append(std::string_view record);
  /// The file may hold at most `bytes` (0: no limit, the default); in append mode what it held
  /// before counts too. Records already taken are kept.
  void set_size_limit(std::uint64_t bytes) { limit_ = bytes; }
  /// Hands every buffered record to the system (a process killed later keeps them). Throws.
  void flush();
  /// Flushes and closes, checking both. Throws OutputError; later calls do nothing.
  void close();

  /// Bytes of whole records that reached the file through this object.
  [[nodiscard]] std::uint64_t bytes_written() const { return written_; }
  /// The file's size once every record taken is written: what it held before (append mode), the
  /// records written and those buffered.
  [[nodiscard]] std::uint64_t size() const { return base_ + written_ + buffer_.size(); }
  [[nodiscard]] bool failed() const { return !failure_.empty(); }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  static constexpr std::size_t kDefaultBuffer = 1 << 16;

 private:
  [[noreturn]] void fail(const std::string& what, int error_number);
  void throw_if_failed() const;

  std::filesystem::path path_;
  int fd_ = -1;
  std::string buffer_;
  std::vector<std::size_t> record_ends_;  // end of each record in buffer_
  std::size_t capacity_;
  std::uint64_t base_ = 0;     // the file's size when opened (append mode)
  std::uint64_t written_ = 0;
  std::uint64_t limit_ = 0;    // 0: none
  std::string failure_;
};

/// Writes `content` to `path` through a temporary file in the same folder, renamed over `path`
/// once it is completely written and closed. On failure the temporary file is removed, `path`
/// is left as it was, and OutputError names `path`.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

/// Flushes std::cout and stdout and closes stdout; throws OutputError ("writing to standard
/// output failed: REASON") if any of it failed (a closed pipe, /dev/full). Call once, at the end.
void finish_standard_output();

}  // namespace frictionlab::support
