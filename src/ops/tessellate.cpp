// Tessellation of surfaces into triangle meshes within a distance tolerance.
//
// Method (docs/surfaces.md has the long form):
//
// 1. Per patch, a quadtree over the parameter domain whose roots are the knot
//    spans (SurfaceView::breakpoints_u/v), so that no cell straddles a line
//    where the surface is less smooth. Cell corners are integers (2^40 steps
//    per span, tolerances::kMeshMaxDepth): neighbours compute the same
//    parameter from the same integer, so they agree exactly on shared
//    vertices without comparing doubles.
// 2. A cell is accepted when (a) the surface on a 7 x 7 grid of its parameters
//    is within tolerances::kMeshSampledDeviationFraction x tolerance of the
//    fan of four triangles from the cell's centre to its corners, and (b) the
//    unit normals at its corners turn by at most tolerances::kMeshMaxNormalTurn
//    (so that sampling can be trusted). Otherwise it is halved in u, in v or
//    both: in the direction(s) whose mid-line bends most (a cylinder is cut
//    across its axis only), both when the error is a twist (z = uv).
// 3. Patch edges are compared with each other once: an edge whose sample
//    points all coincide is collapsed (a pole); two edges whose points at
//    seven normalized parameters agree, in the same or opposite direction,
//    within tolerances::kMeshSharedEdgeRelative of the scale are one shared
//    edge (two patches of a box, or the seam u = 0 / u = 1 of a surface of
//    revolution, or both seams of a torus). Corners of matched edges are
//    unified (union-find), so a box corner or a pole is one vertex.
// 4. Vertices: one per corner class; along each shared edge the union of the
//    cell corners of every side, merged when two sides put a vertex at the
//    same normalized parameter (tolerances::kMeshSameEdgeParameter), so each
//    shared vertex exists once (one index, one position: the first patch's);
//    inside a patch one per integer corner. Normals: the surface's unit
//    normal (normal_at, with its limit at poles), averaged over the patches
//    that share the vertex.
// 5. Each cell is triangulated as a fan from its centre through every vertex
//    on its sides in counter-clockwise (u, v) order, the vertices of finer
//    neighbours and of the other patch of a shared edge included: no
//    T-junction, and the mesh is watertight across shared edges by
//    construction. Consecutive repeats (a collapsed side) are dropped, so a
//    pole gives no degenerate triangle. Counter-clockwise in (u, v) is
//    counter-clockwise seen from S_u x S_v, the side normal_at points to.
// 6. Every final triangle is sampled (edge midpoints, centroid, three inner
//    points) against the surface at the linearly interpolated parameters;
//    cells whose triangles miss are split and steps 4-6 repeat, so the check
//    holds for the triangles actually written, neighbours' vertices included.
#include "casteljau/ops/tessellate.hpp"
#include "casteljau/core/tolerance.hpp"
#include "casteljau/core/vec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "../core/number_text.hpp"

namespace casteljau {
namespace {

using Key = std::int64_t;
constexpr int kDepth = tolerances::kMeshMaxDepth;
constexpr Key kSpan = Key{1} << kDepth;
constexpr double kStep = 1.0 / static_cast<double>(kSpan);

/// Samples per direction of the cell test (fractions k / (kGrid - 1)).
constexpr int kGrid = 7;
/// Normalized parameters at which two patch edges are compared: both ends
/// and interior values away from simple fractions, so that two edges that
/// agree at a few dyadic points only are not taken for one. Symmetric
/// (s and 1 - s), so that the reversed comparison reads the same list
/// backwards.
constexpr std::array<double, 7> kEdgeSamples = {0.0, 0.1234, 0.3141, 0.5, 0.6859, 0.8766, 1.0};

Vec3 to_vec3(const Point& p) { return Vec3::from(p); }

/// Angle between two unit normals, 0 when either is the zero vector (no
/// normal exists there, nothing to compare).
double turn(const Vec3& a, const Vec3& b) {
  if (norm(a) == 0.0 || norm(b) == 0.0) return 0.0;
  return std::acos(std::clamp(dot(a, b), -1.0, 1.0));
}

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
};

// Sides of a patch: 0 v = v_lo, 1 u = u_hi, 2 v = v_hi, 3 u = u_lo; the
// side parameter s in [0,1] increases with u (sides 0, 2) or v (1, 3).
// Corners: 0 (lo,lo), 1 (hi,lo), 2 (lo,hi), 3 (hi,hi).
constexpr std::array<int, 4> kSideStart = {0, 1, 2, 0};
constexpr std::array<int, 4> kSideEnd = {1, 3, 3, 2};

/// (u, v) of the point at side parameter s of side `side`.
std::array<double, 2> side_parameters(const SurfaceView& surface, int side, double s) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  switch (side) {
    case 0: return {du.lerp(s), dv.lower};
    case 1: return {du.upper, dv.lerp(s)};
    case 2: return {du.lerp(s), dv.upper};
    default: return {du.lower, dv.lerp(s)};
  }
}

