// The B-spline and NURBS figures (issue 4), checked on the figure data:
// - the basis panels are the B-spline basis: at sampled u their graphs equal
//   the Cox–de Boor recursion evaluated directly (not through the Bézier
//   pieces that are drawn) and sum to one on the domain, less outside it;
// - local control: the black (unchanged) pieces are the same in both panels,
//   exactly p+1 = 4 pieces are highlighted and they did change;
// - continuity: at the knots of multiplicity 1, 2, 3 the drawn pieces join
//   C², C¹, C⁰ (seed 001: multiplicity m lowers the continuity to p - m),
//   measured with Bézier derivatives at the pieces' ends;
// - the NURBS circle is drawn on the unit circle; a larger weight pulls the
//   curve closer to its control point (seed 001);
// - plane_bspline draws a 1D B-spline as its graph and a 3D one as its projection;
// - the gallery lists the new figures and every one of them lays out into
//   well-formed SVG.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/basis.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/render/bspline_plots.hpp"
#include "casteljau/render/gallery.hpp"
#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/write.hpp"

namespace casteljau::render {
namespace {

/// The B-spline figures, built once per test process (each test runs in its
/// own process under ctest, so the whole gallery is built only where needed).
const std::map<std::string, GalleryFigure>& gallery() {
  static const std::map<std::string, GalleryFigure> figures = [] {
    std::map<std::string, GalleryFigure> by_name;
    auto all = bspline_gallery_figures();
    if (all)
      for (auto& f : *all) by_name.emplace(f.name, std::move(f));
    return by_name;
  }();
  return figures;
}

const Figure& figure_named(const std::string& name) {
  const auto found = gallery().find(name);
  if (found == gallery().end()) {
    ADD_FAILURE() << "no gallery figure " << name;
    static const Figure empty;
    return empty;
  }
  return found->second.figure;
}

/// The value of a graph drawn as Bézier pieces at abscissa x: the piece whose
/// x range holds x, at the parameter where its (linear) x equals x. nullopt
/// when no piece covers x.
std::optional<double> graph_value(const CurveItem& item, double x) {
  for (const auto& piece : item.pieces) {
    const auto& p = piece.control_points();
    const double x0 = p[0][0], x1 = p[p.size() - 1][0];
    if (!(x0 <= x && x <= x1) || x0 == x1) continue;
    return point_at(piece, (x - x0) / (x1 - x0))[1];
  }
  return std::nullopt;
}

/// N_{i,p}(u) straight from the Cox–de Boor recursion (seed 001 with order
/// k = p+1; The NURBS Book eq. 2.5), half-open steps, 0/0 := 0: the reference,
/// valid on the whole knot range (basis_function extrapolates the domain's end
/// pieces outside [t_p, t_{n+1}], as evaluation does). Exponential cost, fine for p <= 3.
double cox_de_boor(const std::vector<double>& t, std::size_t i, int p, double u) {
  if (p == 0) return t[i] <= u && u < t[i + 1] ? 1.0 : 0.0;
  const std::size_t q = static_cast<std::size_t>(p);
  double value = 0.0;
  if (t[i + q] > t[i]) value += (u - t[i]) / (t[i + q] - t[i]) * cox_de_boor(t, i, p - 1, u);
  if (t[i + q + 1] > t[i + 1]) value += (t[i + q + 1] - u) / (t[i + q + 1] - t[i + 1]) * cox_de_boor(t, i + 1, p - 1, u);
  return value;
}

TEST(BSplineFigures, GraphPiecesHaveLinearAbscissae) {
  // What graph_value relies on: x(t) is linear on every piece of a basis
  // graph (Greville abscissae give linear precision), so the control points'
  // x are evenly spaced.
  for (const char* name : {"17_bspline_basis_clamped", "18_bspline_basis_uniform"}) {
    for (const auto& panel : figure_named(name).panels)
      for (const auto& item : panel.curves)
        for (const auto& piece : item.pieces) {
          const auto& p = piece.control_points();
          const double x0 = p[0][0], x1 = p[p.size() - 1][0];
          for (std::size_t j = 0; j < p.size(); ++j)
            EXPECT_NEAR(p[j][0], x0 + (x1 - x0) * static_cast<double>(j) / static_cast<double>(p.size() - 1),
                        1e-14 * std::max(1.0, std::abs(x1)))
                << name;
        }
  }
}

TEST(BSplineFigures, BasisPanelsAreTheBasisAndSumToOne) {
  for (const char* name : {"17_bspline_basis_clamped", "18_bspline_basis_uniform"}) {
    const Figure& figure = figure_named(name);
    ASSERT_EQ(figure.panels.size(), 4u) << name;
    for (std::size_t p = 0; p < 4; ++p) {
      const Panel& panel = figure.panels[p];
      // The knots, from the panel: the dots on the u axis and their "×m" labels.
      std::vector<double> knots;
      const auto dots = std::find_if(panel.markers.begin(), panel.markers.end(),
                                     [](const MarkerItem& m) { return m.label == "knots"; });
      ASSERT_NE(dots, panel.markers.end()) << name;
      for (const Vec2& dot : dots->points) {
        int multiplicity = 1;
        for (const auto& text : panel.texts)
          if (text.position == dot && text.text.rfind("×", 0) == 0) multiplicity = std::stoi(text.text.substr(2));
        knots.insert(knots.end(), static_cast<std::size_t>(multiplicity), dot[0]);
      }
      const int degree = static_cast<int>(p);
      const std::size_t count = knots.size() - p - 1;
      ASSERT_TRUE(validate_knots(knots, degree, count)) << name << " p = " << p;
      // The basis functions are the solid items, one per function, in order.
      std::vector<const CurveItem*> functions;
      for (const auto& item : panel.curves)
        if (item.stroke.dash.empty()) functions.push_back(&item);
      ASSERT_EQ(functions.size(), count) << name << " p = " << p;
      const double lower = knots[p], upper = knots[count];
      for (int s = 0; s <= 40; ++s) {
        // Avoid the knots themselves, where two pieces meet.
        const double u = knots.front() + (knots.back() - knots.front()) * (s + 0.37) / 41.0;
        double sum = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
          const double expected = cox_de_boor(knots, i, degree, u);
          if (lower <= u && u <= upper) {  // the library's A2.4 agrees on the domain
            EXPECT_NEAR(basis_function(knots, degree, static_cast<int>(i), u), expected, 1e-14);
          }
          const auto drawn = graph_value(*functions[i], u);
          // Outside its support a function is not drawn: it is zero there.
          const double value = drawn ? *drawn : 0.0;
          EXPECT_NEAR(value, expected, 1e-14) << name << " p = " << p << " i = " << i << " u = " << u;
          sum += value;
        }
        if (lower <= u && u <= upper) EXPECT_NEAR(sum, 1.0, 1e-14) << name << " p = " << p << " u = " << u;
        else EXPECT_LT(sum, 1.0 - 1e-9) << name << " p = " << p << " u = " << u;
      }
    }
  }
}

TEST(BSplineFigures, LocalControlKeepsTheUnchangedPiecesIdentical) {
  const Figure& figure = figure_named("19_bspline_local_control");
  ASSERT_EQ(figure.panels.size(), 2u);
  const Stroke unchanged = solid(colors::black, 2.0);
  const Stroke highlighted = solid(cycle_color(1), 3.0);
  auto pieces_with = [](const Panel& panel, const Stroke& stroke) {
    std::vector<BezierCurve> pieces;
    for (const auto& item : panel.curves)
      if (item.stroke == stroke) pieces.insert(pieces.end(), item.pieces.begin(), item.pieces.end());
    return pieces;
  };
  const auto before = pieces_with(figure.panels[0], unchanged);
  const auto after = pieces_with(figure.panels[1], unchanged);
  // 8 spans, 4 of them the support of the moved N_(5,3).
  ASSERT_EQ(before.size(), 4u);
  ASSERT_EQ(after.size(), 4u);
  for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(before[i], after[i]) << "unchanged piece " << i;
  const auto changed_before = pieces_with(figure.panels[0], highlighted);
  const auto changed_after = pieces_with(figure.panels[1], highlighted);
  ASSERT_EQ(changed_before.size(), 4u);
  ASSERT_EQ(changed_after.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const Point a = point_at(changed_before[i], 0.5), b = point_at(changed_after[i], 0.5);
    EXPECT_GT(distance(a, b), 1e-3) << "changed piece " << i << " did not move";
  }
}

TEST(BSplineFigures, ContinuityAtKnotsOfMultiplicityOneTwoThree) {
  const Figure& figure = figure_named("20_bspline_continuity");
  ASSERT_GE(figure.panels.size(), 1u);
  const Panel& shape = figure.panels[0];
  // The curve: one black item through every piece (a C⁰ curve has no jump).
  std::vector<BezierCurve> pieces;
  for (const auto& item : shape.curves)
    if (item.label == "cubic B-spline") pieces = item.pieces;
  ASSERT_EQ(pieces.size(), 4u);  // knots 0 1 2 3 4: every span of length 1, so d/dt = d/du
  const double scale = scale_of(pieces[0].control_points());
  auto jump = [&](std::size_t knot, int order) {
    return distance(derivative_at(pieces[knot - 1], 1.0, order), derivative_at(pieces[knot], 0.0, order));
  };
  const double tight = 1e-12 * scale, visible = 1e-2 * scale;
  // u = 1, m = 1: C² (and the third derivative jumps).
  EXPECT_LE(jump(1, 0), tight);
  EXPECT_LE(jump(1, 1), tight);
  EXPECT_LE(jump(1, 2), tight);
  EXPECT_GT(jump(1, 3), visible);
  // u = 2, m = 2: C¹, not C².
  EXPECT_LE(jump(2, 0), tight);
  EXPECT_LE(jump(2, 1), tight);
  EXPECT_GT(jump(2, 2), visible);
  // u = 3, m = 3: C⁰ with a corner.
  EXPECT_LE(jump(3, 0), tight);
  EXPECT_GT(jump(3, 1), visible);
  // And the labels say so.
  std::string labels;
  for (const auto& text : shape.texts) labels += text.text + "\n";
  EXPECT_NE(labels.find("u = 1, m = 1: C²"), std::string::npos) << labels;
  EXPECT_NE(labels.find("u = 2, m = 2: C¹"), std::string::npos) << labels;
  EXPECT_NE(labels.find("u = 3, m = 3: C⁰"), std::string::npos) << labels;
}

TEST(BSplineFigures, NurbsCircleIsDrawnOnTheUnitCircle) {
  const Figure& figure = figure_named("21_nurbs_circle");
  ASSERT_EQ(figure.panels.size(), 1u);
  std::size_t pieces = 0;
  for (const auto& item : figure.panels[0].curves)
    for (const auto& piece : item.pieces) {
      ++pieces;
      EXPECT_TRUE(piece.is_rational());
      for (int i = 0; i <= 64; ++i) {
        const Point p = point_at(piece, i / 64.0);
        EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 1e-15);
      }
    }
  EXPECT_EQ(pieces, 4u);  // four quarter arcs
}

