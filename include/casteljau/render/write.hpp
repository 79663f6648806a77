#pragma once
// Writing figures: SVG as text written by casteljau (deterministic: the same
// figure gives the same bytes), PNG and PDF through cairo, each first encoded
// in memory and then written by io/file's write_file_atomically, the project's
// one writer (the file appears complete or not at all; a FIFO or a device is
// written in place).

#include <filesystem>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/render/figure.hpp"
#include "casteljau/render/layout.hpp"

namespace casteljau::render {

/// The file formats of a figure.
enum class FigureFormat { svg, png, pdf };

/// The format named by the path's extension, any case: .svg, .png or .pdf.
/// Anything else is an error naming the file, before anything is drawn:
/// "cannot write 'f.gif': unknown figure format '.gif' (use .svg, .png or .pdf)".
Expected<FigureFormat> figure_format_of(const std::filesystem::path& path);

/// The scene as an SVG 1.1 document: polylines as <polyline>/<polygon> (no
/// curve commands: curves were flattened by layout()), discs as <circle>,
/// text as <text>, clipping by <clipPath>. Numbers with 2 decimals (1/100 px).
std::string svg_document(const Scene& scene);

/// The scene as the bytes of a width x height PNG (cairo, anti-aliased, RGB
/// on white). Error: cairo's status ("out of memory").
Expected<std::string> png_document(const Scene& scene);

/// The scene as the bytes of a one-page PDF (cairo, vector), one pixel being
/// 0.75 pt (96 dpi), so an 800 px wide figure is 600 pt wide; the scene's
/// title is the document's. Error: cairo's status.
Expected<std::string> pdf_document(const Scene& scene);

/// Lays the figure out (`progress` as for layout()) and encodes it in
/// `format`: the whole file, in memory.
Expected<std::string> figure_document(const Figure& figure, FigureFormat format, Progress progress = {});

/// Lays the figure out (reporting to `progress`) and writes it as SVG (write_file_atomically).
Status write_svg(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

/// Lays the figure out and writes it as PNG (write_file_atomically).
Status write_png(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

/// Lays the figure out and writes it as PDF (write_file_atomically).
Status write_pdf(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

/// The format chosen by the extension (figure_format_of), then written as
/// write_svg, write_png or write_pdf; nothing is written on any error.
Status write_figure(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

}  // namespace casteljau::render