std::array<double, 2> corner_parameters(const SurfaceView& surface, int corner) {
  const Interval du = surface.domain_u(), dv = surface.domain_v();
  return {(corner & 1) != 0 ? du.upper : du.lower, (corner & 2) != 0 ? dv.upper : dv.lower};
}

/// A plain union-find over integers.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

/// How the patches' edges relate: collapsed sides, groups of shared sides
/// (with each side's direction relative to its group) and corner classes.
struct EdgeStructure {
  std::vector<bool> degenerate;  // per side id (4 * patch + side)
  std::vector<int> group;        // per side id: the group's first side
  std::vector<bool> flipped;     // per side id: runs against its group
  std::vector<int> corner_class; // per corner id (4 * patch + corner)
};

EdgeStructure analyse_edges(const std::vector<Patch>& patches, double match_distance) {
  const std::size_t sides = patches.size() * 4;
  // Sample points of every side.
  std::vector<std::array<Vec3, kEdgeSamples.size()>> samples(sides);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    for (int k = 0; k < 4; ++k) {
      for (std::size_t i = 0; i < kEdgeSamples.size(); ++i) {
        const auto uv = side_parameters(patches[p].surface, k, kEdgeSamples[i]);
        samples[p * 4 + k][i] = to_vec3(patches[p].surface.point_at(uv[0], uv[1]));
      }
    }
  }
  EdgeStructure edges;
  edges.degenerate.assign(sides, false);
  for (std::size_t a = 0; a < sides; ++a) {
    bool collapsed = true;
    for (const Vec3& point : samples[a]) collapsed = collapsed && norm(point - samples[a][0]) <= match_distance;
    edges.degenerate[a] = collapsed;
  }
  const std::size_t n = kEdgeSamples.size();
  DisjointSets corners(sides);  // corner ids also run 0 .. 4 * patches
  const auto corner_id = [](std::size_t side, bool end) {
    return static_cast<int>((side / 4) * 4) + (end ? kSideEnd[side % 4] : kSideStart[side % 4]);
  };
  std::vector<std::vector<std::pair<int, bool>>> matches(sides);
  for (std::size_t a = 0; a < sides; ++a) {
    if (edges.degenerate[a]) {
      corners.unite(corner_id(a, false), corner_id(a, true));
      continue;
    }
    for (std::size_t b = a + 1; b < sides; ++b) {
      if (edges.degenerate[b]) continue;
      bool forward = true, backward = true;
      for (std::size_t i = 0; i < n; ++i) {
        forward = forward && norm(samples[a][i] - samples[b][i]) <= match_distance;
        backward = backward && norm(samples[a][i] - samples[b][n - 1 - i]) <= match_distance;
      }
      if (!forward && !backward) continue;
      const bool flip = !forward;
      matches[a].push_back({static_cast<int>(b), flip});
      matches[b].push_back({static_cast<int>(a), flip});
      corners.unite(corner_id(a, false), corner_id(b, flip));
      corners.unite(corner_id(a, true), corner_id(b, !flip));
    }
  }
  // Two collapsed sides at the same point (the poles of two half spheres).
  for (std::size_t a = 0; a < sides; ++a) {
    for (std::size_t b = a + 1; b < sides && edges.degenerate[a]; ++b) {
      if (edges.degenerate[b] && norm(samples[a][0] - samples[b][0]) <= match_distance) {
        corners.unite(corner_id(a, false), corner_id(b, false));
      }
    }
  }
  // Groups by breadth-first search, each side's direction relative to the
  // first side of its group (a contradictory cycle keeps the first answer).
  edges.group.assign(sides, -1);
  edges.flipped.assign(sides, false);
  for (std::size_t start = 0; start < sides; ++start) {
    if (edges.group[start] >= 0) continue;
    edges.group[start] = static_cast<int>(start);
    std::vector<int> queue = {static_cast<int>(start)};
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int side = queue[head];
      for (const auto& [other, flip] : matches[side]) {
        if (edges.group[other] >= 0) continue;
        edges.group[other] = static_cast<int>(start);
        edges.flipped[other] = edges.flipped[side] != flip;
        queue.push_back(other);
      }
    }
  }
  edges.corner_class.resize(sides);
  for (std::size_t c = 0; c < sides; ++c) edges.corner_class[c] = corners.find(static_cast<int>(c));
  return edges;
}

