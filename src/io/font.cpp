// Glyph outlines to Bézier curves (io/font.hpp says what). FreeType opens the
// font, maps characters to glyphs, gives the unhinted outline in font units
// and the kerning; the outline's points and tags become pieces here.
#include "casteljau/io/font.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/core/point_array.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"
#include "text.hpp"

namespace casteljau {
namespace {

struct LibraryDeleter {
  void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
struct FaceDeleter {
  void operator()(FT_Face face) const { FT_Done_Face(face); }
};
using Library = std::unique_ptr<std::remove_pointer_t<FT_Library>, LibraryDeleter>;
using Face = std::unique_ptr<std::remove_pointer_t<FT_Face>, FaceDeleter>;

std::string freetype_message(FT_Error error) {
  switch (error) {
    case FT_Err_Cannot_Open_Resource: return "cannot open it";
    case FT_Err_Unknown_File_Format: return "unknown file format";
    case FT_Err_Invalid_File_Format: return "broken file";
    case FT_Err_Out_Of_Memory: return "out of memory";
    default: return fmt::format("FreeType error {}", error);
  }
}

/// The pieces of one contour of an outline, moved by (dx, dy) and scaled by
/// `scale`: the TrueType and CFF rules of FreeType's documentation (FT_Outline:
/// on points end pieces; a conic off point is a quadratic's control point,
/// two in a row imply the on point midway; two cubic off points make a cubic).
std::optional<PiecewiseBezierCurve> contour_curve(const FT_Outline& outline, int first, int last, double dx, double dy,
                                                  double scale) {
  const auto at = [&](int i) {
    return Vec2{{(outline.points[i].x + dx) * scale, (outline.points[i].y + dy) * scale}};
  };
  const auto tag = [&](int i) { return FT_CURVE_TAG(outline.tags[i]); };
  const int n = last - first + 1;
  // Start at an on point: the first one, or the last if the first is off, or
  // the midpoint of the first two conic off points.
  int start = first;
  Vec2 origin = at(first);
  if (tag(first) != FT_CURVE_TAG_ON) {
    if (tag(last) == FT_CURVE_TAG_ON) origin = at(last), start = last;
    else origin = 0.5 * (at(first) + at(last)), start = last;
  }
  std::vector<BezierCurve> pieces;
  const auto add = [&](std::initializer_list<Vec2> points) {
    std::vector<double> c;
    for (const Vec2& p : points) c.insert(c.end(), {p[0], p[1]});
    pieces.push_back(BezierCurve::make(PointArray::from_trusted(2, std::move(c))).value());
  };
  Vec2 current = origin;
  // Walk the n points after `start` (wrapping), ending back at the origin.
  std::vector<int> order;
  for (int k = 1; k <= n; ++k) order.push_back(first + (start - first + k) % n);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int i = order[k];
    const bool closing = k + 1 == order.size();
    if (tag(i) == FT_CURVE_TAG_ON) {
      const Vec2 p = closing ? origin : at(i);
      if (!(p == current)) add({current, p});
      current = p;
    } else if (tag(i) == FT_CURVE_TAG_CONIC) {
      const Vec2 control = at(i);
      Vec2 end = origin;
      if (!closing) {
        const int j = order[k + 1];
        const bool next_closing = k + 2 == order.size();
        if (tag(j) == FT_CURVE_TAG_ON) {
          end = next_closing ? origin : at(j);
          ++k;
        } else {
          end = 0.5 * (control + at(j));  // two conic off points in a row: the implied on point
        }
      }
      add({current, control, end});
      current = end;
    } else {  // cubic: this and the next point are the two inner control points
      const Vec2 c1 = at(i);
      const Vec2 c2 = k + 1 < order.size() ? at(order[k + 1]) : origin;
      // The end: the point after them, the contour's origin when that is the last one (or past it).
      const Vec2 end = k + 3 < order.size() ? at(order[k + 2]) : origin;
      add({current, c1, c2, end});
      current = end;
      k += 2;
    }
  }
  if (!(current == origin)) add({current, origin});
  if (pieces.empty()) return std::nullopt;  // a lone point draws nothing (fonts hold such contours)
  return PiecewiseBezierCurve::make(std::move(pieces)).value();
}

/// The text set in the face `open` opens (FT_New_Face or FT_New_Memory_Face);
/// `name` names the font in errors.
template <class Open>
Expected<TextOutline> outline_in_face(std::string_view text, const std::string& name, const TextLayout& layout,
                                      Open open) {
  if (layout.size && !(std::isfinite(*layout.size) && *layout.size > 0.0))
    return Error{fmt::format("the size must be a finite length > 0, got {}", *layout.size)};
  auto characters = io_detail::code_points(text);
  if (!characters) return characters.error();
  FT_Library raw_library = nullptr;
  if (FT_Error error = FT_Init_FreeType(&raw_library); error != 0)
    return Error{fmt::format("FreeType cannot start: {}", freetype_message(error)), ErrorKind::io};
  const Library library(raw_library);
  FT_Face raw_face = nullptr;
  if (FT_Error error = open(library.get(), &raw_face); error != 0) {
    if (error == FT_Err_Cannot_Open_Resource)
      return Error{fmt::format("cannot open the font '{}'", name), ErrorKind::io};
    return Error{fmt::format("'{}' is not a font FreeType reads: {}", name, freetype_message(error)),
                 ErrorKind::parse};
  }
  const Face face(raw_face);
  if (!FT_IS_SCALABLE(face.get()))
    return Error{fmt::format("'{}' is a bitmap font: it has no outlines", name)};
  TextOutline result;
  result.units_per_em = face->units_per_EM;
  result.font_name = fmt::format("{} {}", face->family_name ? face->family_name : "",
                                 face->style_name ? face->style_name : "");
  const double scale = layout.size ? *layout.size / face->units_per_EM : 1.0;
  result.line_height = face->height * scale;
  double pen_x = 0.0, pen_y = 0.0, widest = 0.0;
  double farthest = 0.0;  // font units: the outlines' largest coordinate
  std::string beyond;     // the first glyph placed beyond the range of coordinates
  FT_UInt previous = 0;
  for (std::size_t position = 0; position < characters->size(); ++position) {
    const char32_t character = (*characters)[position];
    if (character == U'\n') {
      widest = std::max(widest, pen_x);
      pen_x = 0.0;
      pen_y -= face->height;
      previous = 0;
      continue;
    }
    const FT_UInt glyph = FT_Get_Char_Index(face.get(), character);
    if (layout.kerning && previous != 0 && FT_HAS_KERNING(face.get())) {
      FT_Vector delta{};
      if (FT_Get_Kerning(face.get(), previous, glyph, FT_KERNING_UNSCALED, &delta) == 0) pen_x += delta.x;
    }
    if (FT_Error error = FT_Load_Glyph(face.get(), glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
        error != 0)
      return Error{fmt::format("'{}': glyph {} (for U+{:04X}) cannot be loaded: {}", name, glyph,
                               static_cast<unsigned>(character), freetype_message(error)),
                   ErrorKind::parse};
    const FT_GlyphSlot slot = face->glyph;
    if (slot->format == FT_GLYPH_FORMAT_OUTLINE) {
      const FT_Outline& outline = slot->outline;
      // The scaled outline must stay within the range of model coordinates:
      // the first glyph beyond it is named, after the whole text is measured.
      double glyph_farthest = 0.0;
      for (int i = 0; i < outline.n_points; ++i)
        glyph_farthest = std::max(
            {glyph_farthest, std::abs(outline.points[i].x + pen_x), std::abs(outline.points[i].y + pen_y)});
      farthest = std::max(farthest, glyph_farthest);
      if (glyph_farthest * scale > tolerances::kMaxCoordinate && beyond.empty())
        beyond = fmt::format("the size {:g} puts glyph {} (for U+{:04X}, character {}) {:.3g} from the origin, "
                             "beyond {:g}, the range of coordinates",
                             layout.size.value_or(1.0), glyph, static_cast<unsigned>(character), position,
                             glyph_farthest * scale, tolerances::kMaxCoordinate);
      if (!beyond.empty()) {
        pen_x += slot->advance.x;
        previous = glyph;
        continue;
      }
      int first = 0;
      for (int c = 0; c < outline.n_contours; ++c) {
        const int last = outline.contours[c];
        if (last >= first)
          if (auto curve = contour_curve(outline, first, last, pen_x, pen_y, scale))
            result.contours.push_back(GlyphContour{std::move(*curve), character, glyph, position});
        first = last + 1;
      }
    }
    pen_x += slot->advance.x;  // font units: the load did not scale
    previous = glyph;
  }
  if (!beyond.empty()) {
    // The largest size that fits, rounded down to three digits.
    const double largest = tolerances::kMaxCoordinate / farthest * face->units_per_EM;
    const double digit = std::pow(10.0, std::floor(std::log10(largest)) - 2.0);
    return Error{fmt::format("{}: this text allows a size of at most {:.3g}", beyond,
                             std::floor(largest / digit * (1.0 - 1e-12)) * digit)};
  }
  result.advance = std::max(widest, pen_x) * scale;
  return result;
}

}  // namespace

Expected<TextOutline> text_outline(std::string_view text, const std::filesystem::path& font, const TextLayout& layout) {
  return outline_in_face(text, font.string(), layout, [&](FT_Library library, FT_Face* face) {
    return FT_New_Face(library, font.c_str(), 0, face);
  });
}

Expected<TextOutline> text_outline(std::string_view text, std::span<const unsigned char> font_data,
                                   const std::string& name, const TextLayout& layout) {
  if (font_data.size() > static_cast<std::size_t>(std::numeric_limits<FT_Long>::max()))
    return Error{fmt::format("'{}' is larger than FreeType reads", name)};
  return outline_in_face(text, name, layout, [&](FT_Library library, FT_Face* face) {
    return FT_New_Memory_Face(library, font_data.data(), static_cast<FT_Long>(font_data.size()), 0, face);
  });
}

}  // namespace casteljau
