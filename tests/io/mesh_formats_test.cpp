// The mesh writers byte for byte on a tetrahedron written by hand: the OBJ
// text in full (shortest round-trip numbers, 1-based f a//a), the binary STL
// layout (80-byte header, uint32 count, 50-byte facets of little-endian
// float32, facet normal from the vertices) and the binary PLY header and
// records (little-endian doubles, uchar 3 + uint32 indices). Expected bytes
// are assembled here from the formats' specifications, not from the writers.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "casteljau/io/obj.hpp"
#include "casteljau/io/ply.hpp"
#include "casteljau/io/stl.hpp"

namespace casteljau {
namespace {

TriangleMesh tetrahedron() {
  TriangleMesh mesh;
  mesh.vertices = PointArray::from_trusted(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.1});
  mesh.normals = PointArray::from_trusted(3, {0, 0, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int b = 3; b >= 0; --b) value = (value << 8) | static_cast<unsigned char>(bytes[at + b]);
  return value;
}

float le_float(const std::string& bytes, std::size_t at) {
  const std::uint32_t bits = le32(bytes, at);
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

double le_double(const std::string& bytes, std::size_t at) {
  std::uint64_t bits = 0;
  for (int b = 7; b >= 0; --b) bits = (bits << 8) | static_cast<unsigned char>(bytes[at + b]);
  double value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

TEST(MeshFormats, ObjTextInFull) {
  EXPECT_EQ(to_obj(tetrahedron()),
            "# casteljau tessellation: 4 vertices, 4 triangles\n"
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0.1\n"
            "vn 0 0 -1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\n"
            "f 1//1 3//3 2//2\nf 1//1 2//2 4//4\nf 1//1 4//4 3//3\nf 2//2 3//3 4//4\n");
}

TEST(MeshFormats, BinaryStlLayoutAndFacetNormals) {
  const std::string bytes = to_stl(tetrahedron());
  ASSERT_EQ(bytes.size(), 84u + 4 * 50);
  EXPECT_NE(bytes.substr(0, 5), "solid");
  EXPECT_EQ(le32(bytes, 80), 4u);
  // Facet 0 is (0, 2, 1): (1,0,0)... its normal (b - a) x (c - a) = (0,1,0) x (1,0,0) = (0,0,-1).
  EXPECT_EQ(le_float(bytes, 84), 0.0f);
  EXPECT_EQ(le_float(bytes, 88), 0.0f);
  EXPECT_EQ(le_float(bytes, 92), -1.0f);
  EXPECT_EQ(le_float(bytes, 96 + 12), 0.0f);   // vertex 2 = (0,1,0)
  EXPECT_EQ(le_float(bytes, 96 + 16), 1.0f);
  // Facet 3 is (1, 2, 3): normal (-1,1,0) x (-1,0,0.1) = (0.1, 0.1, 1) / |.|.
  const std::size_t facet = 84 + 3 * 50;
  const double length = std::sqrt(0.1 * 0.1 + 0.1 * 0.1 + 1.0);
  EXPECT_EQ(le_float(bytes, facet), static_cast<float>(0.1 / length));
  EXPECT_EQ(le_float(bytes, facet + 8), static_cast<float>(1.0 / length));
  EXPECT_EQ(le_float(bytes, facet + 12 + 36 - 4), 0.1f);  // vertex 3's z
  EXPECT_EQ(bytes[facet + 48], 0);
  EXPECT_EQ(bytes[facet + 49], 0);
}

TEST(MeshFormats, BinaryPlyHeaderAndRecords) {
  const std::string bytes = to_ply(tetrahedron());
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment written by casteljau\nelement vertex 4\n"
      "property double x\nproperty double y\nproperty double z\n"
      "property double nx\nproperty double ny\nproperty double nz\n"
      "element face 4\nproperty list uchar uint vertex_indices\nend_header\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 4 * 48 + 4 * 13);
  const std::size_t v3 = header.size() + 3 * 48;
  EXPECT_EQ(le_double(bytes, v3 + 16), 0.1);  // z of vertex 3, exact
  EXPECT_EQ(le_double(bytes, v3 + 40), 1.0);  // nz of vertex 3
  const std::size_t f3 = header.size() + 4 * 48 + 3 * 13;
  EXPECT_EQ(bytes[f3], 3);
  EXPECT_EQ(le32(bytes, f3 + 1), 1u);
  EXPECT_EQ(le32(bytes, f3 + 5), 2u);
  EXPECT_EQ(le32(bytes, f3 + 9), 3u);
}

}  // namespace
}  // namespace casteljau