TEST(BSplineFigures, LargerWeightPullsTowardTheControlPoint) {
  const Figure& figure = figure_named("22_nurbs_weight");
  ASSERT_EQ(figure.panels.size(), 1u);
  const Vec2 pulled{{1.0, 1.0}};
  std::vector<double> distances;
  for (const auto& item : figure.panels[0].curves) {
    if (item.label.rfind("w1 = ", 0) != 0) continue;
    ASSERT_EQ(item.pieces.size(), 1u);  // only the first quarter is drawn
    const Point middle = point_at(item.pieces[0], 0.5);
    distances.push_back(std::hypot(middle[0] - pulled[0], middle[1] - pulled[1]));
  }
  ASSERT_EQ(distances.size(), 5u);  // w1 = 0.25, 0.5, 1, 2, 4 in this order
  for (std::size_t k = 1; k < distances.size(); ++k) EXPECT_LT(distances[k], distances[k - 1]);
  // w1 = 1: the middle of the arc is the midpoint between the chord's middle
  // M = (0.5, 0.5) and P1, at distance sqrt(2)/4 (the Bernstein form at t = 1/2:
  // C(1/2) = (P0 + 2w P1 + P2) / (2 + 2w) = (M + w P1) / (1 + w)).
  EXPECT_NEAR(distances[2], std::sqrt(2.0) / 4.0, 1e-15);
}

