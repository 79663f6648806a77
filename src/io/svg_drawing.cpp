// SVG documents to curves (io/svg_drawing.hpp says what). The tree is walked
// once, depth first, carrying the transform to the output units, the
// inherited style and the viewport that percentages refer to. Every shape is
// read as its equivalent path (SVG 2 §10: rect, circle, ellipse, line,
// polyline, polygon each define one), written as path data and read by
// read_svg_path, so arcs and corners follow one code path; numbers are
// written in shortest round-trip form, so nothing is rounded on the way.
#include "casteljau/io/svg_drawing.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/io/svg_path.hpp"
#include "casteljau/io/tolerance.hpp"
#include "svg_length.hpp"
#include "svg_scanner.hpp"
#include "svg_transform.hpp"

namespace casteljau {
namespace {

using io_detail::SvgMatrix;

/// The element's name without a namespace prefix ("svg:path" is "path").
std::string_view local_name(const pugi::xml_node& node) {
  std::string_view name = node.name();
  if (const auto colon = name.find(':'); colon != std::string_view::npos && name.substr(0, colon) == "svg")
    name.remove_prefix(colon + 1);
  return name;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && io_detail::is_svg_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && io_detail::is_svg_space(text.back())) text.remove_suffix(1);
  return text;
}

/// The properties this reader uses, as CSS inherits them.
struct Style {
  FillRule fill_rule = FillRule::nonzero;
  double stroke_width = 1.0;  // in the user units of the element that set it
  bool visible = true;        // visibility (inherited; children may set it back)
};

/// The viewport that percentages refer to: its size in the current user units.
struct Viewport {
  std::optional<double> width, height;
  std::optional<double> diagonal() const {  // SVG 1.1 §7.10: sqrt((w² + h²) / 2)
    if (!width || !height) return std::nullopt;
    return std::sqrt((*width * *width + *height * *height) / 2.0);
  }
};

class Reader {
 public:
  Reader(std::string_view text, const std::string& source) : text_(text), source_(source) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') newlines_.push_back(i);
  }

  Expected<SvgDrawing> read(DrawingUnits units) {
    drawing_.units = units;
    const pugi::xml_parse_result parsed =
        document_.load_buffer(text_.data(), text_.size(), pugi::parse_default | pugi::parse_ws_pcdata_single);
    if (!parsed) {
      const auto [line, column] = place(static_cast<std::size_t>(parsed.offset));
      return Error{fmt::format("{}, line {}, column {}: not well-formed XML: {}", source_, line, column,
                               parsed.description()),
                   ErrorKind::parse};
    }
    const pugi::xml_node root = document_.document_element();
    if (root.empty() || local_name(root) != "svg")
      return Error{fmt::format("{}: the root element is <{}>, an SVG drawing's is <svg>", source_,
                               root.empty() ? std::string_view("none") : std::string_view(root.name()).substr(0, 40)),
                   ErrorKind::parse};
    collect_ids(root);
    auto start = root_placement(root, units);
    if (!start) return start.error();
    auto style = element_style(root, Style{}, start->second);
    if (!style) {
      problem(root, style.error().message);
      style = Style{};
    }
    if (root.attribute("transform")) skip(root, "the root's transform is not applied: it places the drawing, "
                                                "like the root's viewBox");
    walk_children(root, start->first, *style, start->second, 1);
    if (failure_) return *failure_;
    return std::move(drawing_);
  }

