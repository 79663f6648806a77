// The bspline layer in Python, apart from the BSplineCurve class and its
// evaluation (bspline_curve.cpp): knot vectors, the Cox–de Boor basis, the
// exact algorithms (knot insertion/refinement/removal, degree, split,
// reversal, reparameterization, clamping, join, continuity, Bézier pieces)
// and the bridges to the bezier layer. Preconditions the C++ functions
// assert are checked here and refused with ValueError.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/continuity.hpp"
#include "casteljau/bspline/degree.hpp"
#include "casteljau/bspline/join.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/knot_removal.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/core/tolerance.hpp"

namespace casteljau::python {

namespace {

void check_finite_value(double u, const char* what) {
  if (std::isnan(u)) throw py::value_error(fmt::format("{} is NaN", what));
  if (std::isinf(u)) throw py::value_error(fmt::format("{} is infinite", what));
}

void check_degree(int degree) {
  if (degree < 0 || degree > tolerances::kMaxBSplineDegree) {
    throw py::value_error(fmt::format("degree {} is outside 0..{}", degree, tolerances::kMaxBSplineDegree));
  }
}

/// A control point count n+1 given from Python: degree+1 <= count <= kMaxControlPoints.
std::size_t checked_count(long long count, int degree, const char* what) {
  if (count < static_cast<long long>(degree) + 1 || count > static_cast<long long>(tolerances::kMaxControlPoints)) {
    throw py::value_error(fmt::format("{} is {}, a B-spline of degree {} needs {}..{}", what, count, degree,
                                      degree + 1, tolerances::kMaxControlPoints));
  }
  return static_cast<std::size_t>(count);
}

/// A (lower, upper) pair as a finite, non-empty Interval.
Interval interval_from(const std::pair<double, double>& domain, const char* what) {
  if (!std::isfinite(domain.first) || !std::isfinite(domain.second) || !(domain.first < domain.second)) {
    throw py::value_error(
        fmt::format("{} ({}, {}) must be finite with lower < upper", what, domain.first, domain.second));
  }
  return {domain.first, domain.second};
}

/// Knots of a degree-p basis: 0 <= p <= kMaxBSplineDegree, at least 2p+2
/// finite, non-decreasing knots with a non-empty domain (validate_knots),
/// what the basis functions assume.
std::vector<double> basis_knots(const py::object& knots, int degree) {
  check_degree(degree);
  std::vector<double> values = values_from(knots, "knots");
  const std::size_t p = static_cast<std::size_t>(degree);
  if (values.size() < 2 * p + 2) {
    throw py::value_error(
        fmt::format("{} knots given, a basis of degree {} needs at least {}", values.size(), degree, 2 * p + 2));
  }
  unwrap(validate_knots(values, degree, values.size() - p - 1));
  return values;
}

/// A span index for basis_functions: p <= span <= n and t_span < t_{span+1}.
void check_span(const std::vector<double>& knots, int degree, int span) {
  const int n = static_cast<int>(knots.size()) - degree - 2;
  if (span < degree || span > n) {
    throw py::value_error(fmt::format("span {} is outside {}..{} (find_span gives the span of u)", span, degree, n));
  }
  const std::size_t s = static_cast<std::size_t>(span);
  if (!(knots[s] < knots[s + 1])) {
    throw py::value_error(fmt::format("span {} is empty (knot {} = knot {} = {}); find_span never returns an empty span",
                                      span, span, span + 1, knots[s]));
  }
}

/// Re-checks a curve built from projected homogeneous rows (coordinates may overflow).
BSplineCurve revalidated(const BSplineCurve& curve) {
  std::vector<double> weights(curve.weights().begin(), curve.weights().end());
  return unwrap(BSplineCurve::make(curve.degree(), std::vector<double>(curve.knots().begin(), curve.knots().end()),
                                   curve.control_points(), std::move(weights)));
}

std::string continuity_text(const Continuity& c) {
  return fmt::format("Continuity(parametric={}, tangent={})", c.parametric, c.tangent ? "True" : "False");
}

}  // namespace

void bind_bspline(py::module_& module) {
  // ---- knot vectors (knot_vector.hpp) ----
  module.def(
      "validate_knots",
      [](const py::object& knots, int degree, long long control_point_count) {
        check_degree(degree);
        const std::size_t count = checked_count(control_point_count, degree, "control_point_count");
        unwrap(validate_knots(values_from(knots, "knots"), degree, count));
      },
      py::arg("knots"), py::arg("degree"), py::arg("control_point_count"),
      "Checks the knots of a degree-p B-spline with n+1 control points (The NURBS Book §2.2, §3.2): n+p+2 finite, "
      "non-decreasing knots, multiplicities <= p+1, t_p < t_{n+1}. Returns None or raises ValueError naming the "
      "knot.");

  module.def(
      "clamped_uniform_knots",
      [](int degree, long long control_point_count, const std::pair<double, double>& domain) {
        check_degree(degree);
        const std::size_t count = checked_count(control_point_count, degree, "control_point_count");
        return to_numpy(clamped_uniform_knots(degree, count, interval_from(domain, "domain")));
      },
      py::arg("degree"), py::arg("control_point_count"), py::arg("domain") = std::make_pair(0.0, 1.0),
      "Clamped knots with uniform interior spacing over domain = (lower, upper): p+1 copies of each end (The "
      "NURBS Book eq. 2.13), as an (n+p+2,) array.");

  module.def(
      "uniform_knots",
      [](int degree, long long control_point_count, const std::pair<double, double>& domain) {
        check_degree(degree);
        const std::size_t count = checked_count(control_point_count, degree, "control_point_count");
        return to_numpy(uniform_knots(degree, count, interval_from(domain, "domain")));
      },
      py::arg("degree"), py::arg("control_point_count"), py::arg("domain") = std::make_pair(0.0, 1.0),
      "Uniform (cardinal, unclamped) knots whose domain [t_p, t_{n+1}] is `domain` (seed 001's uniform "
      "B-spline), as an (n+p+2,) array.");

  module.def(
      "periodic_knots",
      [](int degree, long long distinct_control_point_count, const std::pair<double, double>& domain) {
        check_degree(degree);
        if (distinct_control_point_count < 1 ||
            distinct_control_point_count > static_cast<long long>(tolerances::kMaxControlPoints)) {
          throw py::value_error(fmt::format("distinct_control_point_count is {}, it must be in 1..{}",
                                            distinct_control_point_count, tolerances::kMaxControlPoints));
        }
        return to_numpy(periodic_knots(degree, static_cast<std::size_t>(distinct_control_point_count),
                                       interval_from(domain, "domain")));
      },
      py::arg("degree"), py::arg("distinct_control_point_count"), py::arg("domain") = std::make_pair(0.0, 1.0),
      "The m + 2p + 1 uniform knots of a closed B-spline with m distinct control points over `domain` (see "
      "make_periodic).");

  module.def(
      "knots_from_rhino",
      [](const py::object& rhino_knots, int degree, long long control_point_count) {
        check_degree(degree);
        const std::size_t count = checked_count(control_point_count, degree, "control_point_count");
        return to_numpy(unwrap(knots_from_rhino(values_from(rhino_knots, "rhino_knots"), degree, count)));
      },
      py::arg("rhino_knots"), py::arg("degree"), py::arg("control_point_count"),
      "The full n+p+2 knots from the Rhino/openNURBS convention (n+p-1 knots, the outermost two dropped), "
      "validated; ValueError with indices of the Rhino vector.");

  module.def(
      "knot_multiplicities",
      [](const py::object& knots) {
        py::list result;
        for (const KnotMultiplicity& k : knot_multiplicities(values_from(knots, "knots"))) {
          result.append(py::make_tuple(k.value, k.multiplicity));
        }
        return result;
      },
      py::arg("knots"),
      "The distinct knot values in order with their multiplicities, as a list of (value, multiplicity) tuples "
      "(C++: KnotMultiplicity structs; exact comparison).");

  module.def(
      "multiplicity_of",
      [](const py::object& knots, double u) {
        check_finite_value(u, "u");
        return multiplicity_of(values_from(knots, "knots"), u);
      },
      py::arg("knots"), py::arg("u"), "How many knots equal u (0 if u is not a knot).");

  // ---- the basis (basis.hpp) ----
  module.def(
      "find_span",
      [](const py::object& knots, int degree, double u) {
        const std::vector<double> values = basis_knots(knots, degree);
        check_finite_value(u, "u");
        return find_span(values, degree, u);
      },
      py::arg("knots"), py::arg("degree"), py::arg("u"),
      "The non-empty span i with t_i <= u < t_{i+1}, p <= i <= n (The NURBS Book A2.1); the last non-empty span "
      "at the end of the domain, the first/last one below/above it. The knots are validated (ValueError).");

  module.def(
      "basis_functions",
      [](const py::object& knots, int degree, int span, double u) {
        const std::vector<double> values = basis_knots(knots, degree);
        check_span(values, degree, span);
        check_finite_value(u, "u");
        DoubleArray result(static_cast<py::ssize_t>(degree) + 1);
        basis_functions(values, degree, span, u, std::span<double>(result.mutable_data(), static_cast<std::size_t>(degree) + 1));
        return result;
      },
      py::arg("knots"), py::arg("degree"), py::arg("span"), py::arg("u"),
      "N_{span-p,p}(u) .. N_{span,p}(u), the p+1 non-zero basis functions, as a (p+1,) array (The NURBS Book "
      "A2.2). span: a non-empty span p <= span <= n (find_span).");

  module.def(
      "basis_function_derivatives",
      [](const py::object& knots, int degree, int span, double u, int order) {
        const std::vector<double> values = basis_knots(knots, degree);
        check_span(values, degree, span);
        check_finite_value(u, "u");
        if (order < 0 || order > tolerances::kMaxDerivativeOrder) {
          throw py::value_error(
              fmt::format("derivative order {} is outside 0..{}", order, tolerances::kMaxDerivativeOrder));
        }
        const std::size_t width = static_cast<std::size_t>(degree) + 1;
        DoubleArray result({static_cast<py::ssize_t>(order) + 1, static_cast<py::ssize_t>(width)});
        basis_function_derivatives(values, degree, span, u, order,
                                   std::span<double>(result.mutable_data(), (static_cast<std::size_t>(order) + 1) * width));
        return result;
      },
      py::arg("knots"), py::arg("degree"), py::arg("span"), py::arg("u"), py::arg("order"),
      "The non-zero basis functions and their derivatives up to `order` as an (order+1, p+1) array, row j the "
      "j-th derivatives (The NURBS Book A2.3; zero rows beyond p).");

  module.def(
      "basis_function",
      [](const py::object& knots, int degree, int index, const py::object& u) -> py::object {
        const std::vector<double> values = basis_knots(knots, degree);
        const int n = static_cast<int>(values.size()) - degree - 2;
        if (index < 0 || index > n) throw py::value_error(fmt::format("index {} is outside 0..{}", index, n));
        const DoubleArray parameters = as_double_array(u, "u");
        if (parameters.ndim() == 0) {
          check_finite_value(parameters.data()[0], "u");
          return py::float_(basis_function(values, degree, index, parameters.data()[0]));
        }
        const DoubleArray us = parameters_from(parameters, "u");
        const std::size_t k = static_cast<std::size_t>(us.shape(0));
        DoubleArray result(static_cast<py::ssize_t>(k));
        double* target = result.mutable_data();
        for_each_checked_chunk(std::span<const double>(us.data(), k), Interval{}, true, "u",
                               [&](std::span<const double> chunk, std::size_t offset) {
                                 for (std::size_t i = 0; i < chunk.size(); ++i) {
                                   target[offset + i] = basis_function(values, degree, index, chunk[i]);
                                 }
                               });
        return result;
      },
      py::arg("knots"), py::arg("degree"), py::arg("index"), py::arg("u"),
      "N_{index,p}(u) by its own triangle (The NURBS Book A2.4), zero outside [t_i, t_{i+p+1}] (no "
      "extrapolation: right for figures of the whole basis). u: a float (a float back) or a (k,) array (an "
      "array back, evaluated in C++).");

  // ---- bridges to the bezier layer and the homogeneous form (bspline_curve.hpp) ----
  module.def(
      "homogeneous_points", [](const BSplineCurve& curve) { return to_numpy(homogeneous_points(curve)); },
      py::arg("curve"),
      "The homogeneous control points (w_i P_i, w_i) as an (n+1, d+1) array, (P_i, 1) for a polynomial curve (The "
      "NURBS Book eq. 4.2).");

  module.def(
      "from_homogeneous",
      [](int degree, const py::object& knots, const py::object& points) {
        check_degree(degree);
        const PointArray rows = points_from(points, "points");
        const int d = rows.dimension() - 1;
        if (d < 1) throw py::value_error("points must have d+1 >= 2 columns, the last one the weight");
        const std::size_t count = checked_count(static_cast<long long>(rows.size()), degree, "the number of points");
        std::vector<double> knot_values = values_from(knots, "knots");
        unwrap(validate_knots(knot_values, degree, count));
        for (std::size_t i = 0; i < rows.size(); ++i) {
          const double w = rows[i][static_cast<std::size_t>(d)];
          if (!(w > 0.0)) throw py::value_error(fmt::format("weight {} is {}, weights must be > 0", i, w));
        }
        return revalidated(from_homogeneous(degree, std::move(knot_values), rows));
      },
      py::arg("degree"), py::arg("knots"), py::arg("points"),
      "The NURBS curve of degree p on `knots` whose homogeneous control points are the (n+1, d+1) array `points` "
      "(last column the weight, > 0; The NURBS Book §4.2).");

  module.def(
      "to_bspline", [](const BezierCurve& curve) { return to_bspline(curve); }, py::arg("curve"),
      "The same curve as a clamped B-spline of degree n on the knots 0^(n+1) 1^(n+1) (seed 001 §1.2.3).");

  module.def(
      "make_periodic",
      [](int degree, const py::object& control_points, const py::object& weights,
         const std::pair<double, double>& domain) {
        std::vector<double> weight_values;
        if (!weights.is_none()) weight_values = values_from(weights, "weights");
        return unwrap(make_periodic(degree, points_from(control_points, "control_points"), std::move(weight_values),
                                    Interval{domain.first, domain.second}));
      },
      py::arg("degree"), py::arg("control_points"), py::arg("weights") = py::none(),
      py::arg("domain") = std::make_pair(0.0, 1.0),
      "A closed uniform B-spline of degree p >= 1 through the polygon P_0..P_{m-1} taken cyclically (m >= p+1; "
      "control points P_0..P_{m-1}, P_0..P_{p-1} on periodic_knots): C(lower) = C(upper), C^(p-1) there.");

  // ---- knot insertion and removal (knot_insertion.hpp, knot_removal.hpp) ----
  module.def(
      "insert_knot",
      [](const BSplineCurve& curve, double u, int times) { return unwrap(insert_knot(curve, u, times)); },
      py::arg("curve"), py::arg("u"), py::arg("times") = 1,
      "The same curve with u inserted `times` times (Boehm; The NURBS Book A5.1 by the refinement A5.4; NURBS on "
      "the homogeneous points). ValueError for u outside the domain or a multiplicity above p+1.");

  module.def(
      "refine_knots",
      [](const BSplineCurve& curve, const py::object& new_knots) {
        return unwrap(refine_knots(curve, values_from(new_knots, "new_knots")));
      },
      py::arg("curve"), py::arg("new_knots"),
      "The same curve with every knot of the (r,) array new_knots inserted, any order (The NURBS Book A5.4).");

  py::class_<KnotRemoval>(module, "KnotRemoval",
                          "The result of remove_knot/remove_knots: the curve, how many knots went and the bound on "
                          "the change (The NURBS Book A5.8).")
      .def_readonly("curve", &KnotRemoval::curve, "The curve with the removable knots removed.")
      .def_readonly("removed", &KnotRemoval::removed, "How many knots were removed.")
      .def_readonly("error_bound", &KnotRemoval::error_bound,
                    "Guaranteed bound on max |C(u) - C_new(u)| over the domain (<= the tolerance).")
      .def("__repr__", [](const KnotRemoval& r) {
        return fmt::format("KnotRemoval(removed={}, error_bound={})", r.removed, r.error_bound);
      })
      .def(py::pickle([](const KnotRemoval& r) { return py::make_tuple(r.curve, r.removed, r.error_bound); },
                      [](const py::tuple& state) {
                        if (state.size() != 3) throw py::value_error("KnotRemoval pickle state must have 3 entries");
                        return KnotRemoval{state[0].cast<BSplineCurve>(), state[1].cast<int>(), state[2].cast<double>()};
                      }));

  module.def(
      "remove_knot",
      [](const BSplineCurve& curve, double u, int times, double tolerance) {
        return unwrap(remove_knot(curve, u, times, tolerance_from(tolerance, "tolerance")));
      },
      py::arg("curve"), py::arg("u"), py::arg("times"), py::arg("tolerance"),
      "Removes the interior knot u up to `times` times while the accumulated bound stays within `tolerance` (The "
      "NURBS Book A5.8; Tiller 1992), as a KnotRemoval object (curve, removed, error_bound).");

  module.def(
      "remove_knots",
      [](const BSplineCurve& curve, double tolerance) {
        return unwrap(remove_knots(curve, tolerance_from(tolerance, "tolerance")));
      },
      py::arg("curve"), py::arg("tolerance"),
      "Removes every removable interior knot within `tolerance` in total (A5.8 from left to right), as a "
      "KnotRemoval object (curve, removed, error_bound).");

  // ---- degree (degree.hpp) ----
  module.def(
      "elevate_degree",
      [](const BSplineCurve& curve, int times) { return unwrap(elevate_degree(curve, times)); }, py::arg("curve"),
      py::arg("times") = 1,
      "The same curve with degree p + times (The NURBS Book §5.5: Bézier pieces elevated, knots removed back; the "
      "result is clamped). ValueError for times < 0 or a size above the limits.");

  py::class_<BSplineDegreeReduction>(module, "BSplineDegreeReduction",
                                     "The result of reduce_degree(BSplineCurve, tolerance): the curve of degree p-1 "
                                     "and its guaranteed error bound.")
      .def_readonly("curve", &BSplineDegreeReduction::curve, "The curve of degree p - 1 (same domain, clamped).")
      .def_readonly("error_bound", &BSplineDegreeReduction::error_bound,
                    "Guaranteed bound on max |C(u) - R(u)| over the domain (<= the tolerance).")
      .def("__repr__", [](const BSplineDegreeReduction& r) {
        return fmt::format("BSplineDegreeReduction(degree={}, error_bound={})", r.curve.degree(), r.error_bound);
      })
      .def(py::pickle([](const BSplineDegreeReduction& r) { return py::make_tuple(r.curve, r.error_bound); },
                      [](const py::tuple& state) {
                        if (state.size() != 2) {
                          throw py::value_error("BSplineDegreeReduction pickle state must have 2 entries");
                        }
                        return BSplineDegreeReduction{state[0].cast<BSplineCurve>(), state[1].cast<double>()};
                      }));

  module.def(
      "reduce_degree",
      [](const BSplineCurve& curve, double tolerance) {
        return unwrap(reduce_degree(curve, tolerance_from(tolerance, "tolerance")));
      },
      py::arg("curve"), py::arg("tolerance"),
      "A B-spline of degree p-1 within `tolerance` (Eck's constrained least squares per Bézier piece, then "
      "remove_knots), as a BSplineDegreeReduction object (curve, error_bound). ValueError for degree < 2, a "
      "NURBS curve or a piece that cannot be reduced within the tolerance.");

  // ---- transformations (transform.hpp) ----
  module.def(
      "reversed", [](const BSplineCurve& curve) { return reversed(curve); }, py::arg("curve"),
      "The same curve traversed backwards on the same domain: C_r(u) = C(a + b - u) (The NURBS Book §6.1).");

  module.def(
      "reparameterized",
      [](const BSplineCurve& curve, const std::pair<double, double>& domain) {
        return unwrap(reparameterized(curve, Interval{domain.first, domain.second}));
      },
      py::arg("curve"), py::arg("domain"),
      "The same curve on the domain (c, d), knots mapped by the increasing affine map (The NURBS Book §6.1); "
      "domain is a (lower, upper) tuple where C++ takes an Interval.");

  module.def(
      "clamped", [](const BSplineCurve& curve) { return clamped(curve); }, py::arg("curve"),
      "The same curve with clamped knots on its domain (ends inserted to multiplicity p by A5.4, the outside "
      "dropped): it starts at its first control point and ends at its last.");

  module.def(
      "split_at",
      [](const BSplineCurve& curve, double u) {
        auto [first, second] = unwrap(split_at(curve, u));
        return py::make_tuple(std::move(first), std::move(second));
      },
      py::arg("curve"), py::arg("u"),
      "(first, second): the curve on [a, u] and on [u, b], both clamped (The NURBS Book §5.3); a tuple where C++ "
      "returns a pair. ValueError unless u is strictly inside the domain.");

  // ---- continuity and join (continuity.hpp, join.hpp) ----
  py::class_<Continuity>(module, "Continuity",
                         "The continuity measured at one parameter (The NURBS Book §2.2, P2.5): parametric C^k and "
                         "geometric G^1.")
      .def_readonly("parametric", &Continuity::parametric,
                    "The highest k <= p with derivatives 0..k agreeing from both sides; -1 for a jump.")
      .def_readonly("tangent", &Continuity::tangent, "G^1: continuous with equal unit tangents on both sides.")
      .def("__eq__", [](const Continuity& a, const Continuity& b) { return a == b; }, py::is_operator())
      .def("__repr__", &continuity_text)
      .def(py::pickle([](const Continuity& c) { return py::make_tuple(c.parametric, c.tangent); },
                      [](const py::tuple& state) {
                        if (state.size() != 2) throw py::value_error("Continuity pickle state must have 2 entries");
                        return Continuity{state[0].cast<int>(), state[1].cast<bool>()};
                      }));

  py::class_<KnotContinuity>(module, "KnotContinuity",
                             "One distinct interior knot: value, multiplicity m, predicted continuity p - m and the "
                             "measured Continuity.")
      .def_readonly("value", &KnotContinuity::value, "The knot value u.")
      .def_readonly("multiplicity", &KnotContinuity::multiplicity, "m, how many knots equal u.")
      .def_readonly("predicted", &KnotContinuity::predicted, "p - m, what the knots guarantee (-1: a jump).")
      .def_readonly("measured", &KnotContinuity::measured, "The Continuity the curve achieves at u.")
      .def("__eq__", [](const KnotContinuity& a, const KnotContinuity& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const KnotContinuity& k) {
        return fmt::format("KnotContinuity(value={}, multiplicity={}, predicted={}, measured={})", k.value,
                           k.multiplicity, k.predicted, continuity_text(k.measured));
      })
      .def(py::pickle(
          [](const KnotContinuity& k) { return py::make_tuple(k.value, k.multiplicity, k.predicted, k.measured); },
          [](const py::tuple& state) {
            if (state.size() != 4) throw py::value_error("KnotContinuity pickle state must have 4 entries");
            return KnotContinuity{state[0].cast<double>(), state[1].cast<int>(), state[2].cast<int>(),
                                  state[3].cast<Continuity>()};
          }));

  module.def(
      "continuity_at",
      [](const BSplineCurve& curve, double u) {
        check_finite_value(u, "u");
        const Interval domain = curve.domain();
        if (!(domain.lower < u && u < domain.upper)) {
          throw py::value_error(fmt::format("u = {} is not strictly inside the domain [{}, {}]", u, domain.lower,
                                            domain.upper));
        }
        return continuity_at(curve, u);
      },
      py::arg("curve"), py::arg("u"),
      "The continuity at u, derivatives from the left and right spans compared order by order (The NURBS Book "
      "A2.3), as a Continuity object. u strictly inside the domain.");

  module.def(
      "continuity_at_knots", [](const BSplineCurve& curve) { return continuity_at_knots(curve); }, py::arg("curve"),
      "continuity_at for every distinct interior knot, in increasing order, as a list of KnotContinuity.");

  py::class_<JoinResult>(module, "JoinResult",
                         "The result of join: the joined curve, the continuity at the joint, its parameter and the "
                         "gap that was closed.")
      .def_readonly("curve", &JoinResult::curve, "first then second as one curve.")
      .def_readonly("continuity", &JoinResult::continuity, "The Continuity measured at the joint.")
      .def_readonly("joint", &JoinResult::joint, "The parameter of the joint (the end of the first domain).")
      .def_readonly("gap", &JoinResult::gap, "Distance between the end of the first and the start of the second.")
      .def("__repr__", [](const JoinResult& r) {
        return fmt::format("JoinResult(joint={}, gap={}, continuity={})", r.joint, r.gap, continuity_text(r.continuity));
      })
      .def(py::pickle(
          [](const JoinResult& r) { return py::make_tuple(r.curve, r.continuity, r.joint, r.gap); },
          [](const py::tuple& state) {
            if (state.size() != 4) throw py::value_error("JoinResult pickle state must have 4 entries");
            return JoinResult{state[0].cast<BSplineCurve>(), state[1].cast<Continuity>(), state[2].cast<double>(),
                              state[3].cast<double>()};
          }));

  module.def(
      "join", [](const BSplineCurve& first, const BSplineCurve& second) { return unwrap(join(first, second)); },
      py::arg("first"), py::arg("second"),
      "first followed by second as one curve (degrees equalized, the joint a knot of multiplicity p at the "
      "midpoint of the two ends; The NURBS Book §5.3 read backwards), as a JoinResult object. ValueError when "
      "the curves do not meet.");

  // ---- Bézier pieces (bezier_pieces.hpp) ----
  py::class_<BezierPieces>(module, "BezierPieces",
                           "Bézier pieces with their parameter intervals: piece i on [breakpoints[i], "
                           "breakpoints[i+1]] (The NURBS Book §5.4).")
      .def(py::init([](const py::object& breakpoints, const std::vector<BezierCurve>& pieces) {
             return BezierPieces{values_from(breakpoints, "breakpoints"), pieces};
           }),
           py::arg("breakpoints"), py::arg("pieces"),
           "From m+1 breakpoints and m BezierCurve pieces (checked by from_bezier_pieces / to_piecewise_bezier).")
      .def_property_readonly("breakpoints", [](const BezierPieces& b) { return to_numpy(b.breakpoints); },
                             "b_0 < ... < b_m as an (m+1,) array.")
      .def_property_readonly("pieces", [](const BezierPieces& b) { return b.pieces; },
                             "The m pieces, a list of BezierCurve, each on [0, 1] in its own parameter.")
      .def("__len__", [](const BezierPieces& b) { return b.pieces.size(); })
      .def("__eq__", [](const BezierPieces& a, const BezierPieces& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const BezierPieces& b) { return fmt::format("BezierPieces({} pieces)", b.pieces.size()); })
      .def(py::pickle([](const BezierPieces& b) { return py::make_tuple(to_numpy(b.breakpoints), b.pieces); },
                      [](const py::tuple& state) {
                        if (state.size() != 2) throw py::value_error("BezierPieces pickle state must have 2 entries");
                        return BezierPieces{values_from(state[0], "breakpoints"),
                                            state[1].cast<std::vector<BezierCurve>>()};
                      }));

  module.def(
      "to_bezier_pieces", [](const BSplineCurve& curve) { return to_bezier_pieces(curve); }, py::arg("curve"),
      "The Bézier pieces of the curve on its domain, one per non-empty span, degree p, rational for NURBS (The "
      "NURBS Book A5.6), as a BezierPieces object.");

  module.def(
      "to_bezier_pieces", [](const PiecewiseBezierCurve& curve) { return to_bezier_pieces(curve); },
      py::arg("curve"), "The pieces of a piecewise Bézier curve with breakpoints 0, 1, ..., m.");

  module.def(
      "to_piecewise_bezier",
      [](const BezierPieces& pieces) { return unwrap(PiecewiseBezierCurve::make(pieces.pieces)); }, py::arg("pieces"),
      "The pieces as a PiecewiseBezierCurve (piece i on [i, i+1]: same shape, uniform parameterization per "
      "piece). ValueError for no piece or pieces of different dimensions.");

  module.def(
      "from_bezier_pieces", [](const BezierPieces& pieces) { return unwrap(from_bezier_pieces(pieces)); },
      py::arg("pieces"),
      "The B-spline with the same pieces (lower degrees elevated, joints knots of multiplicity p, rational pieces "
      "rescaled to agree; The NURBS Book §5.4 read backwards). ValueError names the bad breakpoint, piece or "
      "joint.");
}

}  // namespace casteljau::python
