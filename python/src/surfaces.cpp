// The surfaces layer in Python: BSplineSurface (polynomial and NURBS),
// BezierSurface and CoonsPatch as classes, their evaluation one point at a
// time and in batches (scattered (u, v) pairs and grids, GIL released,
// parameters checked chunk by chunk), the exact operations in one direction
// (knot insertion and refinement, degree elevation, splitting, iso-curves),
// and the constructions (ruled surfaces, revolution, sphere, torus,
// compatible curves, skinning, grid interpolation).
//
// Control nets are (rows, columns, d) numpy arrays, rows along u (as
// ControlNet: P_ij at [i, j]); weights are (rows, columns) arrays. The
// direction of an operation is the string "u" or "v", the blending of a
// Coons patch "linear" or "cubic", a parameterization "uniform", "chord"
// (or "chord-length", "chord_length") or "centripetal".

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/surfaces/bezier_surface.hpp"
#include "casteljau/surfaces/bspline_surface.hpp"
#include "casteljau/surfaces/compatible_curves.hpp"
#include "casteljau/surfaces/control_net.hpp"
#include "casteljau/surfaces/coons.hpp"
#include "casteljau/surfaces/degree.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/grid_interpolation.hpp"
#include "casteljau/surfaces/iso_curve.hpp"
#include "casteljau/surfaces/refinement.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "casteljau/surfaces/ruled.hpp"
#include "casteljau/surfaces/skinning.hpp"
#include "casteljau/surfaces/split.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau::python {