/// A vertex on a patch side: its side parameter and its mesh index.
struct SideVertex {
  double s = 0.0;
  std::uint32_t vertex = 0;
};

/// A vertex of a cell's boundary loop: mesh index and this patch's (u, v).
struct LoopVertex {
  std::uint32_t vertex = 0;
  double u = 0.0, v = 0.0;
};

/// The vertices being assembled in one pass: positions and sums of the
/// patches' unit normals.
struct Assembly {
  std::uint32_t add_vertex(const Vec3& position) {
    positions.push_back(position);
    normals.push_back(Vec3{});
    return static_cast<std::uint32_t>(positions.size() - 1);
  }
  void add_normal(std::uint32_t vertex, const Point& normal) {
    for (int c = 0; c < 3; ++c) normals[vertex][c] += normal[c];
  }
  const Vec3& position(std::uint32_t vertex) const { return positions[vertex]; }
  std::size_t vertex_count() const { return positions.size(); }

  std::vector<Vec3> positions;
  std::vector<Vec3> normals;
};

/// The per-pass vertex tables of one patch.
struct PatchVertices {
  std::map<std::pair<Key, Key>, std::uint32_t> interior;
  std::array<std::vector<std::pair<Key, std::uint32_t>>, 4> side_keys;  // sorted by key
  std::array<std::vector<SideVertex>, 4> side_lists;                    // sorted by s
  std::map<Key, std::vector<Key>> rows;     // v key -> sorted u keys of cell corners
  std::map<Key, std::vector<Key>> columns;  // u key -> sorted v keys of cell corners
};

class Tessellator {
 public:
  Tessellator(std::span<const SurfaceView> views, double tolerance, double match_distance)
      : tolerance_(tolerance) {
    for (const SurfaceView& view : views) patches_.emplace_back(view);
    edges_ = analyse_edges(patches_, match_distance);
  }

  Expected<TriangleMesh> run() {
    cells_.resize(patches_.size());
    for (std::size_t p = 0; p < patches_.size(); ++p) {
      std::vector<Cell> pending;
      for (Key i = 0; i < patches_[p].u_end; i += kSpan) {
        for (Key j = 0; j < patches_[p].v_end; j += kSpan) pending.push_back({i, i + kSpan, j, j + kSpan});
      }
      if (auto refined = refine(p, std::move(pending)); !refined) return refined.error();
    }
    for (;;) {
      assemble();
      std::vector<std::vector<bool>> failed(patches_.size());
      bool any = false;
      for (std::size_t p = 0; p < patches_.size(); ++p) {
        failed[p].assign(cells_[p].size(), false);
      }
      for (const Triangle& triangle : triangles_) {
        if (!triangle.needs_check || failed[triangle.patch][triangle.cell]) continue;
        if (!triangle_within_tolerance(triangle)) {
          const Cell& cell = cells_[triangle.patch][triangle.cell];
          if (cell.u1 - cell.u0 > 1 || cell.v1 - cell.v0 > 1) {
            failed[triangle.patch][triangle.cell] = true;
            any = true;
          }  // else: at the depth limit, kept as it is
        }
      }
      if (!any) break;
      for (std::size_t p = 0; p < patches_.size(); ++p) {
        std::vector<Cell> kept;
        for (std::size_t c = 0; c < cells_[p].size(); ++c) {
          if (!failed[p][c]) {
            kept.push_back(cells_[p][c]);
            continue;
          }
          if (!split(cells_[p][c], true, true, kept)) kept.push_back(cells_[p][c]);
        }
        cells_[p] = std::move(kept);
      }
      if (auto counted = check_count(0); !counted) return counted.error();
    }
    return finish();
  }

