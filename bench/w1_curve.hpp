#pragma once
// W1's curve (shared/docs/performance.md), shared by the workloads that use
// it (W1/W2 evaluation, W7 closest point, W9 arc length; W7 and W9 also on the xy plane): a cubic B-spline in
// 3D with 1000 control points drawn uniformly in [0,100)^3 from a fixed
// splitmix64 stream, on the clamped uniform knots of [0,1]; and the same
// curve as the peers hold it (OpenCASCADE's Geom_BSplineCurve with its
// arrays, SISL's SISLCurve), built once per process.
#include <cstddef>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "support/splitmix.hpp"

#if defined(CASTELJAU_HAVE_OCCT)
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#endif

#if defined(CASTELJAU_HAVE_SISL)
#include <sisl.h>
#endif

namespace casteljau::bench {

inline constexpr int kW1Degree = 3;
inline constexpr std::size_t kW1ControlPoints = 1000;
inline constexpr double kW1Scale = 100.0;

/// The control points, row-major (kW1ControlPoints x 3).
inline std::vector<double> w1_control_points() {
  test::SplitMix random{20261122u};
  std::vector<double> control(kW1ControlPoints * 3);
  for (double& x : control) x = kW1Scale * random.unit();
  return control;
}

/// The curve itself.
inline BSplineCurve w1_curve() {
  return BSplineCurve::from_trusted(kW1Degree, clamped_uniform_knots(kW1Degree, kW1ControlPoints),
                                    PointArray::from_trusted(3, w1_control_points()));
}

/// W1's curve with its z dropped: the plane B-spline (same degree and knots)
/// that the plane-only workloads (W7 and W9 on the xy plane) measure.
inline BSplineCurve w1_plane_curve() {
  const std::vector<double> control = w1_control_points();
  std::vector<double> xy;
  for (std::size_t i = 0; i < kW1ControlPoints; ++i) {
    xy.push_back(control[3 * i]);
    xy.push_back(control[3 * i + 1]);
  }
  return BSplineCurve::from_trusted(kW1Degree, clamped_uniform_knots(kW1Degree, kW1ControlPoints),
                                    PointArray::from_trusted(2, std::move(xy)));
}

#if defined(CASTELJAU_HAVE_OCCT)
/// W1's curve in OpenCASCADE: the poles, the distinct knots with their
/// multiplicities (clamped: p+1 at the ends), and the Geom_BSplineCurve on them.
struct OcctW1 {
  TColgp_Array1OfPnt poles;
  TColStd_Array1OfReal knots;
  TColStd_Array1OfInteger mults;
  Handle(Geom_BSplineCurve) curve;
};

inline const OcctW1& occt_w1() {
  static const OcctW1 w1 = [] {
    const int n = static_cast<int>(kW1ControlPoints), distinct = n - kW1Degree + 1;
    OcctW1 o{TColgp_Array1OfPnt(1, n), TColStd_Array1OfReal(1, distinct), TColStd_Array1OfInteger(1, distinct), {}};
    const std::vector<double> control = w1_control_points();
    for (int i = 0; i < n; ++i) o.poles.SetValue(i + 1, gp_Pnt(control[3 * i], control[3 * i + 1], control[3 * i + 2]));
    const std::vector<double> all = clamped_uniform_knots(kW1Degree, kW1ControlPoints);
    for (int i = 0; i < distinct; ++i) {
      o.knots.SetValue(i + 1, all[static_cast<std::size_t>(kW1Degree + i)]);
      o.mults.SetValue(i + 1, (i == 0 || i == distinct - 1) ? kW1Degree + 1 : 1);
    }
    o.curve = new Geom_BSplineCurve(o.poles, o.knots, o.mults, kW1Degree);
    return o;
  }();
  return w1;
}
#endif

#if defined(CASTELJAU_HAVE_SISL)
/// W1's curve in SISL (newCurve with icopy = 1 copies the arrays; kind 1: polynomial B-spline).
inline SISLCurve* sisl_w1() {
  static SISLCurve* curve = [] {
    std::vector<double> knots = clamped_uniform_knots(kW1Degree, kW1ControlPoints), control = w1_control_points();
    return newCurve(static_cast<int>(kW1ControlPoints), kW1Degree + 1, knots.data(), control.data(), 1, 3, 1);
  }();
  return curve;
}
#endif

}  // namespace casteljau::bench