TEST(BSplinePlots, OneDimensionalBSplineIsDrawnAsItsGraph) {
  const std::vector<double> knots{0, 0, 0, 0.3, 0.3, 1.1, 2, 2, 2};
  const auto curve = BSplineCurve::make(2, knots, *PointArray::make(1, {0.5, -1, 2, 0.25, 3, 1}));
  ASSERT_TRUE(curve) << curve.error().message;
  auto plane = plane_bspline(*curve);
  ASSERT_TRUE(plane) << plane.error().message;
  for (int i = 0; i <= 50; ++i) {
    const double u = 2.0 * i / 50.0;
    const Point graph = point_at(*plane, u);
    EXPECT_NEAR(graph[0], u, 1e-15 * 2.0);
    EXPECT_NEAR(graph[1], point_at(*curve, u)[0], 1e-14);
  }
}

TEST(BSplinePlots, ThreeDimensionalBSplineIsProjected) {
  const auto curve = BSplineCurve::make(2, {0, 0, 0, 1, 2, 2, 2},
                                        *PointArray::make(3, {0, 0, 5, 1, 2, -1, 3, 1, 0, 4, -2, 2}), {1, 2, 0.5, 1});
  ASSERT_TRUE(curve) << curve.error().message;
  auto plane = plane_bspline(*curve);
  ASSERT_TRUE(plane) << plane.error().message;
  for (int i = 0; i <= 20; ++i) {
    const double u = 2.0 * i / 20.0;
    const Point p = point_at(*curve, u), q = point_at(*plane, u);
    EXPECT_NEAR(q[0], p[0], 1e-14);
    EXPECT_NEAR(q[1], p[1], 1e-14);
  }
}

