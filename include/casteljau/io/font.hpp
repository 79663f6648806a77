#pragma once
// Glyph outlines of a font (TrueType's quadratic and CFF's cubic outlines,
// read by FreeType: Debian's libfreetype-dev) as closed piecewise Bézier
// curves, laid out along a line of text with the font's advances and
// kerning. FreeType only reads the file; the outline's points become Bézier
// pieces here: on-curve points end pieces, a TrueType off-curve point is the
// control point of a quadratic, two consecutive ones imply the on-curve
// point midway between them (the TrueType rule), two cubic off-curve points
// are the inner control points of a cubic (CFF).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/core/expected.hpp"

namespace casteljau {

/// One contour of one glyph: a closed curve in R^2, y up (contours of a
/// single point, which some fonts hold, draw nothing and are left out).
struct GlyphContour {
  PiecewiseBezierCurve curve;  ///< closed: its last piece ends where its first begins
  char32_t character = 0;      ///< the character it draws
  std::size_t glyph = 0;       ///< the font's glyph index
  std::size_t position = 0;    ///< the character's index in the text (code points, from 0)
};

/// How the text is set.
struct TextLayout {
  /// The em size in output units; none: font units (the font's own integers).
  std::optional<double> size;
  /// Apply the font's kerning (the 'kern' table FreeType reads).
  bool kerning = true;
};

/// The outlines of a line of text, and its measures in output units.
struct TextOutline {
  std::vector<GlyphContour> contours;  ///< in text order, each glyph's contours in the font's order
  double advance = 0.0;                ///< where the pen ends: the text's width along the baseline
  double units_per_em = 0.0;           ///< the font's em in font units
  double line_height = 0.0;            ///< baseline to baseline (the face's height), for "\n"
  std::string font_name;               ///< family and style, as the font names them
};

/// Sets `text` (UTF-8; "\n" starts a new line one line height lower) in the
/// font at `font` (any format FreeType reads: TrueType, OpenType/CFF, Type 1):
/// glyph i placed at the pen, the pen moved by the glyph's advance and the
/// kerning of the pair (font units, unhinted, unscaled), then everything
/// scaled by size / units_per_em when a size is given. Characters the font
/// lacks draw its .notdef glyph (as every text renderer does). Errors: a
/// font file FreeType cannot open ("'x.ttf' is not a font FreeType reads:
/// unknown file format"), text that is not UTF-8 (naming the byte), a size
/// that is not finite and > 0 or that puts a glyph beyond the range of
/// coordinates (tolerances::kMaxCoordinate: "the size 1e+101 puts glyph 43
/// (for U+0048, character 0) 7.29e+100 from the origin, …: this text allows
/// a size of at most 1.37e+100"), a font without outlines (bitmap fonts).
Expected<TextOutline> text_outline(std::string_view text, const std::filesystem::path& font,
                                   const TextLayout& layout = {});

/// The same with the font's bytes in memory (a font fetched, embedded or
/// fuzzed; FreeType's FT_New_Memory_Face): `name` names it in errors as the
/// path does above. The bytes must outlive the call only.
Expected<TextOutline> text_outline(std::string_view text, std::span<const unsigned char> font_data,
                                   const std::string& name, const TextLayout& layout = {});

}  // namespace casteljau
