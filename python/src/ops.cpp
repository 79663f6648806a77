// The ops layer in Python: curve flattening within a tolerance
// (ops/flatten.hpp), triangle meshes (TriangleMesh, mesh_topology) and the
// tessellation of surfaces of any kind into one mesh (ops/tessellate.hpp).
// Tolerances are floats checked by tolerance_from; the long computations
// run without the GIL.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "casteljau/ops/arc_spline.hpp"
#include "casteljau/ops/bounds.hpp"
#include "casteljau/ops/closest_among_curves.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/curvature_extrema.hpp"
#include "casteljau/ops/inflections.hpp"
#include "casteljau/ops/intersection.hpp"
#include "casteljau/ops/intersections_among_curves.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/ops/mesh.hpp"
#include "casteljau/ops/point_inversion.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau::python {

namespace {

/// An (n, 3) array of finite coordinates (n >= 0) as a PointArray of dimension 3.
PointArray points3_from(const py::handle& object, const std::string& what) {
  const DoubleArray array = as_double_array(object, what);
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw py::value_error(fmt::format("{} must be an (n, 3) array, got shape {}", what, shape_text(array)));
  }
  const double* data = array.data();
  const std::size_t size = static_cast<std::size_t>(array.size());
  for (std::size_t k = 0; k < size; ++k) {
    if (!std::isfinite(data[k])) {
      throw py::value_error(
          fmt::format("{}[{}, {}] is {}", what, k / 3, k % 3, std::isnan(data[k]) ? "NaN" : "infinite"));
    }
  }
  if (size == 0) return PointArray::zeros(3, 0);
  return unwrap(PointArray::make(3, std::vector<double>(data, data + size), what.c_str()));
}

/// An (m, 3) array of integer vertex indices, each in [0, vertex_count).
std::vector<std::array<std::uint32_t, 3>> triangles_from(const py::handle& object, std::size_t vertex_count) {
  const py::array array = py::array::ensure(object);
  if (!array) throw py::type_error("triangles is not convertible to an array of integers");
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::type_error(fmt::format("triangles has dtype {}, expected integers", std::string(py::str(array.dtype()))));
  }
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw py::value_error(fmt::format("triangles must be an (m, 3) array of vertex indices, got shape {}",
                                      shape_text(array)));
  }
  if (static_cast<std::size_t>(array.shape(0)) > tolerances::kMaxMeshTriangles) {
    throw py::value_error(fmt::format("triangles has {} rows, more than the limit {}", array.shape(0),
                                      tolerances::kMaxMeshTriangles));
  }
  // uint64 values above int64's range would wrap: compare before casting.
  if (kind == 'u' && array.dtype().itemsize() == 8) {
    const auto wide = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    for (py::ssize_t k = 0; k < wide.size(); ++k) {
      if (wide.data()[k] >= vertex_count) {
        throw py::value_error(fmt::format("triangles[{}, {}] is {}, outside the {} vertices", k / 3, k % 3,
                                          wide.data()[k], vertex_count));
      }
    }
  }
  const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
  std::vector<std::array<std::uint32_t, 3>> triangles(static_cast<std::size_t>(indices.shape(0)));
  const std::int64_t* data = indices.data();
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::size_t c = 0; c < 3; ++c) {
      const std::int64_t index = data[3 * t + c];
      if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
        throw py::value_error(
            fmt::format("triangles[{}, {}] is {}, outside the {} vertices (indices start at 0)", t, c, index, vertex_count));
      }
      triangles[t][c] = static_cast<std::uint32_t>(index);
    }
  }
  return triangles;
}

TriangleMesh make_mesh(const py::object& vertices, const py::object& normals, const py::object& triangles) {
  TriangleMesh mesh;
  mesh.vertices = points3_from(vertices, "vertices");
  mesh.normals = points3_from(normals, "normals");
  if (mesh.normals.size() != mesh.vertices.size()) {
    throw py::value_error(fmt::format("normals has {} rows, vertices has {}: one normal per vertex",
                                      mesh.normals.size(), mesh.vertices.size()));
  }
  if (mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw py::value_error("vertices has more than 2^32 - 1 rows, beyond 32-bit indices");
  }
  mesh.triangles = triangles_from(triangles, mesh.vertices.size());
  return mesh;
}