 private:
  // --- places and messages ---------------------------------------------------
  std::pair<std::size_t, std::size_t> place(std::size_t offset) const {
    const auto before = std::lower_bound(newlines_.begin(), newlines_.end(), offset);
    const std::size_t line = static_cast<std::size_t>(before - newlines_.begin()) + 1;
    const std::size_t line_start = line == 1 ? 0 : newlines_[line - 2] + 1;
    std::size_t column = 1;  // in UTF-8 characters
    for (std::size_t i = line_start; i < offset && i < text_.size(); ++i)
      if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column;
    return {line, column};
  }
  std::size_t line_of(const pugi::xml_node& node) const {
    const std::ptrdiff_t offset = node.offset_debug();
    return offset < 0 ? 0 : place(static_cast<std::size_t>(offset)).first;
  }
  /// "line 12, <path id='p'>"
  std::string where(const pugi::xml_node& node) const {
    const std::string_view id = node.attribute("id").value();
    return fmt::format("line {}, <{}{}>", line_of(node), local_name(node).substr(0, 40),
                       id.empty() ? std::string() : fmt::format(" id='{}'", id.substr(0, 40)));
  }
  void problem(const pugi::xml_node& node, const std::string& message, ErrorKind kind = ErrorKind::parse) {
    drawing_.problems.push_back(Error{fmt::format("{}, {}: {}", source_, where(node), message), kind});
  }
  void skip(const pugi::xml_node& node, std::string_view why) {
    drawing_.skipped.push_back(fmt::format("line {}: <{}> ({})", line_of(node), local_name(node).substr(0, 40), why));
  }

  // --- attributes and style --------------------------------------------------
  /// A property's value: the style attribute's declaration if any (it wins
  /// over the presentation attribute, CSS cascade), else the attribute.
  std::optional<std::string_view> property(const pugi::xml_node& node, std::string_view name) const {
    std::string_view style = node.attribute("style").value();
    std::optional<std::string_view> found;
    while (!style.empty()) {
      const auto end = style.find(';');
      const std::string_view declaration = style.substr(0, end);
      style = end == std::string_view::npos ? std::string_view() : style.substr(end + 1);
      const auto colon = declaration.find(':');
      if (colon == std::string_view::npos) continue;
      if (trim(declaration.substr(0, colon)) != name) continue;
      std::string_view value = trim(declaration.substr(colon + 1));
      if (const auto important = value.find("!important"); important != std::string_view::npos)
        value = trim(value.substr(0, important));
      found = value;  // the last declaration wins
    }
    if (found) return found;
    const pugi::xml_attribute attribute = node.attribute(std::string(name).c_str());
    if (attribute) return trim(attribute.value());
    return std::nullopt;
  }

  Expected<Style> element_style(const pugi::xml_node& node, Style inherited, const Viewport& viewport) const {
    Style style = inherited;
    if (auto rule = property(node, "fill-rule"); rule && *rule != "inherit") {
      if (*rule == "evenodd") style.fill_rule = FillRule::evenodd;
      else if (*rule == "nonzero") style.fill_rule = FillRule::nonzero;
      else return Error{fmt::format("fill-rule: '{}' is not nonzero or evenodd", rule->substr(0, 40))};
    }
    if (auto width = property(node, "stroke-width"); width && *width != "inherit") {
      auto length = io_detail::parse_svg_length(*width, "stroke-width");
      if (!length) return length.error();
      // A percentage is of the viewport's normalized diagonal.
      auto value = io_detail::svg_length_in_user_units(*length, viewport.diagonal(), "stroke-width");
      if (!value) return value.error();
      if (*value < 0.0) return Error{fmt::format("stroke-width: a negative width ({})", *value)};
      style.stroke_width = *value;
    }
    if (auto visibility = property(node, "visibility"); visibility && *visibility != "inherit")
      style.visible = *visibility == "visible";
    return style;
  }