TEST(BSplinePlots, Errors) {
  const auto rational = BSplineCurve::make(1, {0, 0, 1, 1}, *PointArray::make(1, {0, 1}), {1, 2});
  ASSERT_TRUE(rational);
  EXPECT_FALSE(plane_bspline(*rational));
  Panel panel;
  const auto curve = BSplineCurve::make(1, {0, 0, 1, 1}, *PointArray::make(2, {0, 0, 1, 1}));
  BSplinePlotOptions options;
  options.construction = 1.5;
  const auto status = add_bspline(panel, *curve, options);
  ASSERT_FALSE(status);
  EXPECT_NE(status.error().message.find("1.5"), std::string::npos) << status.error().message;
  // Knots that do not form a basis are named by validate_knots.
  const std::vector<double> decreasing{0, 1, 0.5, 2};
  EXPECT_FALSE(bspline_basis_panel(decreasing, 1));
  EXPECT_FALSE(bspline_basis_panel(decreasing, -1));
}

TEST(BSplinePlots, DegreeZeroStepsJumpAtEveryKnot) {
  const auto curve = BSplineCurve::make(0, {0, 1, 2, 3}, *PointArray::make(1, {1, 3, 2}));
  ASSERT_TRUE(curve);
  auto pieces = plane_pieces(*curve);
  ASSERT_TRUE(pieces);
  ASSERT_EQ(pieces->pieces.size(), 3u);
  EXPECT_EQ(pieces->jumps, (std::vector<bool>{true, true}));
  const auto items = curve_items(*pieces, 0, 3, solid(colors::black));
  EXPECT_EQ(items.size(), 3u);  // the pen is lifted at each jump
  EXPECT_EQ(point_at(pieces->pieces[1], 0.5), (Point{1.5, 3.0}));
}

TEST(BSplinePlots, PlotBasisOfABSplineModel) {
  const auto curve = BSplineCurve::make(2, {0, 0, 0, 1, 2, 3, 3, 3}, *PointArray::make(2, {0, 0, 1, 2, 2, 0, 3, 2, 4, 0}));
  ASSERT_TRUE(curve);
  PlotSource source;
  source.name = "spline.json";
  source.models.push_back(*curve);
  PlotOptions options;
  options.basis = true;
  auto figure = plot_figure({source}, options);
  ASSERT_TRUE(figure) << figure.error().message;
  ASSERT_EQ(figure->panels.size(), 2u);
  EXPECT_NE(figure->panels[1].title.find("B-spline basis"), std::string::npos) << figure->panels[1].title;
  std::size_t solid_items = 0;
  for (const auto& item : figure->panels[1].curves) solid_items += item.stroke.dash.empty() ? 1 : 0;
  EXPECT_EQ(solid_items, 5u);  // N_0..N_4
  // The construction of a B-spline is its de Boor net: p + 1 levels, C(u) last.
  options.basis = false;
  options.bezier.construction = 1.5;
  figure = plot_figure({source}, options);
  ASSERT_TRUE(figure) << figure.error().message;
  const auto& markers = figure->panels[0].markers;
  const auto point = std::find_if(markers.begin(), markers.end(),
                                  [](const MarkerItem& m) { return m.label.rfind("C(1.5)", 0) == 0; });
  ASSERT_NE(point, markers.end());
  const Point expected = casteljau::point_at(*curve, 1.5);
  EXPECT_NEAR(point->points[0][0], expected[0], 1e-14);
  EXPECT_NEAR(point->points[0][1], expected[1], 1e-14);
  options.bezier.construction = 3.5;
  EXPECT_FALSE(plot_figure({source}, options));
}

