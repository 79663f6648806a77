#pragma once
// Building and collecting gallery figures: an empty multi-panel figure, and
// builders that can fail (they read data or run an approximation): the
// first failure stops the gallery with its message.
// Internal to src/render.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/render/gallery.hpp"

namespace casteljau::render::detail {

/// An empty figure of `columns` panels per row, `width` x `height` pixels.
inline Figure figure_of(std::string title, int width, int height, int columns) {
  Figure figure;
  figure.title = std::move(title);
  figure.width = width;
  figure.height = height;
  figure.columns = columns;
  return figure;
}

/// Appends the figure, or returns the error that prevented it.
inline Status append_figure(std::vector<GalleryFigure>& figures, Expected<GalleryFigure> figure) {
  if (!figure) return figure.error();
  figures.push_back(std::move(*figure));
  return {};
}

/// The surface figures of issue 5 (gallery_surfaces.cpp), numbered 30 to 34:
/// a bicubic Bézier patch, a Coons patch with both blendings, B-spline
/// surface local control, the NURBS sphere and torus, a tessellation at two
/// tolerances. The first failure stops them with its message.
Expected<std::vector<GalleryFigure>> surface_gallery_figures();

/// The figures of the questions asked of curves (issue 16; gallery_interpolation.cpp,
/// from 35): equal-parameter against equal-arc-length samples on the head.
/// Errors: a missing or malformed head.csv in `examples_dir`.
Expected<std::vector<GalleryFigure>> query_gallery_figures(const std::filesystem::path& examples_dir);

/// The figures of drawings read (issue 17; gallery_drawings.cpp, 39 and 40):
/// an SVG drawing of `examples_dir` with the control polygons of its pieces,
/// a word in DejaVu Sans with its on- and off-curve points. Errors: a missing
/// sailboat.svg or one with problems, a missing font (fonts-dejavu-core).
Expected<std::vector<GalleryFigure>> drawing_gallery_figures(const std::filesystem::path& examples_dir);

/// The G-code figures (issue 41; gallery_gcode.cpp, 41 to 43): the head and
/// the car cut within 0.01 mm, the seed's half circle as one G2, a word;
/// each program written, read back and drawn over its curves. Errors: a
/// missing head.csv or car.csv, a missing font (fonts-dejavu-core).
Expected<std::vector<GalleryFigure>> gcode_gallery_figures(const std::filesystem::path& examples_dir);

}  // namespace casteljau::render::detail
