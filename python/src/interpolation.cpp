// The interpolation layer in Python (include/casteljau/interpolation/*.hpp):
// parameter values, the C¹ Bézier interpolant, Catmull–Rom, Hermite and
// Ferguson, Lagrange in barycentric form, natural splines, the cubic spline
// and any-degree B-spline interpolation, and least-squares / smoothing /
// tolerance fits. Enums are strings read by the C++ *_from_name functions
// (their ValueError lists the names); structs of options are keyword
// arguments. Also here, though they belong to the bspline layer
// (include/casteljau/bspline/hodograph.hpp): derivative_curve,
// antiderivative_curve and integral, which the scipy-like BSpline's
// derivative / antiderivative / integrate are built on.
//
// Constructions take copies of the inputs (PointArray) and run without the GIL.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/bspline/hodograph.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/interpolation/c1_bezier.hpp"
#include "casteljau/interpolation/catmull_rom.hpp"
#include "casteljau/interpolation/fit.hpp"
#include "casteljau/interpolation/hermite.hpp"
#include "casteljau/interpolation/lagrange.hpp"
#include "casteljau/interpolation/natural_spline.hpp"
#include "casteljau/interpolation/parameterization.hpp"
#include "casteljau/interpolation/spline_interpolation.hpp"

namespace casteljau::python {

namespace {

/// Python's closed=True as the library's Closure.
Closure closure_of(bool closed) { return closed ? Closure::closed : Closure::open; }

/// The parameterization a Python string names (ValueError for another).
Parameterization parameterization_from(const std::string& name) { return unwrap(parameterization_from_name(name)); }

FitEnds fit_ends_from(const std::string& name) {
  if (name == "interpolated") return FitEnds::interpolated;
  if (name == "free") return FitEnds::free;
  throw py::value_error(fmt::format("unknown fit ends '{}', expected interpolated or free", name));
}

/// A weighted fit's weights from Python: None (empty: all 1) or one per
/// point (ValueError for an empty array; the library checks the rest).
std::vector<double> weights_from(const py::object& weights) {
  if (weights.is_none()) return {};
  std::vector<double> w = values_from(weights, "weights");
  if (w.empty()) throw py::value_error("weights is empty, give one weight per point or None");
  return w;
}

/// A count given from Python as a signed integer, checked >= 0.
std::size_t count_from(long long value, const char* what) {
  if (value < 0) throw py::value_error(fmt::format("{} is {}, it must be >= 0", what, value));
  return static_cast<std::size_t>(value);
}

/// An optional d-vector (None: empty).
Point vector_from(const py::object& object, const std::string& what) {
  if (object.is_none()) return {};
  return values_from(object, what);
}

/// One (at_end, order, value) entry of interpolate_bspline's derivatives:
/// at_end a bool or "start" / "end".
EndDerivative end_derivative_from(const py::handle& item, std::size_t index) {
  const std::string what = fmt::format("derivatives[{}]", index);
  if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) || py::len(item) != 3) {
    throw py::type_error(what + " must be a tuple (at_end, order, value): at_end a bool or 'start' / 'end'");
  }
  const py::sequence entry = py::reinterpret_borrow<py::sequence>(item);
  EndDerivative derivative;
  const py::object where = entry[0];
  if (py::isinstance<py::str>(where)) {
    const std::string name = where.cast<std::string>();
    if (name != "start" && name != "end")
      throw py::value_error(fmt::format("{}: end '{}' is neither 'start' nor 'end'", what, name));
    derivative.at_end = name == "end";
  } else if (py::isinstance<py::bool_>(where)) {
    derivative.at_end = where.cast<bool>();
  } else {
    throw py::type_error(what + ": at_end must be a bool or 'start' / 'end'");
  }
  derivative.order = entry[1].cast<int>();
  derivative.value = values_from(entry[2], what + " value");
  return derivative;
}

DoubleArray errors_array(const BSplineFit& fit) { return to_numpy(std::span<const double>(fit.errors)); }

bool same_fit(const BSplineFit& a, const BSplineFit& b) {
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return a.curve == b.curve && a.errors == b.errors && a.max_error == b.max_error && a.worst_point == b.worst_point &&
         a.rms_error == b.rms_error && a.smoothing == b.smoothing &&
         a.effective_degrees_of_freedom == b.effective_degrees_of_freedom && same(a.gcv_score, b.gcv_score) &&
         a.smoothing_from_gcv == b.smoothing_from_gcv;
}

