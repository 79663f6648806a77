#pragma once
// Wavefront OBJ: a triangle mesh as text (Wavefront's "Object Files" appendix
// of the Advanced Visualizer manual; read by Blender, MeshLab, meshio).

#include <string>

#include "casteljau/ops/mesh.hpp"

namespace casteljau {

/// The mesh as OBJ text: one "v x y z" line per vertex, one "vn x y z" per
/// normal (the same index), then one "f a//a b//b c//c" per triangle
/// (1-based indices, vertex and normal together, counter-clockwise seen from
/// the normals' side). Numbers in the shortest text that reads back to the
/// same double, so the positions survive the text exactly. O(size).
std::string to_obj(const TriangleMesh& mesh);

}  // namespace casteljau
