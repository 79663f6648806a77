#pragma once
// numpy <-> casteljau at the Python boundary: what every binding file shares.
//
// Rules (docs/python.md): points are (n, d) arrays, parameters (k,) arrays.
// float64 arrays that are already C-contiguous are read in place (no copy);
// other real dtypes (float32, integers), F-ordered and strided arrays are
// converted to one float64 C-ordered array, once. bool, complex, object and
// string arrays are refused with TypeError. Bad values (NaN, infinities,
// wrong shapes, empty arrays, parameters outside a domain) raise ValueError
// carrying the C++ message, which names what is wrong and where.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <utility>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau::python {

namespace py = pybind11;

/// A float64, C-ordered numpy array (what every kernel reads).
using DoubleArray = py::array_t<double, py::array::c_style>;

/// The value of an Expected, or ValueError with its message.
template <class T>
T unwrap(Expected<T> result) {
  if (!result) throw py::value_error(result.error().message);
  return std::move(result).value();
}

/// Nothing, or ValueError with the message of the Status.
void unwrap(const Status& status);

/// `object` as a float64 C-ordered array: the same array when it already is
/// one, else one conversion (float32, integers, F-order, strides, lists).
/// TypeError for bool, complex, object, string and other non-real dtypes;
/// `what` names the argument in the message.
DoubleArray as_double_array(const py::handle& object, const std::string& what);

/// An (n, d) array of points (n >= 1, d >= 1, finite) as a PointArray.
/// ValueError names the argument, the shape or the first bad coordinate.
PointArray points_from(const py::handle& object, const std::string& what);

/// A (k,) array of parameters (k >= 0) as a float64 array; a 0-d array or a
/// Python float is refused (use the single-point functions). Values are
/// checked later, against a domain, by for_each_checked_chunk.
DoubleArray parameters_from(const py::handle& object, const std::string& what);

/// A (k,) array of finite values (weights, knots, tangents) as a std::vector.
std::vector<double> values_from(const py::handle& object, const std::string& what);

/// A distance tolerance given from Python: finite and > 0, else ValueError
/// naming `what` (defined in core.cpp).
Tolerance tolerance_from(double distance, const std::string& what);

/// "(3, 2)", "(5,)": an array's shape as numpy prints it, for messages.
std::string shape_text(const py::array& array);

/// A single parameter given from Python: finite, and inside `domain` unless
/// `extrapolate`; else ValueError "t = 1.5 is outside the domain [0, 1] …".
void check_parameter(double value, Interval domain, bool extrapolate, const std::string& what);

/// A derivative order given from Python: lowest <= order <=
/// tolerances::kMaxDerivativeOrder, else ValueError naming `what`.
void check_derivative_order(int order, int lowest, const std::string& what);

/// Runs `work` with the GIL released (it must not touch Python objects).
template <class Work>
auto without_gil(Work&& work) {
  py::gil_scoped_release release;
  return work();
}

/// A PointArray as a new (n, d) numpy array.
DoubleArray to_numpy(const PointArray& points);

/// A span of doubles as a new (k,) numpy array.
DoubleArray to_numpy(std::span<const double> values);

/// A single point (d coordinates) as a new (d,) numpy array.
inline DoubleArray to_numpy(const Point& point) { return to_numpy(std::span<const double>(point)); }

/// The (rows, columns) float64 output: a new array when `out` is None, else
/// `out` itself after checking it is a writable, C-contiguous float64 array of
/// exactly that shape (ValueError otherwise), as numpy's out= arguments.
DoubleArray output_array(std::size_t rows, std::size_t columns, const py::object& out);

/// The parameters' position and value checks, done chunk by chunk just before
/// each chunk is evaluated so the values come from cache the second time: `visit`
/// gets (chunk, offset of its first value). Every value must be finite and,
/// unless `extrapolate`, inside `domain`; otherwise ValueError
/// "parameter 17 (1.5) is outside the domain [0, 1]" before any output is
/// written for the chunk. Runs without the GIL.
template <class Visit>
void for_each_checked_chunk(std::span<const double> parameters, Interval domain, bool extrapolate,
                            const std::string& what, Visit&& visit);

/// Raises the ValueError for the first bad value of a chunk (with the GIL).
[[noreturn]] void raise_bad_parameter(std::span<const double> parameters, std::size_t offset, Interval domain,
                                      bool extrapolate, const std::string& what);

/// The batch pattern of every `points_at`-like binding: a (k, width) result
/// (new, or the caller's `out`) filled chunk by chunk by
/// `evaluate(chunk, target)`, target the chunk's rows of the result, after
/// for_each_checked_chunk has checked the chunk's parameters.
template <class Evaluate>
DoubleArray evaluate_batch(const DoubleArray& parameters, std::size_t width, const py::object& out, Interval domain,
                           bool extrapolate, const std::string& what, Evaluate&& evaluate) {
  const std::size_t count = static_cast<std::size_t>(parameters.size());
  DoubleArray result = output_array(count, width, out);
  double* target = result.mutable_data();
  for_each_checked_chunk(std::span<const double>(parameters.data(), count), domain, extrapolate, what,
                         [&](std::span<const double> chunk, std::size_t offset) {
                           evaluate(chunk, std::span<double>(target + offset * width, chunk.size() * width));
                         });
  return result;
}

/// Values per chunk: 2 MiB of parameters, which stay in L2/L3 between the
/// check and the evaluation. Not smaller: the batch kernels write outputs of
/// 4 MiB and more with streaming stores (src/bspline/points_at.cpp), and
/// chunks of 2048 parameters (48 KiB of 3D points) lost that, costing W1 10 %
/// of its throughput; 2^18 parameters of 3D points are 6 MiB.
inline constexpr std::size_t kParameterChunk = std::size_t{1} << 18;

template <class Visit>
void for_each_checked_chunk(std::span<const double> parameters, Interval domain, bool extrapolate,
                            const std::string& what, Visit&& visit) {
  std::size_t bad_chunk = parameters.size();
  {
    py::gil_scoped_release release;
    for (std::size_t offset = 0; offset < parameters.size(); offset += kParameterChunk) {
      const std::span<const double> chunk = parameters.subspan(offset, std::min(kParameterChunk, parameters.size() - offset));
      // One branch-free counting pass (g++ vectorizes this form at -O3; a
      // bool reduction it does not): NaN fails every comparison, ±inf one.
      std::size_t bad = 0;
      if (extrapolate) {
        for (const double u : chunk) bad += !(std::fabs(u) <= std::numeric_limits<double>::max());
      } else {
        for (const double u : chunk) bad += !(domain.lower <= u) | !(u <= domain.upper);
      }
      if (bad != 0) {
        bad_chunk = offset;
        break;
      }
      visit(chunk, offset);
    }
  }
  if (bad_chunk != parameters.size()) raise_bad_parameter(parameters, bad_chunk, domain, extrapolate, what);
}

}  // namespace casteljau::python