void bind_lagrange(py::module_& module) {
  py::class_<BarycentricInterpolant>(
      module, "BarycentricInterpolant",
      "The polynomial of degree <= n through (t_j, P_j) in barycentric form (Berrut & Trefethen, SIAM Review 46(3), "
      "2004): nodes t_0 < ... < t_n, weights w_j (max |w_j| = 1), values P_j. Built by interpolate_lagrange (no "
      "constructor of its own: the weights are computed, not given).")
      .def_property_readonly("nodes", [](const BarycentricInterpolant& b) { return to_numpy(std::span<const double>(b.nodes)); },
                             "t_0 .. t_n (a new array).")
      .def_property_readonly("weights", [](const BarycentricInterpolant& b) { return to_numpy(std::span<const double>(b.weights)); },
                             "w_0 .. w_n, scaled so that max |w_j| = 1 (a new array).")
      .def_property_readonly("values", [](const BarycentricInterpolant& b) { return to_numpy(b.values); },
                             "P_0 .. P_n as an (n+1, d) array (a new array).")
      .def_property_readonly("degree", [](const BarycentricInterpolant& b) { return static_cast<int>(b.nodes.size()) - 1; },
                             "n, the degree bound (number of nodes - 1).")
      .def_property_readonly("dimension", [](const BarycentricInterpolant& b) { return b.values.dimension(); },
                             "d, the number of coordinates.")
      .def_property_readonly("domain", [](const BarycentricInterpolant& b) {
             const Interval domain = b.domain();
             return py::make_tuple(domain.lower, domain.upper);
           }, "(t_0, t_n) (BarycentricInterpolant::domain()).")
      .def("__eq__", [](const BarycentricInterpolant& a, const BarycentricInterpolant& b) { return a == b; },
           py::is_operator())
      .def("__repr__", [](const BarycentricInterpolant& b) {
        const Interval domain = b.domain();
        return fmt::format("BarycentricInterpolant(degree={}, {} nodes in [{}, {}], values in R^{})", b.nodes.size() - 1,
                           b.nodes.size(), domain.lower, domain.upper, b.values.dimension());
      })
      .def(py::pickle(
          [](const BarycentricInterpolant& b) {
            return py::make_tuple(to_numpy(std::span<const double>(b.nodes)), to_numpy(b.values));
          },
          [](const py::tuple& state) {
            if (state.size() != 2) throw py::value_error("BarycentricInterpolant pickle state must have 2 entries");
            // The weights are a deterministic function of the nodes: recomputed.
            return unwrap(interpolate_lagrange(points_from(state[1], "values"), values_from(state[0], "nodes")));
          }));

  module.def(
      "interpolate_lagrange",
      [](const py::object& points, const py::object& parameters) {
        PointArray values = points_from(points, "points");
        std::vector<double> nodes = values_from(parameters, "parameters");
        return unwrap(without_gil([&] { return interpolate_lagrange(values, nodes); }));
      },
      py::arg("points"), py::arg("parameters"),
      "The polynomial of degree <= n through (t_j, P_j) in barycentric form (Berrut & Trefethen 2004, eq. 3.2, 4.2; "
      "the closed-form weights for chebyshev_parameters nodes, eq. 5.4). points (n+1, d), parameters (n+1,) strictly "
      "increasing.");

  module.def(
      "chebyshev_parameters",
      [](long long count, std::pair<double, double> domain) {
        return to_numpy(std::span<const double>(
            unwrap(chebyshev_parameters(count_from(count, "count"), Interval{domain.first, domain.second}))));
      },
      py::arg("count"), py::arg("domain") = std::make_pair(0.0, 1.0),
      "Chebyshev points of the second kind on [a, b], increasing, ends included: (a+b)/2 + (b-a)/2 sin(pi (2j-n)/(2n)) "
      "(Trefethen, Approximation Theory and Approximation Practice, ch. 2). domain: a tuple (a, b).");

  module.def(
      "domain_of",
      [](const BarycentricInterpolant& interpolant) {
        const Interval domain = interpolant.domain();
        return py::make_tuple(domain.lower, domain.upper);
      },
      py::arg("interpolant"), "(t_0, t_n), the interval the interpolant was built on (a tuple).");

  module.def(
      "point_at",
      [](const BarycentricInterpolant& interpolant, double t, bool extrapolate) {
        const double one[1] = {t};
        for_each_checked_chunk(std::span<const double>(one), interpolant.domain(), extrapolate, "t",
                               [](std::span<const double>, std::size_t) {});
        const Point point = point_at(interpolant, t);
        return to_numpy(std::span<const double>(point));
      },
      py::arg("interpolant"), py::arg("t"), py::kw_only(), py::arg("extrapolate") = false,
      "p(t), a (d,) array, by the second (true) barycentric formula (Berrut & Trefethen 2004, eq. 4.2); exactly P_j "
      "at t = t_j. t must lie in the domain unless extrapolate=True (the polynomial continued).");

  module.def(
      "points_at",
      [](const BarycentricInterpolant& interpolant, const py::object& ts, const py::object& out, bool extrapolate) {
        return evaluate_batch(parameters_from(ts, "ts"), static_cast<std::size_t>(interpolant.values.dimension()),
                              out, interpolant.domain(), extrapolate, "ts",
                              [&](std::span<const double> chunk, std::span<double> target) {
                                points_at(interpolant, chunk, target);
                              });
      },
      py::arg("interpolant"), py::arg("ts"), py::kw_only(), py::arg("out") = py::none(), py::arg("extrapolate") = false,
      "p(t) for every t of the (k,) array ts, as a (k, d) array (the barycentric formula in C++, the GIL released). "
      "out: an optional (k, d) C-contiguous float64 array to write into.");

  module.def(
      "to_bezier",
      [](const BarycentricInterpolant& interpolant) {
        return unwrap(without_gil([&] { return to_bezier(interpolant); }));
      },
      py::arg("interpolant"),
      "The same polynomial as a Bézier curve of degree n on [t_0, t_n] mapped to [0, 1] (Bernstein–Vandermonde "
      "system at Chebyshev points, LU with two refinement steps); degrees above 40 are refused (the Bernstein basis "
      "is ill-conditioned: Farouki, CAGD 8, 1991).");
}

