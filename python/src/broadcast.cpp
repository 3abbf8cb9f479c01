#include "broadcast.h"

#include <exception>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

namespace frictionlab::python {
namespace {

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    text += std::to_string(shape[i]);
    text += shape.size() == 1 ? "," : (i + 1 < shape.size() ? "," : "");
  }
  return text + ")";
}

std::string input_is_invalid(std::size_t i, py::handle input, const std::string& rule) {
  return std::string("friction input ") + kInputNames[i] + " = " + std::string(py::repr(input)) + " is invalid: " + rule;
}

// What NumPy's cast to float64 would take silently though it is not a real number: a complex
// value (its imaginary part dropped) and None (NaN).
void check_real(std::size_t i, py::handle input) {
  if (input.is_none()) throw py::type_error(input_is_invalid(i, input, "it must be a number or an array of numbers"));
  const py::array a = py::array::ensure(input);
  if (!a) {
    PyErr_Clear();
    return;  // not an array of anything: the cast says so
  }
  const char kind = a.dtype().kind();
  if (kind == 'c') throw py::type_error(input_is_invalid(i, input, "it must be real, not complex"));
  if (kind == 'O') {
    std::size_t flat = 0;
    for (const py::handle item : a.attr("flat")) {
      if (item.is_none()) {
        throw py::type_error(std::string("friction input ") + kInputNames[i] + " is invalid: its element " +
                             element_name(flat, std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim())) +
                             " is None, not a number");
      }
      ++flat;
    }
  }
}

}  // namespace

BroadcastInputs broadcast_inputs(const std::array<py::handle, 7>& inputs) {
  BroadcastInputs in;
  std::size_t ndim = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    check_real(i, inputs[i]);
    // forcecast: ints, bools and float32 become float64; float64 arrays of any strides are views.
    in.arrays[i] = py::array_t<double, py::array::forcecast>::ensure(inputs[i]);
    if (!in.arrays[i]) {
      PyErr_Clear();
      throw py::type_error(input_is_invalid(i, inputs[i], "it must be a number or an array of numbers"));
    }
    ndim = std::max(ndim, static_cast<std::size_t>(in.arrays[i].ndim()));
  }
  in.shape.assign(ndim, 1);
  for (const auto& a : in.arrays) {
    const std::size_t offset = ndim - static_cast<std::size_t>(a.ndim());
    for (std::size_t d = 0; d < static_cast<std::size_t>(a.ndim()); ++d) {
      const py::ssize_t n = a.shape(static_cast<py::ssize_t>(d));
      py::ssize_t& out = in.shape[offset + d];
      if (n == out || n == 1) continue;
      if (out != 1) {
        std::string shapes;
        for (const auto& b : in.arrays) {
          shapes += (shapes.empty() ? "" : " ") +
                    shape_text(std::vector<py::ssize_t>(b.shape(), b.shape() + b.ndim()));
        }
        throw py::value_error("operands could not be broadcast together with shapes " + shapes);
      }
      out = n;
    }
  }
  in.size = 1;
  for (const py::ssize_t n : in.shape) in.size *= static_cast<std::size_t>(n);
  for (std::size_t i = 0; i < in.arrays.size(); ++i) {
    const auto& a = in.arrays[i];
    const std::size_t offset = ndim - static_cast<std::size_t>(a.ndim());
    in.strides[i].assign(ndim, 0);
    for (std::size_t d = 0; d < static_cast<std::size_t>(a.ndim()); ++d) {
      const auto dim = static_cast<py::ssize_t>(d);
      in.strides[i][offset + d] = a.shape(dim) == 1 ? 0 : a.strides(dim);
    }
    in.data[i] = reinterpret_cast<const char*>(a.data());
  }
  return in;
}

std::optional<ElementError> evaluate_all(const friction::FrictionLaw& law, const BroadcastInputs& in, double* F1,
                                         double* F2, double* M) {
  if (in.size == 0) return std::nullopt;
  const std::size_t ndim = in.shape.size();
  // An odometer over every dimension but the last; the last is the inner loop.
  const std::size_t outer_dims = ndim == 0 ? 0 : ndim - 1;
  const py::ssize_t inner = ndim == 0 ? 1 : in.shape.back();
  std::array<py::ssize_t, 7> inner_stride{};
  for (std::size_t i = 0; i < 7; ++i) inner_stride[i] = ndim == 0 ? 0 : in.strides[i].back();
  std::vector<py::ssize_t> counter(outer_dims, 0);
  std::array<const char*, 7> base = in.data;
  std::size_t flat = 0;
  // Each run of the last dimension is gathered and evaluated in one call (the law's batch evaluation).
  std::vector<friction::ContactInput> row(static_cast<std::size_t>(inner));
  std::vector<friction::FrictionForces> forces(row.size());
  while (true) {
    std::array<const char*, 7> p = base;
    for (auto& c : row) {
      c.U = *reinterpret_cast<const double*>(p[0]);
      c.Omega = *reinterpret_cast<const double*>(p[1]);
      c.a = *reinterpret_cast<const double*>(p[2]);
      c.b = *reinterpret_cast<const double*>(p[3]);
      c.psi = *reinterpret_cast<const double*>(p[4]);
      c.N = *reinterpret_cast<const double*>(p[5]);
      c.k = *reinterpret_cast<const double*>(p[6]);
      for (std::size_t i = 0; i < 7; ++i) p[i] += inner_stride[i];
    }
    std::size_t done = row.size();
    std::optional<ElementError> failed;
    try {
      law.evaluate(std::span<const friction::ContactInput>(row), std::span<friction::FrictionForces>(forces));
    } catch (const friction::BatchError& e) {
      done = e.index();
      try {
        std::rethrow_exception(e.cause());
      } catch (const std::invalid_argument&) {
        failed = ElementError{flat + done, e.cause_message(), true};
      } catch (const std::domain_error&) {  // input outside where the law can be computed
        failed = ElementError{flat + done, e.cause_message(), true};
      } catch (...) {
        failed = ElementError{flat + done, e.cause_message(), false};
      }
    }
    for (std::size_t j = 0; j < done; ++j) {
      F1[flat + j] = forces[j].F1;
      F2[flat + j] = forces[j].F2;
      M[flat + j] = forces[j].M;
    }
    if (failed) return failed;
    flat += row.size();
    // Next outer index: the last outer dimension fastest (C order).
    std::size_t d = outer_dims;
    while (d > 0) {
      --d;
      for (std::size_t i = 0; i < 7; ++i) base[i] += in.strides[i][d];
      if (++counter[d] < in.shape[d]) break;
      for (std::size_t i = 0; i < 7; ++i) base[i] -= in.strides[i][d] * in.shape[d];
      counter[d] = 0;
      if (d == 0) return std::nullopt;
    }
    if (outer_dims == 0) return std::nullopt;
  }
}

std::string element_name(std::size_t index, const std::vector<py::ssize_t>& shape) {
  if (shape.empty()) return "";
  std::vector<std::size_t> at(shape.size());
  for (std::size_t d = shape.size(); d-- > 0;) {
    const auto n = static_cast<std::size_t>(shape[d]);
    at[d] = index % n;
    index /= n;
  }
  std::string text = "[";
  for (std::size_t d = 0; d < at.size(); ++d) text += (d ? ", " : "") + std::to_string(at[d]);
  return text + "]";
}

}  // namespace frictionlab::python
