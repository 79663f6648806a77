// CSV point sets (docs/formats.md, "Point sets"): every accepted form, every
// refused one with the exact message (file, line, field), and the output
// format reading back to the same doubles bit for bit.
#include "casteljau/io/csv.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/model.hpp"
#include "support/examples_dir.hpp"
#include "io_test_support.hpp"

namespace casteljau {
namespace {

PointArray parse(const std::string& text) {
  auto points = parse_points_csv(text, "p.csv");
  EXPECT_TRUE(points.has_value()) << points.error().message;
  return points ? *points : PointArray{};
}

std::string csv_error(const std::string& text) {
  const auto points = parse_points_csv(text, "p.csv");
  EXPECT_FALSE(points.has_value()) << text;
  return points ? std::string{} : points.error().message;
}

PointArray points(int d, std::vector<double> c) { return PointArray::make(d, std::move(c)).value(); }

TEST(PointsCsv, ReadsCommentsHeaderBlankLinesAndBlanksAroundFields) {
  EXPECT_EQ(parse("# a comment\nx,y\n0,0\n\n  # indented comment\n 1 ,\t2 \n4,0\n"), points(2, {0, 0, 1, 2, 4, 0}));
}

TEST(PointsCsv, HeaderIsOptional) { EXPECT_EQ(parse("0,0\n1,2\n"), points(2, {0, 0, 1, 2})); }

TEST(PointsCsv, AnyNamesMakeAHeaderOfAnyWidth) {
  EXPECT_EQ(parse("x,y,z\n1,2,3\n"), points(3, {1, 2, 3}));
  EXPECT_EQ(parse("lon , lat\n1,2\n"), points(2, {1, 2}));
  EXPECT_EQ(parse("t\n0.5\n"), points(1, {0.5}));
}

TEST(PointsCsv, AcceptsCrlfByteOrderMarkAndNoFinalNewline) {
  EXPECT_EQ(parse("\xEF\xBB\xBFx,y\r\n1,2\r\n\r\n3,4"), points(2, {1, 2, 3, 4}));
}

TEST(PointsCsv, NumbersAreReadWholeAndCorrectlyRounded) {
  // The reference is glibc's strtod, an implementation independent of
  // libstdc++'s from_chars that the reader uses.
  const char* texts[] = {"0.1", "-2.5e-3", "1e308", "4e-320", ".5", "5.", "-0", "123456789012345678901234567890"};
  for (const char* text : texts) {
    const auto p = parse(std::string(text) + "\n");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(test::bits_of(p[0][0]), test::bits_of(std::strtod(text, nullptr))) << text;
  }
}

TEST(PointsCsv, AcceptsALeadingPlusAndUnderflowToZero) {
  const auto p = parse("+1,1e-400\n-1,-1e-400\n");
  EXPECT_EQ(p, points(2, {1, 0, -1, -0.0}));
  EXPECT_TRUE(std::signbit(p[1][1]));
}

TEST(PointsCsv, RefusesBadFieldsNamingFileLineAndField) {
  EXPECT_EQ(csv_error("x,y\n0,0\n1,abc\n"), "p.csv, line 3, field 2: 'abc' is not a number");
  EXPECT_EQ(csv_error("# c\n\n0,0\n1,2 # note\n"), "p.csv, line 4, field 2: '2 # note' is not a number");
  EXPECT_EQ(csv_error("0,0\n1,0x10\n"), "p.csv, line 2, field 2: '0x10' is not a number");
  EXPECT_EQ(csv_error("0,0\n1,1e\n"), "p.csv, line 2, field 2: '1e' is not a number");
  EXPECT_EQ(csv_error("0,0\n++1,0\n"), "p.csv, line 2, field 1: '++1' is not a number");
  EXPECT_EQ(csv_error("0,0\n\"1\",0\n"), "p.csv, line 2, field 1: '\"1\"' is not a number");
  EXPECT_EQ(csv_error("0,0\n1,\n"), "p.csv, line 2, field 2: the value is empty, expected a number");
  EXPECT_EQ(csv_error("0,0\n , 1\n"), "p.csv, line 2, field 1: the value is empty, expected a number");
}

TEST(PointsCsv, RefusesNonFiniteValues) {
  EXPECT_EQ(csv_error("x,y\n0,nan\n"), "p.csv, line 2, field 2: 'nan' is NaN, numbers must be finite");
  EXPECT_EQ(csv_error("x,y\n-inf,0\n"), "p.csv, line 2, field 1: '-inf' is infinite, numbers must be finite");
  EXPECT_EQ(csv_error("x,y\n0,Infinity\n"), "p.csv, line 2, field 2: 'Infinity' is infinite, numbers must be finite");
  EXPECT_EQ(csv_error("x,y\n0,1e999\n"),
            "p.csv, line 2, field 2: '1e999' overflows to infinity, numbers must be finite");
  EXPECT_EQ(csv_error("x,y\n0,-1e999\n"),
            "p.csv, line 2, field 2: '-1e999' overflows to infinity, numbers must be finite");
}

TEST(PointsCsv, RefusesRaggedRows) {
  EXPECT_EQ(csv_error("x,y\n0,0\n1,2,3\n"),
            "p.csv, line 3: 3 fields, but the header on line 1 has 2 (every row must have the same number of fields)");
  EXPECT_EQ(csv_error("# c\n0,0,0\n\n1,2\n"),
            "p.csv, line 4: 2 fields, but the first row on line 2 has 3 (every row must have the same number of "
            "fields)");
  EXPECT_EQ(csv_error("x,y\n0\n"),
            "p.csv, line 2: 1 field, but the header on line 1 has 2 (every row must have the same number of fields)");
}

TEST(PointsCsv, RefusesMixedOrLateHeaders) {
  EXPECT_EQ(csv_error("x,1\n0,0\n"), "p.csv, line 1, field 1: 'x' is not a number");
  EXPECT_EQ(csv_error("x,y\n0,0\nx,y\n"), "p.csv, line 3, field 1: 'x' is not a number");
  EXPECT_EQ(csv_error("x,,z\n1,2,3\n"), "p.csv, line 1, field 2: empty column name in the header row");
}

TEST(PointsCsv, RefusesAFileWithoutPoints) {
  const std::string message = "p.csv: no points (only comments and blank lines)";
  EXPECT_EQ(csv_error(""), message);
  EXPECT_EQ(csv_error("\n\n  \n"), message);
  EXPECT_EQ(csv_error("# only a comment\n"), message);
  EXPECT_EQ(csv_error("# c\nx,y\n# header only\n"), "p.csv: no points after the header row on line 2");
}

// Separators (docs/formats.md, "Point sets"): the first row chooses ',', ';'
// or tab; the decimal mark is always '.'. The reference is the same points
// written with ',' and '.'.
TEST(PointsCsv, ReadsSemicolonAndTabSeparatedFilesWithOrWithoutAHeader) {
  const PointArray head = points(2, {9.5, 5, 5.5, 5, 1, 7});
  EXPECT_EQ(parse("x;y\n9.5;5\n5.5;5\n1;7\n"), head);
  EXPECT_EQ(parse("# seed 000\n9.5 ; 5\r\n5.5;5\n\n1;7"), head);
  EXPECT_EQ(parse("x\ty\n9.5\t5\n5.5\t5\n1\t7\n"), head);
  EXPECT_EQ(parse("9.5\t5\n 5.5\t5\t\n1\t7\n"), head);  // blanks around the row are not fields
  EXPECT_EQ(parse("x,y\n9.5,\t5\n5.5\t,5\n1,7\n"), head);  // tabs beside ',' stay blanks
  EXPECT_EQ(parse("t;u;v\n1;2;3\n"), points(3, {1, 2, 3}));
}

TEST(PointsCsv, RefusesDecimalCommasAndSaysHowToConvert) {
  // As the seeds print numbers: A(-3;0), 9,5.
  const std::string hint =
      "uses ',' as the decimal mark; casteljau reads '.' as the decimal mark, and ',', ';' or tabs between values "
      "(convert with: sed 's/,/./g')";
  EXPECT_EQ(csv_error("x;y\n9,5;5\n"), "p.csv, line 2, field 1: '9,5' " + hint);
  EXPECT_EQ(csv_error("9,5;5,5\n"), "p.csv, line 1, field 1: '9,5' " + hint);  // not a header
  EXPECT_EQ(csv_error("9;5\n5;-0,5\n"), "p.csv, line 2, field 2: '-0,5' " + hint);
  EXPECT_EQ(csv_error("x\ty\n9,5\t5\n"), "p.csv, line 2, field 1: '9,5' " + hint);
  EXPECT_EQ(csv_error("9,5\t5\n"), "p.csv, line 1, field 1: '9,5' " + hint);
  // What the hint's command makes of them reads.
  EXPECT_EQ(parse("x;y\n9.5;5\n"), points(2, {9.5, 5}));
  // Not a decimal comma: two commas, or a comma and a point.
  EXPECT_EQ(csv_error("x;y\n1,000,5;5\n"), "p.csv, line 2, field 1: '1,000,5' is not a number");
  EXPECT_EQ(csv_error("x;y\n1,000.5;5\n"), "p.csv, line 2, field 1: '1,000.5' is not a number");
}

TEST(PointsCsv, RefusesRowsWithAnotherSeparatorThanTheFirstRow) {
  EXPECT_EQ(csv_error("x,y\n9.5;5\n"),
            "p.csv, line 2: 1 field, but the header on line 1 has 2 (every row must have the same number of "
            "fields); line 1 separates values by ',', this line has ';'");
  EXPECT_EQ(csv_error("x;y\n9.5,5\n"),
            "p.csv, line 2: 1 field, but the header on line 1 has 2 (every row must have the same number of "
            "fields); line 1 separates values by ';', this line has ','");
  EXPECT_EQ(csv_error("0,0\n9.5\t5\n"),
            "p.csv, line 2: 1 field, but the first row on line 1 has 2 (every row must have the same number of "
            "fields); line 1 separates values by ',', this line has tabs");
  EXPECT_EQ(csv_error("x,y\n9,5;5\n"),
            "p.csv, line 2, field 2: '5;5' is not a number; values are separated by ',' on line 1, and this line has "
            "';' (one separator for the whole file: ',', ';' or tabs)");
}

TEST(PointsCsv, RefusesSpaceSeparatedNumbersWithAHint) {
  EXPECT_EQ(csv_error("9.5 5\n5.5 5\n"),
            "p.csv, line 1, field 1: '9.5 5' holds numbers separated by spaces; casteljau reads ',', ';' or tabs "
            "between values (convert with: sed -E 's/ +/,/g')");
  EXPECT_EQ(csv_error("x,y\n1 2,3\n"),
            "p.csv, line 2, field 1: '1 2' holds numbers separated by spaces; casteljau reads ',', ';' or tabs "
            "between values (convert with: sed -E 's/ +/,/g')");
  EXPECT_EQ(csv_error("x,y\n1 a,3\n"), "p.csv, line 2, field 1: '1 a' is not a number");
}

TEST(PointsCsv, MessagesStayOnOneLineAndShort) {
  // A stray carriage return and a control character inside a field, and a
  // huge field: the message escapes them and is cut.
  EXPECT_EQ(csv_error("0,0\n1,2\r3\n"), "p.csv, line 2, field 2: '2\\x0d3' is not a number");
  // Bytes that are not UTF-8 are escaped too; UTF-8 text is kept.
  EXPECT_EQ(csv_error("0,0\n1,\xff\xc3\n"), "p.csv, line 2, field 2: '\\xff\\xc3' is not a number");
  EXPECT_EQ(csv_error("0,0\n1,\xc3\xa9t\xc3\xa9\n"), "p.csv, line 2, field 2: '\xc3\xa9t\xc3\xa9' is not a number");
  const std::string message = csv_error("0,0\n1," + std::string(100000, 'a') + "\n");
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_LT(message.size(), 200u);
}

TEST(PointsCsv, RefusesMoreThanTheLimitOfPoints) {
  std::string text;
  text.reserve(2 * (tolerances::kMaxControlPoints + 1));
  for (std::size_t i = 0; i <= tolerances::kMaxControlPoints; ++i) text += "0\n";
  EXPECT_EQ(csv_error(text), "p.csv, line 10000001: more than 10000000 points, the limit for one file");
  text.resize(text.size() - 2);  // exactly the limit is accepted
  EXPECT_EQ(parse_points_csv(text, "p.csv").value().size(), tolerances::kMaxControlPoints);
}

TEST(PointsCsv, RefusesAHugeRowWithoutStoringIt) {
  // 50,000,001 empty fields in one row: refused from the comma count alone.
  const std::string text(tolerances::kMaxInputValues, ',');
  EXPECT_EQ(csv_error(text), "p.csv, line 1: more than 50000000 numbers, the limit for one file");
}

TEST(PointsCsv, FormatsShortestRoundTripOnePointPerLine) {
  EXPECT_EQ(format_points_csv(points(2, {2.25, 1.5, 0.1, -0.0})), "2.25,1.5\n0.1,-0\n");
  EXPECT_EQ(format_points_csv(points(3, {1e-17, 1e300, 1.0 / 3})), "1e-17,1e+300,0.3333333333333333\n");
  EXPECT_EQ(format_points_csv(points(1, {5, -7})), "5\n-7\n");
  EXPECT_EQ(format_points_csv(PointArray{}), "");
}

TEST(PointsCsv, AppendWritesNonFiniteComputedValues) {
  std::string out = "x\n";
  const double values[] = {1.0, HUGE_VAL, -HUGE_VAL, std::nan("")};
  append_points_csv(out, values, 2);
  EXPECT_EQ(out, "x\n1,inf\n-inf,nan\n");
}

RC_GTEST_PROP(PointsCsv, OutputReadsBackToTheSameDoubles, ()) {
  const int d = *rc::gen::inRange(1, 5);
  const std::size_t n = *rc::gen::inRange(1, 20);
  const auto coordinates = *rc::gen::container<std::vector<double>>(n * d, test::any_finite_double());
  const auto original = PointArray::make(d, coordinates).value();
  const auto back = parse_points_csv(format_points_csv(original), "round trip");
  RC_ASSERT(back.has_value());
  RC_ASSERT(back->dimension() == d);
  RC_ASSERT(back->size() == n);
  for (std::size_t k = 0; k < coordinates.size(); ++k)
    RC_ASSERT(test::bits_of(back->coordinates()[k]) == test::bits_of(coordinates[k]));
}

TEST(ParseNumber, IsStrictAboutTheWholeText) {
  EXPECT_EQ(*parse_number("0.25"), 0.25);
  EXPECT_EQ(*parse_number("+3"), 3.0);
  EXPECT_EQ(parse_number(" 1").error().message, "' 1' is not a number");
  EXPECT_EQ(parse_number("1,5").error().message, "'1,5' is not a number");
  EXPECT_EQ(parse_number("").error().message, "the value is empty, expected a number");
  EXPECT_EQ(parse_number("NaN").error().message, "'NaN' is NaN, numbers must be finite");
}

TEST(NumbersCsv, ReadsOneColumnWithTheLineOfEachValue) {
  const auto column = parse_numbers_csv("# parameters\nt\n0\n\n0.5\r\n1\n", "t.csv", 10);
  ASSERT_TRUE(column.has_value()) << column.error().message;
  EXPECT_EQ(column->values, (std::vector<double>{0, 0.5, 1}));
  EXPECT_EQ(column->lines, (std::vector<std::size_t>{3, 5, 6}));
}

TEST(NumbersCsv, RefusesSeveralColumnsTooManyValuesAndBadFields) {
  EXPECT_EQ(parse_numbers_csv("t,u\n0,1\n", "t.csv", 10).error().message,
            "t.csv, line 2: 2 fields, expected one number per line");
  EXPECT_EQ(parse_numbers_csv("0\n1\n2\n", "t.csv", 2).error().message,
            "t.csv, line 3: more than 2 values, the limit for one file");
  EXPECT_EQ(parse_numbers_csv("0\nhalf\n", "t.csv", 10).error().message,
            "t.csv, line 2, field 1: 'half' is not a number");
  EXPECT_EQ(parse_numbers_csv("# none\n", "t.csv", 10).error().message,
            "t.csv: no values (only comments and blank lines)");
  EXPECT_EQ(parse_numbers_csv("t\n0\n0,5\n", "t.csv", 10).error().message,
            "t.csv, line 3: 2 fields, but the header on line 1 has 1 (every row must have the same number of fields); "
            "'0,5' uses ',' as the decimal mark, casteljau reads '.' (convert with: sed 's/,/./g')");
}

TEST(PointsCsvFiles, ReadTheExamplesAndNameTheFileInErrors) {
  const std::string examples = test::examples_dir().string();
  const auto head = read_points_csv(examples + "/head.csv");
  ASSERT_TRUE(head.has_value()) << head.error().message;
  EXPECT_EQ(head->size(), 19u);  // seed 000, Figure 3
  EXPECT_EQ(read_points_csv(examples + "/car.csv").value().size(), 26u);
  const auto polygon = read_points_csv(examples + "/notebook_polygon.csv");
  EXPECT_EQ(*polygon, points(2, {0, 0, 1, 2, 2, 2, 4, 1, 4, 0}));  // seed 004

  test::TemporaryFolder folder;
  test::write_text(folder / "bad.csv", "x,y\n1,2\n3,four\n");
  EXPECT_EQ(read_points_csv(folder / "bad.csv").error().message,
            (folder / "bad.csv").string() + ", line 3, field 2: 'four' is not a number");
  EXPECT_EQ(read_points_csv(folder / "missing.csv").error().message,
            "cannot open '" + (folder / "missing.csv").string() + "': No such file or directory");
  test::write_text(folder / "t.csv", "t\n0.25\n");
  EXPECT_EQ(*read_numbers_csv(folder / "t.csv"), std::vector<double>{0.25});
}

}  // namespace
}  // namespace casteljau
