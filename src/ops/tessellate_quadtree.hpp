#pragma once
// Internal to tessellate (ops/tessellate.hpp): how the tessellation's quadtree
// addresses a patch's parameter domain.
//
// The roots are the knot spans (SurfaceView::breakpoints_u/v), so no cell
// straddles a line where the surface is less smooth. A cell corner is an
// integer: span index * 2^kDepth + offset (tolerances::kMeshMaxDepth halvings
// per span), and every parameter is computed from its integer the same way,
// so two neighbours agree exactly on the vertices they share without
// comparing doubles.
//
// Sides of a patch: 0 v = v_lo, 1 u = u_hi, 2 v = v_hi, 3 u = u_lo; the side
// parameter s in [0, 1] increases with u (sides 0, 2) or with v (1, 3), and
// side ids run 4 * patch + side. Corners: 0 (lo, lo), 1 (hi, lo), 2 (lo, hi),
// 3 (hi, hi), ids 4 * patch + corner.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "casteljau/core/vec.hpp"
#include "casteljau/ops/tolerance.hpp"
#include "casteljau/surfaces/surface_view.hpp"

namespace casteljau::tessellation {

using Key = std::int64_t;
constexpr int kDepth = tolerances::kMeshMaxDepth;
constexpr Key kSpan = Key{1} << kDepth;
constexpr double kStep = 1.0 / static_cast<double>(kSpan);

/// A quadtree cell: integer corners (span index * 2^kDepth + offset).
struct Cell {
  Key u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

/// One patch with its knot-span grid.
struct Patch {
  SurfaceView surface;
  std::vector<double> breaks_u, breaks_v;
  Key u_end = 0, v_end = 0;

  explicit Patch(SurfaceView view) : surface(view), breaks_u(view.breakpoints_u()), breaks_v(view.breakpoints_v()) {
    u_end = static_cast<Key>(breaks_u.size() - 1) * kSpan;
    v_end = static_cast<Key>(breaks_v.size() - 1) * kSpan;
  }
  static double parameter(const std::vector<double>& breaks, Key key) {
    const auto span = static_cast<std::size_t>(key >> kDepth);
    const Key offset = key & (kSpan - 1);
    if (offset == 0) return breaks[span];
    return breaks[span] + (breaks[span + 1] - breaks[span]) * (static_cast<double>(offset) * kStep);
  }
  double u_of(Key key) const { return parameter(breaks_u, key); }
  double v_of(Key key) const { return parameter(breaks_v, key); }
  /// The root cells: one per pair of knot spans, u-major.
  std::vector<Cell> roots() const {
    std::vector<Cell> cells;
    for (Key i = 0; i < u_end; i += kSpan) {
      for (Key j = 0; j < v_end; j += kSpan) cells.push_back({i, i + kSpan, j, j + kSpan});
    }
    return cells;
  }
};

/// The corners a side runs from and to (see the header comment).
constexpr std::array<int, 4> kSideStart = {0, 1, 2, 0};
constexpr std::array<int, 4> kSideEnd = {1, 3, 3, 2};

/// (u, v) of the point at side parameter s of side `side`.
inline std::array<double, 2> side_parameters(const SurfaceView& surface, int side, double s) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  switch (side) {
    case 0: return {du.lerp(s), dv.lower};
    case 1: return {du.upper, dv.lerp(s)};
    case 2: return {du.lerp(s), dv.upper};
    default: return {du.lower, dv.lerp(s)};
  }
}

/// (u, v) of corner `corner`.
inline std::array<double, 2> corner_parameters(const SurfaceView& surface, int corner) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  return {(corner & 1) != 0 ? du.upper : du.lower, (corner & 2) != 0 ? dv.upper : dv.lower};
}

/// A surface point (a Point of dimension 3) as a Vec3.
inline Vec3 to_vec3(const Point& p) { return Vec3::from(p); }

/// Halves `cell` in u and/or v into `out`; where the requested direction
/// is at the depth limit, the other one; false (nothing written) when the
/// cell cannot be halved at all.
inline bool split(const Cell& cell, bool in_u, bool in_v, std::vector<Cell>& out) {
  const bool can_u = cell.u1 - cell.u0 > 1, can_v = cell.v1 - cell.v0 > 1;
  in_u = in_u && can_u;
  in_v = in_v && can_v;
  if (!in_u && !in_v) {
    in_u = can_u;
    in_v = can_v;
  }
  if (!in_u && !in_v) return false;
  const Key um = in_u ? cell.u0 + (cell.u1 - cell.u0) / 2 : cell.u1;
  const Key vm = in_v ? cell.v0 + (cell.v1 - cell.v0) / 2 : cell.v1;
  out.push_back({cell.u0, um, cell.v0, vm});
  if (in_u) out.push_back({um, cell.u1, cell.v0, vm});
  if (in_v) out.push_back({cell.u0, um, vm, cell.v1});
  if (in_u && in_v) out.push_back({um, cell.u1, vm, cell.v1});
  return true;
}

}  // namespace casteljau::tessellation
