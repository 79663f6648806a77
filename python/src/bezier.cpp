// The bezier layer in Python: BezierCurve (polynomial and rational) and
// PiecewiseBezierCurve, the Bernstein basis, evaluation (single and batch),
// subdivision, the de Casteljau construction, degree elevation/reduction,
// Bézier's vector form and affine maps. Every precondition a C++ function
// asserts is checked here first and refused with ValueError.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/bezier/affine.hpp"
#include "casteljau/bezier/bernstein.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/construction.hpp"
#include "casteljau/bezier/degree.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bezier/vector_form.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau::python {

namespace {

constexpr Interval kUnit{0.0, 1.0};

/// One parameter: finite and, unless `extrapolate`, inside `domain`.
/// A Bernstein degree n given from Python: 0 <= n <= kMaxBezierDegree.
void check_bezier_degree(int n, const char* what) {
  if (n < 0 || n > tolerances::kMaxBezierDegree) {
    throw py::value_error(fmt::format("{} {} is outside 0..{}", what, n, tolerances::kMaxBezierDegree));
  }
}


/// `value` as a float64 array of 0 or 1 dimensions, every value finite:
/// what the basis functions accept for their parameter.
DoubleArray basis_parameters(const py::object& value, const char* what) {
  DoubleArray array = as_double_array(value, what);
  if (array.ndim() > 1) {
    throw py::value_error(fmt::format("{} must be a float or a (k,) array, got an array of {} dimensions", what,
                                      array.ndim()));
  }
  if (array.ndim() == 0) {
    check_parameter(array.data()[0], kUnit, true, what);
    return array;
  }
  const std::span<const double> values(array.data(), static_cast<std::size_t>(array.size()));
  for_each_checked_chunk(values, kUnit, true, what, [](std::span<const double>, std::size_t) {});
  return array;
}

/// f(t) for a float t (a float back) or for each t of a (k,) array (a (k,)
/// array back), the loop in C++ without the GIL.
template <class F>
py::object map_parameters(const py::object& value, const char* what, F f) {
  const DoubleArray parameters = basis_parameters(value, what);
  if (parameters.ndim() == 0) return py::float_(f(parameters.data()[0]));
  const std::size_t k = static_cast<std::size_t>(parameters.size());
  DoubleArray result(static_cast<py::ssize_t>(k));
  const double* source = parameters.data();
  double* target = result.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < k; ++i) target[i] = f(source[i]);
  }
  return result;
}

/// fill(t, row) writes `width` values for each t: a (width,) array for a
/// float t, a (k, width) array for a (k,) array.
template <class Fill>
DoubleArray rows_for_parameters(const py::object& value, const char* what, std::size_t width, Fill fill) {
  const DoubleArray parameters = basis_parameters(value, what);
  if (parameters.ndim() == 0) {
    DoubleArray result(static_cast<py::ssize_t>(width));
    fill(parameters.data()[0], std::span<double>(result.mutable_data(), width));
    return result;
  }
  const std::size_t k = static_cast<std::size_t>(parameters.size());
  DoubleArray result({static_cast<py::ssize_t>(k), static_cast<py::ssize_t>(width)});
  const double* source = parameters.data();
  double* target = result.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < k; ++i) fill(source[i], std::span<double>(target + i * width, width));
  }
  return result;
}

BezierCurve bezier_from(const py::object& control_points, const py::object& weights) {
  std::vector<double> weight_values;
  if (!weights.is_none()) weight_values = values_from(weights, "weights");
  return unwrap(BezierCurve::make(points_from(control_points, "control_points"), std::move(weight_values)));
}

/// A curve computed from a valid one by extrapolating (t outside [0,1]) is
/// checked again: coordinates may overflow to inf.
BezierCurve revalidated(const BezierCurve& curve, const char* what) {
  std::vector<double> weights(curve.weights().begin(), curve.weights().end());
  auto checked = BezierCurve::make(curve.control_points(), std::move(weights));
  if (!checked) throw py::value_error(fmt::format("{}: {}", what, checked.error().message));
  return std::move(checked).value();
}

/// The weights of a rational curve as a 1-D polynomial Bézier curve: its
/// control points at any split/segment are the new weights, which must stay
/// > 0 (from_homogeneous asserts it) when the parameters leave [0, 1].
BezierCurve weight_curve(const BezierCurve& curve) {
  return BezierCurve::from_trusted(
      PointArray::from_trusted(1, std::vector<double>(curve.weights().begin(), curve.weights().end())));
}

