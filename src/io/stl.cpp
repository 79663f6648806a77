// Binary STL writer (io/stl.hpp).
#include "casteljau/io/stl.hpp"

#include <cassert>
#include <cmath>

#include "binary_output.hpp"

namespace casteljau {

std::string to_stl(const TriangleMesh& mesh) {
  assert(mesh.vertices.dimension() == 3);
  std::string out;
  out.reserve(84 + 50 * mesh.triangles.size());
  // A header that does not begin with "solid": some readers take such files for ASCII STL.
  std::string header = "binary STL written by casteljau";
  header.resize(80, ' ');
  out += header;
  io_detail::append_le32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const auto a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double f[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x = length > 0.0 ? x / length : 0.0;
    for (const double x : n) io_detail::append_float(out, static_cast<float>(x));
    for (const auto& vertex : {a, b, c}) {
      for (int k = 0; k < 3; ++k) io_detail::append_float(out, static_cast<float>(vertex[k]));
    }
    io_detail::append_le16(out, 0);
  }
  return out;
}

}  // namespace casteljau
