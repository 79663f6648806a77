#include "casteljau/io/model.hpp"

#include <cassert>
#include <cstdlib>
#include <type_traits>

#include "casteljau/bezier/evaluate.hpp"
#include "casteljau/bspline/bezier_pieces.hpp"
#include "casteljau/bspline/evaluate.hpp"
#include "casteljau/curves/curve.hpp"

namespace casteljau {
namespace {

/// std::visit with one lambda per alternative.
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

/// True for the curve alternatives of Model: those that meet the curve concept.
template <class T>
constexpr bool is_curve_type = CurveKind<T>;

}  // namespace

bool is_surface(const Model& model) {
  return std::visit([](const auto& m) { return !is_curve_type<std::decay_t<decltype(m)>>; }, model);
}

SurfaceView surface_view(const Model& model) {
  assert(is_surface(model));
  return std::visit(
      [](const auto& m) -> SurfaceView {
        using T = std::decay_t<decltype(m)>;
        if constexpr (is_curve_type<T>) {
          // Unreachable by the precondition; a view of nothing would dangle,
          // so the release build stops here too.
          std::abort();
        } else {
          return SurfaceView(m);
        }
      },
      model);
}

CurveView curve_view(const Model& model) {
  assert(!is_surface(model));
  return std::visit(
      [](const auto& m) -> CurveView {
        if constexpr (is_curve_type<std::decay_t<decltype(m)>>) {
          return CurveView(m);
        } else {
          std::abort();  // unreachable by the precondition (as surface_view)
        }
      },
      model);
}

int dimension_of(const Model& model) {
  return std::visit([](const auto& m) { return m.dimension(); }, model);
}

std::size_t control_point_count(const Model& model) {
  return std::visit(Overloaded{[](const BezierCurve& c) { return c.control_points().size(); },
                               [](const PiecewiseBezierCurve& c) {
                                 std::size_t count = 0;
                                 for (const auto& piece : c.pieces()) count += piece.control_points().size();
                                 return count;
                               },
                               [](const BSplineCurve& c) { return c.control_points().size(); },
                               [](const BezierSurface& s) { return s.control_net().points().size(); },
                               [](const BSplineSurface& s) { return s.control_net().points().size(); },
                               [](const CoonsPatch& p) {
                                 return p.u0().control_points().size() + p.u1().control_points().size() +
                                        p.v0().control_points().size() + p.v1().control_points().size();
                               }},
                    model);
}

const char* type_name(const Model& model) {
  return std::visit(Overloaded{[](const BezierCurve&) { return "bezier"; },
                               [](const PiecewiseBezierCurve&) { return "piecewise_bezier"; },
                               [](const BSplineCurve&) { return "bspline"; },
                               [](const BezierSurface&) { return "bezier_surface"; },
                               [](const BSplineSurface&) { return "bspline_surface"; },
                               [](const CoonsPatch&) { return "coons"; }},
                    model);
}

Expected<Model> to_bspline(const Model& model) {
  return std::visit(Overloaded{[](const BezierCurve& c) -> Expected<Model> { return Model{to_bspline(c)}; },
                               [](const PiecewiseBezierCurve& c) -> Expected<Model> {
                                 auto curve = from_bezier_pieces(to_bezier_pieces(c));
                                 if (!curve) return curve.error();
                                 return Model{std::move(*curve)};
                               },
                               [](const BSplineCurve& c) -> Expected<Model> { return Model{c}; },
                               [](const BezierSurface& s) -> Expected<Model> { return Model{to_bspline_surface(s)}; },
                               [](const BSplineSurface& s) -> Expected<Model> { return Model{s}; },
                               [](const CoonsPatch& p) -> Expected<Model> {
                                 auto surface = to_bspline_surface(p);
                                 if (!surface) return surface.error();
                                 return Model{std::move(*surface)};
                               }},
                    model);
}

}  // namespace casteljau