  /// A length attribute in user units, `fallback` when it is absent.
  std::optional<double> length(const pugi::xml_node& node, const char* name, double fallback,
                               std::optional<double> reference) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) return fallback;
    auto parsed = io_detail::parse_svg_length(attribute.value(), name);
    if (!parsed) {
      problem(node, parsed.error().message);
      return std::nullopt;
    }
    auto value = io_detail::svg_length_in_user_units(*parsed, reference, name);
    if (!value) {
      problem(node, value.error().message, value.error().kind);
      return std::nullopt;
    }
    return *value;
  }

  // --- the root and nested viewports -----------------------------------------
  /// The map from the root's user units to the output units, and the root's viewport.
  Expected<std::pair<SvgMatrix, Viewport>> root_placement(const pugi::xml_node& root, DrawingUnits units) {
    std::optional<std::array<double, 4>> view_box;
    if (const pugi::xml_attribute box = root.attribute("viewBox")) {
      auto parsed = io_detail::parse_svg_view_box(box.value());
      if (!parsed) return with_context(parsed.error(), fmt::format("{}, {}", source_, where(root)));
      view_box = *parsed;
    }
    // The root's width and height, when they are absolute lengths, in px and mm.
    std::optional<double> width_mm, height_mm;
    const auto absolute = [&](const char* name) -> Expected<std::optional<double>> {
      const pugi::xml_attribute attribute = root.attribute(name);
      if (!attribute || trim(attribute.value()) == "auto") return std::optional<double>{};
      auto parsed = io_detail::parse_svg_length(attribute.value(), name);
      if (!parsed) return with_context(parsed.error(), fmt::format("{}, {}", source_, where(root)));
      if (parsed->percent) return std::optional<double>{};
      if (parsed->value < 0.0)
        return Error{fmt::format("{}, {}: a negative {} ({})", source_, where(root), name, trim(attribute.value()))};
      (std::string_view(name) == "width" ? width_mm : height_mm) = parsed->millimetres;
      return std::optional<double>{parsed->value};
    };
    auto width = absolute("width");
    if (!width) return width.error();
    auto height = absolute("height");
    if (!height) return height.error();
    Viewport viewport;
    if (view_box) viewport = Viewport{(*view_box)[2], (*view_box)[3]};
    else viewport = Viewport{*width, *height};
    // Models are y up (docs/formats.md, "The frame"): y is measured up from
    // the page's bottom edge, the viewBox's (min-y + height), else the root's
    // height, else y = 0; x is kept.
    const auto upright = [](double bottom) { return SvgMatrix{1.0, 0.0, 0.0, -1.0, 0.0, bottom}; };
    drawing_.page_bottom = view_box ? (*view_box)[1] + (*view_box)[3] : height->value_or(0.0);
    if (units == DrawingUnits::user) return std::pair{upright(drawing_.page_bottom), viewport};
    // Millimetres: through the root's size, and its viewBox when it has one.
    if (!*width || !*height)
      return Error{fmt::format("{}: millimetres need the root <svg>'s width and height as absolute lengths "
                               "(mm, cm, in, pt, pc, px or a number), and it has {}",
                               source_,
                               !root.attribute("width") && !root.attribute("height")
                                   ? std::string("neither")
                                   : fmt::format("width '{}', height '{}'", root.attribute("width").value(),
                                                 root.attribute("height").value())),
                   ErrorKind::invalid_argument};
    const double mm = io_detail::kSvgMillimetresPerPixel;
    if (!view_box) return std::pair{upright(*height_mm) * io_detail::svg_scale(mm, mm), viewport};  // a user unit is a px
    if ((*view_box)[2] == 0.0 || (*view_box)[3] == 0.0)
      return Error{fmt::format("{}: the root's viewBox has a zero width or height, its size in mm is undefined",
                               source_),
                   ErrorKind::invalid_argument};
    auto map = io_detail::svg_view_box_map(*view_box, 0.0, 0.0, *width_mm, *height_mm,
                                           root.attribute("preserveAspectRatio").value());
    if (!map) return with_context(map.error(), fmt::format("{}, {}", source_, where(root)));
    return std::pair{upright(*height_mm) * *map, viewport};
  }

  /// A nested <svg>, or a <symbol> instanced by <use> (whose width and height
  /// it takes): its placement inside the current user space and its viewport.
  std::optional<std::pair<SvgMatrix, Viewport>> nested_placement(const pugi::xml_node& node,
                                                                 const pugi::xml_node& sizing,
                                                                 const Viewport& outer) {
    const auto x = length(node, "x", 0.0, outer.width), y = length(node, "y", 0.0, outer.height);
    const pugi::xml_node& size_from = sizing.attribute("width") || sizing.attribute("height") ? sizing : node;
    // No width or height, and an outer viewport of unknown size (a root with
    // neither viewBox nor absolute size): without a viewBox the content is
    // only moved by (x, y); with one, its scale is unknown, a problem.
    const bool sized = size_from.attribute("width") && size_from.attribute("height");
    if (!sized && (!outer.width || !outer.height)) {
      if (!x || !y) return std::nullopt;
      if (node.attribute("viewBox")) {
        problem(node, "a viewBox needs the viewport's width and height, which neither this element nor its "
                      "viewport gives",
                ErrorKind::invalid_argument);
        return std::nullopt;
      }
      return std::pair{io_detail::svg_translate(*x, *y), outer};
    }
    const auto width = length(size_from, "width", outer.width.value_or(0.0), outer.width);
    const auto height = length(size_from, "height", outer.height.value_or(0.0), outer.height);
    if (!x || !y || !width || !height) return std::nullopt;
    if (*width < 0.0 || *height < 0.0) {
      problem(node, "a negative width or height", ErrorKind::invalid_argument);
      return std::nullopt;
    }
    if (const pugi::xml_attribute box = node.attribute("viewBox")) {
      auto view_box = io_detail::parse_svg_view_box(box.value());
      if (!view_box) {
        problem(node, view_box.error().message, view_box.error().kind);
        return std::nullopt;
      }
      if ((*view_box)[2] == 0.0 || (*view_box)[3] == 0.0 || *width == 0.0 || *height == 0.0)
        return std::nullopt;  // SVG: not drawn
      auto map = io_detail::svg_view_box_map(*view_box, *x, *y, *width, *height,
                                             node.attribute("preserveAspectRatio").value());
      if (!map) {
        problem(node, map.error().message, map.error().kind);
        return std::nullopt;
      }
      return std::pair{*map, Viewport{(*view_box)[2], (*view_box)[3]}};
    }
    if (*width == 0.0 || *height == 0.0) return std::nullopt;
    return std::pair{io_detail::svg_translate(*x, *y), Viewport{*width, *height}};
  }

  // --- the walk --------------------------------------------------------------
  void collect_ids(const pugi::xml_node& root) {
    for (pugi::xml_node node = root; node;) {
      if (node.type() == pugi::node_element) {
        const char* id = node.attribute("id").value();
        if (*id != '\0') ids_.emplace(id, node);  // the first of a duplicated id wins
      }
      if (node.first_child()) {
        node = node.first_child();
        continue;
      }
      while (node && node != root && !node.next_sibling()) node = node.parent();
      if (!node || node == root) break;
      node = node.next_sibling();
    }
  }

  bool too_deep(const pugi::xml_node& node, int depth) {
    if (++elements_ > tolerances::kMaxSvgElements) {
      if (!failure_)
        failure_ = Error{fmt::format("{}, {}: more than {} elements to draw (<use> instances counted)", source_,
                                     where(node), tolerances::kMaxSvgElements),
                         ErrorKind::limit};
      return true;
    }
    if (depth <= tolerances::kMaxSvgDepth) return false;
    if (!failure_)
      failure_ = Error{fmt::format("{}, {}: elements nested deeper than {} levels (<use> references counted)",
                                   source_, where(node), tolerances::kMaxSvgDepth),
                       ErrorKind::limit};
    return true;
  }

  void walk_children(const pugi::xml_node& parent, const SvgMatrix& to_output, const Style& style,
                     const Viewport& viewport, int depth) {
    for (const pugi::xml_node& child : parent.children()) {
      if (failure_) return;
      if (child.type() != pugi::node_element) continue;
      walk(child, to_output, style, viewport, depth);
      if (local_name(parent) == "switch") return;  // a switch draws its first child only
    }
  }

  void walk(const pugi::xml_node& node, const SvgMatrix& outer, const Style& inherited, const Viewport& viewport,
            int depth, const pugi::xml_node& instanced_by = pugi::xml_node()) {
    if (too_deep(node, depth)) return;
    const std::string_view name = local_name(node);
    if (auto display = property(node, "display"); display && *display == "none") return;
    if (name == "defs" || name == "symbol" || name == "clipPath" || name == "mask" || name == "marker" ||
        name == "pattern" || name == "linearGradient" || name == "radialGradient" || name == "filter" ||
        name == "style" || name == "script" || name == "metadata" || name == "title" || name == "desc") {
      if (!(name == "symbol" && instanced_by)) return;  // drawn only where <use> instances it
    }
    if (name == "text" || name == "image" || name == "foreignObject") {
      skip(node, name == "text" ? "text is not read: convert it to paths" : "not vector geometry");
      return;
    }
    const bool container = name == "g" || name == "a" || name == "switch" || name == "svg" || name == "symbol";
    const bool shape = name == "path" || name == "rect" || name == "circle" || name == "ellipse" ||
                       name == "line" || name == "polyline" || name == "polygon";
    if (!container && !shape && name != "use") return;  // unknown elements are not drawn (SVG 2 §5.8)

    auto style = element_style(node, inherited, viewport);
    if (!style) return problem(node, style.error().message);
    SvgMatrix to_output = outer;
    if (const pugi::xml_attribute transform = node.attribute("transform")) {
      auto matrix = io_detail::parse_svg_transform(transform.value());
      if (!matrix) return problem(node, matrix.error().message);
      to_output = outer * *matrix;
    }
    if (node.attribute("clip-path") || node.attribute("mask")) skip(node, "its clip-path or mask is not applied");

    if (name == "svg" || name == "symbol") {
      auto placed = nested_placement(node, instanced_by ? instanced_by : node, viewport);
      if (!placed) return;
      return walk_children(node, to_output * placed->first, *style, placed->second, depth + 1);
    }
    if (container) return walk_children(node, to_output, *style, viewport, depth + 1);
    if (name == "use") return walk_use(node, to_output, *style, viewport, depth);
    if (!to_output.is_invertible()) return;  // SVG 2: a singular transform draws nothing
    auto data = equivalent_path(node, name, viewport);
    if (!data) return;
    add_path(node, *data, to_output, *style);
  }

  void walk_use(const pugi::xml_node& use, const SvgMatrix& to_output, const Style& style, const Viewport& viewport,
                int depth) {
    std::string_view href = use.attribute("href").value();
    if (href.empty()) href = use.attribute("xlink:href").value();
    href = trim(href);
    if (href.empty()) return;  // SVG: a use without a reference draws nothing
    if (href.front() != '#')
      return skip(use, fmt::format("refers to '{}' outside this file, which is not read", href.substr(0, 60)));
    const auto target = ids_.find(std::string(href.substr(1)));
    if (target == ids_.end()) return problem(use, fmt::format("refers to '{}', which no element has as its id",
                                                              href.substr(0, 60)));
    for (const pugi::xml_node& active : active_uses_)
      if (active == target->second)
        return problem(use, fmt::format("refers to '{}', which contains this <use> (a cycle)", href.substr(0, 60)));
    for (pugi::xml_node up = use; up; up = up.parent())
      if (up == target->second)
        return problem(use, fmt::format("refers to '{}', which contains this <use> (a cycle)", href.substr(0, 60)));
    const auto x = length(use, "x", 0.0, viewport.width), y = length(use, "y", 0.0, viewport.height);
    if (!x || !y) return;
    active_uses_.push_back(target->second);
    walk(target->second, to_output * io_detail::svg_translate(*x, *y), style, viewport, depth + 1, use);
    active_uses_.pop_back();
  }

  // --- shapes ----------------------------------------------------------------
  /// The path data of the element (SVG 2 §10's equivalent paths), or nothing
  /// when it draws nothing or is in error (a problem then says so).
  std::optional<std::string> equivalent_path(const pugi::xml_node& node, std::string_view name,
                                             const Viewport& viewport) {
    if (name == "path") return std::string(node.attribute("d").value());
    if (name == "polyline" || name == "polygon") return polyline_path(node, name == "polygon");
    const auto w = viewport.width, h = viewport.height, diagonal = viewport.diagonal();
    if (name == "line") {
      const auto x1 = length(node, "x1", 0.0, w), y1 = length(node, "y1", 0.0, h);
      const auto x2 = length(node, "x2", 0.0, w), y2 = length(node, "y2", 0.0, h);
      if (!x1 || !y1 || !x2 || !y2) return std::nullopt;
      return fmt::format("M{} {}L{} {}", *x1, *y1, *x2, *y2);
    }
    // SVG 2: an "auto" radius takes the other one's value.
    const auto radius = [&](const char* name, std::optional<double> reference) -> std::optional<std::optional<double>> {
      const pugi::xml_attribute attribute = node.attribute(name);
      if (!attribute || trim(attribute.value()) == "auto") return std::optional<double>{};
      auto value = length(node, name, 0.0, reference);
      if (!value) return std::nullopt;
      if (*value < 0.0) {
        problem(node, fmt::format("{}: a negative radius ({})", name, *value), ErrorKind::invalid_argument);
        return std::nullopt;
      }
      return std::optional<double>{*value};
    };
    if (name == "circle") {
      const auto cx = length(node, "cx", 0.0, w), cy = length(node, "cy", 0.0, h);
      const auto r = radius("r", diagonal);
      if (!cx || !cy || !r) return std::nullopt;
      return ellipse_path(*cx, *cy, r->value_or(0.0), r->value_or(0.0));
    }
    if (name == "ellipse") {
      const auto cx = length(node, "cx", 0.0, w), cy = length(node, "cy", 0.0, h);
      const auto rx = radius("rx", w), ry = radius("ry", h);
      if (!cx || !cy || !rx || !ry) return std::nullopt;
      const double a = rx->value_or(ry->value_or(0.0)), b = ry->value_or(rx->value_or(0.0));
      return ellipse_path(*cx, *cy, a, b);
    }
    // rect
    const auto x = length(node, "x", 0.0, w), y = length(node, "y", 0.0, h);
    const auto width = length(node, "width", 0.0, w), height = length(node, "height", 0.0, h);
    const auto rx = radius("rx", w), ry = radius("ry", h);
    if (!x || !y || !width || !height || !rx || !ry) return std::nullopt;
    if (*width < 0.0 || *height < 0.0) {
      problem(node, fmt::format("a negative {} ({})", *width < 0.0 ? "width" : "height",
                                *width < 0.0 ? *width : *height),
              ErrorKind::invalid_argument);
      return std::nullopt;
    }
    if (*width == 0.0 || *height == 0.0) return std::nullopt;  // SVG: not drawn
    const double a = std::min(rx->value_or(ry->value_or(0.0)), *width / 2.0);
    const double b = std::min(ry->value_or(rx->value_or(0.0)), *height / 2.0);
    const double left = *x, top = *y, right = *x + *width, bottom = *y + *height;
    if (a == 0.0 || b == 0.0) return fmt::format("M{} {}H{}V{}H{}Z", left, top, right, bottom, left);
    // Clockwise on screen from the top edge's start (SVG 2 §10.2).
    return fmt::format("M{} {}H{}A{} {} 0 0 1 {} {}V{}A{} {} 0 0 1 {} {}H{}A{} {} 0 0 1 {} {}V{}A{} {} 0 0 1 {} {}Z",
                       left + a, top, right - a, a, b, right, top + b, bottom - b, a, b, right - a, bottom, left + a,
                       a, b, left, bottom - b, top + b, a, b, left + a, top);
  }

  static std::optional<std::string> ellipse_path(double cx, double cy, double rx, double ry) {
    if (rx == 0.0 || ry == 0.0) return std::nullopt;  // SVG: not drawn
    // Four quarter arcs from (cx + rx, cy), clockwise on screen (SVG 2 §10.3-4).
    return fmt::format("M{} {}A{} {} 0 0 1 {} {}A{} {} 0 0 1 {} {}A{} {} 0 0 1 {} {}A{} {} 0 0 1 {} {}Z", cx + rx,
                       cy, rx, ry, cx, cy + ry, rx, ry, cx - rx, cy, rx, ry, cx, cy - ry, rx, ry, cx + rx, cy);
  }

  /// points="x,y x,y ...": an odd count draws the pairs before the last number
  /// and is a problem (SVG 1.1 §9.7.1's error rule).
  std::optional<std::string> polyline_path(const pugi::xml_node& node, bool polygon) {
    io_detail::SvgScanner in(node.attribute("points").value(), "points");
    std::vector<double> values;
    in.skip_spaces();
    std::optional<Error> error;
    while (!in.done()) {
      if (!values.empty()) in.skip_separator();
      if (!in.at_number()) {
        error = in.error("expected a number, points are x,y pairs");
        break;
      }
      auto value = in.number();
      if (!value) {
        error = value.error();
        break;
      }
      values.push_back(*value);
      in.skip_spaces();
    }
    if (!error && values.size() % 2 == 1)
      error = in.error(fmt::format("an odd count of numbers ({}), points are x,y pairs", values.size()));
    if (error) problem(node, error->message);
    if (values.size() < 2) return std::nullopt;
    std::string data = fmt::format("M{} {}", values[0], values[1]);
    for (std::size_t i = 2; i + 1 < values.size(); i += 2) data += fmt::format("L{} {}", values[i], values[i + 1]);
    if (polygon) data += 'Z';
    return data;
  }

  void add_path(const pugi::xml_node& node, const std::string& data, const SvgMatrix& to_output,
                const Style& style) {
    SvgPathData path = read_svg_path(data);
    if (path.error) problem(node, path.error->message, path.error->kind);
    if (!style.visible) return;
    // The stroke width in output units: exact when the map is a similarity.
    const double stroke_width = style.stroke_width * std::sqrt(to_output.area_scale());
    for (SvgSubpath& subpath : path.subpaths) {
      std::vector<BezierCurve> pieces;
      pieces.reserve(subpath.curve.pieces().size());
      for (const BezierCurve& piece : subpath.curve.pieces()) {
        const PointArray& points = piece.control_points();
        control_points_ += points.size();
        if (control_points_ > tolerances::kMaxControlPoints) {
          if (!failure_)
            failure_ = Error{fmt::format("{}, {}: the drawing needs more than {} control points", source_,
                                         where(node), tolerances::kMaxControlPoints),
                             ErrorKind::limit};
          return;
        }
        std::vector<double> mapped(points.size() * 2);
        for (std::size_t i = 0; i < points.size(); ++i) {
          const Vec2 p = to_output.apply(Vec2{{points[i][0], points[i][1]}});
          mapped[2 * i] = p[0];
          mapped[2 * i + 1] = p[1];
        }
        const bool finite = std::all_of(mapped.begin(), mapped.end(), [](double v) {
          return std::isfinite(v) && std::abs(v) <= tolerances::kMaxCoordinate;
        });
        if (!finite) {
          problem(node, fmt::format("its transforms take a point beyond {:g}, the largest coordinate casteljau takes",
                                    tolerances::kMaxCoordinate),
                  ErrorKind::limit);
          return;
        }
        auto made = BezierCurve::make(PointArray::from_trusted(2, std::move(mapped)),
                                      std::vector<double>(piece.weights().begin(), piece.weights().end()));
        if (!made) return problem(node, made.error().message, made.error().kind);
        pieces.push_back(std::move(*made));
      }
      auto curve = PiecewiseBezierCurve::make(std::move(pieces));
      if (!curve) return problem(node, curve.error().message, curve.error().kind);
      drawing_.curves.push_back(SvgCurve{std::move(*curve), subpath.closed, std::string(local_name(node)),
                                         node.attribute("id").value(), line_of(node), style.fill_rule,
                                         stroke_width});
    }
  }

  std::string_view text_;
  const std::string& source_;
  std::vector<std::size_t> newlines_;
  pugi::xml_document document_;
  std::unordered_map<std::string, pugi::xml_node> ids_;
  std::vector<pugi::xml_node> active_uses_;
  std::size_t control_points_ = 0;
  std::size_t elements_ = 0;
  std::optional<Error> failure_;
  SvgDrawing drawing_;
};

}  // namespace

Expected<SvgDrawing> parse_svg_drawing(std::string_view text, const std::string& source, DrawingUnits units) {
  Reader reader(text, source);
  return reader.read(units);
}

Expected<SvgDrawing> read_svg_drawing(const std::filesystem::path& path, DrawingUnits units) {
  const auto text = read_text_file(path);
  if (!text) return text.error();
  return parse_svg_drawing(*text, display_name(path), units);
}

}  // namespace casteljau