void check_positive_weights(const BezierCurve& weights, const char* what) {
  for (const double w : weights.control_points().coordinates()) {
    if (!(w > 0.0) || !std::isfinite(w)) {
      throw py::value_error(fmt::format("{}: a weight of the result would be {} (the parameters lie outside [0, 1] "
                                        "where the weight function of this rational curve is not positive)",
                                        what, w));
    }
  }
}

void check_degree_growth(const BezierCurve& curve, int extra, const char* what) {
  if (extra < 0) throw py::value_error(fmt::format("{} is {}, it must be >= 0", what, extra));
  if (extra > tolerances::kMaxBezierDegree - curve.degree()) {
    throw py::value_error(fmt::format("degree {} + {} {} is above the limit {}", curve.degree(), what, extra,
                                      tolerances::kMaxBezierDegree));
  }
}

void check_piecewise_parameter(const PiecewiseBezierCurve& curve, double u, bool extrapolate) {
  check_parameter(u, curve.domain(), extrapolate, "u");
}

std::vector<double> affine_translation(const py::object& offset, int dimension) {
  std::vector<double> values = values_from(offset, "translation");
  if (static_cast<int>(values.size()) != dimension) {
    throw py::value_error(
        fmt::format("the translation has {} entries, the map acts on R^{}", values.size(), dimension));
  }
  return values;
}

void check_affine_dimension(long dimension) {
  // d*d entries must stay a sane size (kMaxInputValues, the io limit).
  if (dimension < 1 || static_cast<std::size_t>(dimension) * static_cast<std::size_t>(dimension) >
                           tolerances::kMaxInputValues) {
    throw py::value_error(fmt::format("affine map dimension {} is outside 1..{}", dimension,
                                      static_cast<long>(std::sqrt(static_cast<double>(tolerances::kMaxInputValues)))));
  }
}

DoubleArray linear_part(const AffineMap& map) {
  DoubleArray result({static_cast<py::ssize_t>(map.dimension), static_cast<py::ssize_t>(map.dimension)});
  std::copy(map.linear.begin(), map.linear.end(), result.mutable_data());
  return result;
}

AffineMap affine_from(const py::object& linear, const py::object& translation) {
  const DoubleArray matrix = as_double_array(linear, "linear");
  if (matrix.ndim() != 2 || matrix.shape(0) != matrix.shape(1)) {
    std::string shape;
    for (py::ssize_t i = 0; i < matrix.ndim(); ++i) shape += (i > 0 ? ", " : "") + std::to_string(matrix.shape(i));
    throw py::value_error(fmt::format("linear must be a (d, d) matrix, got an array of shape ({})", shape));
  }
  check_affine_dimension(static_cast<long>(matrix.shape(0)));
  const int d = static_cast<int>(matrix.shape(0));
  std::vector<double> entries(matrix.data(), matrix.data() + matrix.size());
  return unwrap(AffineMap::make(d, std::move(entries), affine_translation(translation, d)));
}

}  // namespace

