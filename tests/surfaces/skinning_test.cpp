// Skinning (lofting) through section curves.
#include "casteljau/surfaces/skinning.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/nurbs/conics.hpp"
#include "casteljau/surfaces/evaluate.hpp"
#include "casteljau/surfaces/ruled.hpp"
#include "support/bspline_generators.hpp"

namespace casteljau {
namespace {

/// Sections that are already compatible (one degree, the knots of the
/// first, on [0, 1]) so that the expected parameters can be computed from
/// the given control points, independently of make_compatible.
std::vector<BSplineCurve> compatible_sections(int count, bool rational) {
  const auto first = *test::bspline_curve({.max_degree = 4, .dimension = 3, .max_extra_points = 5,
                                           .rational = rational ? test::Rational::always : test::Rational::never,
                                           .allow_unclamped = false});
  std::vector<BSplineCurve> sections;
  const auto knots = first.knots();
  const Interval domain = first.domain();
  std::vector<double> unit;
  for (double k : knots) unit.push_back(k == domain.upper ? 1.0 : (k - domain.lower) / domain.length());
  // Sections stacked along z (10 apart), each the first polygon moved by
  // up to 1 in x and y: nearly uniform parameters, so that interpolated
  // weights stay well inside (0, infinity) (see RefusesWeightsThatTurnNegative).
  for (int k = 0; k < count; ++k) {
    std::vector<double> coordinates;
    for (std::size_t i = 0; i < first.control_points().size(); ++i) {
      coordinates.push_back(first.control_points()[i][0] + *test::coordinate() / 100);
      coordinates.push_back(first.control_points()[i][1] + *test::coordinate() / 100);
      coordinates.push_back(10.0 * k + *test::coordinate() / 100);
    }
    // Weights near the first section's (within 5%): the sections of a
    // real loft share their weights more or less (circles, conics).
    std::vector<double> weights;
    if (rational)
      for (double w : first.weights()) weights.push_back(w * (1.0 + 0.01 * *rc::gen::inRange(0, 6)));
    sections.push_back(BSplineCurve::make(first.degree(), unit, PointArray::make(3, coordinates).value(), weights).value());
  }
  return sections;
}

/// eq. 10.8: the chord-length parameters of each control-point column, averaged.
std::vector<double> expected_parameters(const std::vector<BSplineCurve>& sections) {
  const std::size_t count = sections[0].control_points().size();
  std::vector<double> v(sections.size(), 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<double> cumulative{0.0};
    for (std::size_t k = 1; k < sections.size(); ++k)
      cumulative.push_back(cumulative.back() +
                           distance(sections[k - 1].control_points()[i], sections[k].control_points()[i]));
    for (std::size_t k = 0; k < sections.size(); ++k) v[k] += cumulative[k] / cumulative.back() / count;
  }
  return v;
}

RC_GTEST_PROP(Skin, PassesThroughItsSections, ()) {
  const int count = *rc::gen::inRange(2, 7);
  const bool rational = *rc::gen::arbitrary<bool>();
  const auto sections = compatible_sections(count, rational);
  const int degree_v = *rc::gen::inRange(1, count);
  auto skinned = skin(sections, degree_v);
  if (!skinned) RC_FAIL(skinned.error().message);
  const BSplineSurface& surface = *skinned;
  RC_ASSERT(surface.degree_v() == degree_v);
  RC_ASSERT(surface.is_rational() == rational);
  const auto v = section_parameters(sections).value();
  const auto expected = expected_parameters(sections);
  for (int k = 0; k < count; ++k) RC_ASSERT(std::abs(v[k] - expected[k]) <= 1e-14);
  double scale = 0.0;
  for (const auto& s : sections) scale = std::max(scale, test::shape_tolerance(s, 1.0));
  for (int k = 0; k < count; ++k) {
    for (int i = 0; i <= 16; ++i) {
      const double u = i / 16.0;
      RC_ASSERT(distance(point_at(surface, u, v[k]), point_at(sections[k], u)) <= 1e-11 * scale);
    }
  }
}

TEST(Skin, SectionsOfDifferentKindsAreMadeCompatible) {
  // Three circles of different radii and heights (NURBS, two of them as
  // arcs with other knots) and a polynomial square-ish B-spline: the skinned
  // surface passes through all four (the polynomial one with unit weights).
  const double pi = std::numbers::pi;
  std::vector<BSplineCurve> sections;
  sections.push_back(make_circle(ConicFrame{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2.0).value());
  sections.push_back(make_arc(ConicFrame{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, 1.0, 0.0, 2 * pi).value());
  sections.push_back(BSplineCurve::make(1, {0, 0, 0.25, 0.5, 0.75, 1, 1},
                                        PointArray::make({{1.5, 0, 2}, {0, 1.5, 2}, {-1.5, 0, 2}, {0, -1.5, 2}, {1.5, 0, 2}}).value())
                         .value());
  sections.push_back(make_circle(ConicFrame{{0, 0, 3.5}, {1, 0, 0}, {0, 1, 0}}, 2.5).value());
  for (int degree_v : {1, 2, 3}) {
    const auto surface = skin(sections, degree_v).value();
    const auto v = section_parameters(sections).value();
    double worst = 0.0;
    for (std::size_t k = 0; k < sections.size(); ++k)
      for (int i = 0; i <= 64; ++i) {
        const double u = i / 64.0;
        worst = std::max(worst, distance(point_at(surface, u, v[k]), point_at(sections[k], sections[k].domain().lerp(u))));
      }
    EXPECT_LE(worst, 1e-14 * 3.5 * 8) << degree_v;
  }
}

TEST(Skin, TwoSectionsOfDegreeOneAreTheRuledSurface) {
  const auto a = BSplineCurve::make(2, {0, 0, 0, 1, 1, 1}, PointArray::make({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}).value()).value();
  const auto b = BSplineCurve::make(2, {0, 0, 0, 1, 1, 1}, PointArray::make({{0, 0, 1}, {1, -1, 1}, {2, 0, 1}}).value()).value();
  const BSplineCurve both[2] = {a, b};
  const auto skinned = skin(both, 1).value();
  const auto ruled = ruled_surface(a, b).value();
  for (double u : {0.0, 0.3, 1.0})
    for (double v : {0.0, 0.6, 1.0}) EXPECT_LE(distance(point_at(skinned, u, v), point_at(ruled, u, v)), 1e-15 * 4);
}

TEST(Skin, RefusesBadInput) {
  const auto a = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, 0}, {1, 0, 0}}).value()).value();
  const auto b = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, 1}, {1, 0, 1}}).value()).value();
  const auto flat = BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0}, {1, 0}}).value()).value();
  auto message = [](const auto& result) { return result.has_value() ? std::string("ok") : result.error().message; };
  const BSplineCurve one[1] = {a};
  EXPECT_EQ(message(skin(one, 1)), "skinning needs at least 2 sections, found 1");
  const BSplineCurve two[2] = {a, b};
  EXPECT_EQ(message(skin(two, 0)), "degree_v is 0, it must be >= 1");
  EXPECT_EQ(message(skin(two, 2)), "degree_v 2 needs at least 3 sections, found 2");
  const BSplineCurve mixed[3] = {a, b, flat};
  EXPECT_EQ(message(skin(mixed, 1)), "section 2 has 2 coordinates, section 0 has 3; compatible sections need one dimension");
  const BSplineCurve repeated[3] = {a, b, b};
  EXPECT_EQ(message(skin(repeated, 2)), "sections 1 and 2 coincide, chord-length parameters need distinct sections");
  EXPECT_EQ(message(skin(repeated, 2, Parameterization::centripetal)),
            "sections 1 and 2 coincide, centripetal parameters need distinct sections");
  // Uniform parameters do not look at the points: b twice is then a valid
  // (if odd) request, interpolated at v = 0, 0.5, 1.
  EXPECT_EQ(message(skin(repeated, 2, Parameterization::uniform)), "ok");
}

