#pragma once
// Internal to tessellate (ops/tessellate.hpp): the mesh of the current
// quadtree cells, steps 4 and 5 of the method in tessellate.cpp.
//
// Vertices: one per corner class (tessellate_edges.hpp); along each shared
// edge the union of the cell corners of every side, merged when two sides put
// a vertex at the same normalized parameter (tolerances::kMeshSameEdgeParameter),
// so each shared vertex exists once (one index, one position: the first
// patch's); inside a patch one per integer corner. Normals: the surface's
// unit normal (normal_at, with its limit at poles), averaged over the patches
// that share the vertex; where no patch has one, the area-weighted normal of
// the vertex's triangles.
//
// Triangles: each cell is a fan from its centre through every vertex on its
// sides in counter-clockwise (u, v) order, the vertices of finer neighbours
// and of the other patch of a shared edge included: no T-junction, and the
// mesh is watertight across shared edges by construction. Consecutive
// repeats (a collapsed side) are dropped, so a pole gives no degenerate
// triangle. Counter-clockwise in (u, v) is counter-clockwise seen from
// S_u x S_v, the side normal_at points to.
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "casteljau/ops/mesh.hpp"
#include "tessellate_edges.hpp"
#include "casteljau/core/progress.hpp"
#include "tessellate_quadtree.hpp"

namespace casteljau::tessellation {

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

/// A triangle of the fan of one cell.
struct Triangle {
  std::array<LoopVertex, 3> corners;
  std::uint32_t patch = 0;
  std::uint32_t cell = 0;
  /// False for a triangle of the cell's plain fan (centre and two adjacent
  /// cell corners): the cell test has already sampled exactly that triangle.
  bool needs_check = true;
};

/// The vertices, normals and triangles of the patches' cells (one list per
/// patch), rebuilt by each assemble(); patches, edge structure and cells must
/// outlive it (the cells may change between calls).
class MeshAssembly {
 public:
  MeshAssembly(const std::vector<Patch>& patches, const EdgeStructure& edges,
               const std::vector<std::vector<Cell>>& cells)
      : patches_(patches), edges_(edges), cells_(cells) {}

  /// Steps 4 and 5 for the current cells: replaces the vertices and
  /// triangles of the previous call. Reports the cells triangulated as the
  /// part [from, to] of the whole work.
  void assemble(ProgressPart& progress, double from, double to);
  /// The triangles of the last assemble(), per patch in cell order.
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// The position of vertex `vertex`.
  const Vec3& position(std::uint32_t vertex) const { return positions_[vertex]; }
  /// The mesh of the last assemble(): positions, unit normals, triangles.
  TriangleMesh finish() const;

 private:
  /// The per-pass vertex tables of one patch.
  struct PatchVertices {
    std::map<std::pair<Key, Key>, std::uint32_t> interior;
    std::array<std::vector<std::pair<Key, std::uint32_t>>, 4> side_keys;  // sorted by key
    std::array<std::vector<SideVertex>, 4> side_lists;                    // sorted by s
    std::map<Key, std::vector<Key>> rows;     // v key -> sorted u keys of cell corners
    std::map<Key, std::vector<Key>> columns;  // u key -> sorted v keys of cell corners
  };

  std::uint32_t add_vertex(const Vec3& position);
  void add_normal(std::uint32_t vertex, const Point& normal);
  /// The cell corners of every patch by row, column and side.
  void collect_corner_keys();
  /// The normalized side parameter of key `key` on side `side` of patch p.
  double side_s(std::size_t p, int side, Key key) const;
  /// One vertex per corner class, with the normals of every patch there.
  void create_corner_vertices();
  /// The vertices strictly inside shared (or lone) sides: the union of the
  /// cell corners of every side of a group, merged across sides.
  void create_side_vertices();
  /// The mesh index of the cell corner (u, v) of patch p.
  std::uint32_t vertex_at(std::size_t p, Key u, Key v);
  /// Appends the vertices of one cell side, from (u_from, v_from) excluded
  /// towards (u_to, v_to) excluded (an axis-parallel segment).
  void append_side(std::size_t p, Key u_from, Key v_from, Key u_to, Key v_to, std::vector<LoopVertex>& loop);
  /// The fan of cell c of patch p.
  void triangulate(std::size_t p, std::size_t c);

  const std::vector<Patch>& patches_;
  const EdgeStructure& edges_;
  const std::vector<std::vector<Cell>>& cells_;
  std::vector<Vec3> positions_;
  std::vector<Vec3> normal_sums_;  // sums of the patches' unit normals
  std::vector<Triangle> triangles_;
  std::vector<PatchVertices> vertices_;
  std::vector<std::uint32_t> corner_vertex_;
};

}  // namespace casteljau::tessellation
