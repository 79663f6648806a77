// Font outlines (io/font.hpp) against FreeType's own outline decomposition
// (FT_Outline_Decompose, the reference every FreeType renderer draws from):
// every glyph of a TrueType font (DejaVu Sans, quadratic) and of an
// OpenType/CFF font (Cantarell, cubic) gives the same pieces, exactly; the
// layout follows FreeType's advances and kerning; errors for what is not a
// font or not UTF-8. The fonts are Debian's fonts-dejavu-core and
// fonts-cantarell (make deps installs both).
#include "casteljau/io/font.hpp"

#include <gtest/gtest.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace casteljau {
namespace {

const std::filesystem::path kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const std::filesystem::path kCantarell = "/usr/share/fonts/opentype/cantarell/Cantarell-Regular.otf";

/// A segment as FreeType's decomposition gives it: its control points after
/// the current point, in font units.
using Segment = std::vector<std::array<double, 2>>;

struct Recorder {
  std::vector<std::vector<Segment>> contours;  // each contour's segments, with its start point first
  std::array<double, 2> current{};
};

// FreeType computes implied on points as integer midpoints: the outline is
// doubled first (exact), so every midpoint is an integer, and halved here.
std::array<double, 2> half(const FT_Vector* v) { return {v->x / 2.0, v->y / 2.0}; }

int move_to(const FT_Vector* to, void* user) {
  auto* r = static_cast<Recorder*>(user);
  r->contours.emplace_back();
  r->current = half(to);
  return 0;
}
int line_to(const FT_Vector* to, void* user) {
  auto* r = static_cast<Recorder*>(user);
  const auto p = half(to);
  if (p != r->current) r->contours.back().push_back({r->current, p});  // zero-length closing lines draw nothing
  r->current = p;
  return 0;
}
int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
  auto* r = static_cast<Recorder*>(user);
  r->contours.back().push_back({r->current, half(control), half(to)});
  r->current = half(to);
  return 0;
}
int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
  auto* r = static_cast<Recorder*>(user);
  r->contours.back().push_back({r->current, half(c1), half(c2), half(to)});
  r->current = half(to);
  return 0;
}

/// FreeType's decomposition of the glyph of `character`, unhinted, font units.
std::vector<std::vector<Segment>> freetype_contours(FT_Face face, char32_t character) {
  EXPECT_EQ(FT_Load_Glyph(face, FT_Get_Char_Index(face, character), FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING), 0);
  FT_Outline& outline = face->glyph->outline;
  FT_Matrix twice{0x20000, 0, 0, 0x20000};
  FT_Outline_Transform(&outline, &twice);
  const FT_Outline_Funcs funcs{move_to, line_to, conic_to, cubic_to, 0, 0};
  Recorder recorder;
  EXPECT_EQ(FT_Outline_Decompose(&outline, &funcs, &recorder), 0);
  // A contour of one point (fonts hold some) draws nothing: casteljau leaves it out.
  std::erase_if(recorder.contours, [](const std::vector<Segment>& c) { return c.empty(); });
  return recorder.contours;
}