TEST(Skin, RefusesWeightsThatTurnNegative) {
  // One polynomial curve written with all weights 1, 50, 1, 50 (the same
  // curve each time, at four heights): the cubic through the weights 1, 50,
  // 1, 50 at v = 0, 1/3, 2/3, 1 has Bézier ordinates 1, 153.3, -113.3, 50,
  // so the surface would divide by zero between the sections.
  std::vector<BSplineCurve> sections;
  for (int k = 0; k < 4; ++k) {
    const double w = k % 2 == 0 ? 1.0 : 50.0;
    sections.push_back(BSplineCurve::make(1, {0, 0, 1, 1}, PointArray::make({{0, 0, double(k)}, {1, 0, double(k)}}).value(),
                                          {w, w})
                           .value());
  }
  const auto surface = skin(sections, 3, Parameterization::uniform);
  ASSERT_FALSE(surface.has_value());
  // -340/3 up to the rounding of the solve.
  EXPECT_EQ(surface.error().message.rfind("the skinned surface's weight [0][2] is -113.333333333333", 0), 0u)
      << surface.error().message;
  EXPECT_NE(surface.error().message.find(": the sections' weights vary too much for degree_v 3 (try a lower degree_v "
                                         "or sections with closer weights)"),
            std::string::npos);
  EXPECT_TRUE(skin(sections, 1, Parameterization::uniform).has_value());
}

}  // namespace
}  // namespace casteljau
