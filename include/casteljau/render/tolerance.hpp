#pragma once
// The render layer's own tolerances and limits: figures
// (core/tolerance.hpp says why each layer keeps its tolerances beside its code).

#include <limits>

namespace casteljau::tolerances {

// --- Surface figures (render/surface_plots.hpp) ------------------------------

/// Distance tolerance of the shaded image of `plot` and the gallery, relative
/// to the diagonal of the surfaces' control-point box (dimensionless): 1/500
/// of the figure's extent is about one pixel in a 700-pixel panel, so the
/// facets of the mesh do not show in the shading.
inline constexpr double kShadedSurfaceRelativeTolerance = 2e-3;

// --- Figures (render/layout.hpp, render/plots.hpp) ---------------------------

/// A flattened curve deviates from the true curve by at most this many pixels
/// on screen: below what anti-aliasing can show, so curves look smooth.
inline constexpr double kCurveTolerancePixels = 0.25;

/// Flattening tolerance of a curve in a panel with a logarithmic axis,
/// where a model distance is no fixed number of pixels, relative to the
/// curve's control box (a Bernstein graph's: to its height, at most 1): one
/// ten-thousandth, invisible at any canvas size a figure has. Dimensionless.
inline constexpr double kLogAxisRelativeTolerance = 1e-4;

/// Largest Bernstein degree plotted (n + 1 curves of degree n in one figure;
/// beyond this the figure is an unreadable black area and the work is wasted).
inline constexpr int kMaxPlottedBasisDegree = 1000;

/// Largest degree of a curve piece a figure draws. Certifying a segment of a
/// degree-n piece costs two de Casteljau triangles, O(n^2), per trial step
/// (ops/flatten.hpp), and a curve of random control points needs about
/// 50 n^0.4 segments at a quarter pixel (124 at n = 100, 473 at n = 2000),
/// so the time grows like n^2.4 to n^3: measured 0.5 s at degree 500, 1.4 s
/// at 1000, 12 s at 2000 (one core, random control points, 2026-12-01);
/// degree 10,000 (what model JSON accepts) would take many minutes. Beyond
/// 1000, the limit of the Bernstein figures too, figures refuse the curve at
/// once (render/layout.hpp, check_plotted_degree).
inline constexpr int kMaxPlottedCurveDegree = 1000;

/// Largest degree whose de Casteljau construction (plot --construction) a
/// figure draws: its n levels hold n(n+1)/2 segments and n(n-1)/2 points,
/// 20,100 segments at degree 200 (an SVG of about 1.5 MB, already a dark
/// tangle); degree 500 wrote 9 MB, degree 1000 took 6 s of CPU for a PNG.
inline constexpr int kMaxConstructionDegree = 200;

/// Largest width, height or diagonal of the data one figure shows, in model
/// units (about 4.4e304): a range is widened by 5 % margins and, for equal
/// aspect, stretched by up to the plot area's aspect ratio (at most 16384 / 10
/// pixels), and 2^-12 of the largest double keeps all of that finite.
inline constexpr double kMaxPlottedWidth = std::numeric_limits<double>::max() / 4096.0;

}  // namespace casteljau::tolerances