DoubleArray points3_to_numpy(const PointArray& points) {
  DoubleArray array({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(3)});
  const std::span<const double> source = points.coordinates();
  if (!source.empty()) std::memcpy(array.mutable_data(), source.data(), source.size() * sizeof(double));
  return array;
}

py::array_t<std::int64_t> triangles_to_numpy(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  py::array_t<std::int64_t> array({static_cast<py::ssize_t>(triangles.size()), static_cast<py::ssize_t>(3)});
  std::int64_t* target = array.mutable_data();
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::size_t c = 0; c < 3; ++c) target[3 * t + c] = triangles[t][c];
  return array;
}

bool same_mesh(const TriangleMesh& a, const TriangleMesh& b) {
  return a.vertices == b.vertices && a.normals == b.normals && a.triangles == b.triangles;
}

/// A surface object (any kind) as a view; the object must outlive it.
SurfaceView view_of(const py::handle& object, std::size_t index) {
  if (py::isinstance<BSplineSurface>(object)) return SurfaceView(object.cast<const BSplineSurface&>());
  if (py::isinstance<BezierSurface>(object)) return SurfaceView(object.cast<const BezierSurface&>());
  if (py::isinstance<CoonsPatch>(object)) return SurfaceView(object.cast<const CoonsPatch&>());
  throw py::type_error(fmt::format("surfaces[{}] is a {}, expected a BSplineSurface, BezierSurface or CoonsPatch",
                                   index, std::string(py::str(py::type::of(object).attr("__name__")))));
}

void check_unit_parameter(double t, const char* what) {
  if (!std::isfinite(t) || t < 0.0 || t > 1.0) {
    throw py::value_error(fmt::format("{} is {}, it must lie in [0, 1]", what, t));
  }
}

/// flatten's result, computed without the GIL, as (points, parameters).
template <class Compute>
py::tuple polyline_tuple(Compute&& compute) {
  Expected<Polyline> line = Error{};
  {
    py::gil_scoped_release release;
    line = compute();
  }
  Polyline polyline = unwrap(std::move(line));
  return py::make_tuple(to_numpy(polyline.points), to_numpy(std::span<const double>(polyline.parameters)));
}

template <class T>
struct KindTag {
  using type = T;
};

/// f(KindTag<Kind>{}) for each of the curve kinds Kinds.
template <class... Kinds, class F>
void for_curve_kinds(F&& f) {
  (f(KindTag<Kinds>{}), ...);
}

/// The tolerance argument of the arc-length functions: None for the default
/// (1e-12 of the curve's size), else a distance checked as tolerance_from does.
Tolerance arc_length_tolerance(CurveView curve, const py::object& tolerance) {
  if (tolerance.is_none()) return default_arc_length_tolerance(curve);
  return Tolerance{tolerance.cast<double>()};
}

/// Any curve object as a view (the object must outlive it); TypeError otherwise.
CurveView curve_of(const py::handle& object, const char* what) {
  if (py::isinstance<BezierCurve>(object)) return CurveView(object.cast<const BezierCurve&>());
  if (py::isinstance<PiecewiseBezierCurve>(object)) return CurveView(object.cast<const PiecewiseBezierCurve&>());
  if (py::isinstance<BSplineCurve>(object)) return CurveView(object.cast<const BSplineCurve&>());
  throw py::type_error(fmt::format("{} is a {}, expected a BezierCurve, PiecewiseBezierCurve or BSplineCurve", what,
                                   std::string(py::str(py::type::of(object).attr("__name__")))));
}

/// A list of curve objects as views (the objects must outlive them);
/// TypeError naming curves[k] for one that is not a curve.
std::vector<CurveView> curves_of(const py::sequence& curves) {
  std::vector<CurveView> views;
  for (std::size_t k = 0; k < curves.size(); ++k)
    views.push_back(curve_of(curves[k], fmt::format("curves[{}]", k).c_str()));
  return views;
}

