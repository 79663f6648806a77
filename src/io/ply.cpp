// Binary little-endian PLY writer (io/ply.hpp).
#include "casteljau/io/ply.hpp"

#include <fmt/format.h>

#include <cassert>

#include "binary_output.hpp"

namespace casteljau {

std::string to_ply(const TriangleMesh& mesh) {
  assert(mesh.vertices.dimension() == 3 && mesh.normals.dimension() == 3);
  assert(mesh.normals.size() == mesh.vertices.size());
  std::string out = fmt::format(
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment written by casteljau\n"
      "element vertex {}\n"
      "property double x\nproperty double y\nproperty double z\n"
      "property double nx\nproperty double ny\nproperty double nz\n"
      "element face {}\n"
      "property list uchar uint vertex_indices\n"
      "end_header\n",
      mesh.vertices.size(), mesh.triangles.size());
  out.reserve(out.size() + 48 * mesh.vertices.size() + 13 * mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (const double x : mesh.vertices[i]) io_detail::append_double(out, x);
    for (const double x : mesh.normals[i]) io_detail::append_double(out, x);
  }
  for (const auto& t : mesh.triangles) {
    out.push_back(static_cast<char>(3));
    for (const std::uint32_t index : t) io_detail::append_le32(out, index);
  }
  return out;
}

}  // namespace casteljau
