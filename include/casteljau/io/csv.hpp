#pragma once
// Point sets as CSV (docs/formats.md): '#' comment lines, an optional header
// row of column names (x,y or x,y,z, ...), one point per line, fields
// separated by ',' (or ';' or tabs, as the first row shows), '.' the decimal
// mark. Bad rows are errors that name the file, line and field.

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// Parses CSV text into points; `source` names it in errors
/// ("head.csv, line 7, field 2: 'abc' is not a number"). Lines and fields
/// count from 1. Rules (docs/formats.md, "Point sets"):
/// - a line whose first non-blank character is '#' is a comment; blank lines
///   are ignored; "\r\n" line ends and a leading UTF-8 byte order mark are accepted;
/// - fields are separated by one character for the whole file, chosen by its
///   first row (header or point): ';' if the row holds one, a tab if a tab
///   stands inside a ','-separated field ("1\t2"), else ','; spaces and tabs
///   around a field (and around the row) are ignored;
/// - the decimal mark is '.': a field that would be a number with its ','
///   read as '.' ("9,5", as spreadsheets write where ',' is the decimal mark)
///   is refused with the conversion to run ("... uses ',' as the decimal
///   mark; ... (convert with: sed 's/,/./g')"), and so are a row written with
///   another separator than the first row's and numbers separated by spaces,
///   each message saying what was found and what casteljau reads;
/// - the first row is a header when none of its fields is a number, in
///   casteljau's notation or the ones above (non-empty names); a row with
///   some numbers and some non-numbers is a bad row;
/// - a number is the whole field, read by std::from_chars (general format),
///   with an optional leading '+'; NaN, infinities and values that overflow
///   (1e999) are refused; values that underflow (1e-400) read as 0 or subnormal;
/// - every row has as many fields as the first row (header or not);
/// - at least one point; at most tolerances::kMaxControlPoints points.
/// O(size of the text).
Expected<PointArray> parse_points_csv(std::string_view text, const std::string& source);

/// Reads and parses a CSV file (errors name the file as given).
Expected<PointArray> read_points_csv(const std::filesystem::path& path);

/// One number written as text, by the same rules as a CSV field: the whole
/// text (no blanks around it), an optional leading '+', finite. Errors carry
/// no location (the caller adds it): "'abc' is not a number", "'nan' is NaN,
/// numbers must be finite", "'1e999' overflows to infinity, numbers must be finite".
Expected<double> parse_number(std::string_view text);

/// Appends points given row-major (`coordinates.size()` a multiple of
/// `dimension`) to `out` in the format of format_points_csv. Non-finite
/// values (only computed ones can be) are written "inf", "-inf", "nan".
void append_points_csv(std::string& out, std::span<const double> coordinates, int dimension);

/// One point per line, coordinates separated by ',', each written by fmt's
/// "{}" (the shortest text that reads back to the same double: 2.25, 1e-17,
/// -0), lines ended by '\n'. Reading the text back with parse_points_csv
/// gives the same doubles, bit for bit.
std::string format_points_csv(const PointArray& points);

/// A single column of numbers and the line each one came from.
struct NumberColumn {
  std::vector<double> values;
  std::vector<std::size_t> lines;  ///< 1-based line of values[i] in the text
};

/// Parses a single column of numbers (parameters for `eval --params`) with
/// the same rules as parse_points_csv (comments, optional header such as
/// "t"), exactly one field per row, at least one value and at most
/// `max_values` of them.
Expected<NumberColumn> parse_numbers_csv(std::string_view text, const std::string& source, std::size_t max_values);

/// Reads a single column of numbers from a file (parse_numbers_csv rules,
/// at most tolerances::kMaxEvaluationParameters values).
Expected<std::vector<double>> read_numbers_csv(const std::filesystem::path& path);

}  // namespace casteljau
