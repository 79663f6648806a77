#pragma once
// PLY, the Stanford polygon file format (Turk 1994), in its binary
// little-endian form.

#include <string>

#include "casteljau/ops/mesh.hpp"

namespace casteljau {

/// The mesh as binary PLY, returned as bytes in a std::string. The ASCII
/// header declares `format binary_little_endian 1.0`, an element `vertex`
/// with properties `double x, y, z, nx, ny, nz` and an element `face` with
/// `property list uchar uint vertex_indices`. Doubles, not floats, so that the
/// positions and normals survive exactly (STL is the compact, float, format);
/// uint indices because a mesh may have up to tolerances::kMaxMeshTriangles
/// triangles, beyond a ushort or a signed int's comfortable range for
/// readers. Each face is a list of 3 (uchar) followed by three uint32 indices,
/// counter-clockwise seen from the normals' side. Size: header + 48 v + 13 t
/// bytes, O(v + t).
std::string to_ply(const TriangleMesh& mesh);

}  // namespace casteljau
