#include "arrays.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

namespace casteljau::python {

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) {
    if (i > 0) text += ", ";
    text += std::to_string(array.shape(i));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

void check_parameter(double value, Interval domain, bool extrapolate, const std::string& what) {
  if (std::isnan(value)) throw py::value_error(what + " is NaN");
  if (std::isinf(value)) throw py::value_error(what + " is infinite");
  if (!extrapolate && !domain.contains(value)) {
    throw py::value_error(fmt::format("{} = {} is outside the domain [{}, {}] (pass extrapolate=True to evaluate "
                                      "the end pieces continued)",
                                      what, value, domain.lower, domain.upper));
  }
}

void check_derivative_order(int order, int lowest, const std::string& what) {
  if (order < lowest || order > tolerances::kMaxDerivativeOrder) {
    throw py::value_error(fmt::format("{} {} is outside {}..{}", what, order, lowest, tolerances::kMaxDerivativeOrder));
  }
}

void unwrap(const Status& status) {
  if (!status) throw py::value_error(status.error().message);
}

DoubleArray as_double_array(const py::handle& object, const std::string& what) {
  if (object.is_none()) throw py::type_error(what + " is None, expected an array of numbers");
  // np.asarray: no copy for arrays; lists and scalars become arrays. numpy's
  // own ValueError (a ragged nested list) keeps its type, with `what` named.
  py::array array;
  if (py::isinstance<py::array>(object)) {
    array = py::reinterpret_borrow<py::array>(object);
  } else {
    try {
      array = py::module_::import("numpy").attr("asarray")(object);
    } catch (py::error_already_set& error) {
      const std::string message = fmt::format("{} is not an array of numbers: {}", what, error.what());
      if (error.matches(PyExc_ValueError)) throw py::value_error(message);
      throw py::type_error(message);
    }
  }
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    const std::string dtype = py::str(array.dtype());
    throw py::type_error(fmt::format("{} has dtype {}, expected real numbers (float or integer)", what, dtype));
  }
  if (kind == 'f' && array.dtype().itemsize() == 8 && (array.flags() & py::array::c_style) != 0) {
    return py::reinterpret_borrow<DoubleArray>(array);
  }
  // One conversion: to float64, C order (forcecast allows float32/int/strides).
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

PointArray points_from(const py::handle& object, const std::string& what) {
  const DoubleArray array = as_double_array(object, what);
  if (array.ndim() != 2) {
    throw py::value_error(fmt::format("{} must be an (n, d) array of points, got shape {}", what, shape_text(array)));
  }
  if (array.shape(0) == 0) throw py::value_error(what + " is empty: at least one point is needed");
  if (array.shape(1) == 0) throw py::value_error(what + " has points of dimension 0");
  const auto* data = array.data();
  std::vector<double> coordinates(data, data + array.size());
  return unwrap(PointArray::make(static_cast<int>(array.shape(1)), std::move(coordinates), what.c_str()));
}

DoubleArray parameters_from(const py::handle& object, const std::string& what) {
  DoubleArray array = as_double_array(object, what);
  if (array.ndim() != 1) {
    throw py::value_error(fmt::format("{} must be a (k,) array of parameters, got shape {}", what, shape_text(array)));
  }
  return array;
}

std::vector<double> values_from(const py::handle& object, const std::string& what) {
  const DoubleArray array = as_double_array(object, what);
  if (array.ndim() != 1) {
    throw py::value_error(fmt::format("{} must be a (k,) array, got shape {}", what, shape_text(array)));
  }
  std::vector<double> values(array.data(), array.data() + array.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    unwrap(check_finite(values[i], fmt::format("{} [{}]", what, i)));
  }
  return values;
}

DoubleArray to_numpy(const PointArray& points) {
  DoubleArray array({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(points.dimension())});
  const std::span<const double> source = points.coordinates();
  if (!source.empty()) std::memcpy(array.mutable_data(), source.data(), source.size() * sizeof(double));
  return array;
}

DoubleArray to_numpy(std::span<const double> values) {
  DoubleArray array(static_cast<py::ssize_t>(values.size()));
  if (!values.empty()) std::memcpy(array.mutable_data(), values.data(), values.size() * sizeof(double));
  return array;
}

DoubleArray output_array(std::size_t rows, std::size_t columns, const py::object& out) {
  const py::ssize_t shape_rows = static_cast<py::ssize_t>(rows), shape_columns = static_cast<py::ssize_t>(columns);
  if (out.is_none()) return DoubleArray({shape_rows, shape_columns});
  if (!py::isinstance<py::array>(out)) throw py::type_error("out must be a numpy array");
  const py::array array = py::reinterpret_borrow<py::array>(out);
  const bool float64 = array.dtype().kind() == 'f' && array.dtype().itemsize() == 8;
  if (!float64 || (array.flags() & py::array::c_style) == 0 || !array.writeable()) {
    throw py::value_error(fmt::format("out must be a writable C-contiguous float64 array, got dtype {}{}",
                                      std::string(py::str(array.dtype())),
                                      array.writeable() ? "" : " (read-only)"));
  }
  if (array.ndim() != 2 || array.shape(0) != shape_rows || array.shape(1) != shape_columns) {
    throw py::value_error(fmt::format("out has shape {}, the result needs ({}, {})", shape_text(array), rows, columns));
  }
  return py::reinterpret_borrow<DoubleArray>(array);
}

void raise_bad_parameter(std::span<const double> parameters, std::size_t offset, Interval domain, bool extrapolate,
                         const std::string& what) {
  for (std::size_t i = offset; i < parameters.size(); ++i) {
    const double u = parameters[i];
    if (std::isnan(u)) throw py::value_error(fmt::format("{} [{}] is NaN", what, i));
    if (std::isinf(u)) throw py::value_error(fmt::format("{} [{}] is infinite", what, i));
    if (!extrapolate && !domain.contains(u)) {
      throw py::value_error(fmt::format("{} [{}] = {} is outside the domain [{}, {}] (pass extrapolate=True to "
                                        "evaluate the end pieces continued)",
                                        what, i, u, domain.lower, domain.upper));
    }
  }
  throw py::value_error(what + " has a bad value");  // not reached: the chunk had one
}

}  // namespace casteljau::python
