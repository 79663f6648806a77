#pragma once
// The gallery: every seed figure (issue "Foundation", seed notebook 004 and
// seed 003; issue 4's B-spline and NURBS figures from seed 001), rendered as SVG and PNG with an index.html that shows each one
// with one line of explanation. `casteljau gallery` and `make demo` call this.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/point_array.hpp"
#include "casteljau/core/progress.hpp"
#include "casteljau/render/figure.hpp"

namespace casteljau::render {

/// One figure of the gallery: file stem, one line for index.html, the figure.
struct GalleryFigure {
  std::string name;         ///< file stem, e.g. "01_bernstein_20"
  std::string explanation;  ///< one sentence (plain text; measured numbers included)
  Figure figure;
};

/// One section of the gallery: the first and last number of its figures
/// (their names start with the number, "17_bspline_basis_clamped") and what
/// they show, in a phrase.
struct GallerySection {
  int first = 0, last = 0;
  const char* topics = "";
};

/// The gallery's sections in order: the Bézier figures of seed 004 and seed
/// 003, the B-spline and NURBS figures, interpolation, surfaces. The one
/// description of what the gallery holds (`casteljau gallery --help` prints
/// it; a test checks it against the figures built).
std::span<const GallerySection> gallery_sections();

/// The sections as one sentence for a help text: "01-16 Bézier curves (...);
/// 17-22 B-splines and NURBS (...); ...".
std::string gallery_contents();

/// The folder with the seeds' CSV files (head, car, semicircle, spirals...)
/// fixed when casteljau was built.
std::filesystem::path default_examples_dir();

/// The seed notebook's cycle(n): P_k = (cos t_k, sin t_k) / (k+1) with
/// t_k = -pi/2 + 2 k pi / n, k = 0..n (a spiral of n+1 points).
PointArray notebook_cycle(int n);

/// Degree 200 on cycle(200): |point_at_bernstein_sum - point_at| at `samples`
/// evenly spaced t in [0,1] (samples >= 2).
struct EvaluatorComparison {
  std::vector<double> parameters;
  std::vector<double> differences;
  double maximum = 0.0;
  double at = 0.0;  ///< a parameter where the maximum is reached
};
EvaluatorComparison compare_evaluators_on_cycle(int degree, int samples);

/// The seed 003 semicircle cubic (A, B, C, D): |C(t)| - radius at `samples`
/// evenly spaced t, and the largest absolute value.
struct RadialError {
  std::vector<double> parameters;
  std::vector<double> errors;
  double maximum = 0.0;  ///< max |error|
  double at = 0.0;
};
RadialError radial_error(const PointArray& control_points, double radius, int samples);

/// The same for a plane B-spline or NURBS curve (a circle or arc centred at
/// the origin): |C(u)| - radius at `samples` evenly spaced u of its domain
/// (parameters holds the u), by point_at (de Boor). samples >= 2.
RadialError radial_error(const BSplineCurve& curve, double radius, int samples);

/// The gallery's B-spline and NURBS figures (issue 4; they need no seed
/// file): the basis for clamped and uniform knots (17, 18), local control
/// (19), knot multiplicity and continuity (20), the NURBS circle (21) and the
/// pull of one weight (22). gallery_figures() lists them last.
Expected<std::vector<GalleryFigure>> bspline_gallery_figures();

/// The gallery's interpolation figures (issue 3; 23 to 29): the head and the
/// car through c1-bezier at α = 1, 2 and the closed C² cubic, Runge's
/// oscillation, natural splines q = 1..3, smoothing with increasing λ, and
/// every method side by side on each data set. Errors: a missing or
/// malformed head.csv or car.csv in `examples_dir` (named).
Expected<std::vector<GalleryFigure>> interpolation_gallery_figures(const std::filesystem::path& examples_dir);

/// Every gallery figure, built from the CSV files in `examples_dir`.
/// Errors: a missing or malformed seed file (named).
Expected<std::vector<GalleryFigure>> gallery_figures(const std::filesystem::path& examples_dir);

/// The index page: title, then for each figure its SVG image, title and
/// explanation, with links to the .svg and .png files.
std::string gallery_index_html(const std::vector<GalleryFigure>& figures);

/// Builds the gallery and writes NAME.svg, NAME.png for every figure and
/// index.html into `dir` (created with its parents if needed). Each file is
/// written atomically; index.html last, so a complete index means a complete
/// gallery. `progress` hears the fraction done: building every figure is the
/// first tenth, then each figure's share of the rest as it is laid out and written.
Expected<std::vector<GalleryFigure>> write_gallery(const std::filesystem::path& dir,
                                                   const std::filesystem::path& examples_dir, Progress progress = {});

}  // namespace casteljau::render
