// Help, examples and the version (help.hpp).
#include "help.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <charconv>
#include <cstdlib>
#include <memory>

#include "casteljau/version.hpp"

namespace casteljau::cli {
namespace {

/// What the overview (`casteljau --help`) says of a subcommand, and its
/// example: a command runnable from the repository's root as written, and
/// what it shows. (The subcommand's own description, in its --help, is
/// registered with it in cli/<name>_command.cpp.)
struct Entry {
  std::string_view subcommand;
  std::string_view summary;
  std::string_view example;
  std::string_view shows;
};

/// Every subcommand's summary and example, in one place: tests/cli/cli_messages.sh
/// runs each example as its --help prints it, so an example that stops
/// working fails a test.
constexpr std::array kEntries{
    Entry{"eval", "Points or derivatives of curves and surfaces, as CSV",
          "casteljau eval examples/notebook_polygon.csv --at 0.5",
          "the point at t = 0.5 of the Bézier curve of seed 004's polygon: 2.25,1.5"},
    Entry{"plot", "Figures of curves, points and surfaces (SVG, PNG, PDF)",
          "casteljau plot examples/notebook_polygon.csv --construction 0.5 -o construction.svg",
          "the de Casteljau construction of that curve at t = 0.5"},
    Entry{"bernstein", "The Bernstein basis of degree N as a figure", "casteljau bernstein 5 -o bernstein5.png",
          "the six Bernstein polynomials of degree 5"},
    Entry{"gallery", "Every seed figure as SVG and PNG, with an index.html", "casteljau gallery out/gallery",
          "the figures, and out/gallery/index.html showing them all"},
    Entry{"convert", "A model rewritten as Bézier pieces, a B-spline, SVG, DXF, or IGES and STEP for CAD",
          "casteljau convert examples/notebook_polygon.csv --to bspline",
          "the polygon's Bézier curve as the same curve on clamped B-spline knots"},
    Entry{"interpolate", "A curve through the points of a CSV file",
          "casteljau interpolate examples/head.csv --method c1-bezier --alpha 2 -o head.json",
          "seed 000's C1 Bézier curve through the head's points"},
    Entry{"fit", "A B-spline near the points of a CSV file",
          "casteljau fit examples/head.csv --degree 3 --control-points 10 -o head_fit.json",
          "a least-squares cubic B-spline with 10 control points near the head's points"},
    Entry{"length", "The arc length of curves, within a tolerance", "casteljau length examples/semicircle.json",
          "the length of the exact NURBS half circle of radius 3: 3 pi = 9.42477796076938"},
    Entry{"closest", "The nearest point of a curve to query points", "casteljau closest examples/semicircle.json --point 0,5",
          "the point of the half circle of radius 3 nearest to (0, 5): t = 0.5, distance 2, at (0, 3)"},
    Entry{"intersect", "Intersections of two plane curves, or of one with itself, as JSON",
          "casteljau intersect examples/semicircle.json examples/spline.json",
          "where the half circle of radius 3 meets the cubic B-spline of examples/spline.json"},
    Entry{"tessellate", "A triangle mesh of surfaces (OBJ, STL, PLY)",
          "casteljau tessellate examples/sphere.json --tolerance 0.001 -o sphere.stl",
          "a watertight triangle mesh within 0.001 of the NURBS sphere"},
    Entry{"text", "The glyph outlines of a text in a font, as closed curves",
          "casteljau text Bezier --font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf --size 10 -o word.json",
          "each contour of the word's glyphs in DejaVu Sans, an em 10 units long"},
    Entry{"info", "What a file holds: format, unit, models, elements, ids, layers, box, what was skipped",
          "casteljau info examples/sailboat.svg",
          "the drawing's 19 curves from its paths and shapes, their pieces by degree, its box and unit"},
    Entry{"gcode", "A G-code toolpath (G0-G3) of plane curves, within a tolerance",
          "casteljau gcode examples/semicircle.json --tolerance 0.01 -o semicircle.nc",
          "a program that cuts the exact NURBS half circle of radius 3 as one G2 arc, 1 mm deep"},
    Entry{"arcs", "Plane curves as circular arcs and line segments within a tolerance (JSON or DXF)",
          "casteljau arcs examples/sailboat.svg --tolerance 0.01 -o boat.dxf",
          "the drawing's 19 curves as LWPOLYLINE entities with bulges, every point within 0.01 of the curves"},
};

/// The subcommand's entry in kEntries; every subcommand has one.
const Entry& entry_of(const CLI::App& sub) {
  for (const Entry& entry : kEntries)
    if (entry.subcommand == sub.get_name()) return entry;
  assert(false && "every subcommand has its summary and example in kEntries");
  static const Entry none{};
  return none;
}

constexpr std::size_t kDefaultWidth = 80;   ///< help in a pipe or a file: the traditional terminal
constexpr std::size_t kNarrowestWidth = 40;  ///< below this a description column holds no sentence
constexpr std::size_t kNameColumn = 30;      ///< where descriptions start (CLI11's own default)
constexpr std::size_t kNarrowestDescription = 10;  ///< a description column keeps room for a word or two

/// Characters of UTF-8 text: bytes that do not continue a sequence.
std::size_t characters(std::string_view text) {
  std::size_t count = 0;
  for (const char c : text) count += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return count;
}

/// CLI11's formatter with descriptions wrapped to a width (CLI11 2.1 prints
/// each description as one line, 850 characters for eval's).
class WrappingFormatter : public CLI::Formatter {
 public:
  explicit WrappingFormatter(std::size_t width) : width_(width) {
    column_ = std::min(kNameColumn, width_ / 3);
    column_width(column_);
  }

