// casteljau text: the glyph outlines of a line of text in a font (FreeType),
// as model JSON, one closed piecewise_bezier curve per contour (docs/cli.md,
// "text"). The output is built in memory and written once the text is set.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/io/font.hpp"
#include "casteljau/io/model_json.hpp"
#include "commands.hpp"

namespace casteljau::cli {
namespace {

struct TextOptions {
  std::string text;
  std::string font;
  std::string size;
  std::string output;
  bool no_kerning = false;
  const CLI::Option* size_option = nullptr;
};

int run_text(const TextOptions& options) {
  TextLayout layout;
  layout.kerning = !options.no_kerning;
  if (given(options.size_option)) {
    auto size = number_option("--size", options.size);
    if (!size) return fail(size.error());
    if (!(*size > 0.0)) return fail(fmt::format("--size: {} is not an em size > 0", options.size));
    layout.size = *size;
  }
  auto outline = text_outline(options.text, options.font, layout);
  if (!outline) return fail(outline.error());
  if (outline->contours.empty())
    return fail(fmt::format("the text draws no outline in '{}' (only spaces, or glyphs without contours)",
                            options.font));
  std::vector<Model> models;
  models.reserve(outline->contours.size());
  for (GlyphContour& contour : outline->contours) models.emplace_back(std::move(contour.curve));
  return write_output(options.output, models_to_json(models));
}

}  // namespace

void add_text_command(CLI::App& app, int& status) {
  auto options = std::make_shared<TextOptions>();
  CLI::App* text = app.add_subcommand(
      "text",
      "The glyph outlines of STRING (UTF-8; \\n in it starts a new line) set in the font FONT (TrueType, "
      "OpenType/CFF, Type 1: anything FreeType reads), as model JSON: one closed piecewise_bezier curve per "
      "contour, in text order, y up, quadratic pieces for TrueType outlines and cubic ones for CFF, exactly the "
      "font's points. Glyphs are placed with the font's advances and kerning, in font units, or scaled so that an "
      "em is --size long (docs/cli.md).");
  text->add_option("STRING", options->text, "The text to set")->required();
  CLI::Option* font = text->add_option("--font", options->font, "The font file")->type_name("FONT")->required();
  options->size_option =
      text->add_option("--size", options->size, "The em size in output units (default: font units)")->type_name("S");
  text->add_flag("--no-kerning", options->no_kerning, "Place glyphs by their advances alone");
  CLI::Option* output = text->add_option("-o,--output", options->output, kOutputHelp)->type_name("FILE");
  set_action(text, status, {{font}, output}, [options] { return run_text(*options); });
}

}  // namespace casteljau::cli
