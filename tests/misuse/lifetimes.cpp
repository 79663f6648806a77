// Code that would dangle must not compile. Each MISUSE below is compiled on
// its own (-DMISUSE=n, tests/CMakeLists.txt) and must be refused with a
// "deleted" error; MISUSE=0 is the same program written safely, which must
// compile (so a refusal cannot come from a broken include path). The safe
// spellings also run under the sanitizers in tests/core/lifetime_test.cpp.
#include <cstdio>
#include <vector>

#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "casteljau/surfaces/revolution.hpp"
#include "casteljau/surfaces/surface_view.hpp"

using namespace casteljau;

namespace {
Expected<PointArray> triangle() { return PointArray::make(2, {0.0, 0.0, 1.0, 2.0, 2.0, 0.0}); }
}  // namespace

int main() {
  double sum = 0.0;
#if MISUSE == 0
  const BezierCurve curve = BezierCurve::make(*triangle()).value();
  const CurveView view = curve;
  const BSplineSurface sphere = *make_sphere({0.0, 0.0, 0.0}, 1.0);
  const SurfaceView surface = sphere;
  const PointArray points = *triangle();
  for (double x : points.coordinates()) sum += x;
  for (auto point : *triangle()) sum += point[0];  // the value moved out lives through the loop
  const BSplineCurve circle = make_circle(0.0, 0.0, 1.0).value();
  for (double t : circle.knots()) sum += t;
  const Model model = curve;
  sum += curve_view(model).domain().upper + view.domain().upper + surface.domain_u().upper;
  sum += points[0][0];
  sum += arc_length(curve, Interval{0.0, 1.0}, Tolerance{1e-9}).value_or(0.0);
#elif MISUSE == 1  // a view of a temporary curve
  const CurveView view = BezierCurve::make(*triangle()).value();
  sum += view.domain().upper;
#elif MISUSE == 2  // a view of a temporary surface
  const SurfaceView surface = *make_sphere({0.0, 0.0, 0.0}, 1.0);
  sum += surface.domain_u().upper;
#elif MISUSE == 3  // member access through a temporary Expected
  for (double x : triangle()->coordinates()) sum += x;
#elif MISUSE == 4  // a span into a temporary point array
  for (double x : triangle().value().coordinates()) sum += x;
#elif MISUSE == 5  // a span into a temporary curve's knots
  for (double t : make_circle(0.0, 0.0, 1.0).value().knots()) sum += t;
#elif MISUSE == 6  // a view of a temporary model
  const CurveView view = curve_view(Model{BezierCurve::make(*triangle()).value()});
  sum += view.domain().upper;
#elif MISUSE == 7  // a span into a temporary point array, by index
  const auto first = triangle().value()[0];
  sum += first[0];
#elif MISUSE == 8  // a temporary passed where a view is taken: refused too (docs/cpp.md, "Lifetimes")
  sum += arc_length(BezierCurve::make(*triangle()).value(), Interval{0.0, 1.0}, Tolerance{1e-9}).value_or(0.0);
#endif
  std::printf("%g\n", sum);
  return 0;
}
