#pragma once
// Vec<D>: a point or vector of R^D with D fixed at compile time. The fast
// kernels (d = 2 and 3) and the renderer work in Vec<D>; the public curve
// types store points of any dimension in a PointArray (point_array.hpp).

#include <array>
#include <cmath>
#include <cstddef>
#include <span>

namespace casteljau {

/// A point or vector of R^D, a regular value (aggregate of D doubles).
template <int D>
struct Vec {
  static_assert(D >= 1);
  std::array<double, D> coordinates{};

  double& operator[](std::size_t i) { return coordinates[i]; }
  double operator[](std::size_t i) const { return coordinates[i]; }

  /// Reads D coordinates from the start of `source` (which must hold at least D).
  static Vec from(std::span<const double> source) {
    Vec v;
    for (int i = 0; i < D; ++i) v.coordinates[i] = source[i];
    return v;
  }

  Vec& operator+=(const Vec& o) { for (int i = 0; i < D; ++i) coordinates[i] += o.coordinates[i]; return *this; }
  Vec& operator-=(const Vec& o) { for (int i = 0; i < D; ++i) coordinates[i] -= o.coordinates[i]; return *this; }
  Vec& operator*=(double s) { for (auto& c : coordinates) c *= s; return *this; }
  friend Vec operator+(Vec a, const Vec& b) { return a += b; }
  friend Vec operator-(Vec a, const Vec& b) { return a -= b; }
  friend Vec operator*(double s, Vec a) { return a *= s; }
  friend Vec operator*(Vec a, double s) { return a *= s; }
  friend Vec operator-(Vec a) { return a *= -1.0; }
  friend bool operator==(const Vec&, const Vec&) = default;
};

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

/// Euclidean dot product.
template <int D>
double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

/// Euclidean norm, by std::hypot for D = 2 and 3 (no overflow for large coordinates).
template <int D>
double norm(const Vec<D>& a) {
  if constexpr (D == 2) return std::hypot(a[0], a[1]);
  else if constexpr (D == 3) return std::hypot(a[0], a[1], a[2]);
  else return std::sqrt(dot(a, a));
}

/// Euclidean distance between two points.
template <int D>
double distance(const Vec<D>& a, const Vec<D>& b) { return norm(a - b); }

/// (1 - t) a + t b, written as a + t (b - a) like every de Casteljau step here.
template <int D>
Vec<D> lerp(const Vec<D>& a, const Vec<D>& b, double t) { return a + t * (b - a); }

/// z-component of the cross product of two plane vectors (twice the signed triangle area).
inline double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

/// Cross product of two space vectors: orthogonal to both, of length |a| |b| sin(angle)
/// (twice the area of the triangle they span), right-handed.
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

}  // namespace casteljau
