// PNG and PDF through cairo: the Scene's polylines, discs and text, with
// cairo's anti-aliasing. Curves were flattened by layout(): no cairo curve
// primitive is used. Files are written to a temporary name in the target's
// folder and renamed when cairo reports success.
#include <cairo-pdf.h>
#include <cairo.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cctype>
#include <cstring>
#include <numbers>
#include <system_error>
#include <variant>

#include "casteljau/render/write.hpp"

namespace casteljau::render {
namespace {

void set_color(cairo_t* cr, Color c) {
  cairo_set_source_rgba(cr, c.red / 255.0, c.green / 255.0, c.blue / 255.0, c.alpha);
}

void trace(cairo_t* cr, const std::vector<Vec2>& points, bool closed) {
  cairo_new_path(cr);
  for (std::size_t i = 0; i < points.size(); ++i)
    (i == 0 ? cairo_move_to : cairo_line_to)(cr, points[i][0], points[i][1]);
  if (closed) cairo_close_path(cr);
}

void apply_stroke(cairo_t* cr, const Stroke& s) {
  set_color(cr, s.color);
  cairo_set_line_width(cr, s.width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, s.dash.empty() ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
  cairo_set_dash(cr, s.dash.empty() ? nullptr : s.dash.data(), static_cast<int>(s.dash.size()), 0.0);
}

struct Painter {
  cairo_t* cr;

  void operator()(const PathShape& p) const {
    if (p.points.empty()) return;
    trace(cr, p.points, p.closed);
    if (p.fill) {
      set_color(cr, *p.fill);
      if (p.stroke) cairo_fill_preserve(cr);
      else cairo_fill(cr);
    }
    if (p.stroke) {
      apply_stroke(cr, *p.stroke);
      cairo_stroke(cr);
    }
  }
  void operator()(const CircleShape& c) const {
    // A disc is not a curve of the model: cairo_arc is the marker's shape itself.
    cairo_new_path(cr);
    cairo_arc(cr, c.center[0], c.center[1], c.radius, 0.0, 2.0 * std::numbers::pi);
    set_color(cr, c.fill);
    cairo_fill(cr);
  }
  void operator()(const TextShape& t) const {
    cairo_save(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           t.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, t.size);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, t.text.c_str(), &extents);
    const double shift = t.anchor == Anchor::start ? 0.0 : t.anchor == Anchor::middle ? 0.5 : 1.0;
    cairo_translate(cr, t.position[0], t.position[1]);
    cairo_rotate(cr, -t.rotation_degrees * std::numbers::pi / 180.0);
    cairo_move_to(cr, -shift * extents.x_advance, 0.0);
    set_color(cr, t.color);
    cairo_show_text(cr, t.text.c_str());
    cairo_restore(cr);
  }
  void operator()(const ClipBegin& c) const {
    cairo_save(cr);
    cairo_new_path(cr);
    cairo_rectangle(cr, c.area.left, c.area.top, c.area.width, c.area.height);
    cairo_clip(cr);
  }
  void operator()(const ClipEnd&) const { cairo_restore(cr); }
};

void paint(cairo_t* cr, const Scene& scene) {
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  for (const auto& shape : scene.shapes) std::visit(Painter{cr}, shape);
}

/// A fresh temporary file next to `path` (same file system, so rename is atomic).
Expected<std::filesystem::path> temporary_beside(const std::filesystem::path& path) {
  const auto folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::string name = (folder / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = mkstemp(name.data());
  if (fd < 0) return Error{fmt::format("cannot write '{}': {}", path.string(), std::strerror(errno))};
  // mkstemp creates the file private (0600); a figure is an ordinary file.
  fchmod(fd, 0644);
  close(fd);
  return std::filesystem::path(name);
}

Status commit(const std::filesystem::path& temporary, const std::filesystem::path& path, cairo_status_t status) {
  if (status != CAIRO_STATUS_SUCCESS) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return Error{fmt::format("cannot write '{}': {}", path.string(), cairo_status_to_string(status))};
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    return Error{fmt::format("cannot write '{}': {}", path.string(), error.message())};
  }
  return {};
}

}  // namespace

Status write_png(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  auto scene = layout(figure, progress);
  if (!scene) return scene.error();
  auto temporary = temporary_beside(path);
  if (!temporary) return temporary.error();
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, figure.width, figure.height);
  cairo_t* cr = cairo_create(surface);
  paint(cr, *scene);
  cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_write_to_png(surface, temporary->c_str());
  cairo_surface_destroy(surface);
  return commit(*temporary, path, status);
}

Status write_pdf(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  auto scene = layout(figure, progress);
  if (!scene) return scene.error();
  auto temporary = temporary_beside(path);
  if (!temporary) return temporary.error();
  constexpr double kPointsPerPixel = 0.75;  // 96 dpi: CSS pixels in PDF points
  cairo_surface_t* surface = cairo_pdf_surface_create(temporary->c_str(), figure.width * kPointsPerPixel,
                                                      figure.height * kPointsPerPixel);
  if (!scene->title.empty()) cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, scene->title.c_str());
  cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "casteljau");
  cairo_t* cr = cairo_create(surface);
  cairo_scale(cr, kPointsPerPixel, kPointsPerPixel);
  paint(cr, *scene);
  cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  return commit(*temporary, path, status);
}

Status write_figure(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  std::string extension = path.extension().string();
  for (auto& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".svg") return write_svg(figure, path, progress);
  if (extension == ".png") return write_png(figure, path, progress);
  if (extension == ".pdf") return write_pdf(figure, path, progress);
  if (extension.empty())
    return Error{fmt::format("cannot write '{}': the file name has no extension (use .svg, .png or .pdf)", path.string())};
  return Error{fmt::format("cannot write '{}': unknown figure format '{}' (use .svg, .png or .pdf)", path.string(),
                           extension)};
}

}  // namespace casteljau::render
