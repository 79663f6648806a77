#include "casteljau/io/model.hpp"

#include <cassert>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/evaluate.hpp"

namespace casteljau {
namespace {

/// std::visit with one lambda per alternative.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace

Interval domain_of(const Model& model) {
  return std::visit(Overloaded{[](const BezierCurve&) {
                                 return Interval{0.0, 1.0};
                               },
                               [](const PiecewiseBezierCurve& c) {
                                 return Interval{0.0, static_cast<double>(c.size())};
                               },
                               [](const BSplineCurve& c) { return c.domain(); }},
                    model);
}

int dimension_of(const Model& model) {
  return std::visit([](const auto& curve) { return curve.dimension(); }, model);
}

std::size_t control_point_count(const Model& model) {
  return std::visit(Overloaded{[](const BezierCurve& c) { return c.control_points().size(); },
                               [](const PiecewiseBezierCurve& c) {
                                 std::size_t count = 0;
                                 for (const auto& piece : c.pieces()) count += piece.control_points().size();
                                 return count;
                               },
                               [](const BSplineCurve& c) { return c.control_points().size(); }},
                    model);
}

void points_at(const Model& model, std::span<const double> us, std::span<double> out) {
  assert(out.size() == us.size() * static_cast<std::size_t>(dimension_of(model)));
  std::visit([&](const auto& curve) { points_at(curve, us, out); }, model);
}

Point derivative_at(const Model& model, double u, int order) {
  assert(order >= 0);
  return std::visit([&](const auto& curve) { return derivative_at(curve, u, order); }, model);
}

const char* type_name(const Model& model) {
  return std::visit(Overloaded{[](const BezierCurve&) { return "bezier"; },
                               [](const PiecewiseBezierCurve&) { return "piecewise_bezier"; },
                               [](const BSplineCurve&) { return "bspline"; }},
                    model);
}

}  // namespace casteljau
