// What plot_figure makes of its sources (issue 15): a point set drawn as data
// beside curves, with markers apart from control points and a legend that
// says which is which; errors that name the file (and the model) for
// extreme inputs, at plot time and at layout time.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "casteljau/render/layout.hpp"
#include "casteljau/render/plots.hpp"
#include "casteljau/render/tolerance.hpp"

namespace casteljau::render {
namespace {

/// from_trusted: BezierCurve::make refuses coordinates beyond
/// tolerances::kMaxCoordinate (1e100), and the extreme cases below test the
/// figure's own checks, which computed curves can still reach.
PlotSource curve_source(std::string name, const std::vector<std::vector<double>>& points) {
  PlotSource source;
  source.name = std::move(name);
  source.models.push_back(BezierCurve::from_trusted(*PointArray::make(points)));
  return source;
}

PlotSource data_source(std::string name, bool markers, bool polyline) {
  PlotSource source;
  source.name = std::move(name);
  source.points = *PointArray::make({{0, 0}, {1, 1}, {2, 0}});
  source.markers = markers;
  source.polyline = polyline;
  return source;
}

const MarkerItem* marker_labelled(const Panel& panel, const std::string& label) {
  for (const auto& m : panel.markers)
    if (m.label == label) return &m;
  return nullptr;
}

TEST(PlotSources, DataPointsBesideACurveAreDiamondsBeneathTheRedControlDiscs) {
  PlotOptions options;
  options.bezier.control_points = true;
  const auto figure = plot_figure({curve_source("head.json", {{0, 0}, {1, 2}, {2, 0}}), data_source("head.csv", true, false)},
                                  options);
  ASSERT_TRUE(figure) << figure.error().message;
  const Panel& panel = figure->panels[0];
  const MarkerItem* data = marker_labelled(panel, "head.csv (data points)");
  const MarkerItem* control = marker_labelled(panel, "control points");
  ASSERT_TRUE(data && control);
  EXPECT_EQ(data->shape, MarkerShape::diamond);
  EXPECT_EQ(control->shape, MarkerShape::disc);
  EXPECT_EQ(control->color, colors::red);
  EXPECT_NE(data->color, control->color);
  EXPECT_GT(data->diameter, control->diameter);  // a control point on a data point shows both
  EXPECT_EQ(&panel.markers.front(), data);      // beneath: drawn first
  // Both are in the legend of the laid-out figure: its texts name them.
  const auto scene = layout(*figure);
  ASSERT_TRUE(scene);
  int named = 0;
  for (const auto& shape : scene->shapes)
    if (const auto* text = std::get_if<TextShape>(&shape))
      named += text->text == "head.csv (data points)" || text->text == "control points";
  EXPECT_EQ(named, 2);
}

TEST(PlotSources, DataPolylineAndPointsAlone) {
  const auto both = plot_figure({data_source("p.csv", true, true)}, {});
  ASSERT_TRUE(both);
  EXPECT_EQ(both->panels[0].polylines.size(), 1u);
  EXPECT_EQ(both->panels[0].markers.size(), 1u);
  EXPECT_EQ(both->panels[0].markers[0].label, "");  // one point set alone: nothing to tell apart
  const auto line = plot_figure({data_source("p.csv", false, true), curve_source("c.json", {{0, 0}, {1, 1}})}, {});
  ASSERT_TRUE(line);
  EXPECT_TRUE(line->panels[0].markers.empty());
  ASSERT_EQ(line->panels[0].polylines.size(), 1u);
  EXPECT_EQ(line->panels[0].polylines[0].label, "p.csv (polyline)");
}

TEST(PlotSources, ExtremeInputsNameTheFileAndTheModel) {
  // Control points spanning +-1e308: no range of a figure can hold them.
  auto e = plot_figure({curve_source("big.json", {{-1e308, 0}, {1e308, 1}})}, {});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message.rfind("big.json: ", 0), 0u) << e.error().message;
  PlotSource two = curve_source("two.json", {{0, 0}, {1, 1}});
  two.models.push_back(BezierCurve::from_trusted(*PointArray::make({{0, -1e308}, {1, 1e308}})));
  e = plot_figure({two}, {});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message.rfind("two.json[1]: ", 0), 0u) << e.error().message;
  // Each fine alone, too wide together: both named.
  e = plot_figure({curve_source("l.json", {{-4e304, 0}, {0, 1}}), curve_source("r.json", {{0, 0}, {4e304, 1}})}, {});
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("l.json and r.json together"), std::string::npos) << e.error().message;
  auto data = data_source("big.csv", true, false);
  data.points = *PointArray::make({{-1e308, 0}, {1e308, 0}});
  e = plot_figure({data}, {});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message.rfind("big.csv: ", 0), 0u) << e.error().message;
  // A degree beyond what a figure draws is refused at once, named.
  std::vector<std::vector<double>> many;
  for (int i = 0; i <= tolerances::kMaxPlottedCurveDegree + 1; ++i) many.push_back({static_cast<double>(i), 0.0});
  e = plot_figure({curve_source("high.csv", many)}, {});
  ASSERT_FALSE(e);
  EXPECT_EQ(e.error().message.rfind("high.csv: ", 0), 0u) << e.error().message;
  EXPECT_NE(e.error().message.find(std::to_string(tolerances::kMaxPlottedCurveDegree)), std::string::npos);
}

TEST(PlotSources, LayoutErrorsNameTheCurvesFile) {
  // A cubic 1 unit wide at x = 1e10: its quarter pixel (4e-4) is below what
  // double precision certifies there (1e-2): the flattening's error is
  // raised at layout time, and names the file and model it comes from.
  PlotSource far = curve_source("near.json", {{0, 0}, {1, 1}});
  far.models.push_back(
      BezierCurve::make(*PointArray::make({{1e10, 0}, {1e10, 1}, {1e10 + 1, 1}, {1e10 + 1, 0}})).value());
  far.models.erase(far.models.begin());
  const auto figure = plot_figure({far}, {});
  ASSERT_TRUE(figure);
  const auto scene = layout(*figure);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().message.rfind("near.json: ", 0), 0u) << scene.error().message;
}

}  // namespace
}  // namespace casteljau::render
