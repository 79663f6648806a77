// Every Error carries a kind beside its message (core/expected.hpp), so that
// a caller can branch on what went wrong without reading the sentence: one
// real refusal of each kind, from the layer that makes it, and the kinds kept
// when an error travels up with context added.
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/knot_insertion.hpp"
#include "casteljau/bspline/knot_vector.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/io/csv.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model_json.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace casteljau {
namespace {

BezierCurve cubic() {
  return BezierCurve::make(PointArray::make({{0, 0}, {1, 2}, {3, 2}, {4, 0}}).value()).value();
}

TEST(ErrorKind, TheDefaultIsInvalidArgument) {
  const Error error{"the control polygon is empty"};
  EXPECT_EQ(error.kind, ErrorKind::invalid_argument);
  const auto nan = PointArray::make({{0, std::numeric_limits<double>::quiet_NaN()}});
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().kind, ErrorKind::invalid_argument);
  EXPECT_STREQ(name_of(ErrorKind::out_of_domain), "out_of_domain");
  EXPECT_STREQ(name_of(ErrorKind::singular), "singular");
}

TEST(ErrorKind, AParameterOutsideTheDomainIsOutOfDomain) {
  const auto halves = split_at(cubic(), 1.5);
  ASSERT_FALSE(halves.has_value());
  EXPECT_EQ(halves.error().kind, ErrorKind::out_of_domain) << halves.error().message;
  const BSplineCurve spline =
      BSplineCurve::make(2, clamped_uniform_knots(2, 4), PointArray::make({{0, 0}, {1, 1}, {2, 0}, {3, 1}}).value())
          .value();
  const auto inserted = insert_knot(spline, 7.0);
  ASSERT_FALSE(inserted.has_value());
  EXPECT_EQ(inserted.error().kind, ErrorKind::out_of_domain) << inserted.error().message;
}

TEST(ErrorKind, ATooDeepSubdivisionIsALimit) {
  const auto points = subdivide_recursive(cubic(), 1000, 0.5);
  ASSERT_FALSE(points.has_value());
  EXPECT_EQ(points.error().kind, ErrorKind::limit) << points.error().message;
}

TEST(ErrorKind, BadTextIsAParseError) {
  const auto table = parse_points_csv("x,y\n1,2\n3,abc\n", "points.csv");
  ASSERT_FALSE(table.has_value());
  EXPECT_EQ(table.error().kind, ErrorKind::parse) << table.error().message;
  EXPECT_EQ(parse_number("1,5").error().kind, ErrorKind::parse);
  const auto model = parse_models_json("{\"type\": \"bezier\", \"control_points\": [[0, 0], [1]]}", "m.json");
  ASSERT_FALSE(model.has_value());
  EXPECT_EQ(model.error().kind, ErrorKind::parse) << model.error().message;
}

TEST(ErrorKind, AFileThatCannotBeReadIsAnIoError) {
  const auto text = read_text_file("/nonexistent/casteljau/points.csv");
  ASSERT_FALSE(text.has_value());
  EXPECT_EQ(text.error().kind, ErrorKind::io) << text.error().message;
  const Status written = write_file_atomically("/nonexistent/casteljau/out.json", "{}");
  ASSERT_FALSE(written.has_value());
  EXPECT_EQ(written.error().kind, ErrorKind::io) << written.error().message;
}

TEST(ErrorKind, ContextKeepsTheKind) {
  const Error inner{"the file is empty", ErrorKind::io};
  const Error outer = with_context(inner, "reading 'head.csv'");
  EXPECT_EQ(outer.kind, ErrorKind::io);
  EXPECT_EQ(outer.message, "reading 'head.csv': the file is empty");
  const Expected<int> failed = inner;
  EXPECT_EQ(failed.transform_error([](const Error& e) { return with_context(e, "loading"); }).error().kind,
            ErrorKind::io);
}

}  // namespace
}  // namespace casteljau
