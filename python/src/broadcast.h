#pragma once
// NumPy broadcasting of the seven inputs of a friction law (U, Omega, a, b, psi, N, k), and the
// evaluation loop over the broadcast shape. The loop calls FrictionLaw::evaluate() once per
// element, the very function the command line and the simulations call, so that results are the
// C++ results bit for bit; it runs without the GIL.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "friction/law.h"

namespace frictionlab::python {

namespace py = pybind11;

inline constexpr std::array<const char*, 7> kInputNames = {"U", "Omega", "a", "b", "psi", "N", "k"};

/// The seven inputs as float64 arrays (views where NumPy allows: no copy of float64 input), with
/// their broadcast shape and the byte strides of each input along it (0 where broadcast).
struct BroadcastInputs {
  std::array<py::array_t<double>, 7> arrays;
  std::vector<py::ssize_t> shape;
  std::array<std::vector<py::ssize_t>, 7> strides;
  std::array<const char*, 7> data{};
  std::size_t size = 1;
};

/// Converts and broadcasts like NumPy. TypeError for input that is not real numbers (complex
/// values and None too, which NumPy's cast would turn into their real part and NaN), ValueError
/// ("operands could not be broadcast together with shapes ...") for shapes that do not broadcast.
/// Needs the GIL.
[[nodiscard]] BroadcastInputs broadcast_inputs(const std::array<py::handle, 7>& inputs);

/// Why an element could not be evaluated: its flat (C-order) index in the broadcast shape and the
/// law's message.
struct ElementError {
  std::size_t index = 0;
  std::string message;
  bool invalid_input = true;  ///< std::invalid_argument or std::domain_error (ValueError); else RuntimeError
};

/// Evaluates `law` at every element, into C-contiguous F1, F2, M of in.size elements; stops at the
/// first element the law rejects. Does not touch Python objects: call it without the GIL.
[[nodiscard]] std::optional<ElementError> evaluate_all(const friction::FrictionLaw& law, const BroadcastInputs& in,
                                                       double* F1, double* F2, double* M);

/// "[2, 3]": the multi-index of the flat index `index` in `shape` (empty for a 0-d shape).
[[nodiscard]] std::string element_name(std::size_t index, const std::vector<py::ssize_t>& shape);

}  // namespace frictionlab::python
