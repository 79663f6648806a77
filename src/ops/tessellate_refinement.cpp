// Refinement of a tessellation's quadtree and its deviation checks
// (tessellate_refinement.hpp).
#include "tessellate_refinement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "../core/number_text.hpp"

#include "casteljau/ops/tolerance.hpp"

namespace casteljau::tessellation {
namespace {

/// Samples per direction of the cell test (fractions k / (kGrid - 1)).
constexpr int kGrid = 7;

/// Angle between two unit normals, 0 when either is the zero vector (no
/// normal exists there, nothing to compare).
double turn(const Vec3& a, const Vec3& b) {
  if (norm(a) == 0.0 || norm(b) == 0.0) return 0.0;
  return std::acos(std::clamp(dot(a, b), -1.0, 1.0));
}

}  // namespace

Status check_cell_count(std::size_t cells, double tolerance) {
  if (2 * cells > tolerances::kMaxMeshTriangles) {
    return Error{"the tessellation needs more than " + std::to_string(tolerances::kMaxMeshTriangles) +
                 " triangles at tolerance " + detail::number_text(tolerance) + "; use a larger tolerance", ErrorKind::limit};
  }
  return {};
}

CellTest test_cell(const Patch& patch, const Cell& cell, double tolerance) {
  const double ua = patch.u_of(cell.u0), ub = patch.u_of(cell.u1);
  const double va = patch.v_of(cell.v0), vb = patch.v_of(cell.v1);
  std::array<double, kGrid> us{}, vs{};
  for (int k = 0; k < kGrid; ++k) {
    const double f = static_cast<double>(k) / (kGrid - 1);
    us[k] = k == kGrid - 1 ? ub : ua + (ub - ua) * f;
    vs[k] = k == kGrid - 1 ? vb : va + (vb - va) * f;
  }
  std::array<double, kGrid * kGrid * 3> grid{};
  patch.surface.grid_points_at(us, vs, grid);
  const auto at = [&grid](int a, int b) {
    const double* q = grid.data() + (a * kGrid + b) * 3;
    return Vec3{{q[0], q[1], q[2]}};
  };
  constexpr int last = kGrid - 1, mid = kGrid / 2;
  // The fan's vertices in (fraction_u, fraction_v): centre, then corners.
  const Vec3 centre = at(mid, mid);
  const std::array<Vec3, 4> corner = {at(0, 0), at(last, 0), at(last, last), at(0, last)};
  const std::array<std::array<double, 2>, 4> corner_f = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  double error = 0.0;
  for (int a = 0; a < kGrid; ++a) {
    for (int b = 0; b < kGrid; ++b) {
      const double x = static_cast<double>(a) / last - 0.5, y = static_cast<double>(b) / last - 0.5;
      // Which fan triangle: bottom, right, top or left quarter.
      int t = 0;
      if (std::abs(x) >= std::abs(y)) {
        t = x >= 0 ? 1 : 3;
      } else {
        t = y >= 0 ? 2 : 0;
      }
      const auto& f0 = corner_f[t];
      const auto& f1 = corner_f[(t + 1) % 4];
      // Barycentric coordinates in the triangle (centre, corner t, corner t+1).
      const double ax = f0[0] - 0.5, ay = f0[1] - 0.5, bx = f1[0] - 0.5, by = f1[1] - 0.5;
      const double det = ax * by - ay * bx;
      const double l0 = (x * by - y * bx) / det, l1 = (ax * y - ay * x) / det;
      const double lc = 1.0 - l0 - l1;
      const Vec3& p0 = corner[t];
      const Vec3& p1 = corner[(t + 1) % 4];
      const Vec3 linear{{lc * centre[0] + l0 * p0[0] + l1 * p1[0], lc * centre[1] + l0 * p0[1] + l1 * p1[1],
                         lc * centre[2] + l0 * p0[2] + l1 * p1[2]}};
      error = std::max(error, norm(at(a, b) - linear));
    }
  }
  // How much the mid-lines bend in each direction.
  double bend_u = 0.0, bend_v = 0.0;
  for (const int k : {0, mid, last}) {
    const Vec3 a = at(0, k), b = at(last, k), c = at(k, 0), d = at(k, last);
    const Vec3 chord_u{{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}};
    const Vec3 chord_v{{(c[0] + d[0]) / 2, (c[1] + d[1]) / 2, (c[2] + d[2]) / 2}};
    bend_u = std::max(bend_u, norm(at(mid, k) - chord_u));
    bend_v = std::max(bend_v, norm(at(k, mid) - chord_v));
  }
  // The normals' turn is compared along each edge of the cell whose samples
  // spread over more than the flat scale. Along an edge that is flat at the
  // tolerance's scale (a pole, a side pulled to one point by a huge weight)
  // the normal is undefined or meaningless and may turn at random: counting
  // it would halve such cells to the finest level along the whole edge
  // (a fuzzed sphere with a weight of 7e13: ten million triangles, 49 s).
  // The distance test still applies to every cell.
  const double flat = tolerances::kMeshFlatCellFraction * tolerance;
  const auto edge_is_flat = [&](bool along_v, int fixed) {
    Vec3 low = along_v ? at(fixed, 0) : at(0, fixed), high = low;
    for (int k = 1; k < kGrid; ++k) {
      const Vec3 q = along_v ? at(fixed, k) : at(k, fixed);
      for (int c = 0; c < 3; ++c) {
        low[c] = std::min(low[c], q[c]);
        high[c] = std::max(high[c], q[c]);
      }
    }
    return norm(high - low) <= flat;
  };
  const bool flat_v0 = edge_is_flat(false, 0), flat_v1 = edge_is_flat(false, last);  // edges v = va, v = vb
  const bool flat_u0 = edge_is_flat(true, 0), flat_u1 = edge_is_flat(true, last);    // edges u = ua, u = ub
  bool turns_u = false, turns_v = false;
  if (!(flat_v0 && flat_v1 && flat_u0 && flat_u1)) {
    const Vec3 n00 = to_vec3(patch.surface.normal_at(ua, va)), n10 = to_vec3(patch.surface.normal_at(ub, va));
    const Vec3 n01 = to_vec3(patch.surface.normal_at(ua, vb)), n11 = to_vec3(patch.surface.normal_at(ub, vb));
    const auto turns = [](bool edge_flat, const Vec3& a, const Vec3& b) {
      return !edge_flat && turn(a, b) > tolerances::kMeshMaxNormalTurn;
    };
    turns_u = turns(flat_v0, n00, n10) || turns(flat_v1, n01, n11);
    turns_v = turns(flat_u0, n00, n01) || turns(flat_u1, n10, n11);
  }
  const bool too_far = error > tolerances::kMeshSampledDeviationFraction * tolerance;
  CellTest test;
  test.error = error;
  if (!too_far && !turns_u && !turns_v) return test;
  test.needs_split = true;
  test.in_u = turns_u;
  test.in_v = turns_v;
  if (too_far) {
    const double bend = std::max(bend_u, bend_v);
    if (bend < 0.25 * error) {
      test.in_u = test.in_v = true;  // a twist: neither mid-line explains the error
    } else {
      test.in_u = test.in_u || bend_u >= 0.5 * bend;
      test.in_v = test.in_v || bend_v >= 0.5 * bend;
    }
  }
  return test;
}

Status refine(const Patch& patch, double tolerance, std::vector<Cell>& accepted, std::size_t other_cells,
              const RefinementProgress& progress) {
  std::vector<Cell> pending = patch.roots();
  const Key spans_v = patch.v_end / kSpan;
  double done = 0.0;
  while (!pending.empty()) {
    const Cell cell = pending.back();
    pending.pop_back();
    const CellTest test = test_cell(patch, cell, tolerance);
    if (test.needs_split) {
      // A cell at the quadtree's depth limit in a direction it must be halved
      // in: the surface moves by more than the tolerance between parameters
      // 2^-40 of a knot span apart, continuous only in exact arithmetic (a
      // weight 10^13 times its neighbours' does this). Halving the other
      // direction instead would not help: it once made ten million cells
      // along such an edge before the triangle limit refused them (49 s).
      const bool stuck_u = test.in_u && cell.u1 - cell.u0 <= 1, stuck_v = test.in_v && cell.v1 - cell.v0 <= 1;
      if (stuck_u || stuck_v) {
        const double step = stuck_u ? patch.u_of(cell.u1) - patch.u_of(cell.u0) : patch.v_of(cell.v1) - patch.v_of(cell.v0);
        return Error{"the surface cannot be followed by triangles near (u, v) = (" +
                     detail::number_text(patch.u_of(cell.u0)) + ", " + detail::number_text(patch.v_of(cell.v0)) +
                     "): it departs by " + detail::number_text(test.error) + " from flat within a parameter step of " +
                     detail::number_text(step) + " in " + (stuck_u ? "u" : "v") +
                     ", continuous only in exact arithmetic (look for weights or control points many orders of "
                     "magnitude apart)"};
      }
      split(cell, test.in_u, test.in_v, pending);
      if (auto counted = check_cell_count(other_cells + accepted.size() + pending.size(), tolerance); !counted) {
        return counted;
      }
    } else {
      accepted.push_back(cell);
      const auto root = static_cast<std::size_t>((cell.u0 / kSpan) * spans_v + cell.v0 / kSpan);
      const double area =
          static_cast<double>(cell.u1 - cell.u0) * kStep * (static_cast<double>(cell.v1 - cell.v0) * kStep);
      done += progress.root_shares[root] * area;
      progress.progress(progress.from, progress.to, done);
    }
  }
  return {};
}

bool triangle_within_tolerance(const Patch& patch, const Triangle& triangle, const MeshAssembly& assembly,
                               double tolerance) {
  static constexpr std::array<std::array<double, 3>, 7> kWeights = {{{0.5, 0.5, 0.0},
                                                                     {0.0, 0.5, 0.5},
                                                                     {0.5, 0.0, 0.5},
                                                                     {1.0 / 3, 1.0 / 3, 1.0 / 3},
                                                                     {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                                                     {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                                                     {1.0 / 6, 1.0 / 6, 2.0 / 3}}};
  const SurfaceView& surface = patch.surface;
  const double limit = tolerances::kMeshSampledDeviationFraction * tolerance;
  for (const auto& w : kWeights) {
    double u = 0.0, v = 0.0;
    Vec3 linear{};
    for (int k = 0; k < 3; ++k) {
      const LoopVertex& corner = triangle.corners[k];
      u += w[k] * corner.u;
      v += w[k] * corner.v;
      const Vec3& x = assembly.position(corner.vertex);
      for (int c = 0; c < 3; ++c) linear[c] += w[k] * x[c];
    }
    if (norm(to_vec3(surface.point_at(u, v)) - linear) > limit) return false;
  }
  return true;
}

}  // namespace casteljau::tessellation
