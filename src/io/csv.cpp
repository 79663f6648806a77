#include "casteljau/io/csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <system_error>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/model.hpp"
#include "casteljau/io/tolerance.hpp"
#include "text.hpp"

namespace casteljau {
namespace {

using io_detail::in_quotes;

/// What reading one field found. `decimal_comma`: not a number, but one if
/// its single ',' were a '.' ("9,5"), as spreadsheets write numbers where ','
/// is the decimal mark.
enum class FieldKind { number, empty, not_a_number, decimal_comma, nan, infinite, overflow };

struct Field {
  FieldKind kind = FieldKind::not_a_number;
  double value = 0.0;
};

/// Spaces and tabs around a field are not part of it.
std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// Reads a whole (trimmed) field as a double: std::from_chars, general
/// format, correctly rounded; an optional '+' is accepted (from_chars alone
/// refuses it, but every spreadsheet and numpy writes or reads it).
Field read_field(std::string_view text) {
  if (text.empty()) return {FieldKind::empty};
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0.0;
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (ptr != end || ec == std::errc::invalid_argument) {
    const std::size_t comma = text.find(',');
    if (comma != text.npos && text.find(',', comma + 1) == text.npos && text.find('.') == text.npos) {
      std::string dotted(text);
      dotted[comma] = '.';
      if (read_field(dotted).kind == FieldKind::number) return {FieldKind::decimal_comma};
    }
    return {FieldKind::not_a_number};
  }
  if (ec == std::errc::result_out_of_range) {
    // from_chars reports overflow and underflow alike. Underflow reads as the
    // nearest representable value (0 or a subnormal, as in JSON, numpy or
    // Python); overflow is refused. strtod tells them apart (the program runs
    // in the "C" locale, so its decimal point is '.').
    const std::string copy(digits);
    const double rounded = std::strtod(copy.c_str(), nullptr);
    if (std::isinf(rounded)) return {FieldKind::overflow};
    return {FieldKind::number, rounded};
  }
  if (std::isnan(value)) return {FieldKind::nan};
  if (std::isinf(value)) return {FieldKind::infinite};
  return {FieldKind::number, value};
}

/// The numbers of a CSV text, row by row, all rows the same width.
struct Table {
  std::size_t width = 0;
  std::vector<double> values;      // row-major
  std::vector<std::size_t> lines;  // line of each row (only when asked for)
};

std::string where(const std::string& source, std::size_t line) { return fmt::format("{}, line {}", source, line); }

std::string where(const std::string& source, std::size_t line, std::size_t field) {
  return fmt::format("{}, line {}, field {}", source, line, field);
}

/// The separator of a file, chosen by its first row (header or point), so
/// that what spreadsheets and numpy write reads as it is: ';' when the row
/// holds one (a ','-separated row of numbers never does); a tab when one
/// stands inside a ','-separated field rather than around it ("1\t2",
/// "9,5\t5"; "1,\t2" is ',' with a blank); ',' otherwise.
char separator_of(std::string_view row) {
  if (row.find(';') != row.npos) return ';';
  for (std::size_t start = 0;;) {
    const std::size_t comma = row.find(',', start);
    if (trim(row.substr(start, comma == row.npos ? row.npos : comma - start)).find('\t') != row.npos) return '\t';
    if (comma == row.npos) return ',';
    start = comma + 1;
  }
}

std::string separator_name(char separator) {
  return separator == '\t' ? std::string("tabs") : fmt::format("'{}'", separator);
}

/// A separator other than the file's that `text` holds, or 0: what a row
/// written with another separator than the first row's shows.
char other_separator(std::string_view text, char separator) {
  for (const char candidate : {';', '\t', ','}) {
    if (candidate != separator && text.find(candidate) != text.npos) return candidate;
  }
  return 0;
}

/// True when `text` is numbers separated by runs of spaces ("9.5 5", numpy's
/// savetxt default): a hint, not a format casteljau reads.
bool is_blank_separated(std::string_view text) {
  if (text.find(' ') == text.npos) return false;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t blank = std::min(text.find(' ', start), text.size());
    if (blank > start && read_field(text.substr(start, blank - start)).kind != FieldKind::number) return false;
    start = blank + 1;
  }
  return true;
}

/// Where the rows of a file are, for messages.
struct TableContext {
  const std::string& source;
  char separator;
  std::size_t first_row_line;
};

Error field_error(const TableContext& table, std::size_t line, std::size_t index, std::string_view text) {
  const std::string location = where(table.source, line, index);
  if (read_field(text).kind == FieldKind::decimal_comma) {
    return Error{fmt::format("{}: {} uses ',' as the decimal mark; casteljau reads '.' as the decimal mark, and ',', "
                             "';' or tabs between values (convert with: sed 's/,/./g')",
                             location, in_quotes(text)), ErrorKind::parse};
  }
  if (const char other = other_separator(text, table.separator); other != 0 && other != ',') {
    return Error{fmt::format("{}: {} is not a number; values are separated by {} on line {}, and this line has {} "
                             "(one separator for the whole file: ',', ';' or tabs)",
                             location, in_quotes(text), separator_name(table.separator), table.first_row_line,
                             separator_name(other)), ErrorKind::parse};
  }
  if (is_blank_separated(text)) {
    return Error{fmt::format("{}: {} holds numbers separated by spaces; casteljau reads ',', ';' or tabs between "
                             "values (convert with: sed -E 's/ +/,/g')",
                             location, in_quotes(text)), ErrorKind::parse};
  }
  return with_context(parse_number(text).error(), location);
}

/// The shared reader behind points and number columns. `what` names the rows
/// in the limit's message ("points", "values").
Expected<Table> parse_table(std::string_view text, const std::string& source, std::size_t max_rows, bool keep_lines,
                            const char* what) {
  text = io_detail::without_byte_order_mark(text);
  Table table;
  std::size_t rows = 0;
  std::size_t first_row_line = 0;  // the line whose width every row must have
  bool first_row = true;
  bool has_header = false;
  char separator = ',';  // chosen by the first row

  std::size_t line = 0;
  while (!text.empty()) {
    ++line;
    const std::size_t newline = text.find('\n');
    std::string_view row = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    if (!row.empty() && row.back() == '\r') row.remove_suffix(1);  // CRLF

    const std::string_view content = trim(row);
    if (content.empty() || content.front() == '#') continue;  // blank line or comment

    if (first_row) separator = separator_of(content);
    // Fields come from the trimmed row: blanks around the row are not empty
    // fields, also when the blank is the separator (a tab).
    const auto count = static_cast<std::size_t>(std::count(content.begin(), content.end(), separator)) + 1;
    if (!first_row && count != table.width) {
      // A row without the file's separator but with another one was
      // written with another separator: say so. In a file of one column,
      // "0,5" is a decimal comma.
      const char other = count == 1 ? other_separator(content, separator) : 0;
      std::string hint;
      if (other != 0) {
        hint = fmt::format("; line {} separates values by {}, this line has {}", first_row_line,
                           separator_name(separator), separator_name(other));
      } else if (table.width == 1 && read_field(content).kind == FieldKind::decimal_comma) {
        hint = fmt::format("; {} uses ',' as the decimal mark, casteljau reads '.' (convert with: sed 's/,/./g')",
                           in_quotes(content));
      }
      return Error{fmt::format("{}: {} field{}, but {} line {} has {} (every row must have the same number of "
                               "fields){}",
                               where(source, line), count, count == 1 ? "" : "s",
                               has_header ? "the header on" : "the first row on", first_row_line, table.width, hint), ErrorKind::parse};
    }
    const std::size_t row_start = table.values.size();
    if (row_start + count > tolerances::kMaxInputValues) {
      return Error{fmt::format("{}: more than {} numbers, the limit for one file", where(source, line),
                               tolerances::kMaxInputValues), ErrorKind::limit};
    }
    // One pass over the fields, values straight into the table: no per-row
    // copies, so memory stays 8 bytes per number whatever the row's width.
    std::size_t numbers = 0, first_bad = 0, first_empty = 0;  // field indices from 1; 0: none
    std::string_view first_bad_text;
    std::size_t index = 0;
    for (std::size_t start = 0;;) {
      const std::size_t comma = content.find(separator, start);
      const std::string_view field =
          trim(content.substr(start, comma == std::string_view::npos ? content.npos : comma - start));
      ++index;
      const Field parsed = read_field(field);
      if (parsed.kind == FieldKind::number) {
        table.values.push_back(parsed.value);
      } else if (first_bad == 0) {
        first_bad = index;
        first_bad_text = field;
        if (!first_row) break;  // a data row: the first bad field is the error
      }
      // A header's names are no numbers, not even numbers in another
      // notation ("9,5", "9.5 5"): such a row is a bad data row.
      if ((parsed.kind != FieldKind::not_a_number && parsed.kind != FieldKind::empty) ||
          (first_row && parsed.kind == FieldKind::not_a_number && is_blank_separated(field))) {
        ++numbers;
      }
      if (parsed.kind == FieldKind::empty && first_empty == 0) first_empty = index;
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (first_row) {
      first_row = false;
      first_row_line = line;
      table.width = count;
      if (numbers == 0) {
        // A header: column names, none of them a number.
        has_header = true;
        if (first_empty != 0) return Error{where(source, line, first_empty) + ": empty column name in the header row", ErrorKind::parse};
        table.values.resize(row_start);
        continue;
      }
    }
    if (first_bad != 0) return field_error({source, separator, first_row_line}, line, first_bad, first_bad_text);
    if (rows == max_rows) {
      return Error{fmt::format("{}: more than {} {}, the limit for one file", where(source, line), max_rows, what), ErrorKind::limit};
    }
    ++rows;
    if (keep_lines) table.lines.push_back(line);
  }
  if (rows == 0) {
    if (has_header)
      return Error{fmt::format("{}: no {} after the header row on line {}", source, what, first_row_line), ErrorKind::parse};
    return Error{fmt::format("{}: no {} (only comments and blank lines)", source, what), ErrorKind::parse};
  }
  return table;
}

}  // namespace

Expected<PointArray> parse_points_csv(std::string_view text, const std::string& source) {
  auto table = parse_table(text, source, tolerances::kMaxControlPoints, false, "points");
  if (!table) return table.error();
  // Every value was checked finite above: no second pass through make().
  return PointArray::from_trusted(static_cast<int>(table->width), std::move(table->values));
}

Expected<PointArray> read_points_csv(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  return parse_points_csv(*text, display_name(path));
}

Expected<double> parse_number(std::string_view text) {
  const Field field = read_field(text);
  if (field.kind == FieldKind::number) return field.value;
  switch (field.kind) {
    case FieldKind::empty:
      return Error{"the value is empty, expected a number", ErrorKind::parse};
    case FieldKind::nan:
      return Error{in_quotes(text) + " is NaN, numbers must be finite", ErrorKind::parse};
    case FieldKind::infinite:
      return Error{in_quotes(text) + " is infinite, numbers must be finite", ErrorKind::parse};
    case FieldKind::overflow:
      return Error{in_quotes(text) + " overflows to infinity, numbers must be finite", ErrorKind::parse};
    default:
      return Error{in_quotes(text) + " is not a number", ErrorKind::parse};
  }
}

void append_points_csv(std::string& out, std::span<const double> coordinates, int dimension) {
  assert(dimension >= 1 && coordinates.size() % static_cast<std::size_t>(dimension) == 0);
  // The longest shortest-round-trip double is 24 characters (-2.2250738585072014e-308).
  char number[32];
  std::size_t column = 0;
  for (const double x : coordinates) {
    const auto written = fmt::format_to_n(number, sizeof number, "{}", x);
    out.append(number, written.out);
    if (++column == static_cast<std::size_t>(dimension)) {
      out.push_back('\n');
      column = 0;
    } else {
      out.push_back(',');
    }
  }
}

std::string format_points_csv(const PointArray& points) {
  std::string out;
  if (points.empty()) return out;
  append_points_csv(out, points.coordinates(), points.dimension());
  return out;
}

Expected<NumberColumn> parse_numbers_csv(std::string_view text, const std::string& source, std::size_t max_values) {
  auto table = parse_table(text, source, max_values, true, "values");
  if (!table) return table.error();
  if (table->width != 1) {
    return Error{
        fmt::format("{}: {} fields, expected one number per line", where(source, table->lines.front()), table->width), ErrorKind::parse};
  }
  return NumberColumn{std::move(table->values), std::move(table->lines)};
}

Expected<std::vector<double>> read_numbers_csv(const std::filesystem::path& path) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  auto column = parse_numbers_csv(*text, display_name(path), tolerances::kMaxEvaluationParameters);
  if (!column) return column.error();
  return std::move(column->values);
}

}  // namespace casteljau
