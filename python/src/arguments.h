#pragma once
// Python's own argument binding for a function bound as f(*args, **kwargs): positional, then by
// keyword, with the TypeErrors CPython gives a Python function, one line each and naming the
// argument ("Law.__call__() missing 1 required positional argument: 'k'", "... got an unexpected
// keyword argument 'omega'. Did you mean 'Omega'?"), where pybind11's typed overloads would print
// every signature with "U: handle".

#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

namespace frictionlab::python {

namespace py = pybind11;

/// Binds `args` and `kwargs` to the parameters `names` (all required) of the method `function`
/// (its name as Python's messages say it, e.g. "Law.__call__"; counts include self, as Python's
/// do); out[i] is the value of names[i].
/// Throws py::type_error for a missing, unknown, repeated or surplus argument.
void bind_arguments(std::string_view function, std::span<const char* const> names, const py::args& args,
                    const py::kwargs& kwargs, std::span<py::handle> out);

template <std::size_t N>
[[nodiscard]] std::array<py::handle, N> bind_arguments(std::string_view function,
                                                       const std::array<const char*, N>& names,
                                                       const py::args& args, const py::kwargs& kwargs) {
  std::array<py::handle, N> out{};
  bind_arguments(function, names, args, kwargs, out);
  return out;
}

}  // namespace frictionlab::python
