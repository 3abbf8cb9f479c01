#pragma once
// A file the C++ side cannot read is an OSError in Python, of the subclass open() would raise
// (FileNotFoundError, PermissionError, IsADirectoryError), with the command line's message.
// The C++ readers throw std::invalid_argument ("cannot read scenario file 'x': No such file or
// directory"), which is right for the command line's one line but would be a ValueError here.

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>

namespace frictionlab::python {

namespace py = pybind11;

/// If `path` cannot be opened for reading, raises (py::error_already_set) the OSError subclass of
/// that errno with `message` as its text and its errno set; else returns.
void raise_if_unreadable(const std::string& path, const std::string& message);

/// read(), a call that reads the file `path`: its std::invalid_argument becomes an OSError if
/// the file cannot be opened (raise_if_unreadable), and stays a ValueError otherwise.
template <class Read>
decltype(auto) reading_file(const std::string& path, Read&& read) {
  try {
    return read();
  } catch (const std::invalid_argument& e) {
    raise_if_unreadable(path, e.what());
    throw;
  }
}

}  // namespace frictionlab::python
