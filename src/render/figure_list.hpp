#pragma once
// Collecting gallery figures whose builders can fail (they read data or run
// an approximation): the first failure stops the gallery with its message.
// Internal to src/render.

#include <utility>
#include <vector>

#include "casteljau/render/gallery.hpp"

namespace casteljau::render::detail {

/// Appends the figure, or returns the error that prevented it.
inline Status append_figure(std::vector<GalleryFigure>& figures, Expected<GalleryFigure> figure) {
  if (!figure) return figure.error();
  figures.push_back(std::move(*figure));
  return {};
}

}  // namespace casteljau::render::detail
