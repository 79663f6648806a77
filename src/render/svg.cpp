// SVG written by casteljau: every curve is already a polyline (layout()
// flattened it), so only <polyline>, <polygon>, <circle> and <text> appear.
// Deterministic: numbers are formatted by fmt with a fixed number of decimals.
#include <fmt/format.h>

#include <string>
#include <variant>

#include "markup.hpp"
#include "casteljau/io/file.hpp"
#include "casteljau/render/write.hpp"

namespace casteljau::render {
namespace {

/// A coordinate in 1/100 pixel, without "-0.00" (which would make equal
/// figures differ by the sign of a rounded zero).
std::string number(double value) {
  std::string text = fmt::format("{:.2f}", value);
  if (text == "-0.00") return "0.00";
  return text;
}

std::string hex(Color c) { return fmt::format("#{:02x}{:02x}{:02x}", c.red, c.green, c.blue); }


std::string points_attribute(const std::vector<Vec2>& points) {
  std::string out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i) out += ' ';
    out += number(points[i][0]);
    out += ',';
    out += number(points[i][1]);
  }
  return out;
}

std::string stroke_attributes(const Stroke& s) {
  std::string out = fmt::format(" stroke=\"{}\" stroke-width=\"{}\"", hex(s.color), number(s.width));
  if (s.color.alpha < 1.0) out += fmt::format(" stroke-opacity=\"{:.3f}\"", s.color.alpha);
  if (!s.dash.empty()) {
    out += " stroke-dasharray=\"";
    for (std::size_t i = 0; i < s.dash.size(); ++i) out += (i ? "," : "") + number(s.dash[i]);
    out += "\" stroke-linecap=\"butt\"";
  } else {
    out += " stroke-linecap=\"round\"";
  }
  out += " stroke-linejoin=\"round\"";
  return out;
}

std::string fill_attributes(const std::optional<Color>& fill) {
  if (!fill) return " fill=\"none\"";
  std::string out = fmt::format(" fill=\"{}\"", hex(*fill));
  if (fill->alpha < 1.0) out += fmt::format(" fill-opacity=\"{:.3f}\"", fill->alpha);
  return out;
}

const char* anchor_name(Anchor a) {
  switch (a) {
    case Anchor::start: return "start";
    case Anchor::middle: return "middle";
    case Anchor::end: return "end";
  }
  return "start";
}

class SvgWriter {
 public:
  std::string document(const Scene& scene) {
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out_ += fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{0}\" height=\"{1}\" "
        "viewBox=\"0 0 {0} {1}\" font-family=\"DejaVu Sans, Bitstream Vera Sans, Verdana, sans-serif\">\n",
        number(scene.width), number(scene.height));
    if (!scene.title.empty()) out_ += fmt::format("<title>{}</title>\n", detail::xml_escaped(scene.title));
    out_ += fmt::format("<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>\n", number(scene.width),
                        number(scene.height));
    for (const auto& shape : scene.shapes) std::visit([this](const auto& s) { draw(s); }, shape);
    while (open_groups_ > 0) out_ += "</g>\n", --open_groups_;
    out_ += "</svg>\n";
    return std::move(out_);
  }

 private:
  void draw(const PathShape& p) {
    if (p.points.empty()) return;
    out_ += fmt::format("<{} points=\"{}\"", p.closed ? "polygon" : "polyline", points_attribute(p.points));
    out_ += fill_attributes(p.fill);
    if (p.stroke) out_ += stroke_attributes(*p.stroke);
    out_ += "/>\n";
  }
  void draw(const CircleShape& c) {
    out_ += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"", number(c.center[0]), number(c.center[1]),
                        number(c.radius));
    out_ += fill_attributes(c.fill);
    out_ += "/>\n";
  }
  void draw(const TextShape& t) {
    out_ += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{}\" fill=\"{}\"", number(t.position[0]),
                        number(t.position[1]), number(t.size), anchor_name(t.anchor), hex(t.color));
    if (t.bold) out_ += " font-weight=\"bold\"";
    if (t.rotation_degrees != 0.0)
      out_ += fmt::format(" transform=\"rotate({} {} {})\"", number(-t.rotation_degrees), number(t.position[0]),
                          number(t.position[1]));
    out_ += fmt::format(">{}</text>\n", detail::xml_escaped(t.text));
  }
  void draw(const ClipBegin& c) {
    const int id = next_clip_++;
    out_ += fmt::format(
        "<clipPath id=\"clip{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n<g "
        "clip-path=\"url(#clip{})\">\n",
        id, number(c.area.left), number(c.area.top), number(c.area.width), number(c.area.height), id);
    ++open_groups_;
  }
  void draw(const ClipEnd&) {
    if (open_groups_ == 0) return;
    out_ += "</g>\n";
    --open_groups_;
  }

  std::string out_;
  int next_clip_ = 0;
  int open_groups_ = 0;
};

}  // namespace

std::string svg_document(const Scene& scene) { return SvgWriter{}.document(scene); }

Status write_svg(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  auto scene = layout(figure, progress);
  if (!scene) return scene.error();
  return write_file_atomically(path, svg_document(*scene));
}

}  // namespace casteljau::render