namespace {

// --- names given as strings ----------------------------------------------------

Direction direction_from(const std::string& name, const char* what) {
  if (name == "u") return Direction::u;
  if (name == "v") return Direction::v;
  throw py::value_error(fmt::format("{} is '{}', it must be 'u' or 'v'", what, name));
}

CoonsBlending blending_from(const std::string& name) {
  if (name == "linear") return CoonsBlending::linear;
  if (name == "cubic") return CoonsBlending::cubic;
  throw py::value_error(fmt::format("blending is '{}', it must be 'linear' or 'cubic'", name));
}

Parameterization parameterization_from(const std::string& name) { return unwrap(parameterization_from_name(name)); }

// --- control nets and weights ----------------------------------------------------

/// A (rows, columns, d) array as a ControlNet: rows along u. ValueError names
/// the shape or the first coordinate that is not finite ("control_net[1, 2, 0] is NaN").
ControlNet net_from(const py::handle& object, const std::string& what) {
  py::object input = py::reinterpret_borrow<py::object>(object);
  if (!py::isinstance<py::array>(object) && !object.is_none()) {
    // Nested lists: numpy's own ValueError for ragged rows becomes ours (a
    // shape error, not a type error).
    try {
      input = py::module_::import("numpy").attr("asarray")(object);
    } catch (py::error_already_set& error) {
      if (!error.matches(PyExc_ValueError)) throw;
      throw py::value_error(fmt::format("{} is ragged: a control net is a rectangular (rows, columns, d) array "
                                        "({})",
                                        what, std::string(py::str(error.value()))));
    }
  }
  const DoubleArray array = as_double_array(input, what);
  if (array.ndim() != 3) {
    throw py::value_error(fmt::format("{} must be a (rows, columns, d) array of control points, got shape {}", what,
                                      shape_text(array)));
  }
  const std::size_t rows = static_cast<std::size_t>(array.shape(0)), columns = static_cast<std::size_t>(array.shape(1));
  const std::size_t d = static_cast<std::size_t>(array.shape(2));
  if (rows == 0 || columns == 0 || d == 0) {
    throw py::value_error(fmt::format("{} has shape {}: a control net needs at least one row, one column and one "
                                      "coordinate",
                                      what, shape_text(array)));
  }
  if (rows > tolerances::kMaxControlPoints / columns) {
    throw py::value_error(fmt::format("{} has {} x {} control points, more than the limit {}", what, rows, columns,
                                      tolerances::kMaxControlPoints));
  }
  if (d > static_cast<std::size_t>(1) << 20) {
    throw py::value_error(fmt::format("{} has points of dimension {}, more than 2^20 coordinates", what, d));
  }
  const double* data = array.data();
  const std::size_t size = rows * columns * d;
  for (std::size_t k = 0; k < size; ++k) {
    if (!std::isfinite(data[k])) {
      const std::size_t point = k / d;
      throw py::value_error(fmt::format("{}[{}, {}, {}] is {}", what, point / columns, point % columns, k % d,
                                        std::isnan(data[k]) ? "NaN" : "infinite"));
    }
  }
  PointArray points = unwrap(PointArray::make(static_cast<int>(d), std::vector<double>(data, data + size), what.c_str()));
  return unwrap(ControlNet::make(rows, columns, std::move(points)));
}

/// None (or an empty array) for a polynomial surface, else a (rows, columns)
/// array of weights matching the net, flattened row by row (their values are
/// checked by make(): finite and > 0).
std::vector<double> weights_from(const py::object& object, const ControlNet& net) {
  if (object.is_none()) return {};
  const DoubleArray array = as_double_array(object, "weights");
  if (array.size() == 0) return {};
  if (array.ndim() != 2 || static_cast<std::size_t>(array.shape(0)) != net.rows() ||
      static_cast<std::size_t>(array.shape(1)) != net.columns()) {
    throw py::value_error(fmt::format("weights has shape {}, the control net needs ({}, {}): one weight per control "
                                      "point",
                                      shape_text(array), net.rows(), net.columns()));
  }
  return std::vector<double>(array.data(), array.data() + array.size());
}

DoubleArray net_to_numpy(const ControlNet& net) {
  DoubleArray array({static_cast<py::ssize_t>(net.rows()), static_cast<py::ssize_t>(net.columns()),
                     static_cast<py::ssize_t>(net.dimension())});
  const std::span<const double> source = net.points().coordinates();
  if (!source.empty()) std::memcpy(array.mutable_data(), source.data(), source.size() * sizeof(double));
  return array;
}

/// Weights as a (rows, columns) array; (0, 0) for a polynomial surface.
DoubleArray weights_to_numpy(std::span<const double> weights, const ControlNet& net) {
  const bool rational = !weights.empty();
  DoubleArray array({static_cast<py::ssize_t>(rational ? net.rows() : 0),
                     static_cast<py::ssize_t>(rational ? net.columns() : 0)});
  if (rational) std::memcpy(array.mutable_data(), weights.data(), weights.size() * sizeof(double));
  return array;
}

py::tuple interval_tuple(Interval interval) { return py::make_tuple(interval.lower, interval.upper); }


// --- curves given from Python ---------------------------------------------------

/// Any curve class as a B-spline curve: BSplineCurve as it is, a BezierCurve
/// on its clamped knots, a PiecewiseBezierCurve with its joints as knots (the
/// pieces must meet), exactly as model JSON's boundaries (io/model.hpp to_bspline).
BSplineCurve curve_from(const py::handle& object, const std::string& what) {
  if (py::isinstance<BSplineCurve>(object)) return object.cast<BSplineCurve>();
  auto model_of = [&]() -> Model {
    if (py::isinstance<BezierCurve>(object)) return object.cast<BezierCurve>();
    if (py::isinstance<PiecewiseBezierCurve>(object)) return object.cast<PiecewiseBezierCurve>();
    throw py::type_error(fmt::format("{} is a {}, expected a curve (BSplineCurve, BezierCurve or "
                                     "PiecewiseBezierCurve)",
                                     what, std::string(py::str(py::type::of(object).attr("__name__")))));
  };
  Expected<Model> converted = to_bspline(model_of());
  if (!converted) throw py::value_error(what + ": " + converted.error().message);
  return std::get<BSplineCurve>(std::move(converted).value());
}

std::vector<BSplineCurve> curves_from(const py::handle& object, const std::string& what) {
  if (py::isinstance<py::str>(object) || !py::isinstance<py::sequence>(object)) {
    throw py::type_error(what + " must be a sequence of curves");
  }
  const py::sequence sequence = py::reinterpret_borrow<py::sequence>(object);
  std::vector<BSplineCurve> curves;
  curves.reserve(sequence.size());
  for (std::size_t k = 0; k < sequence.size(); ++k) {
    curves.push_back(curve_from(sequence[k], fmt::format("{}[{}]", what, k)));
  }
  return curves;
}

py::list curve_list(std::vector<BSplineCurve> curves) {
  py::list list;
  for (BSplineCurve& curve : curves) list.append(py::cast(std::move(curve)));
  return list;
}

// --- parameters -----------------------------------------------------------------

/// Whether point_at & co. may be asked outside the domain (extrapolate=True):
/// the B-spline and Bézier evaluations continue their end pieces
/// (surfaces/evaluate.hpp); a Coons patch is only defined on [0,1]^2.
template <class Surface>
constexpr bool extrapolates() {
  return !std::is_same_v<Surface, CoonsPatch>;
}

template <class Surface>
void check_extrapolation(bool extrapolate) {
  if (extrapolate && !extrapolates<Surface>()) {
    throw py::value_error("extrapolate=True is not available for a Coons patch: it is defined on [0, 1] x [0, 1] only");
  }
}

template <class Surface>
void check_point(const Surface& surface, double u, double v, bool extrapolate) {
  check_extrapolation<Surface>(extrapolate);
  const SurfaceView view(surface);
  const double one_u[1] = {u}, one_v[1] = {v};
  for_each_checked_chunk(std::span<const double>(one_u), view.domain_u(), extrapolate, "u",
                         [](std::span<const double>, std::size_t) {});
  for_each_checked_chunk(std::span<const double>(one_v), view.domain_v(), extrapolate, "v",
                         [](std::span<const double>, std::size_t) {});
}


void check_orders(int order_u, int order_v) {
  check_derivative_order(order_u, 0, "order_u");
  check_derivative_order(order_v, 0, "order_v");
  if (order_u + order_v > tolerances::kMaxSurfaceDerivativeOrder) {
    throw py::value_error(fmt::format("order_u + order_v = {} is more than the limit of {} for a surface",
                                      order_u + order_v, tolerances::kMaxSurfaceDerivativeOrder));
  }
}

/// A (k, 2) array of (u, v) pairs.
DoubleArray pairs_from(const py::handle& object, const std::string& what) {
  DoubleArray array = as_double_array(object, what);
  if (array.ndim() != 2 || array.shape(1) != 2) {
    throw py::value_error(
        fmt::format("{} must be a (k, 2) array of (u, v) pairs, got shape {}", what, shape_text(array)));
  }
  return array;
}

/// ValueError for the first bad pair at or after `offset` (with the GIL).
[[noreturn]] void raise_bad_pair(const DoubleArray& pairs, std::size_t offset, Interval domain_u, Interval domain_v,
                                 bool extrapolate, const std::string& what) {
  const std::size_t count = static_cast<std::size_t>(pairs.shape(0));
  const double* data = pairs.data();
  for (std::size_t k = offset; k < count; ++k) {
    for (std::size_t c = 0; c < 2; ++c) {
      const double x = data[2 * k + c];
      const Interval domain = c == 0 ? domain_u : domain_v;
      if (std::isnan(x)) throw py::value_error(fmt::format("{}[{}, {}] ({}) is NaN", what, k, c, c == 0 ? "u" : "v"));
      if (std::isinf(x)) {
        throw py::value_error(fmt::format("{}[{}, {}] ({}) is infinite", what, k, c, c == 0 ? "u" : "v"));
      }
      if (!extrapolate && !domain.contains(x)) {
        throw py::value_error(fmt::format("{}[{}, {}] = {} is outside the domain [{}, {}] of {}{}", what, k, c, x,
                                          domain.lower, domain.upper, c == 0 ? "u" : "v",
                                          " (pass extrapolate=True to evaluate the end pieces continued)"));
      }
    }
  }
  throw py::value_error(what + " has a bad value");  // not reached: the chunk had one
}

/// The pairs' checks, as for_each_checked_chunk does for one parameter list:
/// chunk by chunk, the GIL released, each chunk split into its u and v values
/// (two buffers reused per chunk) and checked just before `visit(us, vs, offset)` evaluates it.
template <class Visit>
void for_each_checked_pair_chunk(const DoubleArray& pairs, Interval domain_u, Interval domain_v, bool extrapolate,
                                 const std::string& what, Visit&& visit) {
  const std::size_t count = static_cast<std::size_t>(pairs.shape(0));
  const double* data = pairs.data();
  std::size_t bad_chunk = count;
  {
    py::gil_scoped_release release;
    std::vector<double> us(std::min(count, kParameterChunk)), vs(std::min(count, kParameterChunk));
    for (std::size_t offset = 0; offset < count; offset += kParameterChunk) {
      const std::size_t size = std::min(kParameterChunk, count - offset);
      bool good = true;
      for (std::size_t k = 0; k < size; ++k) {
        const double u = data[2 * (offset + k)], v = data[2 * (offset + k) + 1];
        us[k] = u;
        vs[k] = v;
        if (extrapolate) {
          good &= (u - u == 0.0) & (v - v == 0.0);
        } else {
          good &= (domain_u.lower <= u) & (u <= domain_u.upper) & (domain_v.lower <= v) & (v <= domain_v.upper);
        }
      }
      if (!good) {
        bad_chunk = offset;
        break;
      }
      visit(std::span<const double>(us.data(), size), std::span<const double>(vs.data(), size), offset);
    }
  }
  if (bad_chunk != count) raise_bad_pair(pairs, bad_chunk, domain_u, domain_v, extrapolate, what);
}

/// The (rows, columns, d) float64 output of a grid: a new array, or `out`
/// after checking it is a writable C-contiguous float64 array of that shape.
DoubleArray grid_output(std::size_t rows, std::size_t columns, std::size_t d, const py::object& out) {
  const py::ssize_t shape[3] = {static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns),
                                static_cast<py::ssize_t>(d)};
  if (out.is_none()) return DoubleArray({shape[0], shape[1], shape[2]});
  if (!py::isinstance<py::array>(out)) throw py::type_error("out must be a numpy array");
  const py::array array = py::reinterpret_borrow<py::array>(out);
  const bool float64 = array.dtype().kind() == 'f' && array.dtype().itemsize() == 8;
  if (!float64 || (array.flags() & py::array::c_style) == 0 || !array.writeable()) {
    throw py::value_error(fmt::format("out must be a writable C-contiguous float64 array, got dtype {}{}",
                                      std::string(py::str(array.dtype())), array.writeable() ? "" : " (read-only)"));
  }
  if (array.ndim() != 3 || array.shape(0) != shape[0] || array.shape(1) != shape[1] || array.shape(2) != shape[2]) {
    throw py::value_error(
        fmt::format("out has shape {}, the result needs ({}, {}, {})", shape_text(array), rows, columns, d));
  }
  return py::reinterpret_borrow<DoubleArray>(array);
}