/// The intersections as a list of dicts shaped like the CLI's JSON.
py::list intersection_list(const std::vector<CurveIntersection>& found) {
  py::list result;
  for (const CurveIntersection& x : found) {
    py::dict item;
    item["kind"] = kind_name(x.kind);
    if (x.kind == IntersectionKind::overlap) {
      item["a"] = py::make_tuple(x.a.lower, x.a.upper);
      item["b"] = py::make_tuple(x.b.lower, x.b.upper);
    } else {
      item["a"] = x.a.lower;
      item["b"] = x.b.lower;
      item["point"] = to_numpy(x.point);
      item["multiplicity"] = x.multiplicity;
    }
    result.append(item);
  }
  return result;
}

Tolerance intersection_tolerance(CurveView a, CurveView b, const py::object& tolerance) {
  if (tolerance.is_none()) return default_intersection_tolerance(a, b);
  return tolerance_from(tolerance.cast<double>(), "tolerance");
}

}  // namespace

void bind_ops(py::module_& module) {
  // --- flattening --------------------------------------------------------------
  module.def(
      "flatten",
      [](const BezierCurve& curve, double tolerance, const py::object& max_segments) {
        const Tolerance checked = tolerance_from(tolerance, "tolerance");
        long cap = tolerances::kMaxFlattenSegments;
        if (!max_segments.is_none()) {
          cap = max_segments.cast<long>();
          if (cap < 1 || cap > tolerances::kMaxFlattenSegments) {
            throw py::value_error(fmt::format("max_segments is {}, it must lie in 1..{}", cap,
                                              tolerances::kMaxFlattenSegments));
          }
        }
        return polyline_tuple([&] { return flatten(curve, checked, cap); });
      },
      py::arg("curve"), py::arg("tolerance"), py::arg("max_segments") = py::none(),
      "A polyline through points of the Bézier curve within `tolerance` of it (Hausdorff distance, certified "
      "by chord_deviation_bound; docs/flattening.md), as a tuple (points (m+1, d), parameters (m+1,)) with "
      "parameters 0 = t_0 < ... < t_m = 1 (the C++ returns a Polyline). max_segments: an optional cap (ValueError, "
      "not a truncated polyline, when more are needed). The GIL is released.");

  // Every other curve kind: its Bézier pieces flattened and joined (flatten on CurveView).
  for_curve_kinds<PiecewiseBezierCurve, BSplineCurve>([&module](auto kind) {
    using Kind = typename decltype(kind)::type;
    module.def(
        "flatten",
        [](const Kind& curve, double tolerance) {
          const Tolerance checked = tolerance_from(tolerance, "tolerance");
          return polyline_tuple([&] { return flatten(CurveView(curve), checked); });
        },
        py::arg("curve"), py::arg("tolerance"),
        "A polyline within `tolerance` of the curve: its Bézier pieces flattened as above and joined, as (points "
        "(m+1, d), parameters (m+1,)) on the curve's own parameters (ops/flatten.hpp).");
  });

  // --- arc length (ops/arc_length.hpp), on every curve kind ----------------------
  for_curve_kinds<BezierCurve, PiecewiseBezierCurve, BSplineCurve>([&module](auto kind) {
    using Kind = typename decltype(kind)::type;
    module.def(
        "arc_length",
        [](const Kind& curve, const py::object& tolerance, const py::object& start, const py::object& end) {
          const CurveView view(curve);
          const Tolerance accuracy = arc_length_tolerance(view, tolerance);
          const Interval domain = view.domain();
          const Interval range{start.is_none() ? domain.lower : start.cast<double>(),
                               end.is_none() ? domain.upper : end.cast<double>()};
          return unwrap(without_gil([&] { return arc_length(view, range, accuracy); }));
        },
        py::arg("curve"), py::arg("tolerance") = py::none(), py::kw_only(), py::arg("start") = py::none(),
        py::arg("end") = py::none(),
        "The arc length of the curve (or between the parameters start and end), within the absolute tolerance "
        "(default 1e-12 of the curve's size): adaptive Gauss-Kronrod quadrature on its Bézier pieces, the accuracy "
        "met, not estimated (ops/arc_length.hpp). ValueError for a tolerance not > 0 or below 1e-14 of the size, a "
        "range outside the domain or backwards. The GIL is released.");
    module.def(
        "bounding_box",
        [](const Kind& curve) {
          const Box box = bounding_box(CurveView(curve));
          return py::make_tuple(to_numpy(box.lower), to_numpy(box.upper));
        },
        py::arg("curve"),
        "The tight axis-aligned box of the curve as (lower (d,), upper (d,)): its end points and the points where a "
        "coordinate's derivative vanishes (roots in Bernstein form), not the control polygon's box.");
    module.def(
        "inflection_parameters",
        [](const Kind& curve) {
          return to_numpy(std::span<const double>(unwrap(inflection_parameters(CurveView(curve)))));
        },
        py::arg("curve"),
        "The parameters where a plane curve's signed curvature changes sign, increasing, as a (k,) array (roots of "
        "det[A, A', A''] per Bézier piece; flat points excluded). ValueError unless d == 2.");
    module.def(
        "curvature_extrema",
        [](const Kind& curve) {
          const std::vector<CurvatureExtremum> found = unwrap(curvature_extrema(CurveView(curve)));
          std::vector<double> parameters, curvatures;
          py::array_t<bool> maxima(static_cast<py::ssize_t>(found.size()));
          auto flags = maxima.mutable_unchecked<1>();
          for (std::size_t i = 0; i < found.size(); ++i) {
            parameters.push_back(found[i].parameter);
            curvatures.push_back(found[i].curvature);
            flags(static_cast<py::ssize_t>(i)) = found[i].maximum;
          }
          return py::make_tuple(to_numpy(std::span<const double>(parameters)),
                                to_numpy(std::span<const double>(curvatures)), maxima);
        },
        py::arg("curve"),
        "The local extrema of |curvature| inside the domain as (parameters (k,), curvatures (k,), maximum (k,) "
        "bool): roots of the numerator of dkappa/dt per Bezier piece, junctions where the curvature is continuous "
        "included, the ends, inflections and cusps not (ops/curvature_extrema.hpp). Curvatures are signed in the "
        "plane. ValueError for a curve in R^1.");
    module.def(
        "cusp_parameters",
        [](const Kind& curve) {
          return to_numpy(std::span<const double>(unwrap(cusp_parameters(CurveView(curve)))));
        },
        py::arg("curve"),
        "The parameters of the cusps inside the domain, increasing, as a (k,) array: where the velocity vanishes "
        "and the tangent turns back, or where the tangents on the two sides of a junction are opposite "
        "(ops/curvature_extrema.hpp). ValueError for a curve in R^1.");
    module.def(
        "closest_point",
        [](const Kind& curve, const py::object& point) {
          const std::vector<double> query = values_from(point, "point");
          const NearestPoint nearest = unwrap(closest_point(CurveView(curve), query));
          return py::make_tuple(nearest.parameter, nearest.distance, to_numpy(nearest.point));
        },
        py::arg("curve"), py::arg("point"),
        "The nearest point of the curve to `point` (d,): a tuple (parameter, distance, point (d,)), the global "
        "minimum over the closed domain, ends and knots included; ties to the lowest parameter "
        "(ops/closest_point.hpp). ValueError for a point of another dimension or not finite.");
    module.def(
        "closest_points",
        [](const Kind& curve, const py::object& points) {
          const PointArray queries = points_from(points, "points");
          if (queries.dimension() != curve.dimension())
            throw py::value_error(fmt::format("points has {} columns, the curve lives in R^{}", queries.dimension(),
                                              curve.dimension()));
          std::vector<double> parameters(queries.size()), distances(queries.size());
          unwrap(without_gil([&] { return closest_points(CurveView(curve), queries.coordinates(), parameters, distances); }));
          return py::make_tuple(to_numpy(std::span<const double>(parameters)), to_numpy(std::span<const double>(distances)));
        },
        py::arg("curve"), py::arg("points"),
        "closest_point for each row of `points` (n, d), as (parameters (n,), distances (n,)); each answer starts "
        "from the previous one's bound, so sorted or clustered queries run fastest. The GIL is released.");
    module.def(
        "local_closest_points",
        [](const Kind& curve, const py::object& point) {
          const std::vector<double> query = values_from(point, "point");
          const std::vector<NearestPoint> minima = unwrap(local_closest_points(CurveView(curve), query));
          std::vector<double> parameters, distances, coordinates;
          for (const NearestPoint& m : minima) {
            parameters.push_back(m.parameter);
            distances.push_back(m.distance);
            coordinates.insert(coordinates.end(), m.point.begin(), m.point.end());
          }
          return py::make_tuple(to_numpy(std::span<const double>(parameters)), to_numpy(std::span<const double>(distances)),
                                to_numpy(PointArray::from_trusted(curve.dimension(), std::move(coordinates))));
        },
        py::arg("curve"), py::arg("point"),
        "Every local minimum of the distance from `point` along the curve, the global one first, then by "
        "parameter: (parameters (k,), distances (k,), points (k, d)). Ends count when the distance grows away "
        "from them, corners when it falls into them from both sides.");
    module.def(
        "parameter_at_length",
        [](const Kind& curve, double length, const py::object& tolerance) {
          const CurveView view(curve);
          const Tolerance accuracy = arc_length_tolerance(view, tolerance);
          return unwrap(without_gil([&] { return parameter_at_length(view, length, accuracy); }));
        },
        py::arg("curve"), py::arg("length"), py::arg("tolerance") = py::none(),
        "The parameter at which the length from the start of the domain is `length` (0 <= length <= the curve's "
        "length), within the tolerance in length. ValueError otherwise.");
    module.def(
        "equal_arc_length_parameters",
        [](const Kind& curve, long long count, const py::object& tolerance) {
          const CurveView view(curve);
          const Tolerance accuracy = arc_length_tolerance(view, tolerance);
          if (count < 2) throw py::value_error(fmt::format("count is {}, it must be at least 2", count));
          auto parameters = without_gil(
              [&] { return equal_arc_length_parameters(view, static_cast<std::size_t>(count), accuracy); });
          return to_numpy(std::span<const double>(unwrap(std::move(parameters))));
        },
        py::arg("curve"), py::arg("count"), py::arg("tolerance") = py::none(),
        "count parameters, the ends of the domain included, whose points are equally spaced along the curve "
        "(each length within the tolerance), as a (count,) array: points_at(curve, these) resamples it.");
  });

  // --- point inversion (ops/point_inversion.hpp), every surface kind -------------
  for_curve_kinds<BSplineSurface, BezierSurface, CoonsPatch>([&module](auto kind) {
    using Kind = typename decltype(kind)::type;
    module.def(
        "closest_point",
        [](const Kind& surface, const py::object& point) {
          const std::vector<double> query = values_from(point, "point");
          const SurfaceNearestPoint nearest = unwrap(closest_point(SurfaceView(surface), query));
          return py::make_tuple(nearest.u, nearest.v, nearest.distance, to_numpy(nearest.point));
        },
        py::arg("surface"), py::arg("point"),
        "Point inversion: the point of the surface nearest to `point` (d,), as (u, v, distance, point (d,)): Newton "
        "from the samples of a grid along the knot lines that may be nearest, borders, poles and seams included "
        "(ops/point_inversion.hpp). ValueError for a point of another dimension or not finite.");
  });

  // --- intersections (ops/intersection.hpp), any pair of curve kinds ------------
  module.def(
      "intersections",
      [](const py::object& a, const py::object& b, const py::object& tolerance) {
        const CurveView first = curve_of(a, "a"), second = curve_of(b, "b");
        const Tolerance accuracy = intersection_tolerance(first, second, tolerance);
        return intersection_list(unwrap(without_gil([&] { return intersections(first, second, accuracy); })));
      },
      py::arg("a"), py::arg("b"), py::arg("tolerance") = py::none(),
      "The intersections of two curves of any kinds (both plane, or both in space: there where they pass within "
      "the tolerance), sorted by the parameter on a, as a list of dicts: "
      "{'kind': 'transversal'|'tangent', 'a', 'b', 'point' (d,), 'multiplicity'} for points, {'kind': 'overlap', "
      "'a': (a0, a1), 'b': (b(a0), b(a1))} for shared stretches (ops/intersection.hpp). tolerance: the distance "
      "within which the curves meet (default 1e-9 of the larger size). ValueError for curves of two dimensions "
      "or in R^1, and where they run along one another about the tolerance apart, so that the search cannot "
      "settle (the message names where).");
  module.def(
      "closest_among_curves",
      [](const py::sequence& curves, const py::object& points) {
        const std::vector<CurveView> views = curves_of(curves);
        const PointArray queries = points_from(points, "points");
        const auto answers = unwrap(without_gil([&] { return closest_among_curves(views, queries.coordinates()); }));
        py::array_t<std::int64_t> which(static_cast<py::ssize_t>(answers.size()));
        std::vector<double> parameters, distances;
        for (std::size_t i = 0; i < answers.size(); ++i) {
          which.mutable_data()[i] = static_cast<std::int64_t>(answers[i].curve);
          parameters.push_back(answers[i].nearest.parameter);
          distances.push_back(answers[i].nearest.distance);
        }
        return py::make_tuple(which, to_numpy(std::span<const double>(parameters)),
                              to_numpy(std::span<const double>(distances)));
      },
      py::arg("curves"), py::arg("points"),
      "For each row of `points` (n, d), the nearest point of all the curves (a drawing's), as (curve indices (n,), "
      "parameters (n,) on those curves, distances (n,)); the lowest index where two curves are as near. Curves "
      "are measured nearest bounding box first (ops/closest_among_curves.hpp). ValueError for curves of different "
      "dimensions, points of another, or none. The GIL is released.");
  module.def(
      "intersections_among_curves",
      [](const py::sequence& curves, const py::object& tolerance) {
        const std::vector<CurveView> views = curves_of(curves);
        const std::optional<Tolerance> given =
            tolerance.is_none() ? std::nullopt : std::optional{tolerance_from(tolerance.cast<double>(), "tolerance")};
        auto found = unwrap(without_gil([&] { return intersections_among_curves(views, given); }));
        std::vector<CurveIntersection> intersections;
        for (const IntersectionAmongCurves& x : found) intersections.push_back(x.intersection);
        py::list result = intersection_list(intersections);
        for (std::size_t i = 0; i < found.size(); ++i) {
          result[i]["curve_a"] = found[i].a;
          result[i]["curve_b"] = found[i].b;
        }
        return result;
      },
      py::arg("curves"), py::arg("tolerance") = py::none(),
      "Every intersection among the curves (a drawing's) and of each with itself, as intersections() reports "
      "them with 'curve_a' <= 'curve_b' (their indices; equal for a self-intersection), sorted by curve_a, "
      "curve_b and the parameter on curve_a. tolerance: the same for every pair, or each pair's default (1e-9 of "
      "the larger size). A sweep over the curves' boxes picks the pairs (ops/intersections_among_curves.hpp).");
  module.def(
      "self_intersections",
      [](const py::object& curve, const py::object& tolerance) {
        const CurveView view = curve_of(curve, "curve");
        const Tolerance accuracy = intersection_tolerance(view, view, tolerance);
        return intersection_list(unwrap(without_gil([&] { return self_intersections(view, accuracy); })));
      },
      py::arg("curve"), py::arg("tolerance") = py::none(),
      "The self-intersections of a curve (plane or in space; a < b, both on it), as intersections() reports "
      "them; the joints of its pieces and the seam of a closed curve are not self-intersections, nor is a cusp. "
      "ValueError where it runs back along itself about the tolerance apart (the message names where).");

  module.def(
      "fit_arcs",
      [](const py::object& curve, double tolerance) {
        const CurveView view = curve_of(curve, "curve");
        const Tolerance checked = tolerance_from(tolerance, "tolerance");
        const ArcSpline spline = unwrap(without_gil([&] { return fit_arcs(view, checked); }));
        DoubleArray segments({static_cast<py::ssize_t>(spline.segments.size()), py::ssize_t{5}});
        double* row = segments.mutable_data();
        for (const ArcSegment& s : spline.segments) {
          for (const double x : {s.start[0], s.start[1], s.end[0], s.end[1], s.bulge}) *row++ = x;
        }
        py::dict result;
        result["segments"] = segments;
        result["parameters"] = to_numpy(std::span<const double>(spline.parameters));
        result["deviation_bound"] = spline.deviation_bound;
        return result;
      },
      py::arg("curve"), py::arg("tolerance"),
      "A plane curve as a chain of circular arcs and line segments within `tolerance` of it (certified biarcs, "
      "tangent where the curve is smooth; ops/arc_spline.hpp, docs/cnc.md), as a dict: 'segments' (n, 5), each "
      "row x0, y0, x1, y1, bulge (tan(sweep / 4), > 0 counterclockwise, 0 for a line; DXF's bulge), each "
      "segment starting where the one before ends; 'parameters' (n + 1,), the curve's parameter at each "
      "segment's start and at the end; 'deviation_bound', the largest certified distance (<= tolerance). "
      "ValueError for a curve not in the plane or a tolerance not > 0. The GIL is released.");

  module.def(
      "flatten_segment_count",
      [](const BezierCurve& curve, double tolerance) {
        const Tolerance checked = tolerance_from(tolerance, "tolerance");
        Expected<long> count = Error{};
        {
          py::gil_scoped_release release;
          count = flatten_segment_count(curve, checked);
        }
        return unwrap(std::move(count));
      },
      py::arg("curve"), py::arg("tolerance"),
      "The number of segments flatten() produces for this curve and tolerance, without building the polyline.");

  module.def(
      "control_polygon_flatness", [](const BezierCurve& curve) { return control_polygon_flatness(curve); },
      py::arg("curve"),
      "A certified upper bound on the distance from the curve to its chord [C(0), C(1)]: the largest distance from "
      "a control point to that segment (convex hull property).");

  module.def(
      "chord_deviation_bound",
      [](const BezierCurve& curve, double t0, double t1) {
        check_unit_parameter(t0, "t0");
        check_unit_parameter(t1, "t1");
        if (!(t0 < t1)) throw py::value_error(fmt::format("t0 = {} must be smaller than t1 = {}", t0, t1));
        return chord_deviation_bound(curve, t0, t1);
      },
      py::arg("curve"), py::arg("t0"), py::arg("t1"),
      "A certified upper bound on the distance from C restricted to [t0, t1] (0 <= t0 < t1 <= 1) to the segment "
      "[C(t0), C(t1)] (exact for plane cubics, convex hull of the halves otherwise; docs/flattening.md).");

  // --- meshes ------------------------------------------------------------------
  py::class_<TriangleMesh>(module, "TriangleMesh",
                           "An indexed triangle mesh in R^3 with one unit normal per vertex: the output of "
                           "tessellate and the input of the OBJ, STL and PLY writers. Triangles are "
                           "counter-clockwise seen from the side the normals point to.")
      .def(py::init(&make_mesh), py::arg("vertices"), py::arg("normals"), py::arg("triangles"),
           "A mesh from vertices (n, 3), normals (n, 3), both finite, and triangles (m, 3) of integer vertex indices "
           "in [0, n). ValueError names the bad entry; TypeError for non-integer triangles.")
      .def_property_readonly("vertices", [](const TriangleMesh& m) { return points3_to_numpy(m.vertices); },
                             "Vertex positions, an (n, 3) array (a new array).")
      .def_property_readonly("normals", [](const TriangleMesh& m) { return points3_to_numpy(m.normals); },
                             "One unit normal per vertex, an (n, 3) array (a new array).")
      .def_property_readonly("triangles", [](const TriangleMesh& m) { return triangles_to_numpy(m.triangles); },
                             "Vertex indices, an (m, 3) int64 array (a new array).")
      .def("__eq__", [](const TriangleMesh& a, const TriangleMesh& b) { return same_mesh(a, b); }, py::is_operator())
      .def("__repr__",
           [](const TriangleMesh& m) {
             return fmt::format("TriangleMesh({} vertices, {} triangles)", m.vertices.size(), m.triangles.size());
           })
      .def(py::pickle(
          [](const TriangleMesh& m) {
            return py::make_tuple(points3_to_numpy(m.vertices), points3_to_numpy(m.normals),
                                  triangles_to_numpy(m.triangles));
          },
          [](const py::tuple& state) {
            if (state.size() != 3) throw py::value_error("TriangleMesh pickle state must have 3 entries");
            return make_mesh(state[0], state[1], state[2]);
          }));

  py::class_<MeshTopology>(module, "MeshTopology",
                           "How the triangles of a mesh meet along their edges (mesh_topology's counts).")
      .def_readonly("boundary_edges", &MeshTopology::boundary_edges, "Edges used by exactly one triangle.")
      .def_readonly("non_manifold_edges", &MeshTopology::non_manifold_edges, "Edges used by three or more triangles.")
      .def_readonly("inconsistently_oriented_edges", &MeshTopology::inconsistently_oriented_edges,
                    "Edges used twice with the same orientation.")
      .def_readonly("degenerate_triangles", &MeshTopology::degenerate_triangles,
                    "Triangles with two equal vertex indices or zero area.")
      .def_property_readonly("watertight", &MeshTopology::watertight,
                             "True when closed and edge-manifold: there are triangles, every edge has exactly two, "
                             "used in opposite directions, and no triangle is degenerate.")
      .def("__eq__",
           [](const MeshTopology& a, const MeshTopology& b) {
             return a.boundary_edges == b.boundary_edges && a.non_manifold_edges == b.non_manifold_edges &&
                    a.inconsistently_oriented_edges == b.inconsistently_oriented_edges &&
                    a.degenerate_triangles == b.degenerate_triangles;
           },
           py::is_operator())
      .def("__repr__", [](const MeshTopology& t) {
        return fmt::format("MeshTopology(boundary_edges={}, non_manifold_edges={}, inconsistently_oriented_edges={}, "
                           "degenerate_triangles={}, watertight={})",
                           t.boundary_edges, t.non_manifold_edges, t.inconsistently_oriented_edges,
                           t.degenerate_triangles, t.watertight() ? "True" : "False");
      });

  module.def(
      "mesh_topology",
      [](const TriangleMesh& mesh) {
        py::gil_scoped_release release;
        return mesh_topology(mesh);
      },
      py::arg("mesh"),
      "Counts the mesh's boundary, non-manifold and inconsistently oriented edges and degenerate triangles (an "
      "edge map, O(t log t)), as a MeshTopology.");

  module.def(
      "tessellate",
      [](const py::object& surfaces, double tolerance) {
        const Tolerance checked = tolerance_from(tolerance, "tolerance");
        // The objects are held here for the whole call: the views point into them.
        std::vector<py::object> held;
        const bool one = py::isinstance<BSplineSurface>(surfaces) || py::isinstance<BezierSurface>(surfaces) ||
                         py::isinstance<CoonsPatch>(surfaces);
        if (one) {
          held.push_back(surfaces);
        } else {
          if (py::isinstance<py::str>(surfaces) || !py::isinstance<py::iterable>(surfaces)) {
            throw py::type_error("surfaces must be a surface (BSplineSurface, BezierSurface, CoonsPatch) or a "
                                 "sequence of them");
          }
          for (const py::handle item : surfaces) held.push_back(py::reinterpret_borrow<py::object>(item));
        }
        std::vector<SurfaceView> views;
        views.reserve(held.size());
        for (std::size_t k = 0; k < held.size(); ++k) views.push_back(view_of(held[k], k));
        Expected<TriangleMesh> mesh = Error{};
        {
          py::gil_scoped_release release;
          mesh = tessellate(views, checked);
        }
        return unwrap(std::move(mesh));
      },
      py::arg("surfaces"), py::arg("tolerance"),
      "A TriangleMesh of the surfaces (one surface of any kind, or a sequence of them, all in R^3) within "
      "`tolerance` of them, watertight across shared boundaries and seams (adaptive quadtree per patch, "
      "docs/surfaces.md). Normals are the surfaces' unit normals. The GIL is released.");
}

}  // namespace casteljau::python
