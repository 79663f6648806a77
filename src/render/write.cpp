// Figures to files (render/write.hpp): the format from the extension, the
// bytes from svg.cpp or cairo.cpp, the file from io/file.
#include <fmt/format.h>

#include <string>

#include "casteljau/io/file.hpp"
#include "casteljau/render/write.hpp"

namespace casteljau::render {
namespace {

/// The laid-out scene in `format`.
Expected<std::string> encode(const Scene& scene, FigureFormat format) {
  switch (format) {
    case FigureFormat::svg: return svg_document(scene);
    case FigureFormat::png: return png_document(scene);
    case FigureFormat::pdf: return pdf_document(scene);
  }
  return Error{"unknown figure format"};
}

/// Lays out, encodes and writes. Layout errors are the figure's own; an
/// encoding error (cairo's) names the file it was for, as a write error does.
Status write_as(const Figure& figure, const std::filesystem::path& path, FigureFormat format, Progress progress) {
  auto scene = layout(figure, progress);
  if (!scene) return scene.error();
  auto bytes = encode(*scene, format);
  if (!bytes) return Error{fmt::format("cannot write '{}': {}", display_name(path), bytes.error().message)};
  return write_file_atomically(path, *bytes);
}

}  // namespace

Expected<FigureFormat> figure_format_of(const std::filesystem::path& path) {
  const std::string extension = lowercase_extension(path);
  if (extension == ".svg") return FigureFormat::svg;
  if (extension == ".png") return FigureFormat::png;
  if (extension == ".pdf") return FigureFormat::pdf;
  if (extension.empty()) {
    return Error{fmt::format("cannot write '{}': the file name has no extension (use .svg, .png or .pdf)",
                             display_name(path)), ErrorKind::io};
  }
  return Error{fmt::format("cannot write '{}': unknown figure format '{}' (use .svg, .png or .pdf)",
                           display_name(path), display_name(extension)), ErrorKind::io};
}

Expected<std::string> figure_document(const Figure& figure, FigureFormat format, Progress progress) {
  auto scene = layout(figure, progress);
  if (!scene) return scene.error();
  return encode(*scene, format);
}

Status write_svg(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  return write_as(figure, path, FigureFormat::svg, progress);
}

Status write_png(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  return write_as(figure, path, FigureFormat::png, progress);
}

Status write_pdf(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  return write_as(figure, path, FigureFormat::pdf, progress);
}

Status write_figure(const Figure& figure, const std::filesystem::path& path, Progress progress) {
  auto format = figure_format_of(path);
  if (!format) return format.error();
  return write_as(figure, path, *format, progress);
}

}  // namespace casteljau::render