std::span<const double> span_of(const DoubleArray& array) {
  return {array.data(), static_cast<std::size_t>(array.size())};
}

/// A table of partial derivatives, result[k][l] = d^(k+l) S / du^k dv^l for
/// k + l <= max_order, as a (max_order+1, max_order+1, d) array with NaN
/// where k + l > max_order.
DoubleArray derivative_table_array(const std::vector<std::vector<Point>>& table, int max_order, int dimension) {
  const std::size_t n = static_cast<std::size_t>(max_order) + 1, d = static_cast<std::size_t>(dimension);
  DoubleArray result({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(d)});
  double* target = result.mutable_data();
  std::fill(target, target + n * n * d, std::nan(""));
  for (std::size_t k = 0; k < table.size() && k < n; ++k) {
    for (std::size_t l = 0; l < table[k].size() && k + l < n; ++l) {
      std::copy(table[k][l].begin(), table[k][l].begin() + static_cast<std::ptrdiff_t>(d), target + (k * n + l) * d);
    }
  }
  return result;
}

std::vector<std::vector<Point>> derivatives_table(const BSplineSurface& surface, double u, double v, int max_order) {
  return partial_derivatives_up_to(surface, u, v, max_order);
}
std::vector<std::vector<Point>> derivatives_table(const BezierSurface& surface, double u, double v, int max_order) {
  return partial_derivatives_up_to(to_bspline_surface(surface), u, v, max_order);
}
std::vector<std::vector<Point>> derivatives_table(const CoonsPatch& patch, double u, double v, int max_order) {
  std::vector<std::vector<Point>> table(static_cast<std::size_t>(max_order) + 1);
  for (int k = 0; k <= max_order; ++k) {
    for (int l = 0; k + l <= max_order; ++l) table[static_cast<std::size_t>(k)].push_back(partial_derivative_at(patch, u, v, k, l));
  }
  return table;
}

// --- evaluation, the same for the three surface kinds ----------------------------