void bind_bezier(py::module_& module) {
  // ---- the Bernstein basis (bernstein.hpp) ----
  module.def("binomial", &binomial, py::arg("n"), py::arg("k"),
             "C(n, k) as a float, exact while it fits in 64-bit integers, +inf once it overflows, 0 for k < 0 or "
             "k > n (bernstein.hpp).");

  module.def(
      "bernstein",
      [](int n, int k, const py::object& t) {
        check_bezier_degree(n, "degree n");
        return map_parameters(t, "t", [n, k](double u) { return bernstein(n, k, u); });
      },
      py::arg("n"), py::arg("k"), py::arg("t"),
      "B_{n,k}(t) = C(n,k) t^k (1-t)^(n-k) as one running product (no overflow at any degree; seed 000, 001). "
      "t: a float (a float back) or a (k,) array (an array back, evaluated in C++). Any finite t (outside [0, 1] "
      "the polynomial continues); 0 for k outside 0..n.");

  module.def(
      "bernstein_all",
      [](int n, const py::object& t) {
        check_bezier_degree(n, "degree n");
        return rows_for_parameters(t, "t", static_cast<std::size_t>(n) + 1,
                                   [n](double u, std::span<double> row) { bernstein_all(n, u, row); });
      },
      py::arg("n"), py::arg("t"),
      "B_{n,0}(t) .. B_{n,n}(t) by the triangular recurrence (The NURBS Book A1.3 AllBernstein): an (n+1,) array "
      "for a float t, a (k, n+1) array for a (k,) array. Any finite t.");

  module.def(
      "bernstein_derivatives",
      [](int n, const py::object& t, int order) {
        check_bezier_degree(n, "degree n");
        if (order < 0) throw py::value_error(fmt::format("derivative order {} is negative", order));
        return rows_for_parameters(t, "t", static_cast<std::size_t>(n) + 1, [n, order](double u, std::span<double> row) {
          bernstein_derivatives(n, u, order, row);
        });
      },
      py::arg("n"), py::arg("t"), py::arg("order"),
      "d^r/dt^r B_{n,k}(t), k = 0..n (The NURBS Book eq. 1.10 / 2.9; zero for order > n): an (n+1,) array for a "
      "float t, a (k, n+1) array for a (k,) array.");

  module.def(
      "bezier_basis_polynomial",
      [](int n, int i, const py::object& t) {
        check_bezier_degree(n, "degree n");
        return map_parameters(t, "t", [n, i](double u) { return bezier_basis_polynomial(n, i, u); });
      },
      py::arg("n"), py::arg("i"), py::arg("t"),
      "Bézier's own basis f_i(t) = sum_{k >= i} B_{n,k}(t), f_0 = 1 (seed 001 'polynômes de Bézier', seed 003 "
      "vector form). t a float or a (k,) array, as bernstein.");

  // ---- BezierCurve (bezier_curve.hpp) ----
  py::class_<BezierCurve>(module, "BezierCurve",
                          "A Bézier curve of degree n in R^d: control points P_0..P_n as an (n+1, d) array and, if "
                          "rational, one weight w_k > 0 per point, C(t) = sum w_k P_k B_{n,k}(t) / sum w_k "
                          "B_{n,k}(t) on [0, 1] (seed 000, 004). A value: operations return new curves.")
      .def(py::init(&bezier_from), py::arg("control_points"), py::arg("weights") = py::none(),
           "Validates and builds (BezierCurve::make): 1 to MAX_BEZIER_DEGREE + 1 finite control points, weights None "
           "or n+1 finite values > 0. ValueError names the bad field.")
      .def_property_readonly("degree", &BezierCurve::degree, "n, the number of control points minus one.")
      .def_property_readonly("dimension", &BezierCurve::dimension, "d, the number of coordinates.")
      .def_property_readonly("control_points", [](const BezierCurve& c) { return to_numpy(c.control_points()); },
                             "P_0 .. P_n as an (n+1, d) array (a new array).")
      .def_property_readonly("weights", [](const BezierCurve& c) { return to_numpy(c.weights()); },
                             "w_0 .. w_n, an empty array for a polynomial curve.")
      .def_property_readonly("is_rational", &BezierCurve::is_rational, "True when the curve carries weights.")
      .def_property_readonly("domain", [](const BezierCurve&) { return py::make_tuple(0.0, 1.0); },
                             "(0.0, 1.0), the parameter interval of every Bézier curve.")
      .def("__eq__", [](const BezierCurve& a, const BezierCurve& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const BezierCurve& c) {
        return fmt::format("BezierCurve(degree={}, {} control points in R^{}{})", c.degree(),
                           c.control_points().size(), c.dimension(), c.is_rational() ? ", rational" : "");
      })
      .def(py::pickle(
          [](const BezierCurve& c) { return py::make_tuple(to_numpy(c.control_points()), to_numpy(c.weights())); },
          [](const py::tuple& state) {
            if (state.size() != 2) throw py::value_error("BezierCurve pickle state must have 2 entries");
            return unwrap(BezierCurve::make(points_from(state[0], "control_points"), values_from(state[1], "weights")));
          }));

  module.def(
      "homogeneous_points", [](const BezierCurve& curve) { return to_numpy(homogeneous_points(curve)); },
      py::arg("curve"),
      "The homogeneous control points (w_k P_k, w_k) as an (n+1, d+1) array, (P_k, 1) for a polynomial curve "
      "(The NURBS Book §4.2).");

  module.def(
      "from_homogeneous",
      [](const py::object& points) {
        const PointArray rows = points_from(points, "points");
        const int d = rows.dimension() - 1;
        if (d < 1) throw py::value_error("points must have d+1 >= 2 columns, the last one the weight");
        if (rows.size() > static_cast<std::size_t>(tolerances::kMaxBezierDegree) + 1) {
          throw py::value_error(fmt::format("{} points make a Bézier curve of degree above the limit {}", rows.size(),
                                            tolerances::kMaxBezierDegree));
        }
        for (std::size_t i = 0; i < rows.size(); ++i) {
          const double w = rows[i][static_cast<std::size_t>(d)];
          if (!(w > 0.0)) throw py::value_error(fmt::format("weight {} is {}, weights must be > 0", i, w));
        }
        return revalidated(from_homogeneous(rows), "from_homogeneous");
      },
      py::arg("points"),
      "The rational Bézier curve whose homogeneous control points are the (n+1, d+1) array `points` (last column "
      "the weight, > 0): P_k = first d coordinates / w_k (The NURBS Book §4.2).");

  // ---- evaluation (evaluate.hpp) ----


  module.def(
      "point_at_bernstein_sum",
      [](const BezierCurve& curve, double t, bool extrapolate) {
        check_parameter(t, kUnit, extrapolate, "t");
        return to_numpy(point_at_bernstein_sum(curve, t));
      },
      py::arg("curve"), py::arg("t"), py::kw_only(), py::arg("extrapolate") = false,
      "C(t) by the direct sum sum_k C(n,k) t^k (1-t)^(n-k) P_k as the seed notebook's bezier0 computes it "
      "(overflows to inf/NaN near degree 1030: kept to show where it breaks).");

  module.def(
      "derivative_curve", [](const BezierCurve& curve, int order) { return unwrap(derivative_curve(curve, order)); },
      py::arg("curve"), py::arg("order") = 1,
      "The k-th derivative curve (the hodograph), the Bézier curve of degree n-k with control points n!/(n-k)! "
      "Delta^k P_i (Farin §4.3); the zero curve for k > n. ValueError for a rational curve or a negative order.");

  // ---- the de Casteljau construction (construction.hpp) ----
  module.def(
      "casteljau_construction",
      [](const BezierCurve& curve, double t, bool extrapolate) {
        check_parameter(t, kUnit, extrapolate, "t");
        py::list levels;
        for (const PointArray& level : casteljau_construction(curve, t)) levels.append(to_numpy(level));
        return levels;
      },
      py::arg("curve"), py::arg("t"), py::kw_only(), py::arg("extrapolate") = false,
      "Levels 0..n of the de Casteljau triangle at t as a list of (n+1-r, d) arrays: level 0 the control "
      "polygon, level n the point C(t) (seed 004's demo_casteljau; rational curves projected, Farin §13.3).");

  // ---- subdivision (split.hpp) ----
  module.def(
      "split_at",
      [](const BezierCurve& curve, double t, bool extrapolate) {
        if (!extrapolate || kUnit.contains(t)) {
          auto [left, right] = unwrap(split_at(curve, t));
          return py::make_tuple(std::move(left), std::move(right));
        }
        check_parameter(t, kUnit, extrapolate, "t");
        if (curve.is_rational()) {
          check_positive_weights(extended_segment(weight_curve(curve), 0.0, t), "split_at");
          check_positive_weights(extended_segment(weight_curve(curve), t, 1.0), "split_at");
        }
        return py::make_tuple(revalidated(extended_segment(curve, 0.0, t), "split_at"),
                              revalidated(extended_segment(curve, t, 1.0), "split_at"));
      },
      py::arg("curve"), py::arg("t"), py::kw_only(), py::arg("extrapolate") = false,
      "(left, right): C on [0, t] and on [t, 1], each reparameterized to [0, 1], from the sides of the de "
      "Casteljau triangle (Farin §3.2); a tuple where C++ returns a pair. t strictly inside (0, 1), as for every "
      "curve kind; with extrapolate=True any finite t outside [0, 1] too (blossoming: extended_segment).");

  module.def(
      "segment",
      [](const BezierCurve& curve, double t0, double t1, bool extrapolate) {
        if (!extrapolate) return unwrap(segment(curve, t0, t1));
        check_parameter(t0, kUnit, extrapolate, "t0");
        check_parameter(t1, kUnit, extrapolate, "t1");
        const bool outside = !kUnit.contains(t0) || !kUnit.contains(t1);
        if (outside && curve.is_rational())
          check_positive_weights(extended_segment(weight_curve(curve), t0, t1), "segment");
        BezierCurve piece = extended_segment(curve, t0, t1);
        return outside ? revalidated(piece, "segment") : piece;
      },
      py::arg("curve"), py::arg("t0"), py::arg("t1"), py::kw_only(), py::arg("extrapolate") = false,
      "C restricted to [t0, t1] and reparameterized to [0, 1] (blossoming, Farin §3.4): 0 <= t0 < t1 <= 1, as for "
      "every curve kind; with extrapolate=True any finite t0, t1 (t0 > t1 gives the reversed piece: "
      "extended_segment).");

  module.def(
      "reversed", [](const BezierCurve& curve) { return reversed(curve); }, py::arg("curve"),
      "The same curve traversed backwards: control points (and weights) in reverse order.");

  module.def(
      "subdivide_recursive",
      [](const BezierCurve& curve, int depth, double t) {
        Expected<PointArray> points = [&] {
          py::gil_scoped_release release;
          return subdivide_recursive(curve, depth, t);
        }();
        return to_numpy(unwrap(std::move(points)));
      },
      py::arg("curve"), py::arg("depth"), py::arg("t") = 0.5,
      "Seed 004's recursive subdivision bezier(Ps, r, t): the 2^depth + 1 end points of the 2^depth pieces, in "
      "order, as an array. ValueError for depth < 0 or > 24, or t not strictly inside (0, 1).");

  // ---- degree (degree.hpp) ----
  module.def(
      "elevate_degree",
      [](const BezierCurve& curve, int times) {
        check_degree_growth(curve, times, "times");
        return elevate_degree(curve, times);
      },
      py::arg("curve"), py::arg("times") = 1,
      "The same curve written with degree n + times (Farin §5.1; The NURBS Book eq. 5.36; rational curves on "
      "their homogeneous points). ValueError for times < 0 or a degree above MAX_BEZIER_DEGREE.");

  py::class_<DegreeReduction>(module, "DegreeReduction",
                              "The result of reduce_degree(BezierCurve): the reduced curve and the error it makes.")
      .def_readonly("curve", &DegreeReduction::curve, "R, the curve of degree n - 1.")
      .def_readonly("error_bound", &DegreeReduction::error_bound,
                    "Guaranteed bound on max |C(t) - R(t)| over [0, 1] (control-point differences after elevating R "
                    "back, by the convex hull property).")
      .def_readonly("sampled_error", &DegreeReduction::sampled_error,
                    "max |C(t) - R(t)| sampled at 1025 evenly spaced parameters (<= error_bound).")
      .def("__repr__", [](const DegreeReduction& r) {
        return fmt::format("DegreeReduction(degree={}, error_bound={}, sampled_error={})", r.curve.degree(),
                           r.error_bound, r.sampled_error);
      })
      .def(py::pickle(
          [](const DegreeReduction& r) { return py::make_tuple(r.curve, r.error_bound, r.sampled_error); },
          [](const py::tuple& state) {
            if (state.size() != 3) throw py::value_error("DegreeReduction pickle state must have 3 entries");
            return DegreeReduction{state[0].cast<BezierCurve>(), state[1].cast<double>(), state[2].cast<double>()};
          }));

  module.def(
      "reduce_degree",
      [](const BezierCurve& curve, bool keep_end_points) {
        DegreeReductionOptions options;
        options.keep_end_points = keep_end_points;
        return unwrap(reduce_degree(curve, options));
      },
      py::arg("curve"), py::kw_only(), py::arg("keep_end_points") = true,
      "The L2-closest curve of degree n - 1 (Eck, CAD 27(11), 1995; keep_end_points: the constrained problem) "
      "as a DegreeReduction object (curve, error_bound, sampled_error). ValueError for degree 0 or a rational "
      "curve.");

  module.def(
      "repeat_control_point",
      [](const BezierCurve& curve, int index, int extra) {
        if (index < 0 || index > curve.degree()) {
          throw py::value_error(fmt::format("index {} is outside 0..{}", index, curve.degree()));
        }
        check_degree_growth(curve, extra, "extra");
        return repeat_control_point(curve, index, extra);
      },
      py::arg("curve"), py::arg("index"), py::arg("extra"),
      "Seed 003 fig. 4 b): the curve whose polygon repeats P_index `extra` more times (degree n + extra, pulled "
      "toward P_index; not an elevation).");

  // ---- vector form (vector_form.hpp) ----
  module.def(
      "to_vector_form",
      [](const py::object& control_points) { return to_numpy(to_vector_form(points_from(control_points, "control_points"))); },
      py::arg("control_points"),
      "Bézier's vector form of an (n+1, d) polygon: V_0 = P_0, V_i = P_i - P_{i-1} (seed 003 §1).");

  module.def(
      "from_vector_form",
      [](const py::object& vectors) { return to_numpy(from_vector_form(points_from(vectors, "vectors"))); },
      py::arg("vectors"), "The inverse of to_vector_form: P_0 = V_0, P_i = P_{i-1} + V_i (a running sum).");

  module.def(
      "point_at_vector_form",
      [](const py::object& vectors, double t, bool extrapolate) {
        const PointArray v = points_from(vectors, "vectors");
        if (v.size() > static_cast<std::size_t>(tolerances::kMaxBezierDegree) + 1) {
          throw py::value_error(fmt::format("{} vectors make a degree above the limit {}", v.size(),
                                            tolerances::kMaxBezierDegree));
        }
        check_parameter(t, kUnit, extrapolate, "t");
        return to_numpy(point_at_vector_form(v, t));
      },
      py::arg("vectors"), py::arg("t"), py::kw_only(), py::arg("extrapolate") = false,
      "P(t) = sum_i f_i(t) V_i in Bézier's basis (seed 003 §1; for teaching and as a check of point_at).");

  // ---- affine maps (affine.hpp) ----
  py::class_<AffineMap>(module, "AffineMap",
                        "x -> A x + b on R^d, A a (d, d) matrix and b a (d,) vector (seed 000, 004 §2: Bézier "
                        "curves are affinely invariant).")
      .def(py::init(&affine_from), py::arg("linear"), py::arg("translation"),
           "From a (d, d) matrix A and a (d,) offset b, all finite (AffineMap::make).")
      .def_static(
          "identity",
          [](int dimension) {
            check_affine_dimension(dimension);
            return AffineMap::identity(dimension);
          },
          py::arg("dimension"), "The identity of R^d.")
      .def_static(
          "translate",
          [](const py::object& offset) {
            std::vector<double> values = values_from(offset, "offset");
            check_affine_dimension(static_cast<long>(values.size()));
            return AffineMap::translate(std::move(values));
          },
          py::arg("offset"), "x -> x + b, b a (d,) array (d >= 1).")
      .def_static(
          "scale",
          [](int dimension, double factor) {
            check_affine_dimension(dimension);
            unwrap(check_finite(factor, "the scale factor"));
            return AffineMap::scale(dimension, factor);
          },
          py::arg("dimension"), py::arg("factor"), "x -> s x, uniform scaling about the origin of R^d.")
      .def_static(
          "rotate_2d",
          [](double radians) {
            unwrap(check_finite(radians, "the rotation angle"));
            return AffineMap::rotate_2d(radians);
          },
          py::arg("radians"), "The plane rotation by `radians` about the origin (counter-clockwise).")
      .def(
          "after",
          [](const AffineMap& self, const AffineMap& first) {
            if (first.dimension != self.dimension) {
              throw py::value_error(
                  fmt::format("cannot compose a map of R^{} after one of R^{}", self.dimension, first.dimension));
            }
            return self.after(first);
          },
          py::arg("first"), "The composition self(first(x)).")
      .def_property_readonly("dimension", [](const AffineMap& m) { return m.dimension; },
                             "d, the dimension of the space the map acts on.")
      .def_property_readonly("linear", &linear_part, "A as a (d, d) array (a new array).")
      .def_property_readonly("translation", [](const AffineMap& m) { return to_numpy(m.translation); },
                             "b as a (d,) array (a new array).")
      .def("__eq__",
           [](const AffineMap& a, const AffineMap& b) {
             return a.dimension == b.dimension && a.linear == b.linear && a.translation == b.translation;
           },
           py::is_operator())
      .def("__repr__", [](const AffineMap& m) { return fmt::format("AffineMap(R^{})", m.dimension); })
      .def(py::pickle([](const AffineMap& m) { return py::make_tuple(linear_part(m), to_numpy(m.translation)); },
                      [](const py::tuple& state) {
                        if (state.size() != 2) throw py::value_error("AffineMap pickle state must have 2 entries");
                        return affine_from(state[0], state[1]);
                      }));

  module.def(
      "transformed_point",
      [](const AffineMap& map, const py::object& x) {
        const std::vector<double> point = values_from(x, "x");
        if (static_cast<int>(point.size()) != map.dimension) {
          throw py::value_error(fmt::format("x has {} coordinates, the map acts on R^{}", point.size(), map.dimension));
        }
        return to_numpy(transformed_point(map, point));
      },
      py::arg("map"), py::arg("x"), "A x + b for one (d,) point.");

  module.def(
      "transformed",
      [](const BezierCurve& curve, const AffineMap& map) { return unwrap(transformed(curve, map)); },
      py::arg("curve"), py::arg("map"),
      "The image of the curve under the map: every control point mapped, weights unchanged (affine invariance, "
      "seed 004 §2). ValueError when the dimensions differ.");

  // ---- PiecewiseBezierCurve (piecewise_bezier.hpp) ----
  py::class_<PiecewiseBezierCurve>(module, "PiecewiseBezierCurve",
                                   "m Bézier pieces of one dimension end to end (model JSON's piecewise_bezier, seed "
                                   "000's C1 interpolant): piece i covers [i, i+1], the domain is [0, m].")
      .def(py::init([](const py::iterable& pieces) {
             // Each piece a BezierCurve, or its control points as model JSON's
             // "pieces" hold them (an (n, d) array-like: nested lists, numpy).
             if (py::isinstance<py::str>(pieces) || py::isinstance<py::bytes>(pieces))
               throw py::value_error("pieces must be a sequence of BezierCurve or of (n, d) control point arrays, got a string");
             std::vector<BezierCurve> curves;
             for (const py::handle piece : pieces) {
               if (py::isinstance<BezierCurve>(piece)) curves.push_back(piece.cast<BezierCurve>());
               else curves.push_back(unwrap(BezierCurve::make(points_from(piece, fmt::format("pieces[{}]", curves.size())))));
             }
             return unwrap(PiecewiseBezierCurve::make(std::move(curves)));
           }),
           py::arg("pieces"),
           "From a sequence of pieces (at least one, all of one dimension; PiecewiseBezierCurve::make), each a "
           "BezierCurve or its control points as an (n, d) array-like, as model JSON's piecewise_bezier holds them "
           "(nested lists, or an (m, n, d) numpy array). Pieces need not join.")
      .def_property_readonly("pieces", [](const PiecewiseBezierCurve& c) { return c.pieces(); },
                             "The pieces, a list of BezierCurve (copies).")
      .def_property_readonly("dimension", &PiecewiseBezierCurve::dimension, "d, the number of coordinates.")
      .def_property_readonly("size", &PiecewiseBezierCurve::size, "m, the number of pieces.")
      .def_property_readonly("domain",
                             [](const PiecewiseBezierCurve& c) { return py::make_tuple(0.0, static_cast<double>(c.size())); },
                             "(0.0, m).")
      .def("__len__", &PiecewiseBezierCurve::size)
      .def("__eq__", [](const PiecewiseBezierCurve& a, const PiecewiseBezierCurve& b) { return a == b; },
           py::is_operator())
      .def("__repr__", [](const PiecewiseBezierCurve& c) {
        return fmt::format("PiecewiseBezierCurve({} pieces in R^{})", c.size(), c.dimension());
      })
      .def(py::pickle([](const PiecewiseBezierCurve& c) { return py::make_tuple(c.pieces()); },
                      [](const py::tuple& state) {
                        if (state.size() != 1) throw py::value_error("PiecewiseBezierCurve pickle state must have 1 entry");
                        return unwrap(PiecewiseBezierCurve::make(state[0].cast<std::vector<BezierCurve>>()));
                      }));

  module.def(
      "locate",
      [](const PiecewiseBezierCurve& curve, double u, bool extrapolate) {
        check_piecewise_parameter(curve, u, extrapolate);
        const auto [piece, t] = locate(curve, u);
        return py::make_tuple(piece, t);
      },
      py::arg("curve"), py::arg("u"), py::kw_only(), py::arg("extrapolate") = false,
      "(piece, local t) of u in [0, m]: piece floor(u) (the last one for u = m), t = u - piece.");


}

}  // namespace casteljau::python
