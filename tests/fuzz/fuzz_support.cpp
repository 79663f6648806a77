#include "fuzz_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "casteljau/core/tolerance.hpp"
#include "casteljau/curves/curve_view.hpp"
#include "casteljau/ops/arc_length.hpp"
#include "casteljau/ops/arc_spline.hpp"
#include "casteljau/ops/bounds.hpp"
#include "casteljau/ops/closest_point.hpp"
#include "casteljau/ops/flatten.hpp"
#include "casteljau/ops/intersection.hpp"
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau::fuzz {
namespace {

bool all_finite(std::span<const double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

/// The relative tolerances the operations are asked for: coarse enough that
/// a fuzzed curve needs few pieces, fine enough to exercise the certificates.
constexpr double kRelativeTolerance = 1e-3;

void exercise_curve(CurveView curve, bool full) {
  const Interval domain = curve.domain();
  require(std::isfinite(domain.lower) && std::isfinite(domain.upper) && domain.lower <= domain.upper,
          "a valid curve has a finite domain");
  // Points at the ends, the middle and a few inner parameters: finite.
  const std::array<double, 5> fractions{0.0, 0.25, 0.5, 0.8125, 1.0};
  std::vector<double> us, points(fractions.size() * static_cast<std::size_t>(curve.dimension()));
  for (double f : fractions) us.push_back(domain.lower + f * (domain.upper - domain.lower));
  points_at(curve, us, points);
  require(all_finite(points), "a valid curve evaluates to finite points on its domain");
  const Point derivative = derivative_at(curve, us[2], 1);
  require(all_finite(derivative), "a valid curve has a finite first derivative on its domain");

  const Box box = bounding_box(curve);
  require(all_finite(box.lower) && all_finite(box.upper), "the bounding box of a valid curve is finite");
  if (!full) return;

  const double size = size_of(curve);
  const Tolerance tolerance{std::max(size * kRelativeTolerance, 1e-9)};
  if (auto line = flatten(curve, tolerance); !line) require_message(line.error(), "flatten");
  if (auto length = arc_length(curve, default_arc_length_tolerance(curve)); !length) {
    require_message(length.error(), "arc_length");
  } else {
    require(std::isfinite(*length) && *length >= 0.0, "the arc length of a valid curve is finite and >= 0");
  }
  const Point query(static_cast<std::size_t>(curve.dimension()), 0.5);
  if (auto nearest = closest_point(curve, query); !nearest) {
    require_message(nearest.error(), "closest_point");
  } else {
    require(nearest->parameter >= domain.lower && nearest->parameter <= domain.upper,
            "the nearest point lies on the domain");
  }
  if (curve.dimension() >= 2) {
    if (auto crossings = self_intersections(curve, default_intersection_tolerance(curve, curve)); !crossings) {
      require_message(crossings.error(), "self_intersections");
    }
  }
  if (curve.dimension() == 2) {
    if (auto arcs = fit_arcs(curve, tolerance); !arcs) require_message(arcs.error(), "fit_arcs");
  }
}

void exercise_surface(SurfaceView surface, bool full) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  for (double fu : {0.0, 0.5, 1.0}) {
    for (double fv : {0.0, 0.3, 1.0}) {
      const Point p = surface.point_at(du.lower + fu * (du.upper - du.lower), dv.lower + fv * (dv.upper - dv.lower));
      require(all_finite(p), "a valid surface evaluates to finite points on its domain");
    }
  }
  if (!full) return;
  // The tolerance: 5 % of the diagonal of a 9 x 9 grid of the surface's
  // points (its corners alone can meet while the surface spans metres, and a
  // tolerance a million times finer than the surface is a legitimately long
  // run, not a finding: 4.6 million triangles, 80 s; a 5 x 5 grid missed a
  // spike 2,000 times the sphere's size between its samples, 1.7 s).
  constexpr int kGrid = 9;
  std::array<double, 3> low{}, high{};
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for (int a = 0; a < kGrid; ++a) {
    for (int b = 0; b < kGrid; ++b) {
      const Point p = surface.point_at(du.lower + a * (du.upper - du.lower) / (kGrid - 1),
                                       dv.lower + b * (dv.upper - dv.lower) / (kGrid - 1));
      for (std::size_t c = 0; c < 3 && c < p.size(); ++c) {
        low[c] = std::min(low[c], p[c]);
        high[c] = std::max(high[c], p[c]);
      }
    }
  }
  const double size = std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  if (auto mesh = tessellate(surface, Tolerance{std::max(size * 0.05, 1e-6)}); !mesh) {
    require_message(mesh.error(), "tessellate");
  }
}

}  // namespace

void exercise_model(const Model& model) {
  const bool full = control_point_count(model) <= kFullExerciseControlPoints;
  if (is_surface(model)) {
    exercise_surface(surface_view(model), full);
  } else {
    exercise_curve(curve_view(model), full);
  }
}

void exercise_models(std::span<const Model> models, std::size_t limit) {
  for (std::size_t i = 0; i < models.size() && i < limit; ++i) exercise_model(models[i]);
}

}  // namespace casteljau::fuzz