 private:
  struct Triangle {
    std::array<LoopVertex, 3> corners;
    std::uint32_t patch = 0;
    std::uint32_t cell = 0;
    /// False for a triangle of the cell's plain fan (centre and two adjacent
    /// cell corners): the cell test has already sampled exactly that triangle.
    bool needs_check = true;
  };

  std::size_t cell_count() const {
    std::size_t total = 0;
    for (const auto& cells : cells_) total += cells.size();
    return total;
  }

  /// Every cell gives at least two triangles.
  Status check_count(std::size_t pending) const {
    if (2 * (cell_count() + pending) > tolerances::kMaxMeshTriangles) {
      return Error{"the tessellation needs more than " + std::to_string(tolerances::kMaxMeshTriangles) +
                   " triangles at tolerance " + detail::number_text(tolerance_) + "; use a larger tolerance"};
    }
    return {};
  }

  /// Halves `cell` in u and/or v into `out`; where the requested direction
  /// is at the depth limit, the other one; false (nothing written) when the
  /// cell cannot be halved at all.
  static bool split(const Cell& cell, bool in_u, bool in_v, std::vector<Cell>& out) {
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

  /// Step 2: refines the cells of patch p until each passes the cell test.
  Status refine(std::size_t p, std::vector<Cell> pending) {
    while (!pending.empty()) {
      const Cell cell = pending.back();
      pending.pop_back();
      bool in_u = false, in_v = false;
      if (cell_needs_split(patches_[p], cell, in_u, in_v) && split(cell, in_u, in_v, pending)) {
        if (auto counted = check_count(pending.size()); !counted) return counted;
      } else {
        cells_[p].push_back(cell);
      }
    }
    return {};
  }

  /// The cell test: the 7 x 7 samples against the fan of four triangles from
  /// the centre, and the normals' turn between corners. Sets the directions
  /// to halve in when the cell fails.
  bool cell_needs_split(const Patch& patch, const Cell& cell, bool& in_u, bool& in_v) const {
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
    const Vec3 n00 = to_vec3(patch.surface.normal_at(ua, va)), n10 = to_vec3(patch.surface.normal_at(ub, va));
    const Vec3 n01 = to_vec3(patch.surface.normal_at(ua, vb)), n11 = to_vec3(patch.surface.normal_at(ub, vb));
    const bool turns_u = std::max(turn(n00, n10), turn(n01, n11)) > tolerances::kMeshMaxNormalTurn;
    const bool turns_v = std::max(turn(n00, n01), turn(n10, n11)) > tolerances::kMeshMaxNormalTurn;
    const bool too_far = error > tolerances::kMeshSampledDeviationFraction * tolerance_;
    if (!too_far && !turns_u && !turns_v) return false;
    in_u = turns_u;
    in_v = turns_v;
    if (too_far) {
      const double bend = std::max(bend_u, bend_v);
      if (bend < 0.25 * error) {
        in_u = in_v = true;  // a twist: neither mid-line explains the error
      } else {
        in_u = in_u || bend_u >= 0.5 * bend;
        in_v = in_v || bend_v >= 0.5 * bend;
      }
    }
    return true;
  }

  /// Steps 4 and 5 for the current cells: vertices, normals, triangles.
  void assemble() {
    assembly_ = Assembly{};
    triangles_.clear();
    vertices_.assign(patches_.size(), PatchVertices{});
    collect_corner_keys();
    create_corner_vertices();
    create_side_vertices();
    for (std::size_t p = 0; p < patches_.size(); ++p) {
      for (std::size_t c = 0; c < cells_[p].size(); ++c) triangulate(p, c);
    }
  }

  void collect_corner_keys() {
    for (std::size_t p = 0; p < patches_.size(); ++p) {
      const Patch& patch = patches_[p];
      PatchVertices& table = vertices_[p];
      std::array<std::vector<Key>, 4> on_side;
      for (const Cell& cell : cells_[p]) {
        for (const Key u : {cell.u0, cell.u1}) {
          for (const Key v : {cell.v0, cell.v1}) {
            table.rows[v].push_back(u);
            table.columns[u].push_back(v);
            if (v == 0) on_side[0].push_back(u);
            if (u == patch.u_end) on_side[1].push_back(v);
            if (v == patch.v_end) on_side[2].push_back(u);
            if (u == 0) on_side[3].push_back(v);
          }
        }
      }
      for (auto* lines : {&table.rows, &table.columns}) {
        for (auto& line : *lines) {
          std::sort(line.second.begin(), line.second.end());
          line.second.erase(std::unique(line.second.begin(), line.second.end()), line.second.end());
        }
      }
      for (int k = 0; k < 4; ++k) {
        std::sort(on_side[k].begin(), on_side[k].end());
        on_side[k].erase(std::unique(on_side[k].begin(), on_side[k].end()), on_side[k].end());
        for (const Key key : on_side[k]) table.side_keys[k].push_back({key, 0});
      }
    }
  }

  double side_s(std::size_t p, int side, Key key) const {
    const Patch& patch = patches_[p];
    if (side == 0 || side == 2) {
      const Interval d = patch.surface.domain_u();
      return key == patch.u_end ? 1.0 : (patch.u_of(key) - d.lower) / d.length();
    }
    const Interval d = patch.surface.domain_v();
    return key == patch.v_end ? 1.0 : (patch.v_of(key) - d.lower) / d.length();
  }

  void create_corner_vertices() {
    const std::size_t corners = patches_.size() * 4;
    corner_vertex_.assign(corners, 0);
    std::vector<std::vector<std::size_t>> members(corners);
    for (std::size_t c = 0; c < corners; ++c) members[edges_.corner_class[c]].push_back(c);
    for (std::size_t root = 0; root < corners; ++root) {
      if (members[root].empty()) continue;
      std::vector<std::size_t> seen_patches;
      std::uint32_t vertex = 0;
      for (std::size_t i = 0; i < members[root].size(); ++i) {
        const std::size_t c = members[root][i], p = c / 4;
        const auto uv = corner_parameters(patches_[p].surface, static_cast<int>(c % 4));
        if (i == 0) vertex = assembly_.add_vertex(to_vec3(patches_[p].surface.point_at(uv[0], uv[1])));
        corner_vertex_[c] = vertex;
        if (std::find(seen_patches.begin(), seen_patches.end(), p) != seen_patches.end()) continue;
        seen_patches.push_back(p);
        assembly_.add_normal(vertex, patches_[p].surface.normal_at(uv[0], uv[1]));
      }
    }
  }

  /// The vertices strictly inside shared (or lone) sides: the union of the
  /// cell corners of every side of a group, merged across sides.
  void create_side_vertices() {
    const std::size_t sides = patches_.size() * 4;
    std::vector<std::vector<std::size_t>> members(sides);
    for (std::size_t s = 0; s < sides; ++s) members[edges_.group[s]].push_back(s);
    struct Entry {
      double s = 0.0;  // in the group's direction
      std::size_t side = 0;
      std::size_t index = 0;  // in the side's side_keys
    };
    for (std::size_t root = 0; root < sides; ++root) {
      if (members[root].empty()) continue;
      std::vector<Entry> entries;
      for (const std::size_t side : members[root]) {
        const std::size_t p = side / 4;
        const int k = static_cast<int>(side % 4);
        auto& keys = vertices_[p].side_keys[k];
        if (edges_.degenerate[side]) {
          for (auto& key : keys) key.second = corner_vertex_[p * 4 + kSideStart[k]];
          continue;
        }
        // The first and last keys are the patch's corners.
        for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
          const double s = side_s(p, k, keys[i].first);
          entries.push_back({edges_.flipped[side] ? 1.0 - s : s, side, i});
        }
        keys.front().second = corner_vertex_[p * 4 + kSideStart[k]];
        keys.back().second = corner_vertex_[p * 4 + kSideEnd[k]];
      }
      std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.s < b.s; });
      std::vector<SideVertex> placed;  // each cluster: s in the group's direction, its vertex
      for (std::size_t first = 0; first < entries.size();) {
        // A cluster: entries within kMeshSameEdgeParameter of the first, at most one per side.
        std::vector<std::size_t> cluster = {first};
        std::size_t next = first + 1;
        while (next < entries.size() && entries[next].s - entries[first].s <= tolerances::kMeshSameEdgeParameter) {
          bool same_side = false;
          for (const std::size_t member : cluster) same_side = same_side || entries[member].side == entries[next].side;
          if (same_side) break;
          cluster.push_back(next++);
        }
        std::uint32_t vertex = 0;
        std::vector<std::size_t> seen_patches;
        for (std::size_t i = 0; i < cluster.size(); ++i) {
          const Entry& entry = entries[cluster[i]];
          const std::size_t p = entry.side / 4;
          const int k = static_cast<int>(entry.side % 4);
          auto& key = vertices_[p].side_keys[k][entry.index];
          const auto uv = side_parameters(patches_[p].surface, k, side_s(p, k, key.first));
          if (i == 0) vertex = assembly_.add_vertex(to_vec3(patches_[p].surface.point_at(uv[0], uv[1])));
          key.second = vertex;
          if (std::find(seen_patches.begin(), seen_patches.end(), p) != seen_patches.end()) continue;
          seen_patches.push_back(p);
          assembly_.add_normal(vertex, patches_[p].surface.normal_at(uv[0], uv[1]));
        }
        placed.push_back({entries[first].s, vertex});
        first = next;
      }
      // Every side of the group sees every cluster, at its own parameter:
      // exact for its own vertices, mapped for the others'.
      for (const std::size_t side : members[root]) {
        if (edges_.degenerate[side]) continue;
        const std::size_t p = side / 4;
        const int k = static_cast<int>(side % 4);
        std::vector<SideVertex>& list = vertices_[p].side_lists[k];
        const auto& keys = vertices_[p].side_keys[k];
        std::vector<std::uint32_t> own;
        for (std::size_t i = 1; i + 1 < keys.size(); ++i) {
          list.push_back({side_s(p, k, keys[i].first), keys[i].second});
          own.push_back(keys[i].second);
        }
        std::sort(own.begin(), own.end());
        for (const SideVertex& cluster : placed) {
          if (std::binary_search(own.begin(), own.end(), cluster.vertex)) continue;
          list.push_back({edges_.flipped[side] ? 1.0 - cluster.s : cluster.s, cluster.vertex});
        }
        std::sort(list.begin(), list.end(), [](const SideVertex& a, const SideVertex& b) { return a.s < b.s; });
      }
    }
  }

  /// The mesh index of the cell corner (u, v) of patch p.
  std::uint32_t vertex_at(std::size_t p, Key u, Key v) {
    const Patch& patch = patches_[p];
    const bool u_lo = u == 0, u_hi = u == patch.u_end, v_lo = v == 0, v_hi = v == patch.v_end;
    if ((u_lo || u_hi) && (v_lo || v_hi)) return corner_vertex_[p * 4 + (u_hi ? 1 : 0) + (v_hi ? 2 : 0)];
    const int side = v_lo ? 0 : u_hi ? 1 : v_hi ? 2 : u_lo ? 3 : -1;
    if (side >= 0) {
      const Key key = side == 0 || side == 2 ? u : v;
      const auto& keys = vertices_[p].side_keys[side];
      const auto found = std::lower_bound(keys.begin(), keys.end(), std::pair<Key, std::uint32_t>{key, 0},
                                          [](const auto& a, const auto& b) { return a.first < b.first; });
      return found->second;
    }
    auto& interior = vertices_[p].interior;
    const auto found = interior.find({u, v});
    if (found != interior.end()) return found->second;
    const double pu = patch.u_of(u), pv = patch.v_of(v);
    const std::uint32_t vertex = assembly_.add_vertex(to_vec3(patch.surface.point_at(pu, pv)));
    assembly_.add_normal(vertex, patch.surface.normal_at(pu, pv));
    interior.emplace(std::make_pair(u, v), vertex);
    return vertex;
  }

  /// Appends the vertices of one cell side, from (u_from, v_from) excluded
  /// towards (u_to, v_to) excluded (an axis-parallel segment).
  void append_side(std::size_t p, Key u_from, Key v_from, Key u_to, Key v_to, std::vector<LoopVertex>& loop) {
    const Patch& patch = patches_[p];
    const bool along_u = v_from == v_to;
    const Key fixed = along_u ? v_from : u_from;
    const Key from = along_u ? u_from : v_from, to = along_u ? u_to : v_to;
    const Key low = std::min(from, to), high = std::max(from, to);
    int side = -1;
    if (along_u && fixed == 0) side = 0;
    if (along_u && fixed == patch.v_end) side = 2;
    if (!along_u && fixed == 0) side = 3;
    if (!along_u && fixed == patch.u_end) side = 1;
    std::vector<LoopVertex> found;
    if (side >= 0) {
      if (edges_.degenerate[p * 4 + side]) return;  // one vertex: the corners already carry it
      const double s_low = side_s(p, side, low), s_high = side_s(p, side, high);
      const std::uint32_t end_low = along_u ? vertex_at(p, low, fixed) : vertex_at(p, fixed, low);
      const std::uint32_t end_high = along_u ? vertex_at(p, high, fixed) : vertex_at(p, fixed, high);
      for (const SideVertex& entry : vertices_[p].side_lists[side]) {
        if (entry.s <= s_low || entry.s >= s_high || entry.vertex == end_low || entry.vertex == end_high) continue;
        const auto uv = side_parameters(patch.surface, side, entry.s);
        found.push_back({entry.vertex, uv[0], uv[1]});
      }
    } else {
      const auto& lines = along_u ? vertices_[p].rows : vertices_[p].columns;
      const auto line = lines.find(fixed);
      if (line != lines.end()) {
        const auto& keys = line->second;
        for (auto it = std::upper_bound(keys.begin(), keys.end(), low); it != keys.end() && *it < high; ++it) {
          const Key u = along_u ? *it : fixed, v = along_u ? fixed : *it;
          found.push_back({vertex_at(p, u, v), patch.u_of(u), patch.v_of(v)});
        }
      }
    }
    if (from > to) std::reverse(found.begin(), found.end());
    loop.insert(loop.end(), found.begin(), found.end());
  }

  void triangulate(std::size_t p, std::size_t c) {
    const Patch& patch = patches_[p];
    const Cell& cell = cells_[p][c];
    const std::array<std::array<Key, 2>, 4> corners = {
        {{cell.u0, cell.v0}, {cell.u1, cell.v0}, {cell.u1, cell.v1}, {cell.u0, cell.v1}}};
    std::vector<LoopVertex> loop;
    std::vector<bool> is_corner;
    for (int k = 0; k < 4; ++k) {
      const auto& a = corners[k];
      const auto& b = corners[(k + 1) % 4];
      loop.push_back({vertex_at(p, a[0], a[1]), patch.u_of(a[0]), patch.v_of(a[1])});
      is_corner.push_back(true);
      append_side(p, a[0], a[1], b[0], b[1], loop);
      is_corner.resize(loop.size(), false);
    }
    // A collapsed side repeats one vertex: the triangles between two copies
    // are dropped below; each copy keeps its own (u, v), which is the right
    // one for the triangle on its side of the collapsed run.
    std::vector<std::uint32_t> distinct;
    for (const LoopVertex& vertex : loop) distinct.push_back(vertex.vertex);
    std::sort(distinct.begin(), distinct.end());
    if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3) return;
    const Key cu = cell.u0 + (cell.u1 - cell.u0) / 2, cv = cell.v0 + (cell.v1 - cell.v0) / 2;
    const double pu = patch.u_of(cu), pv = patch.v_of(cv);
    const std::uint32_t centre = assembly_.add_vertex(to_vec3(patch.surface.point_at(pu, pv)));
    assembly_.add_normal(centre, patch.surface.normal_at(pu, pv));
    const LoopVertex middle{centre, pu, pv};
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const LoopVertex& a = loop[i];
      const LoopVertex& b = loop[(i + 1) % loop.size()];
      if (a.vertex == b.vertex) continue;
      const bool plain = is_corner[i] && is_corner[(i + 1) % loop.size()];
      triangles_.push_back({{middle, a, b}, static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(c), !plain});
    }
  }

  /// Step 6: the triangle against the surface at 7 interior and edge points.
  bool triangle_within_tolerance(const Triangle& triangle) const {
    static constexpr std::array<std::array<double, 3>, 7> kWeights = {{{0.5, 0.5, 0.0},
                                                                       {0.0, 0.5, 0.5},
                                                                       {0.5, 0.0, 0.5},
                                                                       {1.0 / 3, 1.0 / 3, 1.0 / 3},
                                                                       {2.0 / 3, 1.0 / 6, 1.0 / 6},
                                                                       {1.0 / 6, 2.0 / 3, 1.0 / 6},
                                                                       {1.0 / 6, 1.0 / 6, 2.0 / 3}}};
    const SurfaceView& surface = patches_[triangle.patch].surface;
    const double limit = tolerances::kMeshSampledDeviationFraction * tolerance_;
    for (const auto& w : kWeights) {
      double u = 0.0, v = 0.0;
      Vec3 linear{};
      for (int k = 0; k < 3; ++k) {
        const LoopVertex& corner = triangle.corners[k];
        u += w[k] * corner.u;
        v += w[k] * corner.v;
        const Vec3& x = assembly_.position(corner.vertex);
        for (int c = 0; c < 3; ++c) linear[c] += w[k] * x[c];
      }
      if (norm(to_vec3(surface.point_at(u, v)) - linear) > limit) return false;
    }
    return true;
  }

  TriangleMesh finish() {
    TriangleMesh mesh;
    const std::size_t n = assembly_.vertex_count();
    std::vector<double> positions(n * 3), normals(n * 3);
    std::vector<Vec3> face_sums(n, Vec3{});
    mesh.triangles.reserve(triangles_.size());
    for (const Triangle& triangle : triangles_) {
      const std::array<std::uint32_t, 3> t = {triangle.corners[0].vertex, triangle.corners[1].vertex,
                                              triangle.corners[2].vertex};
      mesh.triangles.push_back(t);
      // Area-weighted face normals: the fallback where the surface has none.
      const Vec3 face = cross(assembly_.position(t[1]) - assembly_.position(t[0]),
                              assembly_.position(t[2]) - assembly_.position(t[0]));
      for (const std::uint32_t vertex : t) face_sums[vertex] += face;
    }
    for (std::size_t i = 0; i < n; ++i) {
      Vec3 normal = assembly_.normals[i];
      if (norm(normal) == 0.0) normal = face_sums[i];
      const double length = norm(normal);
      for (int c = 0; c < 3; ++c) {
        positions[i * 3 + c] = assembly_.position(static_cast<std::uint32_t>(i))[c];
        normals[i * 3 + c] = length > 0.0 ? normal[c] / length : 0.0;
      }
    }
    mesh.vertices = PointArray::from_trusted(3, std::move(positions));
    mesh.normals = PointArray::from_trusted(3, std::move(normals));
    return mesh;
  }

  std::vector<Patch> patches_;
  double tolerance_ = 0.0;
  EdgeStructure edges_;
  std::vector<std::vector<Cell>> cells_;
  Assembly assembly_;
  std::vector<Triangle> triangles_;
  std::vector<PatchVertices> vertices_;
  std::vector<std::uint32_t> corner_vertex_;
};