/// Compares every glyph of `text` set alone with FreeType's decomposition;
/// returns the number of pieces compared.
std::size_t compare_with_freetype(const std::filesystem::path& font, const std::u32string& characters,
                                  int& quadratic, int& cubic) {
  FT_Library library = nullptr;
  EXPECT_EQ(FT_Init_FreeType(&library), 0);
  FT_Face face = nullptr;
  EXPECT_EQ(FT_New_Face(library, font.c_str(), 0, &face), 0);
  std::size_t compared = 0;
  for (char32_t character : characters) {
    std::string utf8;  // the one character in UTF-8
    if (character < 0x80) utf8 += static_cast<char>(character);
    else if (character < 0x800) utf8 += {static_cast<char>(0xC0 | (character >> 6)), static_cast<char>(0x80 | (character & 0x3F))};
    else utf8 += {static_cast<char>(0xE0 | (character >> 12)), static_cast<char>(0x80 | ((character >> 6) & 0x3F)),
                  static_cast<char>(0x80 | (character & 0x3F))};
    const TextOutline ours = text_outline(utf8, font).value();
    const auto theirs = freetype_contours(face, character);
    EXPECT_EQ(ours.contours.size(), theirs.size()) << "U+" << std::hex << static_cast<unsigned>(character);
    for (std::size_t c = 0; c < std::min(ours.contours.size(), theirs.size()); ++c) {
      const auto& pieces = ours.contours[c].curve.pieces();
      EXPECT_EQ(pieces.size(), theirs[c].size()) << "U+" << std::hex << static_cast<unsigned>(character) << " contour " << c;
      if (pieces.size() != theirs[c].size()) continue;
      for (std::size_t k = 0; k < pieces.size(); ++k) {
        const PointArray& p = pieces[k].control_points();
        EXPECT_EQ(p.size(), theirs[c][k].size());
        if (p.size() != theirs[c][k].size()) continue;
        for (std::size_t i = 0; i < p.size(); ++i) {
          EXPECT_EQ(p[i][0], theirs[c][k][i][0]);
          EXPECT_EQ(p[i][1], theirs[c][k][i][1]);
        }
        if (p.size() == 3) ++quadratic;
        if (p.size() == 4) ++cubic;
        ++compared;
      }
      // Closed: the last piece ends where the first begins, exactly.
      const PointArray& first = pieces.front().control_points();
      const PointArray& last = pieces.back().control_points();
      EXPECT_EQ(first[0][0], last[last.size() - 1][0]);
      EXPECT_EQ(first[0][1], last[last.size() - 1][1]);
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  return compared;
}

TEST(Font, TrueTypeGlyphsAreFreeTypesOwnQuadratics) {
  if (!std::filesystem::exists(kDejaVu)) GTEST_SKIP() << "fonts-dejavu-core is not installed";
  int quadratic = 0, cubic = 0;
  const std::size_t pieces =
      compare_with_freetype(kDejaVu, U"casteljauCASTELJAU0123456789@&%$§éàÆœßgQ?!", quadratic, cubic);
  std::printf("DejaVu Sans: %zu pieces (%d quadratics) equal FreeType's decomposition\n", pieces, quadratic);
  EXPECT_GT(pieces, 500u);
  EXPECT_GT(quadratic, 300);
  EXPECT_EQ(cubic, 0);
}

TEST(Font, CffGlyphsAreFreeTypesOwnCubics) {
  if (!std::filesystem::exists(kCantarell)) GTEST_SKIP() << "fonts-cantarell is not installed";
  int quadratic = 0, cubic = 0;
  const std::size_t pieces = compare_with_freetype(kCantarell, U"casteljauCASTELJAU0123456789@&%$éàgQ?!", quadratic, cubic);
  std::printf("Cantarell: %zu pieces (%d cubics) equal FreeType's decomposition\n", pieces, cubic);
  EXPECT_GT(pieces, 300u);
  EXPECT_GT(cubic, 200);
  EXPECT_EQ(quadratic, 0);
}

TEST(Font, LayoutFollowsAdvancesKerningAndSize) {
  if (!std::filesystem::exists(kDejaVu)) GTEST_SKIP() << "fonts-dejavu-core is not installed";
  FT_Library library = nullptr;
  FT_Init_FreeType(&library);
  FT_Face face = nullptr;
  FT_New_Face(library, kDejaVu.c_str(), 0, &face);
  const FT_UInt a = FT_Get_Char_Index(face, 'A'), v = FT_Get_Char_Index(face, 'V');
  FT_Load_Glyph(face, a, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING);
  const double advance_a = face->glyph->advance.x;
  FT_Load_Glyph(face, v, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING);
  const double advance_v = face->glyph->advance.x;
  FT_Vector kern{};
  FT_Get_Kerning(face, a, v, FT_KERNING_UNSCALED, &kern);
  const double em = face->units_per_EM, height = face->height;
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  ASSERT_LT(kern.x, 0);  // DejaVu Sans kerns AV

  const TextOutline v_alone = text_outline("V", kDejaVu).value();
  const TextOutline kerned = text_outline("AV", kDejaVu).value();
  TextLayout plain;
  plain.kerning = false;
  const TextOutline unkerned = text_outline("AV", kDejaVu, plain).value();
  EXPECT_EQ(kerned.advance, advance_a + kern.x + advance_v);
  EXPECT_EQ(unkerned.advance, advance_a + advance_v);
  EXPECT_EQ(kerned.units_per_em, em);
  // The V of "AV" is the V alone moved by A's advance and the kerning.
  const auto& alone = v_alone.contours.at(0).curve.pieces().at(0).control_points();
  const auto& moved = kerned.contours.back().curve.pieces().at(0).control_points();
  EXPECT_EQ(moved[0][0], alone[0][0] + advance_a + kern.x);
  EXPECT_EQ(moved[0][1], alone[0][1]);
  EXPECT_EQ(kerned.contours.back().character, U'V');
  EXPECT_EQ(kerned.contours.back().position, 1u);
  // --size: an em is that long.
  TextLayout sized;
  sized.size = 10.0;
  const TextOutline small = text_outline("V", kDejaVu, sized).value();
  const auto& scaled = small.contours.at(0).curve.pieces().at(0).control_points();
  EXPECT_DOUBLE_EQ(scaled[0][0], alone[0][0] * 10.0 / em);
  EXPECT_DOUBLE_EQ(small.advance, advance_v * 10.0 / em);
  // A new line starts one line height lower.
  const TextOutline lines = text_outline("V\nV", kDejaVu).value();
  const auto& second = lines.contours.back().curve.pieces().at(0).control_points();
  EXPECT_EQ(second[0][0], alone[0][0]);
  EXPECT_EQ(second[0][1], alone[0][1] - height);
}

TEST(Font, Errors) {
  const auto folder = std::filesystem::temp_directory_path() / "casteljau_font_test";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "not_a_font.ttf") << "hello";
  EXPECT_EQ(text_outline("a", folder / "not_a_font.ttf").error().message,
            "'" + (folder / "not_a_font.ttf").string() + "' is not a font FreeType reads: unknown file format");
  EXPECT_EQ(text_outline("a", folder / "missing.ttf").error().message,
            "cannot open the font '" + (folder / "missing.ttf").string() + "'");
  std::filesystem::remove_all(folder);
  if (!std::filesystem::exists(kDejaVu)) return;
  EXPECT_EQ(text_outline("ab\xff", kDejaVu).error().message,
            "the text is not UTF-8: byte 3 (0xff) does not begin a character");
  EXPECT_EQ(text_outline("\xc0\x80", kDejaVu).error().message,
            "the text is not UTF-8: byte 1 (0xc0) does not begin a character");  // an overlong NUL
  TextLayout zero;
  zero.size = 0.0;
  EXPECT_EQ(text_outline("a", kDejaVu, zero).error().message, "the size must be a finite length > 0, got 0");
}

}  // namespace
}  // namespace casteljau
