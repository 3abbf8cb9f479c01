#include "friction/support/checked_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace frictionlab::support {
namespace {

// Closes the descriptor when the read ends, however it ends.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  [[nodiscard]] int get() const { return fd_; }

 private:
  int fd_;
};

std::string named(std::string_view what, const std::filesystem::path& file) {
  return std::string(what) + " '" + file.string() + "'";
}

// Opens `file` for reading; InputError if it cannot be opened or is a folder.
int open_checked(const std::filesystem::path& file, std::string_view what) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    throw InputError("cannot read " + named(what, file) + ": " + std::strerror(error), error);
  }
  struct stat info {};
  if (::fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
    ::close(fd);
    throw InputError(named(what, file) + " is a folder: give the path of a file", EISDIR);
  }
  return fd;
}

}  // namespace

std::string read_file(const std::filesystem::path& file, std::string_view what) {
  const Descriptor fd(open_checked(file, what));
  struct stat info {};
  (void)::fstat(fd.get(), &info);
  std::string text;
  // Files of /proc report size 0: read in chunks until read(2) says the end (0) or fails (-1).
  if (info.st_size > 0) text.reserve(static_cast<std::size_t>(info.st_size));
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), chunk, sizeof chunk);
    if (n == 0) return text;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      throw InputError("reading " + named(what, file) + " failed: " + std::strerror(error), error);
    }
    text.append(chunk, static_cast<std::size_t>(n));
  }
}

InputStream::InputStream(const std::filesystem::path& file, std::string_view what)
    : std::istream(nullptr), buffer_(file == "-" ? STDIN_FILENO : open_checked(file, what)) {
  rdbuf(&buffer_);
}

InputStream::~InputStream() {
  if (buffer_.fd() != STDIN_FILENO) ::close(buffer_.fd());
}

InputStream::Buffer::int_type InputStream::Buffer::underflow() {
  for (;;) {
    const ssize_t n = ::read(fd_, data_.data(), data_.size());
    if (n > 0) {
      setg(data_.data(), data_.data(), data_.data() + n);
      return traits_type::to_int_type(data_.front());
    }
    if (n == 0) return traits_type::eof();
    if (errno == EINTR) continue;
    // The istream sets badbit (an exception from the buffer is how a stream learns of an error);
    // errno still says why.
    const int error = errno;
    std::system_error failure(error, std::generic_category(), "read");
    errno = error;
    throw failure;
  }
}

}  // namespace frictionlab::support