  std::string make_description(const CLI::App* app) const override {
    const std::string description = app->get_description();
    // A blank line before the usage, except inside --help-all's entries.
    if (description.empty()) return {};
    return joined(wrap(description, available()), 0) + (indent_ > 0 ? "\n" : "\n\n");
  }

  std::string make_option(const CLI::Option* option, bool is_positional) const override {
    return entry(make_option_name(option, is_positional) + make_option_opts(option), make_option_desc(option));
  }

  std::string make_subcommand(const CLI::App* sub) const override {
    return entry(sub->get_display_name(true), std::string(entry_of(*sub).summary));
  }

  std::string make_expanded(const CLI::App* sub) const override {
    // --help-all indents each subcommand's help by two more columns.
    indent_ += 2;
    std::string text = CLI::Formatter::make_expanded(sub);
    indent_ -= 2;
    return text;
  }

 private:
  /// Columns left for text once --help-all's indentation is taken.
  std::size_t available() const { return width_ - std::min(indent_, width_ / 2); }

  /// "  name      description..." with the description wrapped in its column,
  /// on the next line when the name fills the column.
  std::string entry(const std::string& name, const std::string& description) const {
    std::string text = "  " + name;
    if (description.empty()) return text + "\n";
    const std::size_t used = characters(text);
    const std::size_t room = std::max(available() - std::min(column_, available()), kNarrowestDescription);
    text += used >= column_ ? "\n" + std::string(column_, ' ') : std::string(column_ - used, ' ');
    return text + joined(wrap(description, room), column_) + "\n";
  }

  /// The lines joined by newlines, each after the first indented.
  static std::string joined(const std::vector<std::string>& lines, std::size_t indent) {
    std::string text;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (i > 0) text += "\n" + std::string(indent, ' ');
      text += lines[i];
    }
    return text;
  }

  std::size_t width_;
  std::size_t column_ = kNameColumn;
  mutable std::size_t indent_ = 0;
};

/// "Example (the point at t = 0.5 ...):\n  casteljau eval ...": the footer
/// of the subcommand's help (the command is never wrapped: it must stay
/// copyable as one line).
std::string example_footer(const Entry& entry, std::size_t width) {
  std::string text;
  for (const auto& line : wrap("Example (" + std::string(entry.shows) + "):", width)) text += line + "\n";
  return text + "  " + std::string(entry.example);
}

/// Lines joined by newlines.
std::string lines_of(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& line : lines) text += (text.empty() ? "" : "\n") + line;
  return text;
}

}  // namespace

std::string version_line() { return std::string("casteljau ") + CASTELJAU_VERSION_STRING; }

std::size_t help_width() {
  std::size_t width = 0;
  if (const char* columns = std::getenv("COLUMNS"); columns != nullptr) {
    const std::string_view text = columns;
    std::size_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc() && end == text.data() + text.size()) width = value;
  }
  winsize size{};
  if (width == 0 && ::isatty(STDOUT_FILENO) == 1 && ::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0) {
    width = size.ws_col;
  }
  if (width == 0) width = kDefaultWidth;
  return std::max(width, kNarrowestWidth);
}

std::vector<std::string> wrap(std::string_view text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t line_characters = 0;
  std::size_t start = 0;
  const auto end_line = [&] {
    lines.push_back(std::move(line));
    line.clear();
    line_characters = 0;
  };
  while (start <= text.size()) {
    const std::size_t newline = text.find('\n', start);
    const std::string_view paragraph =
        text.substr(start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
    std::size_t at = 0;
    while (at < paragraph.size()) {
      const std::size_t word_start = paragraph.find_first_not_of(' ', at);
      if (word_start == std::string_view::npos) break;
      const std::size_t word_end = std::min(paragraph.find(' ', word_start), paragraph.size());
      const std::string_view word = paragraph.substr(word_start, word_end - word_start);
      const std::size_t length = characters(word);
      if (line_characters > 0 && line_characters + 1 + length > width) end_line();
      if (line_characters > 0) {
        line += ' ';
        ++line_characters;
      }
      line += word;
      line_characters += length;
      at = word_end;
    }
    end_line();
    if (newline == std::string_view::npos) break;
    start = newline + 1;
  }
  return lines;
}

void set_up_help(CLI::App& app) {
  const std::size_t width = help_width();
  auto formatter = std::make_shared<WrappingFormatter>(width);
  app.formatter(formatter);
  app.set_version_flag("--version", version_line(), "Print the version (" + version_line() + ") and exit");
  app.footer(lines_of(wrap("casteljau SUBCOMMAND --help shows the subcommand's options and an example; docs/cli.md "
                           "describes them all.",
                           width)));
  for (CLI::App* sub : app.get_subcommands({})) {
    sub->formatter(formatter);
    sub->footer(example_footer(entry_of(*sub), width));
  }
}

}  // namespace casteljau::cli
