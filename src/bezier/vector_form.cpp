#include "casteljau/bezier/vector_form.hpp"

#include <vector>

#include "casteljau/bezier/bernstein.hpp"

namespace casteljau {

PointArray to_vector_form(const PointArray& control_points) {
  const int d = control_points.dimension();
  std::vector<double> v(control_points.coordinates().begin(), control_points.coordinates().end());
  for (std::size_t i = control_points.size(); i-- > 1;)
    for (int j = 0; j < d; ++j) v[i * d + j] -= v[(i - 1) * d + j];
  return PointArray::from_trusted(d, std::move(v));
}

PointArray from_vector_form(const PointArray& vectors) {
  const int d = vectors.dimension();
  std::vector<double> p(vectors.coordinates().begin(), vectors.coordinates().end());
  for (std::size_t i = 1; i < vectors.size(); ++i)
    for (int j = 0; j < d; ++j) p[i * d + j] += p[(i - 1) * d + j];
  return PointArray::from_trusted(d, std::move(p));
}

Point point_at_vector_form(const PointArray& vectors, double t) {
  const int d = vectors.dimension();
  const int n = static_cast<int>(vectors.size()) - 1;
  std::vector<double> basis(n + 1);
  bernstein_all(n, t, basis);
  Point point(d, 0.0);
  double tail = 0.0;  // f_i(t) = sum_{k >= i} B_{n,k}(t), accumulated from k = n down
  std::vector<double> f(n + 1);
  for (int i = n; i >= 1; --i) f[i] = (tail += basis[i]);
  f[0] = 1.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < d; ++j) point[j] += f[i] * vectors[i][j];
  return point;
}

}  // namespace casteljau
