#pragma once
// Building and collecting gallery figures: an empty multi-panel figure, and
// builders that can fail (they read data or run an approximation): the
// first failure stops the gallery with its message.
// Internal to src/render.

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

}  // namespace casteljau::render::detail
