// The mesh of a tessellation's current cells (tessellate_assembly.hpp):
// vertices shared along patch sides and welded edges, one fan per cell.
#include "tessellate_assembly.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "casteljau/ops/tolerance.hpp"

namespace casteljau::tessellation {

std::uint32_t MeshAssembly::add_vertex(const Vec3& position) {
  positions_.push_back(position);
  normal_sums_.push_back(Vec3{});
  return static_cast<std::uint32_t>(positions_.size() - 1);
}

void MeshAssembly::add_normal(std::uint32_t vertex, const Point& normal) {
  normal_sums_[vertex] += to_vec3(normal);
}

void MeshAssembly::assemble(ProgressPart& progress, double from, double to) {
  positions_.clear();
  normal_sums_.clear();
  triangles_.clear();
  vertices_.assign(patches_.size(), PatchVertices{});
  collect_corner_keys();
  create_corner_vertices();
  create_side_vertices();
  std::size_t total = 0, done = 0;
  for (const auto& cells : cells_) total += cells.size();
  for (std::size_t p = 0; p < patches_.size(); ++p) {
    for (std::size_t c = 0; c < cells_[p].size(); ++c) {
      triangulate(p, c);
      progress(from, to, static_cast<double>(++done) / static_cast<double>(total));
    }
  }
}

void MeshAssembly::collect_corner_keys() {
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

double MeshAssembly::side_s(std::size_t p, int side, Key key) const {
  const Patch& patch = patches_[p];
  if (side == 0 || side == 2) {
    const Interval d = patch.surface.domain_u();
    return key == patch.u_end ? 1.0 : (patch.u_of(key) - d.lower) / d.length();
  }
  const Interval d = patch.surface.domain_v();
  return key == patch.v_end ? 1.0 : (patch.v_of(key) - d.lower) / d.length();
}

void MeshAssembly::create_corner_vertices() {
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
      if (i == 0) vertex = add_vertex(to_vec3(patches_[p].surface.point_at(uv[0], uv[1])));
      corner_vertex_[c] = vertex;
      if (std::find(seen_patches.begin(), seen_patches.end(), p) != seen_patches.end()) continue;
      seen_patches.push_back(p);
      add_normal(vertex, patches_[p].surface.normal_at(uv[0], uv[1]));
    }
  }
}

void MeshAssembly::create_side_vertices() {
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
        if (i == 0) vertex = add_vertex(to_vec3(patches_[p].surface.point_at(uv[0], uv[1])));
        key.second = vertex;
        if (std::find(seen_patches.begin(), seen_patches.end(), p) != seen_patches.end()) continue;
        seen_patches.push_back(p);
        add_normal(vertex, patches_[p].surface.normal_at(uv[0], uv[1]));
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

std::uint32_t MeshAssembly::vertex_at(std::size_t p, Key u, Key v) {
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
  const std::uint32_t vertex = add_vertex(to_vec3(patch.surface.point_at(pu, pv)));
  add_normal(vertex, patch.surface.normal_at(pu, pv));
  interior.emplace(std::make_pair(u, v), vertex);
  return vertex;
}

void MeshAssembly::append_side(std::size_t p, Key u_from, Key v_from, Key u_to, Key v_to,
                               std::vector<LoopVertex>& loop) {
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

void MeshAssembly::triangulate(std::size_t p, std::size_t c) {
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
  const std::uint32_t centre = add_vertex(to_vec3(patch.surface.point_at(pu, pv)));
  add_normal(centre, patch.surface.normal_at(pu, pv));
  const LoopVertex middle{centre, pu, pv};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const LoopVertex& a = loop[i];
    const LoopVertex& b = loop[(i + 1) % loop.size()];
    if (a.vertex == b.vertex) continue;
    const bool plain = is_corner[i] && is_corner[(i + 1) % loop.size()];
    triangles_.push_back({{middle, a, b}, static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(c), !plain});
  }
}

TriangleMesh MeshAssembly::finish() const {
  TriangleMesh mesh;
  const std::size_t n = positions_.size();
  std::vector<double> positions(n * 3), normals(n * 3);
  std::vector<Vec3> face_sums(n, Vec3{});
  mesh.triangles.reserve(triangles_.size());
  for (const Triangle& triangle : triangles_) {
    const std::array<std::uint32_t, 3> t = {triangle.corners[0].vertex, triangle.corners[1].vertex,
                                            triangle.corners[2].vertex};
    mesh.triangles.push_back(t);
    // Area-weighted face normals: the fallback where the surface has none.
    const Vec3 face = cross(position(t[1]) - position(t[0]), position(t[2]) - position(t[0]));
    for (const std::uint32_t vertex : t) face_sums[vertex] += face;
  }
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 normal = normal_sums_[i];
    if (norm(normal) == 0.0) normal = face_sums[i];
    const double length = norm(normal);
    for (int c = 0; c < 3; ++c) {
      positions[i * 3 + c] = positions_[i][c];
      normals[i * 3 + c] = length > 0.0 ? normal[c] / length : 0.0;
    }
  }
  mesh.vertices = PointArray::from_trusted(3, std::move(positions));
  mesh.normals = PointArray::from_trusted(3, std::move(normals));
  return mesh;
}

}  // namespace casteljau::tessellation