/// The largest absolute coordinate of the patches on a 9 x 9 parameter grid
/// each: the scale of the relative limits (tolerance floor, edge matching).
double scale_of_patches(std::span<const SurfaceView> patches) {
  constexpr int kSamples = 9;
  double scale = 0.0;
  for (const SurfaceView& patch : patches) {
    std::array<double, kSamples> us{}, vs{};
    for (int k = 0; k < kSamples; ++k) {
      us[k] = patch.domain_u().lerp(static_cast<double>(k) / (kSamples - 1));
      vs[k] = patch.domain_v().lerp(static_cast<double>(k) / (kSamples - 1));
    }
    std::vector<double> grid(kSamples * kSamples * 3);
    patch.grid_points_at(us, vs, grid);
    for (const double x : grid) scale = std::max(scale, std::abs(x));
  }
  return scale;
}

}  // namespace

Expected<TriangleMesh> tessellate(std::span<const SurfaceView> patches, Tolerance tolerance) {
  if (patches.empty()) return Error{"no surface to tessellate"};
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (patches[p].dimension() != 3) {
      return Error{"patch " + std::to_string(p) + " is in R^" + std::to_string(patches[p].dimension()) +
                   ", tessellation needs 3D surfaces"};
    }
  }
  const double e = tolerance.distance;
  if (!std::isfinite(e) || !(e > 0.0)) {
    return Error{"the tessellation tolerance is " + detail::number_text(e) + ", it must be finite and > 0"};
  }
  const double scale = scale_of_patches(patches);
  const double smallest = tolerances::kMeshSmallestToleranceFactor * 0x1p-52 * scale;
  if (e < smallest) {
    return Error{"the tessellation tolerance " + detail::number_text(e) + " is below what double precision can " +
                 "check on surfaces of size " + detail::number_text(scale) + " (at least " +
                 detail::number_text(smallest) + ")"};
  }
  // Shared edges agree to rounding; at least a tiny absolute distance so that
  // surfaces at the origin (scale 0) still compare.
  const double match_distance = std::max(tolerances::kMeshSharedEdgeRelative * scale, tolerances::kScaleFloor);
  Tessellator tessellator(patches, e, match_distance);
  return tessellator.run();
}

}  // namespace casteljau