template <class Surface>
void bind_evaluation(py::module_& module, const char* kind) {
  const std::string extrapolation =
      extrapolates<Surface>() ? " u, v must lie in the domain unless extrapolate=True (the end pieces continued)."
                              : " u, v must lie in [0, 1] (extrapolate=True is refused for a Coons patch).";
  module.def(
      "point_at",
      [](const Surface& surface, double u, double v, bool extrapolate) {
        check_point(surface, u, v, extrapolate);
        return to_numpy(point_at(surface, u, v));
      },
      py::arg("surface"), py::arg("u"), py::arg("v"), py::kw_only(), py::arg("extrapolate") = false,
      (fmt::format("S(u, v) of a {}, a (d,) array (The NURBS Book A3.5/A4.3 for B-splines, A1.7 de Casteljau for "
                   "Bézier patches, Coons 1967 for Coons patches).",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "points_at",
      [](const Surface& surface, const py::object& uv, const py::object& out, bool extrapolate) {
        check_extrapolation<Surface>(extrapolate);
        const DoubleArray pairs = pairs_from(uv, "uv");
        const std::size_t d = static_cast<std::size_t>(surface.dimension());
        DoubleArray result = output_array(static_cast<std::size_t>(pairs.shape(0)), d, out);
        double* target = result.mutable_data();
        const SurfaceView view(surface);
        for_each_checked_pair_chunk(pairs, view.domain_u(), view.domain_v(), extrapolate, "uv",
                                    [&](std::span<const double> us, std::span<const double> vs, std::size_t offset) {
                                      points_at(surface, us, vs,
                                                std::span<double>(target + offset * d, us.size() * d));
                                    });
        return result;
      },
      py::arg("surface"), py::arg("uv"), py::kw_only(), py::arg("out") = py::none(), py::arg("extrapolate") = false,
      (fmt::format("S(u, v) of a {} at every row (u, v) of the (k, 2) array uv, as a (k, d) array: the scattered "
                   "batch kernel (surfaces/evaluate.hpp points_at, which takes us and vs apart), the GIL released. "
                   "out: an optional (k, d) C-contiguous float64 array to write into.",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "grid_points_at",
      [](const Surface& surface, const py::object& us, const py::object& vs, const py::object& out,
         bool extrapolate) {
        check_extrapolation<Surface>(extrapolate);
        const DoubleArray u_values = parameters_from(us, "us");
        const DoubleArray v_values = parameters_from(vs, "vs");
        const std::size_t rows = static_cast<std::size_t>(u_values.shape(0));
        const std::size_t columns = static_cast<std::size_t>(v_values.shape(0));
        const std::size_t d = static_cast<std::size_t>(surface.dimension());
        DoubleArray result = grid_output(rows, columns, d, out);
        double* target = result.mutable_data();
        const SurfaceView view(surface);
        const std::span<const double> v_span = span_of(v_values);
        for_each_checked_chunk(v_span, view.domain_v(), extrapolate, "vs", [](std::span<const double>, std::size_t) {});
        if (columns == 0) return result;
        // Chunks of us: each one a block of whole rows of the grid.
        for_each_checked_chunk(span_of(u_values), view.domain_u(), extrapolate, "us",
                               [&](std::span<const double> chunk, std::size_t offset) {
                                 grid_points_at(surface, chunk, v_span,
                                                std::span<double>(target + offset * columns * d,
                                                                  chunk.size() * columns * d));
                               });
        return result;
      },
      py::arg("surface"), py::arg("us"), py::arg("vs"), py::kw_only(), py::arg("out") = py::none(),
      py::arg("extrapolate") = false,
      (fmt::format("S(us[a], vs[b]) of a {} on the grid of the (k,) array us by the (l,) array vs, as a (k, l, d) "
                   "array, u the slow index (The NURBS Book §3.4 evaluated on a grid: the basis of each parameter "
                   "once). No copy of float64 us, vs; the GIL released; out: an optional (k, l, d) C-contiguous "
                   "float64 array to write into. Agrees with points_at to rounding.",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "partial_derivative_at",
      [](const Surface& surface, double u, double v, int order_u, int order_v, bool extrapolate) {
        check_orders(order_u, order_v);
        check_point(surface, u, v, extrapolate);
        Point value;
        {
          // High orders of rational surfaces cost O(order_u^2 order_v^2 d) (A4.4).
          py::gil_scoped_release release;
          value = partial_derivative_at(surface, u, v, order_u, order_v);
        }
        return to_numpy(value);
      },
      py::arg("surface"), py::arg("u"), py::arg("v"), py::arg("order_u"), py::arg("order_v"), py::kw_only(),
      py::arg("extrapolate") = false,
      (fmt::format("d^(k+l) S / du^k dv^l of a {} at (u, v), a (d,) array (The NURBS Book A3.6; NURBS by eq. 4.20 "
                   "/ A4.4). At a knot, the span to the right. order_u + order_v <= tolerances.MAX_DERIVATIVE_ORDER.",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "partial_derivatives_up_to",
      [](const Surface& surface, double u, double v, int max_order, bool extrapolate) {
        if (max_order < 0 || max_order > tolerances::kMaxSurfaceDerivativeOrder) {
          throw py::value_error(fmt::format("max_order {} is outside 0..{} (the limit for a surface)", max_order,
                                            tolerances::kMaxSurfaceDerivativeOrder));
        }
        check_point(surface, u, v, extrapolate);
        std::vector<std::vector<Point>> table;
        {
          // O(max_order^4 d) for a rational surface (A4.4's SKL).
          py::gil_scoped_release release;
          table = derivatives_table(surface, u, v, max_order);
        }
        return derivative_table_array(table, max_order, surface.dimension());
      },
      py::arg("surface"), py::arg("u"), py::arg("v"), py::arg("max_order"), py::kw_only(),
      py::arg("extrapolate") = false,
      (fmt::format("All partial derivatives of a {} with k + l <= max_order in one pass (The NURBS Book A3.6 / "
                   "A4.4's SKL), as a (max_order+1, max_order+1, d) array D with D[k, l] = d^(k+l) S / du^k dv^l "
                   "and NaN where k + l > max_order (the C++ returns a triangular nested vector; for Bézier patches "
                   "through to_bspline_surface, for Coons patches one partial_derivative_at per entry).",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "normal_at",
      [](const Surface& surface, double u, double v, bool extrapolate) {
        if (surface.dimension() != 3) {
          throw py::value_error(fmt::format("normal_at needs a surface in R^3, this one is in R^{}", surface.dimension()));
        }
        check_point(surface, u, v, extrapolate);
        return to_numpy(normal_at(surface, u, v));
      },
      py::arg("surface"), py::arg("u"), py::arg("v"), py::kw_only(), py::arg("extrapolate") = false,
      (fmt::format("The unit normal (S_u x S_v) / |S_u x S_v| of a {} in R^3 at (u, v), a (3,) array; at a "
                   "degenerate edge (a pole) the limit from inside the domain, the zero vector where no limit "
                   "exists (surfaces/evaluate.hpp normal_at).",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "normals_at",
      [](const Surface& surface, const py::object& uv, const py::object& out, bool extrapolate) {
        if (surface.dimension() != 3) {
          throw py::value_error(fmt::format("normals_at needs a surface in R^3, this one is in R^{}", surface.dimension()));
        }
        check_extrapolation<Surface>(extrapolate);
        const DoubleArray pairs = pairs_from(uv, "uv");
        DoubleArray result = output_array(static_cast<std::size_t>(pairs.shape(0)), 3, out);
        double* target = result.mutable_data();
        const SurfaceView view(surface);
        for_each_checked_pair_chunk(pairs, view.domain_u(), view.domain_v(), extrapolate, "uv",
                                    [&](std::span<const double> us, std::span<const double> vs, std::size_t offset) {
                                      for (std::size_t k = 0; k < us.size(); ++k) {
                                        const Point n = normal_at(surface, us[k], vs[k]);
                                        std::copy(n.begin(), n.end(), target + (offset + k) * 3);
                                      }
                                    });
        return result;
      },
      py::arg("surface"), py::arg("uv"), py::kw_only(), py::arg("out") = py::none(), py::arg("extrapolate") = false,
      (fmt::format("normal_at of a {} in R^3 at every row (u, v) of the (k, 2) array uv, as a (k, 3) array (no C++ "
                   "batch: one normal_at per pair, the GIL released).",
                   kind) +
       extrapolation)
          .c_str());

  module.def(
      "breakpoints_u", [](const Surface& surface) { return to_numpy(SurfaceView(surface).breakpoints_u()); },
      py::arg("surface"),
      fmt::format("The distinct knots of the u direction of a {} inside its domain, both ends included, "
                  "increasing: where the surface may be less smooth (SurfaceView::breakpoints_u).",
                  kind)
          .c_str());
  module.def(
      "breakpoints_v", [](const Surface& surface) { return to_numpy(SurfaceView(surface).breakpoints_v()); },
      py::arg("surface"),
      fmt::format("The distinct knots of the v direction of a {} inside its domain, both ends included, "
                  "increasing (SurfaceView::breakpoints_v).",
                  kind)
          .c_str());
  module.def(
      "breakpoints",
      [](const Surface& surface) {
        const SurfaceView view(surface);
        return py::make_tuple(to_numpy(view.breakpoints_u()), to_numpy(view.breakpoints_v()));
      },
      py::arg("surface"),
      fmt::format("(breakpoints_u(surface), breakpoints_v(surface)) of a {} as a tuple of two arrays (Python "
                  "only: SurfaceView::breakpoints_u and breakpoints_v together).",
                  kind)
          .c_str());
}

// --- the classes ---------------------------------------------------------------------

BSplineSurface make_bspline_surface(int degree_u, int degree_v, const py::object& knots_u, const py::object& knots_v,
                                    const py::object& control_net, const py::object& weights) {
  ControlNet net = net_from(control_net, "control_net");
  std::vector<double> weight_values = weights_from(weights, net);
  return unwrap(BSplineSurface::make(degree_u, degree_v, values_from(knots_u, "knots_u"),
                                     values_from(knots_v, "knots_v"), std::move(net), std::move(weight_values)));
}

BezierSurface make_bezier_surface(const py::object& control_net, const py::object& weights) {
  ControlNet net = net_from(control_net, "control_net");
  std::vector<double> weight_values = weights_from(weights, net);
  return unwrap(BezierSurface::make(std::move(net), std::move(weight_values)));
}

CoonsPatch make_coons_patch(const py::object& u0, const py::object& u1, const py::object& v0, const py::object& v1,
                            const std::string& blending) {
  const CoonsBlending kind = blending_from(blending);
  return unwrap(CoonsPatch::make(curve_from(u0, "u0"), curve_from(u1, "u1"), curve_from(v0, "v0"),
                                 curve_from(v1, "v1"), kind));
}

void bind_classes(py::module_& module) {
  py::class_<BSplineSurface>(module, "BSplineSurface",
                             "A tensor-product B-spline or NURBS surface of degrees (p, q) in R^d: knots_u s_0.."
                             "s_{n+p+1}, knots_v t_0..t_{m+q+1}, control net P_ij as an (n+1, m+1, d) array (rows "
                             "along u) and, for NURBS, one weight w_ij > 0 per control point as an (n+1, m+1) array "
                             "(The NURBS Book eqs. 3.11 and 4.15). A value: operations return new surfaces.")
      .def(py::init(&make_bspline_surface), py::arg("degree_u"), py::arg("degree_v"), py::arg("knots_u"),
           py::arg("knots_v"), py::arg("control_net"), py::arg("weights") = py::none(),
           "Validates and builds (BSplineSurface::make): degrees in [0, MAX_BSPLINE_DEGREE], at least p+1 rows and "
           "q+1 columns, each knot vector non-decreasing with n+p+2 (m+q+2) entries, finite control points, "
           "weights None or a (rows, columns) array of finite values > 0. ValueError names the bad field.")
      .def_property_readonly("degree_u", &BSplineSurface::degree_u, "p, the degree in u.")
      .def_property_readonly("degree_v", &BSplineSurface::degree_v, "q, the degree in v.")
      .def(
          "degree", [](const BSplineSurface& s, const std::string& d) { return s.degree(direction_from(d, "direction")); },
          py::arg("direction"), "p for 'u', q for 'v'.")
      .def_property_readonly("knots_u", [](const BSplineSurface& s) { return to_numpy(s.knots_u()); },
                             "s_0 .. s_{n+p+1} (a new array).")
      .def_property_readonly("knots_v", [](const BSplineSurface& s) { return to_numpy(s.knots_v()); },
                             "t_0 .. t_{m+q+1} (a new array).")
      .def(
          "knots",
          [](const BSplineSurface& s, const std::string& d) { return to_numpy(s.knots(direction_from(d, "direction"))); },
          py::arg("direction"), "knots_u for 'u', knots_v for 'v' (a new array).")
      .def_property_readonly("control_net", [](const BSplineSurface& s) { return net_to_numpy(s.control_net()); },
                             "P_ij as an (n+1, m+1, d) array, rows along u (a new array).")
      .def_property_readonly("weights", [](const BSplineSurface& s) { return weights_to_numpy(s.weights(), s.control_net()); },
                             "w_ij as an (n+1, m+1) array; an empty (0, 0) array for a polynomial surface.")
      .def_property_readonly("is_rational", &BSplineSurface::is_rational, "True when the surface carries weights (NURBS).")
      .def_property_readonly("dimension", &BSplineSurface::dimension, "d, the number of coordinates.")
      .def_property_readonly("domain_u", [](const BSplineSurface& s) { return interval_tuple(s.domain_u()); },
                             "(s_p, s_{n+1}).")
      .def_property_readonly("domain_v", [](const BSplineSurface& s) { return interval_tuple(s.domain_v()); },
                             "(t_q, t_{m+1}).")
      .def(
          "domain",
          [](const BSplineSurface& s, const std::string& d) { return interval_tuple(s.domain(direction_from(d, "direction"))); },
          py::arg("direction"), "domain_u for 'u', domain_v for 'v'.")
      .def("__eq__", [](const BSplineSurface& a, const BSplineSurface& b) { return a == b; }, py::is_operator())
      .def("__repr__",
           [](const BSplineSurface& s) {
             return fmt::format("BSplineSurface(degree=({}, {}), {} x {} control points in R^{}{}, domain [{}, {}] x "
                                "[{}, {}])",
                                s.degree_u(), s.degree_v(), s.control_net().rows(), s.control_net().columns(),
                                s.dimension(), s.is_rational() ? ", rational" : "", s.domain_u().lower,
                                s.domain_u().upper, s.domain_v().lower, s.domain_v().upper);
           })
      .def(py::pickle(
          [](const BSplineSurface& s) {
            return py::make_tuple(s.degree_u(), s.degree_v(), to_numpy(s.knots_u()), to_numpy(s.knots_v()),
                                  net_to_numpy(s.control_net()), weights_to_numpy(s.weights(), s.control_net()));
          },
          [](const py::tuple& state) {
            if (state.size() != 6) throw py::value_error("BSplineSurface pickle state must have 6 entries");
            return make_bspline_surface(state[0].cast<int>(), state[1].cast<int>(), state[2], state[3], state[4],
                                        state[5]);
          }));

  py::class_<BezierSurface>(module, "BezierSurface",
                            "A tensor-product Bézier patch of degrees (n, m) in R^d on [0, 1]^2: control net P_ij as "
                            "an (n+1, m+1, d) array (rows along u) and, if rational, weights w_ij > 0 as an (n+1, "
                            "m+1) array (Farin ch. 14-15; The NURBS Book eq. 1.12).")
      .def(py::init(&make_bezier_surface), py::arg("control_net"), py::arg("weights") = py::none(),
           "Validates and builds (BezierSurface::make): degrees up to MAX_BEZIER_DEGREE in each direction, finite "
           "control points, weights None or a (rows, columns) array of finite values > 0.")
      .def_property_readonly("degree_u", &BezierSurface::degree_u, "n = rows - 1.")
      .def_property_readonly("degree_v", &BezierSurface::degree_v, "m = columns - 1.")
      .def_property_readonly("control_net", [](const BezierSurface& s) { return net_to_numpy(s.control_net()); },
                             "P_ij as an (n+1, m+1, d) array, rows along u (a new array).")
      .def_property_readonly("weights", [](const BezierSurface& s) { return weights_to_numpy(s.weights(), s.control_net()); },
                             "w_ij as an (n+1, m+1) array; an empty (0, 0) array for a polynomial patch.")
      .def_property_readonly("is_rational", &BezierSurface::is_rational, "True when the patch carries weights.")
      .def_property_readonly("dimension", &BezierSurface::dimension, "d, the number of coordinates.")
      .def_property_readonly("domain_u", [](const BezierSurface&) { return py::make_tuple(0.0, 1.0); }, "(0, 1).")
      .def_property_readonly("domain_v", [](const BezierSurface&) { return py::make_tuple(0.0, 1.0); }, "(0, 1).")
      .def("__eq__", [](const BezierSurface& a, const BezierSurface& b) { return a == b; }, py::is_operator())
      .def("__repr__",
           [](const BezierSurface& s) {
             return fmt::format("BezierSurface(degree=({}, {}), {} x {} control points in R^{}{})", s.degree_u(),
                                s.degree_v(), s.control_net().rows(), s.control_net().columns(), s.dimension(),
                                s.is_rational() ? ", rational" : "");
           })
      .def(py::pickle(
          [](const BezierSurface& s) {
            return py::make_tuple(net_to_numpy(s.control_net()), weights_to_numpy(s.weights(), s.control_net()));
          },
          [](const py::tuple& state) {
            if (state.size() != 2) throw py::value_error("BezierSurface pickle state must have 2 entries");
            return make_bezier_surface(state[0], state[1]);
          }));

  py::class_<CoonsPatch>(module, "CoonsPatch",
                         "A Coons patch on [0, 1]^2 spanned by four boundary curves u0 = P(0, v), u1 = P(1, v), "
                         "v0 = P(u, 0), v1 = P(u, 1), bilinearly ('linear') or cubically ('cubic', Hermite) blended "
                         "(Coons 1967; seed 001 §2 corrected; Farin ch. 22).")
      .def(py::init(&make_coons_patch), py::arg("u0"), py::arg("u1"), py::arg("v0"), py::arg("v1"),
           py::arg("blending") = "linear",
           "Validates and builds (CoonsPatch::make): four curves (BSplineCurve, BezierCurve or "
           "PiecewiseBezierCurve, each written as a B-spline and mapped to [0, 1]) of one dimension, meeting at the "
           "corners within tolerances.JOINT_RELATIVE_GAP of their scale; blending 'linear' or 'cubic'. ValueError "
           "names the corner and the gap.")
      .def_property_readonly("u0", &CoonsPatch::u0, "P(0, v) as a BSplineCurve on [0, 1].")
      .def_property_readonly("u1", &CoonsPatch::u1, "P(1, v) as a BSplineCurve on [0, 1].")
      .def_property_readonly("v0", &CoonsPatch::v0, "P(u, 0) as a BSplineCurve on [0, 1].")
      .def_property_readonly("v1", &CoonsPatch::v1, "P(u, 1) as a BSplineCurve on [0, 1].")
      .def_property_readonly("blending", [](const CoonsPatch& p) { return std::string(blending_name(p.blending())); },
                             "'linear' or 'cubic' (blending_name).")
      .def_property_readonly("dimension", &CoonsPatch::dimension, "d, the number of coordinates.")
      .def_property_readonly("domain_u", [](const CoonsPatch&) { return py::make_tuple(0.0, 1.0); }, "(0, 1).")
      .def_property_readonly("domain_v", [](const CoonsPatch&) { return py::make_tuple(0.0, 1.0); }, "(0, 1).")
      .def("__eq__", [](const CoonsPatch& a, const CoonsPatch& b) { return a == b; }, py::is_operator())
      .def("__repr__",
           [](const CoonsPatch& p) {
             return fmt::format("CoonsPatch(blending='{}', boundaries of degrees u0 {}, u1 {}, v0 {}, v1 {} in R^{})",
                                blending_name(p.blending()), p.u0().degree(), p.u1().degree(), p.v0().degree(),
                                p.v1().degree(), p.dimension());
           })
      .def(py::pickle(
          [](const CoonsPatch& p) {
            return py::make_tuple(p.u0(), p.u1(), p.v0(), p.v1(), std::string(blending_name(p.blending())));
          },
          [](const py::tuple& state) {
            if (state.size() != 5) throw py::value_error("CoonsPatch pickle state must have 5 entries");
            return make_coons_patch(state[0], state[1], state[2], state[3], state[4].cast<std::string>());
          }));
}

// --- operations in one direction and conversions -----------------------------------

void bind_operations(py::module_& module) {
  module.def(
      "insert_knot",
      [](const BSplineSurface& surface, const std::string& direction, double value, int times) {
        return unwrap(insert_knot(surface, direction_from(direction, "direction"), value, times));
      },
      py::arg("surface"), py::arg("direction"), py::arg("value"), py::arg("times") = 1,
      "The surface with `value` inserted `times` times into the knots of direction 'u' or 'v' (Boehm's "
      "algorithm on every row or column, The NURBS Book A5.3). The surface does not change. ValueError: value "
      "not finite or outside that domain, times < 0, a multiplicity above degree + 1.");

  module.def(
      "refine_knots",
      [](const BSplineSurface& surface, const std::string& direction, const py::object& new_knots) {
        const Direction which = direction_from(direction, "direction");
        const std::vector<double> values = values_from(new_knots, "new_knots");
        return unwrap(refine_knots(surface, which, values));
      },
      py::arg("surface"), py::arg("direction"), py::arg("new_knots"),
      "The surface with every value of the (k,) array new_knots inserted in direction 'u' or 'v' (knot "
      "refinement, The NURBS Book A5.5 on every row or column). ValueError as insert_knot, naming the entry.");

  module.def(
      "elevate_degree",
      [](const BSplineSurface& surface, const std::string& direction, int times) {
        return unwrap(elevate_degree(surface, direction_from(direction, "direction"), times));
      },
      py::arg("surface"), py::arg("direction"), py::arg("times") = 1,
      "The same surface with its degree in 'u' or 'v' raised by `times` (The NURBS Book §5.5 through the curve's "
      "elevate_degree; continuity unchanged; clamped in that direction). ValueError: times < 0, a degree above "
      "MAX_BSPLINE_DEGREE, too many control points.");
  module.def(
      "elevate_degree",
      [](const BezierSurface& surface, const std::string& direction, int times) {
        return unwrap(elevate_degree(surface, direction_from(direction, "direction"), times));
      },
      py::arg("surface"), py::arg("direction"), py::arg("times") = 1,
      "The same Bézier patch with degree n + times in 'u' or 'v' (Farin §5.1 / The NURBS Book eq. 5.36 on every "
      "row or column). ValueError: times < 0, a degree above MAX_BEZIER_DEGREE.");

  module.def(
      "split_at",
      [](const BSplineSurface& surface, const std::string& direction, double value) {
        auto parts = unwrap(split_at(surface, direction_from(direction, "direction"), value));
        return py::make_tuple(std::move(parts.first), std::move(parts.second));
      },
      py::arg("surface"), py::arg("direction"), py::arg("value"),
      "The two parts of the surface at `value` of direction 'u' or 'v', as a tuple: [lower, value] and [value, "
      "upper] in that direction, both clamped (The NURBS Book §5.3 / A5.3). ValueError: value not finite or not "
      "strictly inside the domain.");
  module.def(
      "split_at",
      [](const BezierSurface& surface, const std::string& direction, double t) {
        auto parts = unwrap(split_at(surface, direction_from(direction, "direction"), t));
        return py::make_tuple(std::move(parts.first), std::move(parts.second));
      },
      py::arg("surface"), py::arg("direction"), py::arg("t"),
      "The two halves of a Bézier patch at t of direction 'u' or 'v', as a tuple, each reparameterized to [0, 1] "
      "(de Casteljau's subdivision on every row or column, Farin §3.2). ValueError: t not strictly inside (0, 1).");

  module.def(
      "iso_curve",
      [](const BSplineSurface& surface, const std::string& fixed, double value) {
        return unwrap(iso_curve(surface, direction_from(fixed, "fixed"), value));
      },
      py::arg("surface"), py::arg("fixed"), py::arg("value"),
      "The BSplineCurve of the free parameter with `fixed` ('u' or 'v') held at `value`: v -> S(value, v) for "
      "fixed='u', u -> S(u, value) for fixed='v' (The NURBS Book §3.4 eq. 3.14, §4.4 for NURBS). ValueError: "
      "value not finite or outside the domain of `fixed`.");
  module.def(
      "iso_curve",
      [](const BezierSurface& surface, const std::string& fixed, double value) {
        return unwrap(iso_curve(surface, direction_from(fixed, "fixed"), value));
      },
      py::arg("surface"), py::arg("fixed"), py::arg("value"),
      "The BezierCurve of the free parameter of a Bézier patch with `fixed` ('u' or 'v') held at value in [0, 1] "
      "(de Casteljau on the rows, The NURBS Book A1.7's first stage).");

  module.def(
      "to_bspline_surface", [](const BezierSurface& surface) { return to_bspline_surface(surface); },
      py::arg("surface"),
      "The same Bézier patch as a BSplineSurface on the knots 0^(n+1) 1^(n+1) and 0^(m+1) 1^(m+1) (exact).");
  module.def(
      "to_bspline_surface", [](const CoonsPatch& patch) { return unwrap(to_bspline_surface(patch)); },
      py::arg("patch"),
      "The Coons patch as an exact BSplineSurface when its boundaries are polynomial (The NURBS Book §10.5: the "
      "ruled surfaces minus the corner surface, made compatible). ValueError for rational boundaries.");

  module.def(
      "transposed", [](const BSplineSurface& surface) { return transposed(surface); }, py::arg("surface"),
      "The same surface with u and v exchanged: T(v, u) = S(u, v) (control net and weights transposed).");

  module.def(
      "homogeneous_net",
      [](const BSplineSurface& surface) { return net_to_numpy(homogeneous_net(surface)); }, py::arg("surface"),
      "The homogeneous net (w_ij P_ij, w_ij) as an (n+1, m+1, d+1) array, (P_ij, 1) for a polynomial surface "
      "(The NURBS Book eq. 4.16).");

  module.def(
      "from_homogeneous",
      [](int degree_u, int degree_v, const py::object& knots_u, const py::object& knots_v, const py::object& net) {
        const ControlNet homogeneous = net_from(net, "net");
        const int width = homogeneous.dimension();
        if (width < 2) {
          throw py::value_error("net must have at least 2 coordinates per point (the point and its weight)");
        }
        // Validate through make() on the projected net, then build with the C++ call.
        const std::size_t count = homogeneous.rows() * homogeneous.columns();
        const std::size_t d = static_cast<std::size_t>(width) - 1;
        std::vector<double> weights(count), points(count * d);
        const std::span<const double> source = homogeneous.points().coordinates();
        for (std::size_t k = 0; k < count; ++k) {
          const double w = source[k * (d + 1) + d];
          if (!(w > 0.0)) {
            throw py::value_error(fmt::format("net[{}, {}, {}] (a weight) is {}, weights must be > 0",
                                              k / homogeneous.columns(), k % homogeneous.columns(), d, w));
          }
          weights[k] = w;
          for (std::size_t c = 0; c < d; ++c) points[k * d + c] = source[k * (d + 1) + c] / w;
        }
        std::vector<double> u_knots = values_from(knots_u, "knots_u"), v_knots = values_from(knots_v, "knots_v");
        unwrap(BSplineSurface::make(
            degree_u, degree_v, u_knots, v_knots,
            unwrap(ControlNet::make(homogeneous.rows(), homogeneous.columns(),
                                    unwrap(PointArray::make(static_cast<int>(d), std::move(points), "point")))),
            std::move(weights)));
        return from_homogeneous(degree_u, degree_v, std::move(u_knots), std::move(v_knots), homogeneous);
      },
      py::arg("degree_u"), py::arg("degree_v"), py::arg("knots_u"), py::arg("knots_v"), py::arg("net"),
      "The NURBS surface whose homogeneous net is the (n+1, m+1, d+1) array net, last coordinate the weight "
      "(> 0): P_ij = first d coordinates / w_ij (The NURBS Book eq. 4.16). ValueError as BSplineSurface().");

  module.def(
      "blending_functions",
      [](const std::string& blending, double t, int order) {
        const CoonsBlending kind = blending_from(blending);
        if (order < 0) throw py::value_error(fmt::format("order {} is negative, it must be >= 0", order));
        const std::array<double, 2> f = blending_functions(kind, t, order);
        return py::make_tuple(f[0], f[1]);
      },
      py::arg("blending"), py::arg("t"), py::arg("order") = 0,
      "(f0^(k)(t), f1^(k)(t)) of a Coons patch's blending 'linear' (1 - t, t) or 'cubic' (2t^3 - 3t^2 + 1, 3t^2 - "
      "2t^3; seed 001 §2 corrected), as a tuple.");
}

// --- constructions -------------------------------------------------------------------

void bind_constructions(py::module_& module) {
  module.def(
      "ruled_surface",
      [](const py::object& first, const py::object& second) {
        return unwrap(ruled_surface(curve_from(first, "first"), curve_from(second, "second")));
      },
      py::arg("first"), py::arg("second"),
      "The ruled surface S(u, v) = (1 - v) C0(u) + v C1(u) on [0, 1]^2 between two curves made compatible (The "
      "NURBS Book §10.3-10.4): degree (p, 1). Any curve class (written as a B-spline first).");

  module.def(
      "revolve",
      [](const py::object& profile, const py::object& axis_point, const py::object& axis_direction, double angle) {
        const BSplineCurve curve = curve_from(profile, "profile");
        const std::vector<double> point = values_from(axis_point, "axis_point");
        const std::vector<double> direction = values_from(axis_direction, "axis_direction");
        return unwrap(revolve(curve, point, direction, angle));
      },
      py::arg("profile"), py::arg("axis_point"), py::arg("axis_direction"), py::arg("angle"),
      "The exact NURBS surface swept by the 3D profile turning by `angle` radians (0 < angle <= 2 pi) around the "
      "axis through axis_point along axis_direction (The NURBS Book A8.1): u around the axis on [0, 1], v the "
      "profile's parameter; degree (2, q).");

  module.def(
      "make_sphere",
      [](const py::object& center, double radius) {
        return unwrap(make_sphere(values_from(center, "center"), radius));
      },
      py::arg("center"), py::arg("radius"),
      "The sphere |S - center| = radius (center a point of R^3, first as in every make_*) as an exact NURBS "
      "surface of degree (2, 2), 9 x 5 control points, poles "
      "at v = 0 and v = 1, outward normals (a semicircle revolved, The NURBS Book §8.5).");

  module.def(
      "make_torus",
      [](const py::object& center, const py::object& axis, double major_radius, double minor_radius) {
        return unwrap(make_torus(values_from(center, "center"), values_from(axis, "axis"), major_radius, minor_radius));
      },
      py::arg("center"), py::arg("axis"), py::arg("major_radius"), py::arg("minor_radius"),
      "The ring torus around the axis through center as an exact NURBS surface of degree (2, 2), 9 x 9 control "
      "points, outward normals (a circle revolved, The NURBS Book §8.5). ValueError when minor_radius >= "
      "major_radius.");

  module.def(
      "make_compatible",
      [](const py::object& curves) {
        const std::vector<BSplineCurve> input = curves_from(curves, "curves");
        return curve_list(unwrap(make_compatible(input)));
      },
      py::arg("curves"),
      "The curves rewritten on [0, 1] with one degree and one knot vector, each without changing its shape (The "
      "NURBS Book §10.3), as a list of BSplineCurve. Any curve classes.");

  module.def(
      "section_parameters",
      [](const py::object& sections, const std::string& parameterization) {
        const std::vector<BSplineCurve> curves = curves_from(sections, "sections");
        const Parameterization kind = parameterization_from(parameterization);
        return to_numpy(unwrap(section_parameters(curves, kind)));
      },
      py::arg("sections"), py::arg("parameterization") = "chord",
      "The parameters v_0 = 0 < ... < v_K = 1 at which skin() places the sections, averaged over the columns of "
      "the compatible sections (The NURBS Book eq. 10.8), as a (K+1,) array.");

  module.def(
      "skin",
      [](const py::object& sections, int degree_v, const std::string& parameterization) {
        const std::vector<BSplineCurve> curves = curves_from(sections, "sections");
        const Parameterization kind = parameterization_from(parameterization);
        return unwrap(skin(curves, degree_v, kind));
      },
      py::arg("sections"), py::arg("degree_v"), py::arg("parameterization") = "chord",
      "The skinned (lofted) BSplineSurface through the section curves, S(u, v_k) = C_k(u), of degree (p, "
      "degree_v) (The NURBS Book §10.3). ValueError: fewer than 2 sections, degree_v < 1 or > K, coincident "
      "sections.");

  module.def(
      "grid_parameters",
      [](const py::object& points, const std::string& parameterization) {
        const ControlNet grid = net_from(points, "points");
        const Parameterization kind = parameterization_from(parameterization);
        const GridParameters parameters = unwrap(grid_parameters(grid, kind));
        return py::make_tuple(to_numpy(parameters.u), to_numpy(parameters.v));
      },
      py::arg("points"), py::arg("parameterization") = "chord",
      "The parameters (u, v) that interpolate_grid gives the rows and columns of the (rows, columns, d) grid of "
      "points, averaged (The NURBS Book eq. 9.13 / A9.3), as a tuple of two arrays.");

  module.def(
      "interpolate_grid",
      [](const py::object& points, int degree_u, int degree_v, const std::string& parameterization) {
        const ControlNet grid = net_from(points, "points");
        const Parameterization kind = parameterization_from(parameterization);
        return unwrap(interpolate_grid(grid, degree_u, degree_v, kind));
      },
      py::arg("points"), py::arg("degree_u") = 3, py::arg("degree_v") = 3, py::arg("parameterization") = "chord",
      "The BSplineSurface of degree (degree_u, degree_v) through the (rows, columns, d) grid of points at the "
      "parameters of grid_parameters (The NURBS Book A9.4). ValueError: a degree < 1, too few rows or columns, "
      "coincident rows or columns.");
}

}  // namespace

void bind_surfaces(py::module_& module) {
  bind_classes(module);
  bind_evaluation<BSplineSurface>(module, "B-spline or NURBS surface");
  bind_evaluation<BezierSurface>(module, "Bézier patch");
  bind_evaluation<CoonsPatch>(module, "Coons patch");
  bind_operations(module);
  bind_constructions(module);
}

}  // namespace casteljau::python
