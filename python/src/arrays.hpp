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

#include <cstddef>
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

/// A PointArray as a new (n, d) numpy array.
DoubleArray to_numpy(const PointArray& points);

/// A span of doubles as a new (k,) numpy array.
DoubleArray to_numpy(std::span<const double> values);

/// The (rows, columns) float64 output: a new array when `out` is None, else
/// `out` itself after checking it is a writable, C-contiguous float64 array of
/// exactly that shape (ValueError otherwise), as numpy's out= arguments.
DoubleArray output_array(std::size_t rows, std::size_t columns, const py::object& out);

/// The parameters' position and value checks, done chunk by chunk just before
/// each chunk is evaluated so the values are read from memory once: `visit`
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

/// Values per chunk: 16 KiB of parameters, well inside L1/L2 while the
/// chunk's points are evaluated.
inline constexpr std::size_t kParameterChunk = 2048;

template <class Visit>
void for_each_checked_chunk(std::span<const double> parameters, Interval domain, bool extrapolate,
                            const std::string& what, Visit&& visit) {
  std::size_t bad_chunk = parameters.size();
  {
    py::gil_scoped_release release;
    for (std::size_t offset = 0; offset < parameters.size(); offset += kParameterChunk) {
      const std::span<const double> chunk = parameters.subspan(offset, std::min(kParameterChunk, parameters.size() - offset));
      // One branch-free pass: NaN fails both comparisons, ±inf fails one.
      bool good = true;
      if (extrapolate) {
        for (const double u : chunk) good &= (u - u == 0.0);
      } else {
        for (const double u : chunk) good &= (domain.lower <= u) & (u <= domain.upper);
      }
      if (!good) {
        bad_chunk = offset;
        break;
      }
      visit(chunk, offset);
    }
  }
  if (bad_chunk != parameters.size()) raise_bad_parameter(parameters, bad_chunk, domain, extrapolate, what);
}

}  // namespace casteljau::python
