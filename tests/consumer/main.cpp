// Uses the installed casteljau package: exit 0 when the notebook value comes out.
#include <casteljau/bezier/evaluate.hpp>
#include <cstdio>

int main() {
  using namespace casteljau;
  const auto curve = BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {2, 2}, {4, 1}, {4, 0}}).value());
  if (!curve) return 1;
  const Point p = point_at(*curve, 0.5);
  std::printf("%g,%g\n", p[0], p[1]);
  return (p == Point{2.25, 1.5}) ? 0 : 1;
}
