// Wavefront OBJ writer (io/obj.hpp). fmt's "{}" writes a double in the
// shortest form that reads back to the same value (Ryu-style, as model JSON).
#include "casteljau/io/obj.hpp"

#include <fmt/format.h>

#include <cassert>
#include <iterator>

namespace casteljau {

std::string to_obj(const TriangleMesh& mesh) {
  assert(mesh.vertices.dimension() == 3 && mesh.normals.dimension() == 3);
  assert(mesh.normals.size() == mesh.vertices.size());
  fmt::memory_buffer out;
  auto inserter = std::back_inserter(out);
  fmt::format_to(inserter, "# casteljau tessellation: {} vertices, {} triangles\n", mesh.vertices.size(),
                 mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto p = mesh.vertices[i];
    fmt::format_to(inserter, "v {} {} {}\n", p[0], p[1], p[2]);
  }
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    const auto n = mesh.normals[i];
    fmt::format_to(inserter, "vn {} {} {}\n", n[0], n[1], n[2]);
  }
  for (const auto& t : mesh.triangles) {
    // OBJ indices start at 1.
    fmt::format_to(inserter, "f {0}//{0} {1}//{1} {2}//{2}\n", t[0] + 1ULL, t[1] + 1ULL, t[2] + 1ULL);
  }
  return fmt::to_string(out);
}

}  // namespace casteljau