/// A small well-formedness check of SVG text: every tag closed in order,
/// attribute values quoted, '&' only in entities.
::testing::AssertionResult well_formed(const std::string& text) {
  std::vector<std::string> open;
  for (std::size_t i = 0; (i = text.find('<', i)) != std::string::npos;) {
    const std::size_t end = text.find('>', i);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unterminated tag at " << i;
    const std::string tag = text.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.empty()) return ::testing::AssertionFailure() << "empty tag";
    if (tag[0] == '?' || tag[0] == '!') continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return ::testing::AssertionFailure() << "odd quotes in <" << tag << ">";
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        return ::testing::AssertionFailure() << "</" << tag.substr(1) << "> closes " << (open.empty() ? "nothing" : open.back());
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find_first_of(" \n\t")));
    }
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> never closed";
  for (std::size_t i = 0; (i = text.find('&', i)) != std::string::npos; ++i) {
    const std::size_t semicolon = text.find(';', i);
    if (semicolon == std::string::npos || semicolon - i > 6) return ::testing::AssertionFailure() << "bare & at " << i;
  }
  return ::testing::AssertionSuccess();
}

TEST(BSplineFigures, GalleryListsTheNewFiguresAsWellFormedSvg) {
  auto all = gallery_figures(default_examples_dir());
  ASSERT_TRUE(all) << all.error().message;
  std::map<std::string, const GalleryFigure*> by_name;
  for (const auto& f : *all) by_name[f.name] = &f;
  const std::vector<std::string> names{"17_bspline_basis_clamped", "18_bspline_basis_uniform",
                                       "19_bspline_local_control", "20_bspline_continuity", "21_nurbs_circle",
                                       "22_nurbs_weight", "11_semicircle"};
  for (const auto& name : names) {
    ASSERT_EQ(by_name.count(name), 1u) << name;
    auto scene = layout(by_name[name]->figure);
    ASSERT_TRUE(scene) << name << ": " << scene.error().message;
    const std::string svg = svg_document(*scene);
    EXPECT_TRUE(well_formed(svg)) << name;
    EXPECT_EQ(svg.find("<path"), std::string::npos) << name << ": curves must be flattened polylines";
  }
  // The B-spline figures follow the 16 Bézier ones, in order (the
  // interpolation figures, 23 and up, come after them).
  ASSERT_GE(all->size(), 22u);
  EXPECT_EQ((*all)[16].name, "17_bspline_basis_clamped");
  EXPECT_EQ((*all)[21].name, "22_nurbs_weight");
  const std::string html = gallery_index_html(*all);
  for (const auto& name : names) EXPECT_NE(html.find("src=\"" + name + ".svg\""), std::string::npos) << name;
  // The semicircle figure now draws the exact NURBS arc and states its error.
  EXPECT_NE(by_name["11_semicircle"]->explanation.find("NURBS arc"), std::string::npos);
}

TEST(BSplineFigures, SemicircleArcRadialErrorIsRounding) {
  // The bound for the NURBS circle: radius error <= 1e-15 R.
  const auto circle = BSplineCurve::make(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                                         *PointArray::make(2, {-3, 0, -3, 3, 0, 3, 3, 3, 3, 0}),
                                         {1, std::sqrt(0.5), 1, std::sqrt(0.5), 1});
  ASSERT_TRUE(circle);
  const RadialError error = radial_error(*circle, 3.0, 100001);
  EXPECT_LE(error.maximum, 1e-15 * 3.0);
  EXPECT_EQ(error.parameters.front(), 0.0);
  EXPECT_EQ(error.parameters.back(), 1.0);
}

}  // namespace
}  // namespace casteljau::render
