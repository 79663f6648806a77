// SVG's transform lists and viewBox maps (svg_transform.hpp says what).
#include "svg_transform.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "svg_scanner.hpp"

namespace casteljau::io_detail {
namespace {

double radians(double degrees) { return std::fmod(degrees, 360.0) * std::numbers::pi / 180.0; }

/// The transform functions and the counts of numbers each takes.
struct TransformFunction {
  std::string_view name;
  int fewest, most;  // rotate takes 1 or 3: checked where it is built
};
constexpr TransformFunction kFunctions[] = {
    {"matrix", 6, 6}, {"translate", 1, 2}, {"scale", 1, 2}, {"rotate", 1, 3}, {"skewX", 1, 1}, {"skewY", 1, 1},
};

std::string counts_of(const TransformFunction& function) {
  if (function.name == "rotate") return "1 or 3 numbers";
  if (function.fewest == function.most) return fmt::format("{} number{}", function.fewest, function.fewest > 1 ? "s" : "");
  return fmt::format("{} or {} numbers", function.fewest, function.most);
}

SvgMatrix build(std::string_view name, const std::vector<double>& v) {
  if (name == "matrix") return SvgMatrix{v[0], v[1], v[2], v[3], v[4], v[5]};
  if (name == "translate") return svg_translate(v[0], v.size() > 1 ? v[1] : 0.0);
  if (name == "scale") return svg_scale(v[0], v.size() > 1 ? v[1] : v[0]);
  if (name == "rotate") {
    if (v.size() == 1) return svg_rotate(v[0]);
    return svg_translate(v[1], v[2]) * svg_rotate(v[0]) * svg_translate(-v[1], -v[2]);
  }
  if (name == "skewX") return SvgMatrix{1.0, 0.0, std::tan(radians(v[0])), 1.0, 0.0, 0.0};
  return SvgMatrix{1.0, std::tan(radians(v[0])), 0.0, 1.0, 0.0, 0.0};  // skewY
}

}  // namespace

double SvgMatrix::area_scale() const { return std::abs(a * d - b * c); }

bool SvgMatrix::is_invertible() const {
  const double det = a * d - b * c;
  return std::isfinite(det) && det != 0.0;
}

SvgMatrix operator*(const SvgMatrix& m, const SvgMatrix& n) {
  return SvgMatrix{m.a * n.a + m.c * n.b, m.b * n.a + m.d * n.b, m.a * n.c + m.c * n.d,
                   m.b * n.c + m.d * n.d, m.a * n.e + m.c * n.f + m.e, m.b * n.e + m.d * n.f + m.f};
}

SvgMatrix svg_translate(double tx, double ty) { return SvgMatrix{1.0, 0.0, 0.0, 1.0, tx, ty}; }
SvgMatrix svg_scale(double sx, double sy) { return SvgMatrix{sx, 0.0, 0.0, sy, 0.0, 0.0}; }

SvgMatrix svg_rotate(double degrees) {
  // Multiples of 90 degrees exactly, so rotate(90) maps integers to integers.
  const double turns = std::fmod(degrees, 360.0);
  double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
  if (turns == 0.0) c = 1.0, s = 0.0;
  if (turns == 90.0 || turns == -270.0) c = 0.0, s = 1.0;
  if (turns == 180.0 || turns == -180.0) c = -1.0, s = 0.0;
  if (turns == 270.0 || turns == -90.0) c = 0.0, s = -1.0;
  return SvgMatrix{c, s, -s, c, 0.0, 0.0};
}

Expected<SvgMatrix> parse_svg_transform(std::string_view text) {
  SvgScanner in(text, "transform");
  SvgMatrix total;
  in.skip_spaces();
  bool first = true;
  while (!in.done()) {
    if (!first) {
      // comma-wsp between transforms; at the end only spaces may follow.
      in.skip_separator();
      if (in.done()) return in.error("a transform list does not end with a comma");
    }
    first = false;
    const std::size_t start = in.position();
    const std::string_view name = in.word();
    const TransformFunction* function = nullptr;
    for (const TransformFunction& f : kFunctions)
      if (f.name == name) function = &f;
    if (function == nullptr)
      return in.error_at(start, name.empty() ? "expected a transform: matrix, translate, scale, rotate, skewX or skewY"
                                             : fmt::format("'{}' is not a transform (matrix, translate, scale, "
                                                           "rotate, skewX, skewY)",
                                                           name.substr(0, 40)));
    in.skip_spaces();
    if (in.done() || in.peek() != '(') return in.error(fmt::format("expected '(' after {}", name));
    in.advance();
    in.skip_spaces();
    std::vector<double> values;
    while (in.at_number()) {
      auto value = in.number();
      if (!value) return value.error();
      values.push_back(*value);
      in.skip_separator();
    }
    if (in.done() || in.peek() != ')') {
      if (in.done()) return in.error(fmt::format("{} is not closed by ')'", name));
      return in.error(fmt::format("expected a number or ')' in {}", name));
    }
    const int count = static_cast<int>(values.size());
    if (count < function->fewest || count > function->most || (name == "rotate" && count == 2))
      return in.error(fmt::format("{} takes {}, found {}", name, counts_of(*function), count));
    in.advance();
    total = total * build(name, values);
    in.skip_spaces();
  }
  return total;
}

Expected<std::array<double, 4>> parse_svg_view_box(std::string_view text) {
  SvgScanner in(text, "viewBox");
  std::array<double, 4> box{};
  in.skip_spaces();
  for (std::size_t i = 0; i < 4; ++i) {
    if (i > 0) in.skip_separator();
    if (!in.at_number()) return in.error("expected a number, a viewBox is min-x min-y width height");
    auto value = in.number();
    if (!value) return value.error();
    box[i] = *value;
  }
  in.skip_spaces();
  if (!in.done()) return in.error("a viewBox has four numbers, min-x min-y width height");
  if (box[2] < 0.0 || box[3] < 0.0)
    return Error{fmt::format("viewBox: a negative {} ({})", box[2] < 0.0 ? "width" : "height",
                             box[2] < 0.0 ? box[2] : box[3]),
                 ErrorKind::invalid_argument};
  return box;
}

Expected<SvgMatrix> svg_view_box_map(const std::array<double, 4>& view_box, double x, double y, double width,
                                     double height, std::string_view aspect) {
  SvgScanner in(aspect, "preserveAspectRatio");
  in.skip_spaces();
  std::string_view align = in.word();
  if (align == "defer") {
    in.skip_spaces();
    align = in.word();
  }
  if (align.empty()) align = "xMidYMid";
  in.skip_spaces();
  std::string_view meet_or_slice = in.word();
  if (meet_or_slice.empty()) meet_or_slice = "meet";
  in.skip_spaces();
  const bool known_align = align == "none" || (align.size() == 8 && (align.substr(0, 4) == "xMin" ||
                                                                      align.substr(0, 4) == "xMid" ||
                                                                      align.substr(0, 4) == "xMax") &&
                                                (align.substr(4) == "YMin" || align.substr(4) == "YMid" ||
                                                 align.substr(4) == "YMax"));
  if (!known_align || (meet_or_slice != "meet" && meet_or_slice != "slice") || !in.done())
    return Error{fmt::format("preserveAspectRatio: '{}' is not none or x{{Min,Mid,Max}}Y{{Min,Mid,Max}} "
                             "with meet or slice",
                             aspect.substr(0, 60)),
                 ErrorKind::parse};
  double sx = width / view_box[2], sy = height / view_box[3];
  if (align != "none") {
    sx = sy = meet_or_slice == "meet" ? std::min(sx, sy) : std::max(sx, sy);
  }
  double tx = x - view_box[0] * sx, ty = y - view_box[1] * sy;
  if (align != "none") {
    const double free_x = width - view_box[2] * sx, free_y = height - view_box[3] * sy;
    const std::string_view ax = align.substr(1, 3), ay = align.substr(5, 3);
    if (ax == "Mid") tx += free_x / 2.0;
    if (ax == "Max") tx += free_x;
    if (ay == "Mid") ty += free_y / 2.0;
    if (ay == "Max") ty += free_y;
  }
  return SvgMatrix{sx, 0.0, 0.0, sy, tx, ty};
}

}  // namespace casteljau::io_detail
