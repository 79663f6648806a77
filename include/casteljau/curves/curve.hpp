#pragma once
// The curve concept: what every curve kind of casteljau offers, under one
// name with one meaning and one failure contract, so that an algorithm is
// written once and runs on every kind (the model is kurbo's ParamCurve
// trait family; ARCHITECTURE.md, "The curve concept", says why a concept
// plus a view rather than a base class).
//
// Two levels:
//   Curve      what can be evaluated: domain, dimension, degree, points and
//              derivatives of any order one at a time and in batches (the
//              parameter check inside the batch kernel), breakpoints, Bézier
//              pieces. BezierCurve, PiecewiseBezierCurve, BSplineCurve and
//              CurveView (the non-owning view of any of them) meet it.
//   CurveKind  a Curve that is also a value one can cut, turn and map:
//              split_at, segment, reversed, transformed, derivative_curve,
//              each returning the same kind. The three kinds meet it.
// Written once on CurveView, so on every kind: differential geometry
// (curves/differential_geometry.hpp), flattening (ops/flatten.hpp), and the
// ops layer's questions (arc length, ...).
//
// Adding a curve kind: the type in its layer with the free functions below,
// then one line in CurveView's list (curves/curve_view.hpp) and the static
// checks at the end of this file; Model (io/model.hpp) and every front end
// reach it through CurveView.

#include <concepts>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/bezier/affine.hpp"
#include "casteljau/bezier/bezier_curve.hpp"
#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bezier/piecewise_bezier.hpp"
#include "casteljau/bezier/split.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/bspline_curve.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/bspline/hodograph.hpp"
#include "casteljau/bspline/transform.hpp"
#include "casteljau/core/expected.hpp"
#include "casteljau/core/interval.hpp"
#include "casteljau/core/point_array.hpp"

namespace casteljau {

/// What every curve evaluates (see the file comment). Parameters outside
/// domain() extrapolate in the scalar and plain batch functions;
/// points_at_within refuses them. Batches write into the caller's storage.
template <class C>
concept Curve = requires(const C& c, double u, int k, std::span<const double> us, std::span<double> out,
                         Interval allowed) {
  { c.domain() } -> std::same_as<Interval>;
  { c.dimension() } -> std::same_as<int>;
  { c.degree() } -> std::same_as<int>;
  { c.is_rational() } -> std::same_as<bool>;
  { point_at(c, u) } -> std::same_as<Point>;
  { derivative_at(c, u, k) } -> std::same_as<Point>;
  { derivatives_up_to(c, u, k) } -> std::same_as<std::vector<Point>>;
  points_at(c, us, out);
  { points_at_within(c, us, allowed, out) } -> std::same_as<std::size_t>;
  derivatives_at(c, us, k, out);
  points_and_derivatives_at(c, us, out, out);
  { breakpoints(c) } -> std::same_as<std::vector<double>>;
  { to_bezier_pieces(c) } -> std::same_as<BezierPieces>;
};

/// A curve kind: a Curve that is a regular value (copy, ==) and that cuts,
/// turns and maps into its own kind, with the errors of
/// core/parameter_checks.hpp for split_at and segment on every kind.
template <class C>
concept CurveKind = Curve<C> && std::copyable<C> && std::equality_comparable<C> &&
                    requires(const C& c, double u, int k, const AffineMap& map) {
                      { split_at(c, u) } -> std::same_as<Expected<std::pair<C, C>>>;
                      { segment(c, u, u) } -> std::same_as<Expected<C>>;
                      { reversed(c) } -> std::same_as<C>;
                      { transformed(c, map) } -> std::same_as<Expected<C>>;
                      { derivative_curve(c, k) } -> std::same_as<Expected<C>>;
                    };

static_assert(CurveKind<BezierCurve>);
static_assert(CurveKind<PiecewiseBezierCurve>);
static_assert(CurveKind<BSplineCurve>);

}  // namespace casteljau
