#pragma once
// Point sets as CSV (docs/formats.md): '#' comment lines, an optional header
// row (x,y or x,y,z, ...), one point per line, fields separated by ','.
// Bad rows are errors that name the line and the field.

#include <filesystem>
#include <string>
#include <string_view>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// Parses CSV text; `source` names it in errors ("head.csv, line 7, field 2:
/// 'abc' is not a number"). All rows must have the same number of fields;
/// NaN, infinite values and empty fields are refused; an empty point set is refused.
Expected<PointArray> parse_points_csv(std::string_view text, const std::string& source);

/// Reads and parses a CSV file (errors name the file).
Expected<PointArray> read_points_csv(const std::filesystem::path& path);

/// One point per line, coordinates separated by ',', each written as the
/// shortest text that reads back to the same double.
std::string format_points_csv(const PointArray& points);

/// Reads a single column of numbers (parameters for `eval --params`), same rules.
Expected<std::vector<double>> read_numbers_csv(const std::filesystem::path& path);

}  // namespace casteljau