void bind_fit(py::module_& module) {
  py::class_<BSplineFit>(module, "BSplineFit",
                         "A fitted B-spline with what it achieved (fit.hpp): errors are |C(t_i) - P_i| at each point's "
                         "own parameter (The NURBS Book §9.4.1; Craven & Wahba 1979 for GCV).")
      .def_readonly("curve", &BSplineFit::curve, "The fitted curve (clamped, domain [t_0, t_m]).")
      .def_property_readonly("errors", &errors_array, "|C(t_i) - P_i| for every point (a new array).")
      .def_readonly("max_error", &BSplineFit::max_error, "max_i errors[i].")
      .def_readonly("worst_point", &BSplineFit::worst_point, "An i where errors[i] = max_error.")
      .def_readonly("rms_error", &BSplineFit::rms_error, "sqrt(sum errors[i]^2 / (m+1)).")
      .def_readonly("smoothing", &BSplineFit::smoothing, "lambda of the penalty (0 for plain least squares).")
      .def_readonly("effective_degrees_of_freedom", &BSplineFit::effective_degrees_of_freedom,
                    "tr H, the trace of the hat matrix (Hutchinson & de Hoog 1985 for smoothing fits).")
      .def_readonly("gcv_score", &BSplineFit::gcv_score,
                    "GCV(lambda) (Craven & Wahba 1979, eq. 1.3, summed over the coordinates); NaN when tr H = m+1.")
      .def_readonly("smoothing_from_gcv", &BSplineFit::smoothing_from_gcv, "True when lambda was chosen by GCV.")
      .def("__eq__", &same_fit, py::is_operator())
      .def("__repr__", [](const BSplineFit& f) {
        return fmt::format("BSplineFit({} control points, degree {}, max_error={}, rms_error={}, smoothing={}{})",
                           f.curve.control_points().size(), f.curve.degree(), f.max_error, f.rms_error, f.smoothing,
                           f.smoothing_from_gcv ? " (gcv)" : "");
      })
      .def(py::pickle(
          [](const BSplineFit& f) {
            return py::make_tuple(f.curve, errors_array(f), f.max_error, f.worst_point, f.rms_error, f.smoothing,
                                  f.effective_degrees_of_freedom, f.gcv_score, f.smoothing_from_gcv);
          },
          [](const py::tuple& state) {
            if (state.size() != 9) throw py::value_error("BSplineFit pickle state must have 9 entries");
            BSplineFit fit{state[0].cast<BSplineCurve>(), values_from(state[1], "errors")};
            fit.max_error = state[2].cast<double>();
            fit.worst_point = state[3].cast<std::size_t>();
            fit.rms_error = state[4].cast<double>();
            fit.smoothing = state[5].cast<double>();
            fit.effective_degrees_of_freedom = state[6].cast<double>();
            fit.gcv_score = state[7].cast<double>();
            fit.smoothing_from_gcv = state[8].cast<bool>();
            return fit;
          }));

  module.def(
      "approximation_knots",
      [](const py::object& parameters, int degree, long long control_point_count) {
        const std::vector<double> t = values_from(parameters, "parameters");
        const std::size_t count = count_from(control_point_count, "control_point_count");
        if (degree < 1 || degree > tolerances::kMaxBSplineDegree)
          throw py::value_error(fmt::format("degree {} is outside 1..{}", degree, tolerances::kMaxBSplineDegree));
        if (count < static_cast<std::size_t>(degree) + 1 || count > t.size()) {
          throw py::value_error(fmt::format("control_point_count {} is outside {}..{} (degree + 1 .. the number of "
                                            "parameters)", count, degree + 1, t.size()));
        }
        for (std::size_t i = 1; i < t.size(); ++i) {
          if (!(t[i - 1] < t[i]))
            throw py::value_error(fmt::format("parameters must increase strictly: parameter {} is {}, parameter {} is {}",
                                              i, t[i], i - 1, t[i - 1]));
        }
        return to_numpy(std::span<const double>(approximation_knots(t, degree, count)));
      },
      py::arg("parameters"), py::arg("degree"), py::arg("control_point_count"),
      "The knots of a least-squares fit with n+1 control points of degree p (The NURBS Book eq. 9.68-9.69): p+1 copies "
      "of t_0 and t_m and interior knots that put a parameter in every span. ValueError for the C++ preconditions.");

  module.def(
      "fit_least_squares",
      [](const py::object& points, const py::object& parameters, int degree, long long control_point_count,
         const std::string& ends) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        const std::size_t count = count_from(control_point_count, "control_point_count");
        const FitEnds fit_ends = fit_ends_from(ends);
        return unwrap(without_gil([&] { return fit_least_squares(data, t, degree, count, fit_ends); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("degree"), py::arg("control_point_count"),
      py::arg("ends") = "interpolated",
      "The least-squares B-spline of degree p with control_point_count control points on approximation_knots (The "
      "NURBS Book §9.4.1, A9.7's system): minimizes sum |C(t_i) - P_i|^2. ends: 'interpolated' (C(t_0) = P_0, "
      "C(t_m) = P_m) or 'free' (scipy's make_lsq_spline). Returns a BSplineFit.");

  module.def(
      "fit_least_squares_on_knots",
      [](const py::object& points, const py::object& parameters, int degree, const py::object& knots,
         const py::object& weights, const std::string& ends) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        std::vector<double> u = values_from(knots, "knots");
        const std::vector<double> w = weights_from(weights);
        const FitEnds fit_ends = fit_ends_from(ends);
        return unwrap(without_gil([&] { return fit_least_squares_on_knots(data, t, degree, std::move(u), w, fit_ends); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("degree"), py::arg("knots"), py::arg("weights") = py::none(),
      py::arg("ends") = "free",
      "The weighted least-squares B-spline of degree p on the given knots (The NURBS Book §9.4.1 with §9.4.4's "
      "weights; de Boor, A Practical Guide to Splines, ch. XIV): minimizes sum w_i |C(t_i) - P_i|^2. weights: None "
      "(all 1) or one w_i >= 0 per point; scipy's make_lsq_spline(t, P, knots, k=p, w=s) is weights = s**2 (scipy "
      "squares its weights with the residual). ends: 'free' (the default here) or 'interpolated' (knots clamped at t_0 "
      "and t_m). ValueError names a Schoenberg–Whitney violation. Returns a BSplineFit.");

  module.def(
      "fit_smoothing",
      [](const py::object& points, const py::object& parameters, int degree, long long control_point_count,
         std::optional<double> smoothing, const std::string& ends, const py::object& weights) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        SmoothingOptions options;
        options.degree = degree;
        options.control_point_count = count_from(control_point_count, "control_point_count");
        options.smoothing = smoothing;
        options.ends = fit_ends_from(ends);
        options.weights = weights_from(weights);
        return unwrap(without_gil([&] { return fit_smoothing(data, t, options); }));
      },
      py::arg("points"), py::arg("parameters"), py::kw_only(), py::arg("degree") = 3,
      py::arg("control_point_count") = 0, py::arg("smoothing") = py::none(), py::arg("ends") = "free",
      py::arg("weights") = py::none(),
      "The B-spline minimizing sum w_i |C(t_i) - P_i|^2 + lambda int |C''|^2 (Reinsch 1967; lambda by GCV, Craven & "
      "Wahba 1979, when smoothing is None). The fields of the C++ SmoothingOptions are keyword arguments: degree >= 2, "
      "control_point_count (0: a knot at every interior parameter, the smoothing spline itself), smoothing (lambda "
      ">= 0 or None), ends ('free' or 'interpolated'), weights (None: all 1, or one w_i >= 0 per point, not "
      "squared). With degree 3, 0 control points and free ends it equals scipy's make_smoothing_spline(t, y, w=w, "
      "lam=lambda) per coordinate (GCV weighs the residuals as the fit does; scipy 1.10's GCV leaves them "
      "unweighted). Returns a BSplineFit.");

  module.def(
      "fit_to_tolerance",
      [](const py::object& points, const py::object& parameters, int degree, double tolerance, const std::string& ends) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        const Tolerance wanted = tolerance_from(tolerance, "tolerance");
        const FitEnds fit_ends = fit_ends_from(ends);
        return unwrap(without_gil([&] { return fit_to_tolerance(data, t, degree, wanted, fit_ends); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("degree"), py::arg("tolerance"), py::arg("ends") = "interpolated",
      "Least squares refined (spans with errors above the tolerance split at the middle of their points) until every "
      "|C(t_i) - P_i| <= tolerance (The NURBS Book §9.4.1 fits, Schoenberg–Whitney checked). ValueError when it "
      "cannot be reached. Returns a BSplineFit.");
}

}  // namespace

void bind_interpolation(py::module_& module) {
  // ---- parameterization.hpp ----
  module.def(
      "parameterization_from_name",
      [](const std::string& name) { return std::string(name_of(parameterization_from(name))); },
      py::arg("name"),
      "The canonical name ('uniform', 'chord', 'centripetal') of a parameterization name (also 'chord-length'); "
      "ValueError lists the names. (C++ returns the enum; Python uses the names.)");

  module.def(
      "parameter_values",
      [](const py::object& points, const std::string& kind, bool closed) {
        const PointArray data = points_from(points, "points");
        return to_numpy(std::span<const double>(unwrap(parameter_values(data, parameterization_from(kind), closure_of(closed)))));
      },
      py::arg("points"), py::arg("kind"), py::arg("closed") = false,
      "Normalized parameter values 0 = t_0 < ... = 1 with steps |P_{i+1} - P_i|^e, e = 0, 1, 1/2 for kind 'uniform', "
      "'chord', 'centripetal' (The NURBS Book eq. 9.4-9.6; Lee 1989). closed: one more value for the closing step.");

  module.def(
      "function_parameters",
      [](const py::object& points) {
        const PointArray data = points_from(points, "points");
        return to_numpy(std::span<const double>(unwrap(function_parameters(data))));
      },
      py::arg("points"),
      "The first coordinate of each point as its parameter (a function y(x)): x must increase strictly, points need "
      "at least 2 coordinates. Not normalized.");

  module.def(
      "without_closing_duplicate",
      [](const py::object& points) { return to_numpy(without_closing_duplicate(points_from(points, "points"))); },
      py::arg("points"),
      "The points without a last point that repeats the first (within tolerances::kJointRelativeGap of the scale), "
      "for closed curves; other points unchanged (a new (n, d) array).");

  // ---- c1_bezier.hpp ----
  module.def(
      "interpolate_c1_bezier",
      [](const py::object& points, double alpha, bool closed) {
        const PointArray data = points_from(points, "points");
        return unwrap(interpolate_c1_bezier(data, alpha, closure_of(closed)));
      },
      py::arg("points"), py::arg("alpha") = 1.0, py::arg("closed") = false,
      "Seed 000's C1 interpolant: cubic Bézier pieces P_i, Q_i, R_i, P_{i+1} on [i, i+1] with tangents "
      "(P_{i+1} - P_{i-1})/alpha (alpha = 2: uniform Catmull–Rom). closed: the cyclic extension. A PiecewiseBezierCurve.");

  // ---- catmull_rom.hpp ----
  module.def(
      "interpolate_catmull_rom",
      [](const py::object& points, const py::object& parameters, bool closed) {
        const PointArray data = points_from(points, "points");
        const std::vector<double> t = values_from(parameters, "parameters");
        return unwrap(interpolate_catmull_rom(data, t, closure_of(closed)));
      },
      py::arg("points"), py::arg("parameters"), py::arg("closed") = false,
      "The Catmull–Rom spline through the points at the parameters (uniform, chord or centripetal from "
      "parameter_values; Yuksel, Schaefer & Keyser, CAD 43(7), 2011; Barry & Goldman 1988) as a C1 cubic B-spline. "
      "closed: parameters has one more value, for the return to P_0.");

  // ---- hermite.hpp ----
  module.def(
      "ferguson_curve",
      [](const py::object& start, const py::object& start_tangent, const py::object& end, const py::object& end_tangent) {
        return unwrap(ferguson_curve(values_from(start, "start"), values_from(start_tangent, "start_tangent"),
                                     values_from(end, "end"), values_from(end_tangent, "end_tangent")));
      },
      py::arg("start"), py::arg("start_tangent"), py::arg("end"), py::arg("end_tangent"),
      "Ferguson's cubic (seed 001; Farin §7.1): C(0) = start, C'(0) = start_tangent, C(1) = end, C'(1) = end_tangent, "
      "as a BezierCurve with control points P0, P0 + T0/3, P1 - T1/3, P1. Each argument a (d,) array.");

  module.def(
      "interpolate_hermite",
      [](const py::object& points, const py::object& tangents, const py::object& parameters, bool closed) {
        const PointArray data = points_from(points, "points");
        const PointArray slopes = points_from(tangents, "tangents");
        const std::vector<double> t = values_from(parameters, "parameters");
        return unwrap(interpolate_hermite(data, slopes, t, closure_of(closed)));
      },
      py::arg("points"), py::arg("tangents"), py::arg("parameters"), py::arg("closed") = false,
      "The C1 piecewise cubic with C(t_i) = P_i and C'(t_i) = T_i (scipy's CubicHermiteSpline in parametric form; "
      "Farin §7.1) as a cubic B-spline with double interior knots. tangents (n, d) like points.");

  // ---- lagrange.hpp ----
  bind_lagrange(module);

  // ---- natural_spline.hpp ----
  module.def(
      "interpolate_natural",
      [](const py::object& points, const py::object& parameters, int order) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        return unwrap(without_gil([&] { return interpolate_natural(data, t, order); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("order"),
      "The natural spline of order q (degree 2q-1, minimizing int |s^(q)|^2; de Boor, A Practical Guide to Splines, "
      "ch. XIII; Schoenberg 1964) through the points, as a clamped B-spline with a knot at each interior parameter.");

  // ---- spline_interpolation.hpp ----
  module.def(
      "end_condition_from_name",
      [](const std::string& name) { return std::string(name_of(unwrap(end_condition_from_name(name)))); },
      py::arg("name"),
      "The canonical name ('natural', 'clamped', 'not-a-knot', 'periodic') of an end condition name (also "
      "'not_a_knot'); ValueError lists the names. (C++ returns the enum; Python uses the names.)");

  module.def(
      "interpolate_cubic",
      [](const py::object& points, const py::object& parameters, const std::string& ends,
         const py::object& start_tangent, const py::object& end_tangent) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        CubicEnds cubic_ends;
        cubic_ends.condition = unwrap(end_condition_from_name(ends));
        const bool clamped = cubic_ends.condition == EndCondition::clamped;
        if (!clamped && (!start_tangent.is_none() || !end_tangent.is_none()))
          throw py::value_error("start_tangent and end_tangent are for clamped ends only, ends is '" + ends + "'");
        if (clamped && (start_tangent.is_none() || end_tangent.is_none()))
          throw py::value_error("clamped ends need start_tangent and end_tangent");
        cubic_ends.start_tangent = vector_from(start_tangent, "start_tangent");
        cubic_ends.end_tangent = vector_from(end_tangent, "end_tangent");
        return unwrap(without_gil([&] { return interpolate_cubic(data, t, cubic_ends); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("ends") = "not-a-knot", py::kw_only(),
      py::arg("start_tangent") = py::none(), py::arg("end_tangent") = py::none(),
      "The C2 cubic B-spline through the points (de Boor, A Practical Guide to Splines, ch. IV), equal to scipy's "
      "make_interp_spline(t, P, k=3, bc_type=...): ends 'natural', 'clamped' (with start_tangent and end_tangent, "
      "(d,) derivatives with respect to t), 'not-a-knot' or 'periodic' (parameters has one more value, for the "
      "return to P_0). The C++ CubicEnds struct as keyword arguments.");

  module.def(
      "interpolate_bspline",
      [](const py::object& points, const py::object& parameters, int degree, const py::object& derivatives) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        std::vector<EndDerivative> ends;
        if (!derivatives.is_none()) {
          std::size_t index = 0;
          for (const py::handle item : derivatives) ends.push_back(end_derivative_from(item, index++));
        }
        return unwrap(without_gil([&] { return interpolate_bspline(data, t, degree, ends); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("degree"), py::arg("derivatives") = py::none(),
      "The B-spline of degree p through the points on knots averaging the parameters (The NURBS Book eq. 9.8, A9.1; "
      "with end derivatives §9.2.2, eq. 9.22). derivatives: a sequence of (at_end, order, value) tuples, at_end a "
      "bool or 'start' / 'end', value a (d,) array (the C++ EndDerivative).");

  module.def(
      "interpolate_on_knots",
      [](const py::object& points, const py::object& parameters, int degree, const py::object& knots,
         const py::object& derivatives) {
        PointArray data = points_from(points, "points");
        std::vector<double> t = values_from(parameters, "parameters");
        std::vector<double> u = values_from(knots, "knots");
        std::vector<EndDerivative> ends;
        if (!derivatives.is_none()) {
          std::size_t index = 0;
          for (const py::handle item : derivatives) ends.push_back(end_derivative_from(item, index++));
        }
        return unwrap(without_gil([&] { return interpolate_on_knots(data, t, degree, std::move(u), ends); }));
      },
      py::arg("points"), py::arg("parameters"), py::arg("degree"), py::arg("knots"), py::arg("derivatives") = py::none(),
      "The B-spline of degree p on the given knots through the points, with optional end derivatives, by collocation "
      "(The NURBS Book §9.2.1 eq. 9.10, §9.2.2; de Boor, A Practical Guide to Splines, ch. XIII): scipy's "
      "make_interp_spline(t, P, k=p, t=knots, bc_type=...). len(knots) = len(points) + len(derivatives) + p + 1, the "
      "parameters run from knots[p] to knots[-p-1]; ValueError names a Schoenberg–Whitney violation. derivatives as "
      "for interpolate_bspline: (at_end, order, value) tuples.");

  // ---- fit.hpp ----
  bind_fit(module);

  // ---- bspline/hodograph.hpp (bspline layer, bound here: see the file comment) ----
  module.def(
      "derivative_curve",
      [](const BSplineCurve& curve, int order) { return unwrap(derivative_curve(curve, order)); },
      py::arg("curve"), py::arg("order") = 1,
      "C^(k) as a B-spline curve of degree p-k on the knots without the k first and last (The NURBS Book eq. 3.8, "
      "A3.3, as FITPACK's splder); knots of basis functions that vanish are dropped (scipy raises there), k > p gives "
      "the zero curve of degree 0. Polynomial curves only (ValueError for NURBS).");

  module.def(
      "antiderivative_curve",
      [](const BSplineCurve& curve, int order) { return unwrap(antiderivative_curve(curve, order)); },
      py::arg("curve"), py::arg("order") = 1,
      "The k-th antiderivative as a B-spline curve of degree p+k, each end knot once more per order, control points "
      "by cumulative sums (de Boor, A Practical Guide to Splines, ch. X; FITPACK's splantider): A(u) = integral from "
      "t_0 of the full B-spline sum, so A(t_p) = 0 on clamped knots. Polynomial curves only.");

  module.def(
      "integral",
      [](const BSplineCurve& curve, double a, double b) {
        const Point value = unwrap(integral(curve, a, b));
        return to_numpy(std::span<const double>(value));
      },
      py::arg("curve"), py::arg("a"), py::arg("b"),
      "The integral of C(u) du from a to b, a (d,) array, as A(b) - A(a) with A = antiderivative_curve (scipy's "
      "BSpline.integrate with extrapolate=True: outside the domain the end pieces continue). Polynomial curves only.");
}

}  // namespace casteljau::python
