// Interpolation of a grid of points by a B-spline surface (NURBS Book A9.4).
#include "casteljau/surfaces/grid_interpolation.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/surfaces/evaluate.hpp"
#include "support/generators.hpp"

namespace casteljau {
namespace {

/// A 3D grid from rows of points.
ControlNet grid_of(const std::vector<std::vector<std::vector<double>>>& rows) { return ControlNet::make(rows).value(); }

/// A wavy grid: Q_kl = (x_k, y_l, sin x_k cos y_l) with uneven spacing.
ControlNet wavy_grid(int rows, int columns) {
  std::vector<std::vector<std::vector<double>>> q(static_cast<std::size_t>(rows));
  for (int k = 0; k < rows; ++k)
    for (int l = 0; l < columns; ++l) {
      const double x = k + 0.3 * std::sin(1.7 * k + l);
      const double y = 0.8 * l + 0.2 * std::cos(k * l);
      q[static_cast<std::size_t>(k)].push_back({x, y, std::sin(x) * std::cos(y)});
    }
  return grid_of(q);
}

/// eq. 9.13: chord parameters of each column, averaged (the reference for grid_parameters).
std::vector<double> averaged_chords(const ControlNet& q, bool along_u) {
  const std::size_t count = along_u ? q.rows() : q.columns();
  const std::size_t lines = along_u ? q.columns() : q.rows();
  std::vector<double> t(count, 0.0);
  for (std::size_t l = 0; l < lines; ++l) {
    std::vector<double> cumulative{0.0};
    for (std::size_t k = 1; k < count; ++k)
      cumulative.push_back(cumulative.back() + (along_u ? distance(q(k - 1, l), q(k, l)) : distance(q(l, k - 1), q(l, k))));
    for (std::size_t k = 0; k < count; ++k) t[k] += cumulative[k] / cumulative.back() / static_cast<double>(lines);
  }
  return t;
}

TEST(InterpolateGrid, ReproducesItsDataAtTheAveragedParameters) {
  for (auto kind : {Parameterization::chord_length, Parameterization::centripetal, Parameterization::uniform}) {
    for (auto [p, q] : {std::pair{3, 3}, std::pair{2, 4}, std::pair{1, 1}, std::pair{5, 2}}) {
      const ControlNet grid = wavy_grid(9, 7);
      const auto surface = interpolate_grid(grid, p, q, kind).value();
      EXPECT_EQ(surface.degree_u(), p);
      EXPECT_EQ(surface.degree_v(), q);
      const auto parameters = grid_parameters(grid, kind).value();
      double worst = 0.0;
      for (std::size_t k = 0; k < grid.rows(); ++k)
        for (std::size_t l = 0; l < grid.columns(); ++l)
          worst = std::max(worst, distance(point_at(surface, parameters.u[k], parameters.v[l]), grid(k, l)));
      EXPECT_LE(worst, 1e-14 * scale_of(grid.points()) * 8) << name_of(kind) << " " << p << " " << q;
    }
  }
}

TEST(InterpolateGrid, ChordParametersAreAveragedOverTheLines) {
  const ControlNet grid = wavy_grid(6, 5);
  const auto parameters = grid_parameters(grid).value();
  const auto u = averaged_chords(grid, true), v = averaged_chords(grid, false);
  for (std::size_t k = 0; k < u.size(); ++k) EXPECT_NEAR(parameters.u[k], u[k], 1e-15) << k;
  for (std::size_t l = 0; l < v.size(); ++l) EXPECT_NEAR(parameters.v[l], v[l], 1e-15) << l;
  EXPECT_EQ(parameters.u.back(), 1.0);
  EXPECT_EQ(parameters.v.front(), 0.0);
}

/// P(x, y) = sum a_ij x^i y^j, i, j <= 3, by Horner in each variable.
double bicubic(const std::vector<double>& a, double x, double y) {
  double result = 0.0;
  for (int i = 3; i >= 0; --i) {
    double row = 0.0;
    for (int j = 3; j >= 0; --j) row = row * y + a[static_cast<std::size_t>(4 * i + j)];
    result = result * x + row;
  }
  return result;
}

RC_GTEST_PROP(InterpolateGrid, ReproducesABicubicPolynomialSurface, ()) {
  // Data sampled from (x, y, P(x, y)) on a uniform grid of [0,1]^2 and
  // uniform parameters: u_k = x_k, v_l = y_l, and the bicubic spline space
  // contains P, so the interpolant is P itself (uniqueness), everywhere.
  const int rows = *rc::gen::inRange(4, 10), columns = *rc::gen::inRange(4, 10);
  const auto a = *rc::gen::container<std::vector<double>>(16, test::coordinate());
  std::vector<std::vector<std::vector<double>>> q(static_cast<std::size_t>(rows));
  for (int k = 0; k < rows; ++k)
    for (int l = 0; l < columns; ++l) {
      const double x = static_cast<double>(k) / (rows - 1), y = static_cast<double>(l) / (columns - 1);
      q[static_cast<std::size_t>(k)].push_back({x, y, bicubic(a, x, y)});
    }
  const auto surface = interpolate_grid(grid_of(q), 3, 3, Parameterization::uniform).value();
  double size = 0.0;
  for (double c : a) size += std::abs(c);  // bounds |P| on [0,1]^2
  for (int s = 0; s < 30; ++s) {
    const double x = *test::unit_parameter(), y = *test::unit_parameter();
    const Point p = point_at(surface, x, y);
    RC_ASSERT(std::abs(p[0] - x) <= 1e-13);
    RC_ASSERT(std::abs(p[1] - y) <= 1e-13);
    RC_ASSERT(std::abs(p[2] - bicubic(a, x, y)) <= 1e-13 * std::max(1.0, size));
  }
}

TEST(InterpolateGrid, APoleRowIsLeftOutOfTheAverage) {
  // Row 0 is one repeated point (a pole): its zero-length column polylines
  // still count, but the row polyline of length 0 is skipped for v.
  std::vector<std::vector<std::vector<double>>> q;
  q.push_back({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
  q.push_back({{1, 0, 0.5}, {0.5, 0.8, 0.5}, {-0.5, 0.8, 0.5}, {-1, 0, 0.5}});
  q.push_back({{2, 0, 0}, {1, 1.7, 0}, {-1, 1.7, 0}, {-2, 0, 0}});
  q.push_back({{3, 0, -1}, {1.5, 2.6, -1}, {-1.5, 2.6, -1}, {-3, 0, -1}});
  const auto grid = grid_of(q);
  const auto surface = interpolate_grid(grid, 2, 3).value();
  const auto parameters = grid_parameters(grid).value();
  const auto v = averaged_chords(grid_of({q[1], q[2], q[3]}), false);
  for (std::size_t l = 0; l < v.size(); ++l) EXPECT_NEAR(parameters.v[l], v[l], 1e-15);
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t l = 0; l < 4; ++l)
      EXPECT_LE(distance(point_at(surface, parameters.u[k], parameters.v[l]), grid(k, l)), 1e-14 * 3 * 8);
}

TEST(InterpolateGrid, RefusesBadInput) {
  auto message = [](const auto& result) { return result.has_value() ? std::string("ok") : result.error().message; };
  const ControlNet small = wavy_grid(3, 5);
  EXPECT_EQ(message(interpolate_grid(small)), "a grid of 3 rows cannot be interpolated with degree_u 3, it needs at least 4 rows");
  EXPECT_EQ(message(interpolate_grid(small, 2, 5)),
            "a grid of 5 columns cannot be interpolated with degree_v 5, it needs at least 6 columns");
  EXPECT_EQ(message(interpolate_grid(small, 0, 1)), "degree_u is 0, it must be >= 1");
  EXPECT_EQ(message(interpolate_grid(grid_of({{{0, 0}, {1, 0}}}), 1, 1)),
            "a grid of 1 rows cannot be interpolated with degree_u 1, it needs at least 2 rows");
  std::vector<std::vector<std::vector<double>>> q = {{{0, 0}, {1, 0}, {2, 0}}, {{0, 1}, {1, 1}, {2, 1}},
                                                     {{0, 1}, {1, 1}, {2, 1}}, {{0, 3}, {1, 3}, {2, 3}}};
  EXPECT_EQ(message(interpolate_grid(grid_of(q), 2, 2)), "rows 1 and 2 coincide, chord-length parameters need distinct rows");
  std::vector<std::vector<std::vector<double>>> same = {{{0, 0}, {0, 0}}, {{0, 0}, {0, 0}}};
  EXPECT_EQ(message(interpolate_grid(grid_of(same), 1, 1)), "all the rows coincide, chord-length parameters need distinct rows");
}

}  // namespace
}  // namespace casteljau
