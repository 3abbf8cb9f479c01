#include "file_errors.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <system_error>

namespace frictionlab::python {

void raise_if_unreadable(const std::string& path, const std::string& message) {
  int err = 0;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    err = EISDIR;
  } else {
    // O_NONBLOCK: a FIFO must not block this check.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
      err = errno;
    } else {
      ::close(fd);
    }
  }
  if (err == 0) return;
  // OSError(errno, ...) is constructed as the subclass for that errno; the raised exception is
  // that subclass made with the message alone, so that str() is the command line's line.
  const auto kind = py::reinterpret_borrow<py::object>(py::reinterpret_borrow<py::object>(PyExc_OSError)(err, "").get_type());
  py::object exception = kind(message);
  exception.attr("errno") = err;
  PyErr_SetObject(kind.ptr(), exception.ptr());
  throw py::error_already_set();
}

}  // namespace frictionlab::python
