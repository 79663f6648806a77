#pragma once
// Writing figures: SVG as text written by casteljau (deterministic: the same
// figure gives the same bytes), PNG and PDF through cairo. Every writer is
// atomic: the file appears complete or not at all (temporary file + rename).

#include <filesystem>
#include <string>

#include "casteljau/core/expected.hpp"
#include "casteljau/render/figure.hpp"
#include "casteljau/render/layout.hpp"

namespace casteljau::render {

/// The scene as an SVG 1.1 document: polylines as <polyline>/<polygon> (no
/// curve commands: curves were flattened by layout()), discs as <circle>,
/// text as <text>, clipping by <clipPath>. Numbers with 2 decimals (1/100 px).
std::string svg_document(const Scene& scene);

/// Lays the figure out (`progress` as for layout()) and writes it as SVG.
Status write_svg(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

/// Lays the figure out and writes a width x height PNG (cairo, anti-aliased, RGB on white).
Status write_png(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

/// Lays the figure out and writes a one-page PDF (cairo, vector), one pixel
/// being 0.75 pt (96 dpi), so an 800 px wide figure is 600 pt wide.
Status write_pdf(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

/// The format chosen by the extension (case-insensitive): .svg, .png or .pdf.
/// Anything else is an error naming the file, before anything is written.
Status write_figure(const Figure& figure, const std::filesystem::path& path, Progress progress = {});

}  // namespace casteljau::render
